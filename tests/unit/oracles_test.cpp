// Tests of verify/src/oracles.cpp (and verify/src/cgal_oracle.cpp when CGAL is there): the
// oracles give known exact answers, and every bound check fails on a deliberately broken field
// (a checker that cannot fail checks nothing).

#include "geodex/verify/oracles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geodex/verify/mesh_generators.h"

#ifdef GEODEX_HAVE_CGAL_ORACLE
#include "geodex/verify/cgal_oracle.h"
#endif

namespace geodex::verify {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Index of the vertex at (x, y) in a soup (exact match).
Index vertexAt(const TriangleSoup& soup, double x, double y) {
  for (std::size_t v = 0; v < soup.positions.size(); ++v)
    if (soup.positions[v].x() == x && soup.positions[v].y() == y) return static_cast<Index>(v);
  ADD_FAILURE() << "no vertex at (" << x << ", " << y << ")";
  return 0;
}

// === Euclidean =================================================================================

TEST(Oracles, EuclideanDistances) {
  const std::vector<Vec3> points{{0, 0, 0}, {3, 4, 0}, {1, 2, 2}};
  EXPECT_EQ(euclideanDistances(points, Vec3(0, 0, 0)), (std::vector<double>{0, 5, 3}));
  const std::vector<Vec3> sources{{0, 0, 0}, {3, 4, 1}};
  EXPECT_EQ(euclideanDistances(points, sources), (std::vector<double>{0, 1, 3}));
}

TEST(Oracles, SurfacePointPosition) {
  const TriangleSoup soup = gridMesh(2, 2, 2.0, 2.0);
  EXPECT_EQ(surfacePointPosition(soup, SurfacePoint::atVertex(4)), Vec3(1, 1, 0));
  EXPECT_TRUE(surfacePointPosition(soup, SurfacePoint::onEdge(0, 1, 0.25))
                  .isApprox(Vec3(0.25, 0, 0)));
  const auto& f = soup.faces[0];
  const Vec3 expected = 0.2 * soup.positions[f[0]] + 0.3 * soup.positions[f[1]] +
                        0.5 * soup.positions[f[2]];
  EXPECT_EQ(surfacePointPosition(soup, SurfacePoint::inFace(0, 0.2, 0.3, 0.5)), expected);
  EXPECT_THROW(surfacePointPosition(soup, SurfacePoint::onEdge(0, 8, 0.5)), std::invalid_argument);
  EXPECT_THROW(surfacePointPosition(soup, SurfacePoint::inFace(0, 0.5, 0.6, 0.1)),
               std::invalid_argument);
  EXPECT_THROW(surfacePointPosition(soup, SurfacePoint::atVertex(9)), std::invalid_argument);
}

// An edge point's parameter runs from one end (0) to the other (1): beyond either end it is no
// point of the edge, and the oracles refuse it rather than extrapolate along the edge's line.
TEST(Oracles, SurfacePointPositionRefusesAnEdgeParameterBeyondEitherEnd) {
  const TriangleSoup soup = gridMesh(2, 2, 2.0, 2.0);
  EXPECT_NO_THROW(surfacePointPosition(soup, SurfacePoint::onEdge(0, 1, 1.0)));
  for (const double t : {-0.5, 1.5, std::nextafter(1.0, 2.0)})
    EXPECT_THROW(surfacePointPosition(soup, SurfacePoint::onEdge(0, 1, t)), std::invalid_argument)
        << t;
}

// === Edge-graph Dijkstra =======================================================================

TEST(Oracles, EdgeGraphDijkstraOnAGridHasTheKnownValues) {
  // Unit cells, diagonals (i,j)–(i+1,j+1): min(i,j) diagonal steps then |i−j| axis steps.
  const int n = 5;
  const TriangleSoup soup = gridMesh(n, n, n, n, DiagonalPattern::AllOneWay);
  const auto d = edgeGraphDijkstra(soup, {{0, 0.0}});
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      EXPECT_NEAR(d[j * (n + 1) + i], std::min(i, j) * std::sqrt(2.0) + std::abs(i - j), 1e-12);
  // Initial distances offset the result; several sources take the minimum.
  const auto two = edgeGraphDijkstra(soup, {{0, 0.5}, {static_cast<Index>(n * (n + 1) + n), 0.0}});
  EXPECT_DOUBLE_EQ(two[0], 0.5);
  EXPECT_DOUBLE_EQ(two[1], 1.5);
  EXPECT_DOUBLE_EQ(two[n * (n + 1) + n - 1], 1.0);
}

TEST(Oracles, EdgeGraphDijkstraUnreachableAndUnreferencedAreInfinite) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}};
  soup.faces = {{0, 1, 2}, {4, 5, 6}};  // vertex 3 unreferenced, {4,5,6} another component
  const auto d = edgeGraphDijkstra(soup, {{0, 0.0}});
  EXPECT_EQ(d[1], 1.0);
  EXPECT_EQ(d[3], kInf);
  EXPECT_EQ(d[4], kInf);
  EXPECT_EQ(d[6], kInf);
  // From the unreferenced vertex itself: 0 there, like the solver, and nothing else reached.
  const auto fromIsolated = edgeGraphDijkstra(soup, {{3, 0.0}});
  EXPECT_EQ(fromIsolated[3], 0.0);
  EXPECT_EQ(fromIsolated[0], kInf);
  EXPECT_THROW(edgeGraphDijkstra(soup, {{7, 0.0}}), std::invalid_argument);
  EXPECT_THROW(edgeGraphDijkstra(soup, {{0, -1.0}}), std::invalid_argument);
}

