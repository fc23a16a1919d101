#pragma once
// What the whole-solve properties share: a solve watched by the full-tier invariant checker whose
// degeneracy counters go to the coverage gate, and the accuracy the properties hold results to.

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "coverage.h"
#include "generators.h"
#include "geodex/geodesic_solver.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/oracles.h"

namespace geodex::proptest {

/// The solver's accuracy contract (DESIGN.md; tolerance.h's "1e-9 × diagonal accuracy target"):
/// every distance within this × the mesh's bounding-box diagonal of the exact one. Properties that
/// compare a solve with an exact oracle use it as it is.
inline constexpr double kAccuracy = 1e-9;
/// Two solves that both meet the contract differ by at most twice it: the tolerance of every
/// property comparing two solves (metamorphic relations, symmetry, adding a source).
inline constexpr double kTwoSolves = 2.0 * kAccuracy;

struct Solved {
  std::vector<double> distances;
  DegeneracyCounters counters;
};

/// Where a failing solve's mesh is written (the current directory: build/<preset>/tests/property
/// under CTest). The last failing solve of a run is the shrunk one: it overwrites the others.
inline constexpr const char* kFailureMeshFile = "property-failure.off";

/// Writes a soup as OFF with round-trip precision.
inline void writeOff(const TriangleSoup& soup, const std::string& path) {
  if (std::FILE* f = std::fopen(path.c_str(), "w")) {
    std::fprintf(f, "OFF\n%zu %zu 0\n", soup.positions.size(), soup.faces.size());
    for (const Vec3& p : soup.positions)
      std::fprintf(f, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    for (const auto& t : soup.faces) std::fprintf(f, "3 %u %u %u\n", t[0], t[1], t[2]);
    std::fclose(f);
  }
}

/// Forwards every event to two observers.
struct TeeObserver : SolverObserver {
  SolverObserver& first;
  SolverObserver& second;
  TeeObserver(SolverObserver& a, SolverObserver& b) : first(a), second(b) {}
  void onPropagation(const PropagationEvent& e) override {
    first.onPropagation(e);
    second.onPropagation(e);
  }
  void onEdgeUpdate(const EdgeUpdateEvent& e) override {
    first.onEdgeUpdate(e);
    second.onEdgeUpdate(e);
  }
  void onWindowDropped(const WindowDroppedEvent& e) override {
    first.onWindowDropped(e);
    second.onWindowDropped(e);
  }
  void onFinish(const GeodesicSolver& s) override {
    first.onFinish(s);
    second.onFinish(s);
  }
};

/// Solves with verify::InvariantChecker(CheckLevel::Full) attached (and `extra`, if given); fails
/// the property at the first violated step-6 or end-of-run invariant. The counters go to the
/// coverage gate.
inline Solved solveChecked(const Mesh& mesh, const std::vector<SurfacePoint>& sources,
                           GeodesicSolver* reuse = nullptr, SolverObserver* extra = nullptr) {
  GeodesicSolver local(mesh);
  GeodesicSolver& solver = reuse != nullptr ? *reuse : local;
  verify::InvariantChecker checker(verify::CheckLevel::Full, /*throwOnViolation=*/false);
  TeeObserver tee(checker, extra != nullptr ? *extra : checker);
  solver.setObserver(extra != nullptr ? static_cast<SolverObserver*>(&tee) : &checker);
  solver.solve(sources);
  solver.setObserver(nullptr);
  recordSolve(solver.counters());
  if (const verify::InvariantViolation* v = checker.firstViolation()) {
    std::ostringstream os;
    os.precision(17);
    writeOff(mesh.soup(), kFailureMeshFile);
    os << v->what() << "\n  mesh written to "
       << (std::filesystem::current_path() / kFailureMeshFile).string() << "; replay: geodex check "
       << kFailureMeshFile << " --level full";
    for (const SurfacePoint& p : sources) os << " --source " << formatSurfacePoint(p);
    if (v->edge != kNoIndex) {
      os << "\n  edge " << v->edge << " (length " << v->edgeLength << "), incoming from "
         << v->branch << ":";
      for (const Interval& w : v->incoming)
        os << " [" << w.b0 << ", " << w.b1 << "] s=(" << w.source.x() << ", " << w.source.y()
           << ") sigma=" << w.sigma;
    }
    RC_FAIL(os.str());
  }
  const auto d = solver.vertexDistances();
  return {{d.begin(), d.end()}, solver.counters()};
}

/// Largest |a[i] − b[i]| over the entries where both are finite; +inf if one is finite and the
/// other is not.
inline double maxDifference(std::span<const double> a, std::span<const double> b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isfinite(a[i]) != std::isfinite(b[i])) return INFINITY;
    if (std::isfinite(a[i])) worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst;
}

/// Index of the entry where |a − b| is largest (for messages).
inline std::size_t worstIndex(std::span<const double> a, std::span<const double> b) {
  std::size_t best = 0;
  double worst = -1.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = std::isfinite(a[i]) && std::isfinite(b[i]) ? std::abs(a[i] - b[i]) : INFINITY;
    if (d > worst) {
      worst = d;
      best = i;
    }
  }
  return best;
}

inline std::string describeCounters(const DegeneracyCounters& c) {
  std::ostringstream os;
  for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k)
    os << (k ? " " : "") << name(static_cast<DegeneracyKind>(k)) << "=" << c.count[k];
  os << " cases=" << c.cases;
  return os.str();
}

}  // namespace geodex::proptest
