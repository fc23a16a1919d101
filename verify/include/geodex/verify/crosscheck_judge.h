#pragma once
// How `geodex crosscheck` judges what another exact-geodesic program wrote for a case: against
// geodex's distances, computed with the full checking tier (fuzz_solver's checkSolver: the step-6
// invariants at every edge update, the unfolding check, the bounds, Lipschitz, the planar oracles
// where the case is planar), and against the independent oracles themselves on the program's
// distances. Running the program is the caller's (apps/external_program.h); this is the part
// that needs no process.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/verify/crosscheck_cases.h"

namespace geodex::verify {

/// What can be wrong with a program's run on one case.
enum class FindingKind : std::uint8_t {
  WrongDistance,  ///< off by more than the tolerance × the largest distance, or an oracle broken
  Reachability,   ///< reachable where geodex finds unreachable, or the other way round
  LineCount,      ///< not one line per vertex (a missing output file has none)
  BadValue,       ///< a line that is not one number
  Crash,          ///< non-zero exit status, or killed by a signal
  Timeout,        ///< still running at the time limit (its process group was killed)
};
inline constexpr std::size_t kNumFindingKinds = 6;

/// "wrong-distance", "reachability", "line-count", "bad-value", "crash", "timeout": the names in
/// finding directories and reports.
std::string_view name(FindingKind k);

/// A value at or above this in a program's output means unreachable: reference codes print
/// their "infinity" (1e100 in Kirsanov's MMP and VTP) rather than inf.
inline constexpr double kUnreachableAtLeast = 1e99;

/// Below this relative tolerance the oracles are not asked for more: it is the accuracy they
/// (and geodex, DESIGN.md) are held to.
inline constexpr double kOracleRel = 1e-9;

/// geodex's answer for a case.
struct Reference {
  std::vector<double> distances;  ///< #V, file units, +inf unreachable
  /// Non-empty when geodex's own checks failed on the case (a geodex bug, to report): the case
  /// cannot be judged.
  std::string problem;
  /// The degeneracies the case exercises: Fig. 6's G1–G5 and Algorithm 2's D1–D4 as counted in
  /// geodex's solve, and the mesh-level ones (flat vertices, needles, zero-area faces,
  /// boundaries, components, …), e.g. "G4 ×3".
  std::vector<std::string> exercised;
};

/// Solves the case with every check on. Never throws for a mesh geodex refuses: that is a
/// problem too.
Reference referenceDistances(const CrossCheckCase& c);

/// A program's output file, one value per line, read without trusting it.
struct ProgramDistances {
  std::vector<double> values;  ///< one per line; +inf for every way of writing "unreachable"
  std::size_t badLine = 0;     ///< the first line (1-based) that is not one number; 0 if none
  std::string badText;         ///< that line, shortened
};

/// Each line: optional blanks, one number strtod reads (inf, nan and exponents included),
/// optional blanks. inf, nan, a negative value and anything ≥ kUnreachableAtLeast mean
/// unreachable. A last line without a newline counts; an empty text has no lines.
ProgramDistances parseDistances(std::string_view text);

struct VertexError {
  Index vertex = 0;
  double expected = 0.0, got = 0.0;
  double error = 0.0;  ///< |got − expected|; +inf where one of them is unreachable
};

struct Judgement {
  std::optional<FindingKind> kind;  ///< none: the program agrees
  std::string what;                 ///< one line saying what is wrong
  double largestDistance = 0.0;     ///< the scale of the tolerance: geodex's largest finite distance
  double allowed = 0.0;             ///< the error allowed: tolerance × that scale
  std::vector<VertexError> worst;   ///< up to kWorstVertices, worst first
  /// #V: |got − expected| per vertex, +inf where reachability differs (empty when the output had
  /// the wrong length or a bad line)
  std::vector<double> error;
  std::vector<std::string> oracles;  ///< one line per oracle run on the program's distances
};
inline constexpr std::size_t kWorstVertices = 8;

/// Judges a program's distances; `tolerance` is relative to the largest distance.
Judgement judgeDistances(const CrossCheckCase& c, const Reference& reference, const ProgramDistances& got,
                         double tolerance);

}  // namespace geodex::verify
