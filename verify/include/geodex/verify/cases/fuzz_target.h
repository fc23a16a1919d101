#pragma once
// The six fuzz targets and what a check of one of their cases returns (Verdict). Each target's
// byte format, decoder, check, description, picture and seeds are in cases/<target>.h, beside
// the libFuzzer main of the same name in fuzz/; geodex/verify/repro.h dispatches by target and
// runs `geodex repro`.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

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

}  // namespace geodex::verify
