// Mesh units (solver/src/mesh.cpp): geodex measures a mesh in a power of two of its largest
// coordinate, so that a mesh scaled by 2^k has the same geometry in mesh units bit for bit, and
// every answer — distances, points, paths, stop distance, targets, counters — is the unscaled
// one times 2^k, exactly. Expected values come from the unscaled solve and ldexp, never from
// the scaled code path itself.
#include "geodex/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "geodex/tolerance.h"
#include "geodex/verify/mesh_generators.h"

namespace geodex {
namespace {

TriangleSoup scaled(TriangleSoup soup, int k) {
  for (Vec3& p : soup.positions) p = Vec3(std::ldexp(p.x(), k), std::ldexp(p.y(), k), std::ldexp(p.z(), k));
  return soup;
}

// Whether every non-zero coordinate of the soup scaled by 2^k is a normal double (then the scaled
// mesh is exactly the same mesh, and the answers must be exactly the same).
bool staysNormal(const TriangleSoup& soup, int k) {
  for (const Vec3& p : soup.positions)
    for (int i = 0; i < 3; ++i)
      if (p[i] != 0.0 && !std::isnormal(std::ldexp(p[i], k))) return false;
  return true;
}

// A bumpy height field (saddles, convex and flat vertices, a boundary) with a few hand-picked
// quirks: exactly representable coordinates are not needed, rounding is part of the test.
TriangleSoup bumpyMesh() {
  return verify::heightFieldMesh(6, 5, 1.7, 1.3, [](double x, double y) {
    return 0.3 * std::sin(3.1 * x) * std::cos(2.3 * y) + 0.05 * x * y;
  });
}

struct Answers {
  std::vector<double> vertex;
  double edgePoint, facePoint, pathLength;
  std::vector<Vec3> pathPoints;
  DegeneracyCounters counters;
  SolveStats stats;
};

Answers solveAll(const Mesh& mesh, const SolveOptions& options = {}) {
  const std::vector<SurfacePoint> sources{SurfacePoint::atVertex(3),
                                          SurfacePoint::onEdge(15, 16, 0.375),
                                          SurfacePoint::inFace(40, 0.2, 0.3, 0.5)};
  GeodesicSolver solver(mesh);
  solver.solve(sources, options);
  Answers a;
  a.vertex.assign(solver.vertexDistances().begin(), solver.vertexDistances().end());
  a.edgePoint = solver.distance(SurfacePoint::onEdge(11, 12, 0.625));
  a.facePoint = solver.distance(SurfacePoint::inFace(17, 0.5, 0.25, 0.25));
  const GeodesicPath path = solver.path(SurfacePoint::atVertex(41));
  a.pathLength = path.length;
  for (const PathPoint& p : path.points) a.pathPoints.push_back(p.position);
  a.counters = solver.counters();
  a.stats = solver.stats();
  return a;
}

void expectScaledBitForBit(const Answers& unit, const Answers& got, int k) {
  ASSERT_EQ(got.vertex.size(), unit.vertex.size());
  for (std::size_t v = 0; v < got.vertex.size(); ++v)
    EXPECT_EQ(got.vertex[v], std::ldexp(unit.vertex[v], k)) << "2^" << k << " vertex " << v;
  EXPECT_EQ(got.edgePoint, std::ldexp(unit.edgePoint, k)) << "2^" << k;
  EXPECT_EQ(got.facePoint, std::ldexp(unit.facePoint, k)) << "2^" << k;
  EXPECT_EQ(got.pathLength, std::ldexp(unit.pathLength, k)) << "2^" << k;
  ASSERT_EQ(got.pathPoints.size(), unit.pathPoints.size()) << "2^" << k;
  for (std::size_t i = 0; i < got.pathPoints.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(got.pathPoints[i][c], std::ldexp(unit.pathPoints[i][c], k)) << "2^" << k << " point " << i;
  EXPECT_EQ(got.counters.count, unit.counters.count) << "2^" << k;
  EXPECT_EQ(got.counters.cases, unit.counters.cases) << "2^" << k;
  EXPECT_EQ(got.counters.degenerateCases, unit.counters.degenerateCases) << "2^" << k;
  EXPECT_EQ(got.counters.zeroAreaFaces, unit.counters.zeroAreaFaces) << "2^" << k;
  EXPECT_EQ(got.counters.childEdgesSeenFromOutside, unit.counters.childEdgesSeenFromOutside);
  EXPECT_EQ(got.stats.intervalsCreated, unit.stats.intervalsCreated) << "2^" << k;
  EXPECT_EQ(got.stats.intervalsPropagated, unit.stats.intervalsPropagated) << "2^" << k;
  EXPECT_EQ(got.stats.shadowsClosed, unit.stats.shadowsClosed) << "2^" << k;
  EXPECT_EQ(got.stats.radius, std::ldexp(unit.stats.radius, k)) << "2^" << k;
}

const int kScales[] = {-1000, -900, -600, -300, -100, -77, -1, 1, 77, 100, 300, 600, 900, 1000};

TEST(MeshUnits, EveryAnswerOfAMeshScaledByAPowerOfTwoIsTheUnscaledOneScaledBitForBit) {
  const TriangleSoup soup = bumpyMesh();
  const Answers unit = solveAll(Mesh(soup));
  for (const int k : kScales) {
    if (!staysNormal(soup, k)) continue;
    const Mesh mesh(scaled(soup, k));
    expectScaledBitForBit(unit, solveAll(mesh), k);
  }
}

TEST(MeshUnits, StopDistanceAndTargetsScaleBitForBit) {
  const TriangleSoup soup = bumpyMesh();
  SolveOptions stop;
  stop.stopDistance = 0.75;
  SolveOptions targets;
  targets.targets = {SurfacePoint::atVertex(30), SurfacePoint::onEdge(7, 8, 0.5)};
  const Answers unitStop = solveAll(Mesh(soup), stop);
  const Answers unitTargets = solveAll(Mesh(soup), targets);
  ASSERT_GT(std::count(unitStop.vertex.begin(), unitStop.vertex.end(), kInfinity), 0);
  for (const int k : kScales) {
    if (!staysNormal(soup, k)) continue;
    const Mesh mesh(scaled(soup, k));
    SolveOptions scaledStop = stop;
    scaledStop.stopDistance = std::ldexp(stop.stopDistance, k);
    expectScaledBitForBit(unitStop, solveAll(mesh, scaledStop), k);
    expectScaledBitForBit(unitTargets, solveAll(mesh, targets), k);
  }
}

TEST(MeshUnits, TheUnitIsTheLargestCoordinateOfTheVerticesFacesUse) {
  TriangleSoup soup = bumpyMesh();
  const Mesh plain(soup);
  EXPECT_EQ(plain.unit(), 1.0);  // the largest coordinate is 1.7
  soup.positions.emplace_back(1e300, -1e300, 0.0);  // used by no face: no part of the geometry
  const Mesh withFarVertex(soup);
  EXPECT_EQ(withFarVertex.unit(), 1.0);
  EXPECT_EQ(withFarVertex.boundingBoxDiagonal(), plain.boundingBoxDiagonal());
  EXPECT_EQ(exactGeodesicDistance(withFarVertex, std::vector{SurfacePoint::atVertex(0)}).back(), kInfinity);
}

TEST(MeshUnits, ADistanceBeyondTheLargestDoubleIsAnErrorNotInfinity) {
  // Two strips 1.7e308 long folded into a U: every edge is a finite double, but the way from one
  // end of the U to the other is 3.4e308. +inf would say "unreachable": it must be refused.
  TriangleSoup soup;
  soup.positions = {Vec3(0, 0, 0),           Vec3(0, 0, 1e306),          // a0, a1
                    Vec3(1.7e308, 0, 0),     Vec3(1.7e308, 0, 1e306),    // b0, b1 (the bend)
                    Vec3(0, 1e306, 0),       Vec3(0, 1e306, 1e306)};     // c0, c1
  soup.faces = {{0, 2, 3}, {0, 3, 1}, {2, 4, 5}, {2, 5, 3}};
  const Mesh mesh(soup);
  GeodesicSolver solver(mesh);
  try {
    solver.solve(std::vector{SurfacePoint::atVertex(0)});
    ADD_FAILURE() << "distance to vertex 4 is " << solver.vertexDistances()[4];
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), "distance-overflow") << e.what();
    EXPECT_NE(std::string(e.what()).find("largest double"), std::string::npos) << e.what();
  }
  // The refusal comes after the solve: in mesh units (2^1023 here) the whole field is there, for
  // the checks in verify/ to judge the refusal by.
  EXPECT_EQ(mesh.meshUnit().exponent, 1023);
  const double along = 1.7e308 / mesh.unit(), across = std::hypot(along, 1e306 / mesh.unit());
  EXPECT_NEAR(solver.vertexDistancesInMeshUnits()[4], along + across, 1e-12);  // the U unfolded
  // From the bend every distance is representable.
  solver.solve(std::vector{SurfacePoint::atVertex(2)});
  EXPECT_NEAR(solver.vertexDistances()[0], 1.7e308, 1e294);
}

}  // namespace
// A vertex inside a plane has an angle sum of 2π; computed from a tilted, irregular triangulation
// it carries rounding of a few ulps of 2π, either way. A flat vertex is no pseudo-source
// (tol::kFlatVertexAngle): one made a saddle by its rounding would emit windows for nothing (the
// reference code's factor of ~15 on CAD faces). The plane here is tilted and its interior points
// jittered so that the rounding is there to be tolerated: the test says how large it got
// (two ulps of 2π above it).
TEST(FlatVertices, NoVertexInsideATiltedPlaneIsAPseudoSourceWhateverItsAngleSumsRounding) {
  const int n = 24;
  TriangleSoup soup;
  const Vec3 u = Vec3(1.0, 0.3, -0.7).normalized();
  const Vec3 v = u.cross(Vec3(0.2, 1.0, 0.4)).normalized();
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool inside = i > 0 && i < n && j > 0 && j < n;
      // A fixed jitter, a third of the spacing at most, from the indices.
      const double jx = inside ? 0.33 * std::sin(12.9898 * i + 78.233 * j) : 0.0;
      const double jy = inside ? 0.33 * std::sin(39.3468 * i + 11.135 * j) : 0.0;
      soup.positions.push_back(0.7 * ((i + jx) * u + (j + jy) * v));
    }
  }
  const auto at = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      soup.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      soup.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  const Mesh mesh(soup);
  double largestExcess = 0.0;  // of an angle sum over 2π
  for (int j = 1; j < n; ++j) {
    for (int i = 1; i < n; ++i) {
      const Index w = at(i, j);
      largestExcess = std::max(largestExcess, mesh.angleSum(w) - 2.0 * std::numbers::pi);
      EXPECT_FALSE(mesh.isPseudoSourceVertex(w))
          << "vertex " << w << ": angle sum 2π + " << mesh.angleSum(w) - 2.0 * std::numbers::pi;
    }
  }
  // Some angle sum came out at least two ulps of 2π (8.9e-16 each) above it.
  const double ulp = std::nextafter(2.0 * std::numbers::pi, 4.0) - 2.0 * std::numbers::pi;
  EXPECT_GE(largestExcess, 2.0 * ulp);
  EXPECT_LT(largestExcess, 1e-2 * tol::kFlatVertexAngle);
}

