// The mesh cases' shared steps: validation, the Mesh, a checked solve, the unfolding check
// (mesh_case.h).
#include "mesh_case.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "check_support.h"
#include "geodex/error.h"
#include "geodex/mesh_io.h"
#include "geodex/tolerance.h"
#include "geodex/verify/invariant_checker.h"

namespace geodex::verify::detail {
namespace {

struct UnfoldingFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// True if one of the solve's vertex distances is beyond the largest double in file units.
bool someDistanceOverflows(const GeodesicSolver& solver) {
  for (double d : solver.vertexDistancesInMeshUnits())
    if (inFileUnitsRange(d, solver.mesh().meshUnit()) == ScaledRange::Overflow) return true;
  return false;
}

}  // namespace

bool soupValid(const TriangleSoup& soup) {
  std::vector<MeshIssue> issues;
  validateMesh(soup, issues);
  for (const MeshIssue& i : issues)
    if (i.severity == Severity::Error) return false;
  return true;
}

std::optional<Mesh> buildMesh(const TriangleSoup& soup, Verdict& v) {
  try {
    return Mesh(soup);
  } catch (const std::exception& e) {
    fail(v, "validated-mesh-refused", std::string("validateMesh found no error but Mesh threw: ") + e.what());
    return std::nullopt;
  }
}

std::string describeSoup(const TriangleSoup& soup) {
  std::ostringstream os;
  os << std::setprecision(17) << "OFF\n" << soup.positions.size() << " " << soup.faces.size() << " 0\n";
  for (const Vec3& p : soup.positions) os << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& f : soup.faces) os << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  return os.str();
}

// ===  The unfolding check =======================================================================

void UnfoldingChecker::checkChild(const PropagationEvent& p, const MadeChild& made) {
  const Index face = p.face, edge = p.edge;
  const Interval& window = p.window;
  const Edge& E = mesh_.edge(edge);
  const Edge& C = mesh_.edge(made.edge);
  const Interval& child = made.interval;
  auto why = [&] {
    std::ostringstream os;
    os << std::setprecision(17) << "window " << describeInterval(window) << " on edge " << edge
       << " (" << E.vertex[0] << "-" << E.vertex[1] << ") crossing face " << face << " made "
       << describeInterval(child) << " on edge " << made.edge << " (" << C.vertex[0] << "-"
       << C.vertex[1] << ") by branch " << name(p.result.branch) << ": ";
    return os.str();
  };
  if (mesh_.localEdgeIndex(face, made.edge) < 0 || made.edge == edge)
    throw UnfoldingFailure(why() + "the child is not on another edge of the crossed face");
  if (child.side != mesh_.sideOf(made.edge, face))
    throw UnfoldingFailure(why() + "the child's source is not on the crossed face's side");
  if (child.sigma != window.sigma || child.origin != window.origin)
    throw UnfoldingFailure(why() + "the child's sigma or origin differs from its parent's");
  // In mesh units, as the intervals are.
  const auto at = [&](Index x) { return mesh_.positionInMeshUnits(x); };
  const Vec3 o = at(E.vertex[0]);
  const Vec3 dir = (at(E.vertex[1]) - o).normalized();
  Index apex = kNoIndex;
  for (Index x : mesh_.face(face))
    if (x != E.vertex[0] && x != E.vertex[1]) apex = x;
  const Vec3 rel = at(apex) - o;
  const Vec3 perp = rel - rel.dot(dir) * dir;
  const double h = perp.norm();
  const double scale = std::max(rel.norm(), E.length);
  if (!(h > 1e-9 * scale)) return;  // zero-area or needle face: no reliable in-plane normal
  const Vec3 n = perp / h;
  const Vec3 s3 = o + window.source.x() * dir - window.source.y() * n;
  const Vec3 co = at(C.vertex[0]);
  const Vec3 cdir = (at(C.vertex[1]) - co).normalized();
  // The normal's rounding grows as the face gets thinner, and moves s3 by that × |s|.
  const double amplification = 1e-14 * window.source.norm() * (rel.norm() / h);
  // s3 and the sample point are placed in 3D, each to the rounding of its coordinates
  // (tol::kPositionRoundingRel): far from the origin that is more than a small face's
  // unfolding can be checked to
  // (corpus/fuzz_two_faces/regress/unfolding-points-placed-far-from-origin).
  const double placing = 2.0 * tol::kPositionRoundingRel *
                         std::max({o.cwiseAbs().maxCoeff(), co.cwiseAbs().maxCoeff(), s3.cwiseAbs().maxCoeff()});
  for (double x : {child.b0, 0.5 * (child.b0 + child.b1), child.b1}) {
    const double truth = (co + x * cdir - s3).norm();
    const double claim = std::hypot(x - child.source.x(), child.source.y());
    const double tolerance = 1e-11 * (truth + C.length + E.length) + amplification + placing;
    ++checked;
    if (!(std::abs(claim - truth) <= tolerance)) {
      std::ostringstream os;
      os << std::setprecision(17) << why() << "at x = " << x << " the child gives sigma + " << claim
         << " but the unfolded parent source is " << truth << " away";
      throw UnfoldingFailure(os.str());
    }
  }
}

bool solveChecked(GeodesicSolver& solver, std::span<const SurfacePoint> sources,
                  const SolveOptions& options, Verdict& v) {
  try {
    solver.solve(sources, options);
    return true;
  } catch (const InputError& e) {
    if (e.kind() == "distance-overflow" && someDistanceOverflows(solver)) return true;
    fail(v, "unexpected-exception", e.what());
  } catch (const InvariantViolation& e) {
    std::ostringstream os;
    os << e.what() << "\n  edge " << e.edge << " length " << fmt(e.edgeLength) << " branch " << e.branch;
    for (const Interval& w : e.before) os << "\n  before   " << describeInterval(w);
    for (const Interval& w : e.incoming) os << "\n  incoming " << describeInterval(w);
    for (const Interval& w : e.after) os << "\n  after    " << describeInterval(w);
    fail(v, e.invariant(), os.str());
  } catch (const UnfoldingFailure& e) {
    fail(v, "unfolding", e.what());
  } catch (const InternalError& e) {
    fail(v, "internal-check", e.what());
  } catch (const std::exception& e) {
    fail(v, "unexpected-exception", e.what());
  }
  return false;
}

}  // namespace geodex::verify::detail
