#pragma once
// The six fuzz targets, what a check of one of their cases returns (Verdict), and a corpus file
// described readably (Seed). Each target's byte format, decoder, check, description, picture and
// seeds are in cases/<target>.h, named after the libFuzzer main in fuzz/; geodex/verify/repro.h
// dispatches by target and runs `geodex repro`.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "geodex/degeneracy.h"

namespace geodex::verify {

enum class FuzzTarget : std::uint8_t { MeshIo, Predicates, EdgeUpdate, Propagation, TwoFaces, Solver };
inline constexpr std::array<FuzzTarget, 6> kFuzzTargets{
    FuzzTarget::MeshIo,      FuzzTarget::Predicates, FuzzTarget::EdgeUpdate,
    FuzzTarget::Propagation, FuzzTarget::TwoFaces,   FuzzTarget::Solver};

/// "fuzz_mesh_io", "fuzz_predicates", "fuzz_edge_update", "fuzz_propagation", "fuzz_two_faces",
/// "fuzz_solver".
std::string_view name(FuzzTarget t);
/// Accepts the full name or the part after "fuzz_" ("solver"); nullopt otherwise.
std::optional<FuzzTarget> parseFuzzTarget(std::string_view s);

struct Verdict {
  /// The bytes decoded into a case (false: skipped, which is a pass).
  bool interesting = false;
  /// Empty when every check passed; else the name of the first broken check: an invariant of
  /// InvariantChecker ("pointwise-min", …), an oracle ("euclidean-lower-bound", "upper-bound",
  /// "lipschitz", "planar-agreement", "two-face-distance", "unfolding", "path-length",
  /// "stop-distance", "symmetry", "edge-query", "distance-values"), "exact-predicates",
  /// "scale-invariance", "child-range", "coverage", "soundness", "invented-source", "slice",
  /// "unexpected-exception", "validated-mesh-refused", "soup-shape", "round-trip",
  /// "mesh-geometry", "internal-check".
  std::string failed;
  std::string message;  ///< what broke, with the numbers
  std::string summary;  ///< one line on what the case exercised
  /// G1–G5 (Fig. 6 branches) and D1–D4 (Algorithm 2 reports) the case hit.
  DegeneracyCounters degeneracies;
  bool ok() const { return failed.empty(); }
};

// Each target's decoded input, defined in its cases/<target>.h.
struct MeshIoCase;
struct PredicateCase;
struct EdgeUpdateCase;
struct PropagationCase;
struct TwoFaceCase;
struct SolverCase;
/// A decoded input of any target.
using FuzzCase =
    std::variant<MeshIoCase, PredicateCase, EdgeUpdateCase, PropagationCase, TwoFaceCase, SolverCase>;

/// A corpus file described readably. Each target's cases/<target>.h returns its own
/// (predicateSeeds(), solverSeeds(), …; seeds(FuzzTarget) in repro.h asks the right one), and
/// fuzz/make_seeds writes them to corpus/<target>/<dir>/<name>, or with --check verifies that the
/// committed files are exactly these bytes and still are what their names say.
struct Seed {
  std::string name;
  std::vector<std::uint8_t> bytes;
  /// Returns "" when the seed is what its name says, else why not.
  std::function<std::string(const FuzzCase&, const Verdict&)> expect;
  /// "seed", or "regress" for reproducers of bugs (written here when they can be described).
  std::string dir = "seed";
  /// A regress file named open-*: a bug not fixed yet; the check it fails (with GEODEX_CHECKS).
  std::string openCheck = {};
  /// A reproducer whose fix is that the input is now refused, so the target skips its bytes.
  bool refusedNow = false;
};

}  // namespace geodex::verify