// The other side of tol::kFlatVertexAngle: a vertex whose angle sum exceeds 2π by 1e-10, five
// orders above the rounding of a flat vertex's angle sum (the test above), is a saddle, and a
// saddle is a pseudo-source: shortest paths bend around it, and the wedge behind it that the
// windows passing either side leave open (1e-10 × their length wide) is its windows' to fill.
// The fan here is a regular hexagon whose rim goes up and down by h in turn: each corner angle is
// π/3 + √3 h² to first order, so the excess is 6√3 h².
TEST(Saddles, AVertexWhoseAngleSumExceeds2PiByATenthOfANanoradianIsAPseudoSource) {
  const double h = std::sqrt(1e-10 / (6.0 * std::sqrt(3.0)));
  TriangleSoup soup;
  soup.positions.push_back(Vec3(0, 0, 0));
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    soup.positions.push_back(Vec3(std::cos(a), std::sin(a), k % 2 == 0 ? h : -h));
  }
  for (Index k = 0; k < 6; ++k) soup.faces.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const Mesh mesh(soup);
  const double excess = mesh.angleSum(0) - 2.0 * std::numbers::pi;
  EXPECT_NEAR(excess, 1e-10, 1e-12);
  EXPECT_TRUE(mesh.isPseudoSourceVertex(0)) << "angle sum 2π + " << excess;
}

}  // namespace geodex
