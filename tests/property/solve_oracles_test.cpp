// Whole solves on small generated meshes against oracles that share nothing with the solver
// (verify/oracles.h): Euclidean distance on planar convex meshes, the visibility graph on planar
// domains with holes and reflex corners, Euclidean ≤ d ≤ edge-graph Dijkstra and 1-Lipschitz on
// any mesh, and traced paths whose length is the distance. The full-tier invariant checker
// watches every solve (solve_helpers.h).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <sstream>

#include "generators.h"
#include "solve_helpers.h"

namespace geodex::proptest {
namespace {

std::string at(std::size_t v, double got, double want) {
  std::ostringstream os;
  os.precision(17);
  os << " (vertex " << v << ": " << got << " vs " << want << ")";
  return os.str();
}

RC_GTEST_PROP(WholeSolve, PlanarConvexMeshesGiveEuclideanDistances, ()) {
  MeshCase mc = *gen::planarConvexMeshCase();
  const double scale = *gen::decimalScale();
  for (Vec3& p : mc.soup.positions) p *= scale;
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, src.kind);
  const Solved s = solveChecked(mesh, {src.point});
  const auto euclid = verify::euclideanDistances(mc.soup.positions,
                                                 verify::surfacePointPosition(mc.soup, src.point));
  const double err = maxDifference(s.distances, euclid);
  recordAccuracy("planar convex vs Euclidean", err / mesh.boundingBoxDiagonal());
  if (!(err <= kAccuracy * mesh.boundingBoxDiagonal())) {
    const std::size_t v = worstIndex(s.distances, euclid);
    RC_FAIL("scaled by " + std::to_string(scale) + ": error " +
            std::to_string(err / mesh.boundingBoxDiagonal()) + " x diagonal" +
            at(v, s.distances[v], euclid[v]));
  }
}

RC_GTEST_PROP(WholeSolve, PlanarDomainsWithBoundaryMatchTheVisibilityGraph, ()) {
  const MeshCase mc = *gen::planarDomainMeshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, src.kind);
  const Solved s = solveChecked(mesh, {src.point});
  const Vec3 p = verify::surfacePointPosition(mc.soup, src.point);
  const auto exact =
      verify::planarDomainDistances(verify::planarBoundaryPolygons(mc.soup), Vec2(p.x(), p.y()),
                                    verify::planarPositions(mc.soup));
  const double err = maxDifference(s.distances, exact);
  recordAccuracy("planar domain vs visibility graph", err / mesh.boundingBoxDiagonal());
  if (!(err <= kAccuracy * mesh.boundingBoxDiagonal())) {
    const std::size_t v = worstIndex(s.distances, exact);
    RC_FAIL("error " + std::to_string(err / mesh.boundingBoxDiagonal()) + " x diagonal" +
            at(v, s.distances[v], exact[v]));
  }
}

// On any mesh: Euclidean ≤ d ≤ edge-graph Dijkstra, and |d(u) − d(v)| ≤ |uv| on every edge.
// verify/'s checks allow relTol × (|bound| + largest value): the accuracy contract.
RC_GTEST_PROP(WholeSolve, DistancesLieBetweenEuclideanAndEdgeGraphAndAreLipschitz, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, src.kind);
  const Solved s = solveChecked(mesh, {src.point});
  const auto euclid = verify::euclideanDistances(mc.soup.positions,
                                                 verify::surfacePointPosition(mc.soup, src.point));
  const auto graph = verify::edgeGraphDijkstra(mesh, std::vector<SurfacePoint>{src.point});
  const auto lower = verify::checkEuclideanLowerBound(s.distances, euclid, kAccuracy);
  if (!lower.ok()) RC_FAIL("below the Euclidean distance: " + lower.summary());
  const auto upper = verify::checkUpperBound(s.distances, graph, kAccuracy);
  if (!upper.ok()) RC_FAIL("above the edge-graph distance: " + upper.summary());
  const auto lipschitz = verify::checkLipschitz(mesh, s.distances, kAccuracy);
  if (!lipschitz.ok()) RC_FAIL("not 1-Lipschitz along edges: " + lipschitz.summary());
}

// A traced path starts at the target, ends at a source, and is as long as the distance.
RC_GTEST_PROP(WholeSolve, PathLengthEqualsDistance, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  const SourceCase target = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, target.kind);
  GeodesicSolver solver(mesh);
  solveChecked(mesh, {src.point}, &solver);
  const double tol = kAccuracy * mesh.boundingBoxDiagonal();
  const double d = solver.distance(target.point);
  RC_ASSERT(std::isfinite(d));
  const GeodesicPath path = solver.path(target.point);
  std::ostringstream ctx;
  ctx.precision(17);
  ctx << "source " << formatSurfacePoint(src.point) << ", target "
      << formatSurfacePoint(target.point) << ": distance " << d << ", path length " << path.length
      << " over " << path.points.size() << " points";
  if (path.points.empty()) RC_FAIL("no path: " + ctx.str());
  const Vec3 from = verify::surfacePointPosition(mc.soup, target.point);
  const Vec3 to = verify::surfacePointPosition(mc.soup, src.point);
  if (!((path.points.front().position - from).norm() <= tol))
    RC_FAIL("the path does not start at the target: " + ctx.str());
  if (!((path.points.back().position - to).norm() <= tol))
    RC_FAIL("the path does not end at the source: " + ctx.str());
  recordAccuracy("path length vs distance", std::abs(path.length - d) / mesh.boundingBoxDiagonal());
  if (!(std::abs(path.length - d) <= tol))
    RC_FAIL("path length differs from the distance: " + ctx.str());
}

}  // namespace
}  // namespace geodex::proptest