TEST(Oracles, EdgeGraphDijkstraFromSurfacePointsIsAnUpperBound) {
  const TriangleSoup soup = jitteredGridMesh(6, 6, 3.0, 3.0, 0.1, 5);
  const std::vector<SurfacePoint> sources{SurfacePoint::inFace(13, 0.2, 0.3, 0.5)};
  const auto d = edgeGraphDijkstra(soup, sources);
  const Vec3 x = surfacePointPosition(soup, sources[0]);
  // Planar convex: the geodesic is the straight line, so Dijkstra ≥ Euclidean with equality at
  // the face's corners (joined straight to the source).
  const auto euclid = euclideanDistances(soup.positions, x);
  for (std::size_t v = 0; v < d.size(); ++v) EXPECT_GE(d[v], euclid[v] - 1e-15);
  for (Index v : soup.faces[13]) EXPECT_DOUBLE_EQ(d[v], euclid[v]);
  // An edge point reaches the corners of both faces on the edge directly.
  const auto& f = soup.faces[20];
  const auto de = edgeGraphDijkstra(soup, {SurfacePoint::onEdge(f[0], f[1], 0.3)});
  const Vec3 y = surfacePointPosition(soup, SurfacePoint::onEdge(f[0], f[1], 0.3));
  for (Index v : f) EXPECT_DOUBLE_EQ(de[v], (soup.positions[v] - y).norm());
  int direct = 0;
  for (std::size_t v = 0; v < de.size(); ++v) direct += de[v] == (soup.positions[v] - y).norm();
  EXPECT_EQ(direct, 4);  // the edge's ends and both opposite corners
}

TEST(Oracles, MeshOverloadsReadOnlyTheSoup) {
  const TriangleSoup soup = icosphereMesh(1, 1.0);
  const Mesh mesh(soup);
  EXPECT_EQ(edgeGraphDijkstra(mesh, {{3, 0.0}}), edgeGraphDijkstra(soup, {{3, 0.0}}));
  const std::vector<SurfacePoint> sources{SurfacePoint::inFace(5, 0.2, 0.2, 0.6)};
  EXPECT_EQ(edgeGraphDijkstra(mesh, sources), edgeGraphDijkstra(soup, sources));
  std::vector<double> d = edgeGraphDijkstra(soup, {{3, 0.0}});
  EXPECT_TRUE(checkLipschitz(mesh, d, 1e-12).ok());
  d[7] += 2.0;
  EXPECT_FALSE(checkLipschitz(mesh, d, 1e-12).ok());
}

// === Planar domains ============================================================================

