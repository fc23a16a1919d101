#pragma once
// `geodex check`: one solve with the step-6 invariants checked live and the Fig. 6 decisions
// re-evaluated exactly, then the oracles of DESIGN.md, each independent of the solver's logic:
//
//   bounds            Euclidean ≤ d ≤ edge-graph Dijkstra
//   lipschitz         |d(u) − d(v)| ≤ |uv| on every edge
//   planar            planar meshes: Euclidean (convex) / visibility-graph paths (non-convex)
//   symmetry          d(a, b) = d(b, a) for a few far vertices b of the first source a
//   metamorphic       rigid motion, scaling by 1e-6 and 1e+6, vertex relabelling, face
//                     reordering, 1→3 coplanar face splits leave distances unchanged (or scaled)
//   paths             traced paths: length = distance, straight when unfolded, bending only at
//                     pseudo-source vertices
//   exact-predicates  the ε decision of every Fig. 6 case equals the exact one away from ε
//   cgal              CGAL Surface_mesh_shortest_path (advisory: reported, never a verdict —
//                     Epick is only good to ~1e-7 and wrong by 1% on some CAD meshes)

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "geodex/geodesic_solver.h"
#include "geodex/verify/invariant_checker.h"

namespace geodex::verify {

struct OracleResult {
  OracleResult() = default;
  explicit OracleResult(std::string oracleName) : name(std::move(oracleName)) {}
  std::string name;
  std::uint64_t checked = 0;
  std::uint64_t failed = 0;
  double maxError = 0.0;     ///< relative, as the oracle defines it (see check.cpp)
  std::string firstFailure;  ///< empty when none failed
  bool advisory = false;     ///< reported but never fails the check (cgal)
};

struct CheckOptions {
  CheckLevel level = CheckLevel::Cheap;
  /// Oracles to run (names above); empty means all but cgal.
  std::vector<std::string> oracles;
  /// When set, the `cgal` oracle: distances per vertex from the sources (the CLI provides it
  /// when built with CGAL).
  std::function<std::vector<double>(const TriangleSoup&, const std::vector<SurfacePoint>&)> cgal;
  /// Where to write a reproducer of the first failure (empty: none).
  std::string reproducerPath;
  std::string meshPath;  ///< for the reproducer and reports
};

struct CheckResult {
  DegeneracyCounters counters;
  SolveStats stats;
  std::vector<InvariantTally> invariants;
  std::vector<OracleResult> oracles;
  std::vector<std::string> violations;  ///< one sentence each, first first
  std::string reproducer;               ///< file written, or empty
  bool ok() const { return violations.empty(); }
};

// The oracles on a given distance field `d` (per vertex, from `sources`), so that a test can hand
// them a perturbed field and see them fail. runChecks() calls these with the solver's field.
OracleResult planarOracle(const Mesh& mesh, const std::vector<SurfacePoint>& sources, std::span<const double> d);
OracleResult metamorphicOracle(const Mesh& mesh, const std::vector<SurfacePoint>& sources, std::span<const double> d);
/// `dFromA`: the field of the single source `a`.
OracleResult symmetryOracle(const Mesh& mesh, const SurfacePoint& a, std::span<const double> dFromA);
/// Traces paths with `solver` (already solved) and compares their lengths with `d`.
OracleResult pathOracle(const GeodesicSolver& solver, std::span<const double> d);
/// One Fig. 6 case: whether `decided` matches the exact decision; false when the configuration
/// is too close to ambiguity to judge (then `agrees` is not set).
bool judgeFig6(const LocalWindow& w, Fig6Branch decided, bool& agrees);

/// All oracle names, in report order.
const std::vector<std::string>& oracleNames();

/// Runs the solve with checks and the chosen oracles. Throws InputError for unknown oracles or
/// bad sources.
CheckResult runChecks(const Mesh& mesh, const std::vector<SurfacePoint>& sources,
                      const CheckOptions& options);

void writeCheckText(std::ostream& out, const CheckResult& r);
/// One JSON object: {"cases", "degeneracies", "violations", "invariants", "oracles", "ok", ...}.
void writeCheckJson(std::ostream& out, const CheckResult& r);

}  // namespace geodex::verify