/// The L [0,2]² minus (1,2]², reflex corner (1, 1).
std::vector<Polygon2> lShape() {
  return {{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
}

/// [0,3]² minus the hole [1,2]² (given counter-clockwise: the domain must fix it).
std::vector<Polygon2> squareWithHole() {
  return {{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
}

TEST(PlanarDomain, NormalizesOrientationAndFindsReflexVertices) {
  const PlanarDomain hole(squareWithHole());
  ASSERT_EQ(hole.loops().size(), 2u);
  EXPECT_EQ(hole.loops()[0].size(), 4u);
  EXPECT_EQ(hole.reflexVertices().size(), 4u);  // the hole's corners, not the outer ones
  for (const Vec2& c : hole.reflexVertices()) {
    EXPECT_TRUE(c.x() == 1 || c.x() == 2);
    EXPECT_TRUE(c.y() == 1 || c.y() == 2);
  }
  // Given clockwise, a repeated closing vertex, and a straight vertex on an edge: same domain.
  const PlanarDomain l({{{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}, {1, 0}, {0, 0}}});
  ASSERT_EQ(l.reflexVertices().size(), 1u);
  EXPECT_EQ(l.reflexVertices()[0], Vec2(1, 1));
}

TEST(PlanarDomain, ContainsClosedDomain) {
  const PlanarDomain l(lShape());
  EXPECT_TRUE(l.contains({0.5, 0.5}));
  EXPECT_TRUE(l.contains({1, 1}));      // the reflex corner
  EXPECT_TRUE(l.contains({1.5, 1}));    // on a boundary edge
  EXPECT_TRUE(l.contains({0, 0}));
  EXPECT_FALSE(l.contains({1.5, 1.5}));
  EXPECT_FALSE(l.contains({-0.1, 0.5}));
  const PlanarDomain h(squareWithHole());
  EXPECT_FALSE(h.contains({1.5, 1.5}));
  EXPECT_TRUE(h.contains({1.5, 1}));
  EXPECT_TRUE(h.contains({0.5, 1.5}));
}

TEST(PlanarDomain, SegmentAdmissibility) {
  const PlanarDomain l(lShape());
  EXPECT_TRUE(l.segmentInside({0.2, 0.2}, {1.8, 0.8}));
  EXPECT_TRUE(l.segmentInside({1.8, 0.2}, {0.2, 1.8}));    // passes through (1, 1): touches
  EXPECT_TRUE(l.segmentInside({2, 1}, {0.5, 1}));          // runs along the edge (2,1)–(1,1)
  EXPECT_TRUE(l.segmentInside({1, 0}, {1, 2}));            // along the edge (1,1)–(1,2)
  EXPECT_FALSE(l.segmentInside({1.8, 0.6}, {0.6, 1.8}));   // cuts the missing quadrant
  EXPECT_FALSE(l.segmentInside({2, 1}, {1, 2}));           // both ends on the boundary, outside
  EXPECT_FALSE(l.segmentInside({1.9, 0.9}, {0.9, 1.9}));   // crosses it just past the corner
  EXPECT_TRUE(l.segmentInside({1.9, 0.1}, {0.1, 1.9}));    // the diagonal through the corner
  const PlanarDomain h(squareWithHole());
  EXPECT_FALSE(h.segmentInside({0.5, 1.5}, {2.5, 1.5}));   // through the hole
  EXPECT_TRUE(h.segmentInside({0.5, 1}, {2.5, 1}));        // along the hole's bottom edge
  EXPECT_TRUE(h.segmentInside({1, 1}, {2, 1}));            // exactly the hole's edge
  EXPECT_FALSE(h.segmentInside({1, 1}, {2, 2}));           // the hole's diagonal
  EXPECT_TRUE(h.segmentInside({0, 0}, {1, 1}));            // corner to corner, touching
  EXPECT_FALSE(h.segmentInside({0, 0.5}, {3, 2.5}));       // grazes through the hole
}

TEST(PlanarDomain, LShapeDistancesGoAroundTheReflexCorner) {
  const Vec2 s(1.8, 0.6);
  const Vec2 c(1, 1);
  const std::vector<Vec2> queries{{0.6, 1.8}, {0.2, 0.4}, {1, 2}, {1.8, 0.6}};
  const auto d = planarDomainDistances(lShape(), s, queries);
  EXPECT_NEAR(d[0], (s - c).norm() + (c - queries[0]).norm(), 1e-14);  // hidden: via c
  EXPECT_NEAR(d[1], (s - queries[1]).norm(), 1e-14);                   // visible: straight
  EXPECT_NEAR(d[2], (s - c).norm() + 1.0, 1e-14);
  EXPECT_EQ(d[3], 0.0);
  // Along the boundary through the corner is straight, not a detour.
  const auto along = planarDomainDistances(lShape(), {2, 1}, std::vector<Vec2>{{0.5, 1}, {1, 2}});
  EXPECT_NEAR(along[0], 1.5, 1e-14);
  EXPECT_NEAR(along[1], 2.0, 1e-14);
  EXPECT_THROW(planarDomainDistances(lShape(), s, std::vector<Vec2>{{1.5, 1.5}}),
               std::invalid_argument);
  EXPECT_THROW(planarDomainDistances(lShape(), {3, 3}, std::vector<Vec2>{{0.5, 0.5}}),
               std::invalid_argument);
}

TEST(PlanarDomain, SquareWithHoleDistancesGoAroundTheHole) {
  const Vec2 s(0.5, 1.5);
  const auto d = planarDomainDistances(
      squareWithHole(), s, std::vector<Vec2>{{2.5, 1.5}, {2.5, 1.0}, {1.5, 2.5}, {0.5, 1}});
  // Around either side: to a corner, along the hole's edge, from the opposite corner.
  EXPECT_NEAR(d[0], 2 * std::sqrt(0.5) + 1.0, 1e-14);
  // (2.5, 1): via (1, 1), then straight along the bottom edge and on.
  EXPECT_NEAR(d[1], std::sqrt(0.5) + 1.5, 1e-14);
  EXPECT_NEAR(d[2], std::sqrt(0.5) + std::sqrt(0.5 * 0.5 + 0.5 * 0.5), 1e-14);
  EXPECT_NEAR(d[3], 0.5, 1e-14);
  // Two reflex bends: from below-left of the hole to above-right, diagonally opposite.
  const auto far = planarDomainDistances(squareWithHole(), {1.5, 0.5},
                                         std::vector<Vec2>{{1.5, 2.5}});
  EXPECT_NEAR(far[0], 2 * std::sqrt(0.5) + 1.0, 1e-14);
}

/// The L's distance from (2, 0), written out: straight unless the segment enters x > 1, y > 1.
double lDistanceFromCorner(const Vec2& q) {
  const Vec2 s(2, 0), c(1, 1);
  if (q.y() > 1) {
    const double xAtY1 = s.x() + (q.x() - s.x()) / q.y();  // where s→q crosses y = 1
    if (xAtY1 > 1) return (s - c).norm() + (c - q).norm();
  }
  return (s - q).norm();
}

TEST(PlanarDomain, MatchesTheClosedFormOnAnLShapedMesh) {
  const TriangleSoup soup = lShapeMesh(12, 2.0, DiagonalPattern::Alternating);
  const auto xy = planarPositions(soup);
  const auto d = planarDomainDistances(planarBoundaryPolygons(soup), {2, 0}, xy);
  int hidden = 0;
  for (std::size_t v = 0; v < xy.size(); ++v) {
    EXPECT_NEAR(d[v], lDistanceFromCorner(xy[v]), 1e-13) << "vertex " << v;
    hidden += d[v] > (xy[v] - Vec2(2, 0)).norm() + 1e-12;
  }
  EXPECT_GT(hidden, 10);  // the test exercises the bend
  // And it sits between the Euclidean and the edge-graph bounds on the mesh.
  const Index s = vertexAt(soup, 2, 0);
  const auto euclid = euclideanDistances(soup.positions, soup.positions[s]);
  const auto graph = edgeGraphDijkstra(soup, {{s, 0.0}});
  EXPECT_TRUE(checkEuclideanLowerBound(d, euclid, 1e-12).ok());
  EXPECT_TRUE(checkUpperBound(d, graph, 1e-12).ok());
  EXPECT_TRUE(checkLipschitz(soup, d, 1e-12).ok());
}

TEST(PlanarDomain, IndependentOfTheTriangulation) {
  // Same domain, two diagonal patterns (vertex numbering is the same): same distances.
  const TriangleSoup a = squareWithHoleMesh(10, 1.0, 0.4, DiagonalPattern::AllOneWay);
  const TriangleSoup b = squareWithHoleMesh(10, 1.0, 0.4, DiagonalPattern::Alternating);
  const Vec2 s(0.05, 0.5);
  const auto da = planarDomainDistances(planarBoundaryPolygons(a), s, planarPositions(a));
  const auto db = planarDomainDistances(planarBoundaryPolygons(b), s, planarPositions(b));
  EXPECT_EQ(da, db);
}

TEST(PlanarDomain, BoundaryPolygonsOfASoup) {
  const auto loops = planarBoundaryPolygons(gridMesh(3, 2, 3.0, 2.0));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 10u);
  // A pinch: two triangles sharing only vertex 0.
  TriangleSoup bowtie;
  bowtie.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  bowtie.faces = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_THROW(planarBoundaryPolygons(bowtie), std::invalid_argument);
}

// PlanarDomain takes a flat mesh for an embedding of the domain its boundary encloses; a mesh
// folded over itself is intrinsically flat too, but is not one. Two faces folded onto each other
// (fuzz_solver's moved grid vertices make such folds: a reduction of
// corpus/fuzz_solver/regress/vertex-agreement-edge-source-1.75e-10-from-a-vertex-beside-a-vertex-source):
// the planar oracle called the apex (0.5, 2.5), a corner of both faces, unreachable. Nor is an
// annulus wound twice around itself, whose face areas add up to what its boundary loops enclose.
TEST(PlanarDomain, AFlatMeshFoldedOntoItselfOrWoundTwiceIsNoEmbeddingOfItsBoundary) {
  EXPECT_TRUE(coversItsDomainOnce(gridMesh(3, 2, 3.0, 2.0),
                                  planarBoundaryPolygons(gridMesh(3, 2, 3.0, 2.0))));
  const TriangleSoup holed = squareWithHoleMesh(8, 1.0, 0.25);
  EXPECT_TRUE(coversItsDomainOnce(holed, planarBoundaryPolygons(holed)));
  // 80,000 faces, whose areas add up to the loops' only to 5e-13 of the sum in doubles.
  const TriangleSoup large = squareWithHoleMesh(200, 1.0, 0.3);
  EXPECT_TRUE(coversItsDomainOnce(large, planarBoundaryPolygons(large)));
  const TriangleSoup lShape = lShapeMesh(4, 1.0, DiagonalPattern::Alternating);
  EXPECT_TRUE(coversItsDomainOnce(lShape, planarBoundaryPolygons(lShape)));

  // Far from the origin, where the loop's own coordinates cancel: 1e-6 across at 1000.
  TriangleSoup far = gridMesh(4, 4, 1e-6, 1e-6);
  for (Vec3& p : far.positions) p += Vec3(1000, 1000, 0);
  EXPECT_TRUE(coversItsDomainOnce(far, planarBoundaryPolygons(far)));

  TriangleSoup folded;
  folded.positions = {{0, 1, 0}, {0.5, 2.5, 0}, {1, 2, 0}, {0, 2.5, 0}};
  folded.faces = {{0, 2, 1}, {1, 2, 3}};
  EXPECT_FALSE(coversItsDomainOnce(folded, planarBoundaryPolygons(folded)));
  // A sliver folded onto its neighbour: both apexes above the edge they share, the sliver's 1e-8
  // above it, its area 1e-8 of the mesh's. Its boundary is a simple polygon.
  TriangleSoup sliver;
  sliver.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 1e-8, 0}};
  sliver.faces = {{0, 1, 2}, {1, 0, 3}};
  EXPECT_FALSE(coversItsDomainOnce(sliver, planarBoundaryPolygons(sliver)));

  // Radii 1 and 2, twelve sectors a sheet; vertex k and k + 12 share a position.
  TriangleSoup twice;
  const int n = 12;
  for (int k = 0; k < 2 * n; ++k)
    for (double r : {1.0, 2.0})
      twice.positions.emplace_back(r * std::cos(2 * std::numbers::pi * k / n),
                                   r * std::sin(2 * std::numbers::pi * k / n), 0.0);
  for (int k = 0; k < 2 * n; ++k) {
    const Index in = 2 * k, out = 2 * k + 1, in1 = 2 * ((k + 1) % (2 * n)), out1 = in1 + 1;
    twice.faces.push_back({in, out, out1});
    twice.faces.push_back({in, out1, in1});
  }
  const auto loops = planarBoundaryPolygons(twice);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_FALSE(coversItsDomainOnce(twice, loops));
  // The same annulus wound once is one.
  TriangleSoup once = twice;
  once.faces.resize(2 * n);
  once.faces[2 * n - 2] = {2 * (n - 1), 2 * (n - 1) + 1, 1};
  once.faces[2 * n - 1] = {2 * (n - 1), 1, 0};
  EXPECT_TRUE(coversItsDomainOnce(once, planarBoundaryPolygons(once)));
}

// A flat sheet wound past a full turn about a corner: a fan of four faces about (0, 0), from the
// spoke to (1, 0) round to the spoke to (1, 1) at 405°, its last face over its first. Every face
// turns counter-clockwise (area 1/2 each), so the face areas add up to the area its one boundary
// loop encloses (2), as an embedding's would; what gives it away is the loop crossing itself. Its
// last spoke, (1, 1) to (0, 0), crosses its first rim edge, (1, 0) to (0, 1), at (1/2, 1/2); its
// last rim edge, (0, -1) to (1, 1), crosses the first spoke at (1/2, 0) and the first rim edge at
// (2/3, 1/3). Each crossing is far inside both segments: no end of a loop edge comes within
// 1/sqrt(5) of an edge it is not next to.
TEST(PlanarDomain, ASheetWoundPastAFullTurnAboutACornerIsNoEmbeddingOfItsBoundary) {
  TriangleSoup wound;
  wound.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 1, 0}};
  wound.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
  const auto loops = planarBoundaryPolygons(wound);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), 6u);
  EXPECT_FALSE(coversItsDomainOnce(wound, loops));
  // Its first three faces, three quarters of a turn, are one.
  TriangleSoup threeQuarters = wound;
  threeQuarters.positions.pop_back();
  threeQuarters.faces.pop_back();
  EXPECT_TRUE(coversItsDomainOnce(threeQuarters, planarBoundaryPolygons(threeQuarters)));
}

// === Bound checks ==============================================================================

struct Fields {
  TriangleSoup soup = jitteredGridMesh(10, 8, 5.0, 4.0, 0.12, 99, DiagonalPattern::Alternating);
  Index source = 37;
  std::vector<double> euclid = euclideanDistances(soup.positions, soup.positions[source]);
  std::vector<double> graph = edgeGraphDijkstra(soup, {{source, 0.0}});
};

TEST(BoundChecks, PassOnTrueFields) {
  const Fields f;
  // Planar convex mesh: the Euclidean field is the geodesic field.
  const CheckReport lower = checkEuclideanLowerBound(f.euclid, f.euclid, 1e-12);
  EXPECT_TRUE(lower.ok()) << lower.summary();
  EXPECT_EQ(lower.checked, f.soup.positions.size());
  EXPECT_TRUE(checkUpperBound(f.euclid, f.graph, 1e-12).ok());
  const CheckReport lipschitz = checkLipschitz(f.soup, f.euclid, 1e-12);
  EXPECT_TRUE(lipschitz.ok()) << lipschitz.summary();
  EXPECT_GT(lipschitz.checked, f.soup.faces.size());  // every edge once: E = V + F − 1 here
  EXPECT_TRUE(checkLipschitz(f.soup, f.graph, 1e-12).ok());  // Dijkstra is 1-Lipschitz too
  EXPECT_TRUE(checkAgreement(f.euclid, f.euclid, 0.0).ok());
  EXPECT_TRUE(checkSymmetry(2.0, 2.0 * (1 + 1e-13), 1e-12).ok());
}

TEST(BoundChecks, EuclideanLowerBoundFailsBelowEuclidean) {
  const Fields f;
  std::vector<double> d = f.euclid;
  d[5] *= 0.9;
  const CheckReport r = checkEuclideanLowerBound(d, f.euclid, 1e-9);
  EXPECT_EQ(r.failed, 1u);
  EXPECT_NE(r.firstFailure.find("vertex 5"), std::string::npos) << r.firstFailure;
  EXPECT_GT(r.maxError, 1e-3);
  // Within the tolerance passes, just beyond it fails.
  d = f.euclid;
  d[5] -= 0.5e-9 * (f.euclid[5] + *std::max_element(f.euclid.begin(), f.euclid.end()));
  EXPECT_TRUE(checkEuclideanLowerBound(d, f.euclid, 1e-9).ok());
  d[5] = f.euclid[5] - 2e-9 * (f.euclid[5] + *std::max_element(f.euclid.begin(), f.euclid.end()));
  EXPECT_FALSE(checkEuclideanLowerBound(d, f.euclid, 1e-9).ok());
  // Negative, NaN: fail. Unreachable: satisfies a lower bound.
  d = f.euclid;
  d[0] = -1.0;
  EXPECT_FALSE(checkEuclideanLowerBound(d, f.euclid, 1e-9).ok());
  d[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(checkEuclideanLowerBound(d, f.euclid, 1e-9).ok());
  d[0] = kInf;
  EXPECT_TRUE(checkEuclideanLowerBound(d, f.euclid, 1e-9).ok());
}

TEST(BoundChecks, UpperBoundFailsAboveDijkstraAndOnReachabilityMismatch) {
  const Fields f;
  std::vector<double> d = f.euclid;
  d[60] = f.graph[60] * 1.01;
  const CheckReport r = checkUpperBound(d, f.graph, 1e-9);
  EXPECT_EQ(r.failed, 1u);
  EXPECT_NE(r.firstFailure.find("vertex 60"), std::string::npos) << r.firstFailure;
  d = f.euclid;
  d[7] = kInf;  // "unreachable" but the edge graph reaches it
  const CheckReport unreachable = checkUpperBound(d, f.graph, 1e-9);
  EXPECT_EQ(unreachable.failed, 1u);
  EXPECT_EQ(unreachable.maxError, kInf);
  std::vector<double> graph = f.graph;
  graph[7] = kInf;
  EXPECT_TRUE(checkUpperBound(d, graph, 1e-9).ok());  // both unreachable
  EXPECT_FALSE(checkUpperBound(f.euclid, graph, 1e-9).ok());
  EXPECT_THROW(checkUpperBound(std::vector<double>(3), f.graph, 1e-9), std::invalid_argument);
}

TEST(BoundChecks, LipschitzFailsOnAJump) {
  const Fields f;
  std::vector<double> d = f.euclid;
  d[45] += 1.5;  // cells are 0.5 × 0.5: every edge at vertex 45 is shorter than this jump
  const CheckReport r = checkLipschitz(f.soup, d, 1e-9);
  EXPECT_GE(r.failed, 4u);  // an interior vertex has four or eight edges (checkerboard)
  EXPECT_NE(r.firstFailure.find("45"), std::string::npos) << r.firstFailure;
  // Edges with an infinite end are skipped; NaN fails.
  d = f.euclid;
  d[45] = kInf;
  EXPECT_TRUE(checkLipschitz(f.soup, d, 1e-9).ok());
  d[45] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(checkLipschitz(f.soup, d, 1e-9).ok());
}

TEST(BoundChecks, LipschitzRefusesAFieldOfAnotherMesh) {
  // A field with a value more than the mesh has vertices belongs to another mesh: refused, as by
  // the other checks, rather than judged on the vertices the two happen to share.
  const Fields f;
  std::vector<double> d = f.euclid;
  d.push_back(0.0);
  EXPECT_THROW(checkLipschitz(f.soup, d, 1e-9), std::invalid_argument);
}

TEST(BoundChecks, SymmetryAndAgreementFail) {
  EXPECT_FALSE(checkSymmetry(1.0, 1.001, 1e-9).ok());
  EXPECT_FALSE(checkSymmetry(1.0, kInf, 1e-9).ok());
  EXPECT_TRUE(checkSymmetry(kInf, kInf, 1e-9).ok());
  EXPECT_EQ(checkSymmetry(1.0, 1.0, 0.0).checked, 1u);
  const Fields f;
  std::vector<double> d = f.euclid;
  d[3] += 1e-6;
  EXPECT_FALSE(checkAgreement(d, f.euclid, 1e-9).ok());
  EXPECT_TRUE(checkAgreement(d, f.euclid, 1e-6).ok());
  d[3] = kInf;
  EXPECT_FALSE(checkAgreement(d, f.euclid, 1e-3).ok());
}

// A NaN or −∞ is no distance, even where the reference has none either (an unreachable vertex):
// it fails as such, not as a reachability mismatch or a match of two infinities.
TEST(BoundChecks, AgreementFailsOnWhatIsNoDistanceWhereverItIs) {
  const std::vector<double> reference{kInf, kInf, 1.0, kInf};
  const std::vector<double> d{std::nan(""), -kInf, std::nan(""), kInf};
  const CheckReport r = checkAgreement(d, reference, 1e-9);
  EXPECT_EQ(r.failed, 3u) << r.summary();
  EXPECT_NE(r.firstFailure.find("not a distance"), std::string::npos) << r.firstFailure;
  EXPECT_EQ(checkAgreement(reference, d, 1e-9).failed, 3u);  // the other way round
}

// The tolerance a bound allows is allowed: a value exactly that far from its reference passes,
// and one an ulp beyond it fails.
TEST(BoundChecks, AValueExactlyAtTheAllowedDistanceFromItsBoundPasses) {
  const std::vector<double> reference{1.0};
  EXPECT_TRUE(checkAgreement(std::vector<double>{1.5}, reference, 0.0, 0.5).ok());
  EXPECT_FALSE(
      checkAgreement(std::vector<double>{std::nextafter(1.5, 2.0)}, reference, 0.0, 0.5).ok());
  EXPECT_TRUE(checkUpperBound(std::vector<double>{1.5}, reference, 0.0, 0.5).ok());
}

// === CGAL differential oracle ==================================================================

#ifdef GEODEX_HAVE_CGAL_ORACLE

TEST(CgalOracle, FlatGridMatchesEuclidean) {
  const TriangleSoup soup = gridMesh(12, 10, 3.0, 2.5, DiagonalPattern::Alternating);
  const Index source = 5 * 13 + 4;
  CgalTiming timing;
  const auto d = cgalGeodesicDistances(soup, {SurfacePoint::atVertex(source)}, &timing);
  const auto euclid = euclideanDistances(soup.positions, soup.positions[source]);
  const CheckReport r = checkAgreement(d, euclid, 1e-6);
  EXPECT_TRUE(r.ok()) << r.summary();
  EXPECT_GE(timing.totalSeconds(), 0.0);
}

TEST(CgalOracle, FaceAndEdgeSourcesUseOurBarycentricOrder) {
  // Asymmetric barycentrics: any permutation mistake moves the source and breaks agreement.
  const TriangleSoup soup = jitteredGridMesh(6, 6, 3.0, 3.0, 0.1, 11, DiagonalPattern::Alternating);
  CgalGeodesicOracle oracle(soup);
  for (Index f = 0; f < soup.faces.size(); f += 7) {
    const SurfacePoint p = SurfacePoint::inFace(f, 0.1, 0.3, 0.6);
    oracle.solve({p});
    const auto euclid = euclideanDistances(soup.positions, surfacePointPosition(soup, p));
    const CheckReport r = checkAgreement(oracle.vertexDistances(), euclid, 1e-6);
    EXPECT_TRUE(r.ok()) << "face " << f << ": " << r.summary();
  }
  // Point queries: distance to a face point and to an edge point.
  oracle.solve({SurfacePoint::atVertex(0)});
  const SurfacePoint q = SurfacePoint::inFace(40, 0.5, 0.25, 0.25);
  EXPECT_NEAR(oracle.distance(q), surfacePointPosition(soup, q).norm(), 1e-6);
  const auto& g = soup.faces[40];
  const SurfacePoint r = SurfacePoint::onEdge(g[1], g[2], 0.3);
  EXPECT_NEAR(oracle.distance(r), surfacePointPosition(soup, r).norm(), 1e-6);
}

TEST(CgalOracle, EdgeSourcesLandWhereTheySay) {
  // CGAL 5.5.1 mirrors edge sources (t ↔ 1 − t); the oracle must compensate. Every edge
  // direction of several faces, interior and border edges, at an asymmetric t.
  const TriangleSoup soup = jitteredGridMesh(5, 5, 2.5, 2.5, 0.1, 3, DiagonalPattern::Alternating);
  CgalGeodesicOracle oracle(soup);
  int border = 0;
  for (Index fi : {0u, 9u, 17u, 26u, 49u}) {
    const auto& f = soup.faces[fi];
    for (int k = 0; k < 3; ++k) {
      for (bool reversed : {false, true}) {
        const Index a = f[k], b = f[(k + 1) % 3];
        const SurfacePoint e = reversed ? SurfacePoint::onEdge(b, a, 0.2) : SurfacePoint::onEdge(a, b, 0.2);
        oracle.solve({e});
        const auto euclid = euclideanDistances(soup.positions, surfacePointPosition(soup, e));
        const CheckReport r = checkAgreement(oracle.vertexDistances(), euclid, 1e-6);
        EXPECT_TRUE(r.ok()) << "edge " << e.vertex << "->" << e.toVertex << ": " << r.summary();
      }
      const Vec3 mid = 0.5 * (soup.positions[f[k]] + soup.positions[f[(k + 1) % 3]]);
      border += mid.x() == 0.0 || mid.y() == 0.0 || mid.x() == 2.5 || mid.y() == 2.5;
    }
    // A face point with one zero coordinate is an edge point too.
    const SurfacePoint p = SurfacePoint::inFace(fi, 0.0, 0.7, 0.3);
    oracle.solve({p});
    const auto euclid = euclideanDistances(soup.positions, surfacePointPosition(soup, p));
    EXPECT_TRUE(checkAgreement(oracle.vertexDistances(), euclid, 1e-6).ok()) << "face " << fi;
  }
  EXPECT_GE(border, 2);  // both of CGAL's edge-source paths were exercised
}

TEST(CgalOracle, SeveralSourcesTakeTheMinimum) {
  const TriangleSoup soup = gridMesh(8, 8, 2.0, 2.0);
  const auto d = cgalGeodesicDistances(soup, {SurfacePoint::atVertex(0), SurfacePoint::atVertex(80)});
  const std::vector<Vec3> sources{soup.positions[0], soup.positions[80]};
  EXPECT_TRUE(checkAgreement(d, euclideanDistances(soup.positions, sources), 1e-6).ok());
}

TEST(CgalOracle, AgreesWithThePlanarDomainOracleOnAnLShape) {
  const TriangleSoup soup = lShapeMesh(10, 2.0);
  const Index s = vertexAt(soup, 1.8, 0.2);
  const auto d = cgalGeodesicDistances(soup, {SurfacePoint::atVertex(s)});
  const auto exact = planarDomainDistances(planarBoundaryPolygons(soup), {1.8, 0.2},
                                           planarPositions(soup));
  const CheckReport r = checkAgreement(d, exact, 1e-6);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CgalOracle, SquareWithHoleAgreesWithThePlanarDomainOracle) {
  const TriangleSoup soup = squareWithHoleMesh(9, 3.0, 0.4, DiagonalPattern::Alternating);
  const auto d = cgalGeodesicDistances(soup, {SurfacePoint::atVertex(0)});
  const auto exact = planarDomainDistances(planarBoundaryPolygons(soup), {0, 0},
                                           planarPositions(soup));
  const CheckReport r = checkAgreement(d, exact, 1e-6);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CgalOracle, SphereDistancesSitBetweenTheBounds) {
  const TriangleSoup soup = icosphereMesh(2, 1.0);
  const auto d = cgalGeodesicDistances(soup, {SurfacePoint::atVertex(0)});
  const auto euclid = euclideanDistances(soup.positions, soup.positions[0]);
  const auto graph = edgeGraphDijkstra(soup, {{0, 0.0}});
  EXPECT_TRUE(checkEuclideanLowerBound(d, euclid, 1e-9).ok());
  EXPECT_TRUE(checkUpperBound(d, graph, 1e-9).ok());
  EXPECT_TRUE(checkLipschitz(soup, d, 1e-9).ok());
  // Shorter than the edge graph somewhere, longer than the chord away from the source.
  double gap = 0.0;
  for (std::size_t v = 0; v < d.size(); ++v) gap = std::max(gap, graph[v] - d[v]);
  EXPECT_GT(gap, 1e-3);
  EXPECT_GT(d[3], euclid[3] * 1.01);  // vertex 3 is the antipode: π·r-ish against 2r
}

TEST(CgalOracle, UnreferencedAndUnreachableAreInfinite) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}};
  soup.faces = {{0, 1, 2}, {4, 5, 6}};
  const auto d = cgalGeodesicDistances(soup, {SurfacePoint::atVertex(0)});
  EXPECT_NEAR(d[1], 1.0, 1e-12);
  EXPECT_EQ(d[3], kInf);
  EXPECT_EQ(d[4], kInf);
  EXPECT_THROW(cgalGeodesicDistances(soup, {SurfacePoint::atVertex(3)}), std::invalid_argument);
  TriangleSoup flipped = gridMesh(2, 1, 2.0, 1.0);
  std::swap(flipped.faces[1][0], flipped.faces[1][1]);  // inconsistent winding
  EXPECT_THROW(CgalGeodesicOracle{flipped}, std::invalid_argument);
}

#endif  // GEODEX_HAVE_CGAL_ORACLE

}  // namespace
}  // namespace geodex::verify
