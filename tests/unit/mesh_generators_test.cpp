// Tests of verify/src/mesh_generators.cpp: the advertised counts, planarity, no duplicated or
// unreferenced vertices, consistent winding (CCW from +z, outward on spheres), determinism.

#include "geodex/verify/mesh_generators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <tuple>

#include "geodex/verify/oracles.h"

namespace geodex::verify {
namespace {

// === Helpers ===================================================================================

double signedAreaXY(const TriangleSoup& soup, const std::array<Index, 3>& f) {
  const Vec3 a = soup.positions[f[1]] - soup.positions[f[0]];
  const Vec3 b = soup.positions[f[2]] - soup.positions[f[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

Vec3 faceNormal(const TriangleSoup& soup, const std::array<Index, 3>& f) {
  return (soup.positions[f[1]] - soup.positions[f[0]])
      .cross(soup.positions[f[2]] - soup.positions[f[0]]);
}

/// Indices in range, no repeated index in a face, every vertex referenced, no two equal
/// positions, every directed edge used once at most (consistent winding) and every undirected
/// edge by one or two faces.
void expectWellFormed(const TriangleSoup& soup) {
  std::set<std::tuple<double, double, double>> seen;
  for (const Vec3& p : soup.positions) {
    EXPECT_TRUE(isFinite(p));
    EXPECT_TRUE(seen.emplace(p.x(), p.y(), p.z()).second)
        << "duplicated position (" << p.transpose() << ")";
  }
  std::vector<int> uses(soup.positions.size(), 0);
  std::map<std::pair<Index, Index>, int> directed;
  for (const auto& f : soup.faces) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_LT(f[k], soup.positions.size());
      ASSERT_NE(f[k], f[(k + 1) % 3]);
      ++uses[f[k]];
      ++directed[{f[k], f[(k + 1) % 3]}];
    }
  }
  for (std::size_t v = 0; v < uses.size(); ++v) EXPECT_GT(uses[v], 0) << "unreferenced " << v;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "directed edge " << edge.first << "->" << edge.second
                        << " used by " << count << " faces: inconsistent winding";
  }
}

/// Every edge has two faces (a closed surface).
void expectClosed(const TriangleSoup& soup) {
  std::map<std::pair<Index, Index>, int> undirected;
  for (const auto& f : soup.faces)
    for (int k = 0; k < 3; ++k) ++undirected[std::minmax(f[k], f[(k + 1) % 3])];
  for (const auto& [edge, count] : undirected) EXPECT_EQ(count, 2);
  // Euler characteristic of a sphere.
  EXPECT_EQ(static_cast<long>(soup.positions.size()) - static_cast<long>(undirected.size()) +
                static_cast<long>(soup.faces.size()),
            2);
}

/// z = 0 everywhere and every face counter-clockwise seen from +z; returns the total area.
double expectPlanarCounterClockwise(const TriangleSoup& soup) {
  for (const Vec3& p : soup.positions) EXPECT_EQ(p.z(), 0.0);
  double area = 0.0;
  for (const auto& f : soup.faces) {
    const double a = signedAreaXY(soup, f);
    EXPECT_GT(a, 0.0);
    area += a;
  }
  return area;
}

/// Angle sum at each vertex (atan2 of edge vectors), for the flat-vertex count.
std::vector<double> angleSums(const TriangleSoup& soup) {
  std::vector<double> sum(soup.positions.size(), 0.0);
  for (const auto& f : soup.faces) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = soup.positions[f[(k + 1) % 3]] - soup.positions[f[k]];
      const Vec3 b = soup.positions[f[(k + 2) % 3]] - soup.positions[f[k]];
      sum[f[k]] += std::atan2(a.cross(b).norm(), a.dot(b));
    }
  }
  return sum;
}

// === Planar grids ==============================================================================

TEST(MeshGenerators, GridCountsPositionsAndWinding) {
  for (DiagonalPattern pattern : {DiagonalPattern::AllOneWay, DiagonalPattern::Alternating}) {
    const TriangleSoup soup = gridMesh(5, 3, 2.5, 1.5, pattern);
    EXPECT_EQ(soup.positions.size(), 6u * 4u);
    EXPECT_EQ(soup.faces.size(), 2u * 5u * 3u);
    expectWellFormed(soup);
    EXPECT_NEAR(expectPlanarCounterClockwise(soup), 2.5 * 1.5, 1e-12);
    // Vertex (i, j) has index j·(nx+1) + i and the far corner is exactly (width, height).
    EXPECT_EQ(soup.positions[0], Vec3(0, 0, 0));
    EXPECT_EQ(soup.positions[2 * 6 + 3], Vec3(2.5 * 3 / 5, 1.5 * 2 / 3, 0));
    EXPECT_EQ(soup.positions.back(), Vec3(2.5, 1.5, 0));
  }
}

TEST(MeshGenerators, GridPatternsDiffer) {
  const TriangleSoup oneWay = gridMesh(2, 2, 1, 1, DiagonalPattern::AllOneWay);
  const TriangleSoup alternating = gridMesh(2, 2, 1, 1, DiagonalPattern::Alternating);
  // Cell (1, 0) has odd i+j: AllOneWay joins 1–5, Alternating joins 2–4.
  auto hasEdge = [](const TriangleSoup& s, Index a, Index b) {
    for (const auto& f : s.faces)
      for (int k = 0; k < 3; ++k)
        if (std::minmax(f[k], f[(k + 1) % 3]) == std::minmax(a, b)) return true;
    return false;
  };
  EXPECT_TRUE(hasEdge(oneWay, 1, 5));
  EXPECT_FALSE(hasEdge(oneWay, 2, 4));
  EXPECT_TRUE(hasEdge(alternating, 2, 4));
  EXPECT_FALSE(hasEdge(alternating, 1, 5));
  EXPECT_TRUE(hasEdge(alternating, 0, 4));  // cell (0, 0) keeps the main diagonal
}

TEST(MeshGenerators, GridRejectsBadArguments) {
  EXPECT_THROW(gridMesh(0, 3, 1, 1), std::invalid_argument);
  EXPECT_THROW(gridMesh(3, 3, -1, 1), std::invalid_argument);
}

TEST(MeshGenerators, JitteredGridMovesOnlyInteriorVerticesDeterministically) {
  const int nx = 8, ny = 6;
  const TriangleSoup regular = gridMesh(nx, ny, 4.0, 3.0);
  const TriangleSoup a = jitteredGridMesh(nx, ny, 4.0, 3.0, 0.15, 42);
  const TriangleSoup b = jitteredGridMesh(nx, ny, 4.0, 3.0, 0.15, 42);
  const TriangleSoup c = jitteredGridMesh(nx, ny, 4.0, 3.0, 0.15, 43);
  ASSERT_EQ(a.positions.size(), regular.positions.size());
  EXPECT_EQ(a.faces, regular.faces);
  expectWellFormed(a);
  EXPECT_NEAR(expectPlanarCounterClockwise(a), 12.0, 1e-12);  // the rectangle is unchanged
  int moved = 0;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const std::size_t v = static_cast<std::size_t>(j) * (nx + 1) + i;
      const Vec3 offset = a.positions[v] - regular.positions[v];
      const bool boundary = i == 0 || j == 0 || i == nx || j == ny;
      if (boundary) {
        EXPECT_EQ(offset.norm(), 0.0);
      }
      EXPECT_LE(std::abs(offset.x()), 0.15 * 0.5 + 1e-15);
      EXPECT_LE(std::abs(offset.y()), 0.15 * 0.5 + 1e-15);
      moved += offset.norm() > 0.0;
    }
  }
  EXPECT_EQ(moved, (nx - 1) * (ny - 1));
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_NE(a.positions, c.positions);
  EXPECT_THROW(jitteredGridMesh(nx, ny, 4.0, 3.0, 0.2, 1), std::invalid_argument);
}

TEST(MeshGenerators, JitterAtTheLimitNeverFlipsATriangle) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const TriangleSoup soup =
        jitteredGridMesh(10, 10, 1.0, 1.0, 0.1666, seed, DiagonalPattern::Alternating);
    for (const auto& f : soup.faces) ASSERT_GT(signedAreaXY(soup, f), 0.0) << "seed " << seed;
  }
}

TEST(MeshGenerators, NeedleFan) {
  const int n = 1000;
  const double apex = 1e-6;
  const TriangleSoup soup = needleFanMesh(n, apex, 2.0);
  EXPECT_EQ(soup.positions.size(), static_cast<std::size_t>(n + 2));
  EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(n));
  expectWellFormed(soup);
  expectPlanarCounterClockwise(soup);
  for (const auto& f : soup.faces) EXPECT_EQ(f[0], 0u);  // the centre is in every needle
  for (std::size_t v = 1; v < soup.positions.size(); ++v)
    EXPECT_NEAR(soup.positions[v].norm(), 2.0, 1e-15);
  // A half disc is allowed (convex), more is not.
  const TriangleSoup half = needleFanMesh(8, std::numbers::pi / 8, 1.0);
  EXPECT_NEAR(expectPlanarCounterClockwise(half), 8 * 0.5 * std::sin(std::numbers::pi / 8), 1e-14);
  EXPECT_THROW(needleFanMesh(8, std::numbers::pi / 7, 1.0), std::invalid_argument);
}

TEST(MeshGenerators, LShape) {
  const int n = 8;
  const TriangleSoup soup = lShapeMesh(n, 2.0);
  EXPECT_EQ(soup.positions.size(), static_cast<std::size_t>((n + 1) * (n + 1) - (n / 2) * (n / 2)));
  EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(3 * n * n / 2));
  expectWellFormed(soup);
  EXPECT_NEAR(expectPlanarCounterClockwise(soup), 3.0, 1e-12);
  for (const Vec3& p : soup.positions) EXPECT_FALSE(p.x() > 1.0 && p.y() > 1.0);
  // One boundary loop whose only reflex vertex is the corner (1, 1).
  const auto loops = planarBoundaryPolygons(soup);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), static_cast<std::size_t>(4 * n));
  const PlanarDomain domain(loops);
  ASSERT_EQ(domain.reflexVertices().size(), 1u);
  EXPECT_EQ(domain.reflexVertices()[0], Vec2(1.0, 1.0));
  EXPECT_THROW(lShapeMesh(7, 1.0), std::invalid_argument);
}

TEST(MeshGenerators, SquareWithHole) {
  EXPECT_EQ(squareHoleCells(10, 0.4), 4);
  EXPECT_EQ(squareHoleCells(10, 0.45), 4);  // 4.5 → nearest even
  EXPECT_EQ(squareHoleCells(9, 0.4), 3);    // 3.6 → nearest odd
  EXPECT_EQ(squareHoleCells(10, 0.99), 8);  // a ring of one cell stays
  EXPECT_EQ(squareHoleCells(10, 0.01), 2);
  EXPECT_THROW(squareHoleCells(3, 0.0), std::invalid_argument);

  for (int n : {9, 10}) {
    const int h = squareHoleCells(n, 0.4);
    const TriangleSoup soup = squareWithHoleMesh(n, 3.0, 0.4);
    EXPECT_EQ(soup.positions.size(), static_cast<std::size_t>((n + 1) * (n + 1) - (h - 1) * (h - 1)));
    EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(2 * (n * n - h * h)));
    expectWellFormed(soup);
    const double hole = 3.0 * h / n;
    EXPECT_NEAR(expectPlanarCounterClockwise(soup), 9.0 - hole * hole, 1e-12);
    const auto loops = planarBoundaryPolygons(soup);
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_EQ(loops[0].size(), static_cast<std::size_t>(4 * n));
    EXPECT_EQ(loops[1].size(), static_cast<std::size_t>(4 * h));
    // The four hole corners are the reflex vertices, centred.
    const PlanarDomain domain(loops);
    ASSERT_EQ(domain.reflexVertices().size(), 4u);
    for (const Vec2& c : domain.reflexVertices()) {
      EXPECT_NEAR(std::abs(c.x() - 1.5), hole / 2, 1e-12);
      EXPECT_NEAR(std::abs(c.y() - 1.5), hole / 2, 1e-12);
    }
  }
}

// === Height fields =============================================================================

TEST(MeshGenerators, HeightField) {
  auto z = [](double x, double y) { return std::sin(x) * std::cos(2 * y); };
  const TriangleSoup soup = heightFieldMesh(6, 5, 3.0, 2.0, z, DiagonalPattern::Alternating);
  EXPECT_EQ(soup.positions.size(), 7u * 6u);
  EXPECT_EQ(soup.faces.size(), 60u);
  expectWellFormed(soup);
  for (const Vec3& p : soup.positions) EXPECT_EQ(p.z(), z(p.x(), p.y()));
  for (const auto& f : soup.faces) EXPECT_GT(signedAreaXY(soup, f), 0.0);  // CCW from above
  for (const auto& f : soup.faces) EXPECT_GT(faceNormal(soup, f).z(), 0.0);
}

TEST(MeshGenerators, QuantizedHeightFieldHasTerracesAndFlatVertices) {
  const int nx = 24, ny = 20, levels = 4;
  const TriangleSoup soup = quantizedHeightField(nx, ny, 7, levels);
  EXPECT_EQ(soup.positions.size(), static_cast<std::size_t>((nx + 1) * (ny + 1)));
  EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(2 * nx * ny));
  expectWellFormed(soup);
  std::set<double> heights;
  for (const Vec3& p : soup.positions) {
    EXPECT_EQ(p.z(), std::round(p.z()));
    EXPECT_GE(p.z(), 0.0);
    EXPECT_LE(p.z(), levels - 1.0);
    EXPECT_EQ(p.x(), std::round(p.x()));  // integer grid
    heights.insert(p.z());
  }
  EXPECT_GE(heights.size(), 2u);  // not flat
  int horizontal = 0;
  for (const auto& f : soup.faces) {
    const Vec3 n = faceNormal(soup, f);
    EXPECT_GT(n.z(), 0.0);
    horizontal += n.x() == 0.0 && n.y() == 0.0;
  }
  EXPECT_GT(horizontal, static_cast<int>(soup.faces.size()) / 3) << "few coplanar faces";
  const auto sums = angleSums(soup);
  int flat = 0, interior = 0;
  for (int j = 1; j < ny; ++j) {
    for (int i = 1; i < nx; ++i) {
      ++interior;
      flat += std::abs(sums[j * (nx + 1) + i] - 2 * std::numbers::pi) < 1e-12;
    }
  }
  EXPECT_GT(flat, interior / 3) << "few flat vertices";
  EXPECT_EQ(quantizedHeightField(nx, ny, 7, levels).positions, soup.positions);
  EXPECT_NE(quantizedHeightField(nx, ny, 8, levels).positions, soup.positions);
  for (const Vec3& p : quantizedHeightField(5, 5, 1, 1).positions) EXPECT_EQ(p.z(), 0.0);
}

TEST(MeshGenerators, BumpyHeightFieldDrawsEveryHeightFromItsSeed) {
  const TriangleSoup soup = bumpyHeightField(5, 4, 0.3, 11);
  EXPECT_EQ(soup.positions.size(), 6u * 5u);
  EXPECT_EQ(soup.faces.size(), 40u);
  expectWellFormed(soup);
  SplitMix64 rng(11);  // row by row, one draw per vertex
  for (const Vec3& p : soup.positions) {
    EXPECT_EQ(p.x(), std::round(p.x()));
    EXPECT_EQ(p.z(), rng.uniform(-0.3, 0.3));
  }
  EXPECT_NE(bumpyHeightField(5, 4, 0.3, 12).positions, soup.positions);
}

TEST(MeshGenerators, FarSourcePatchJoinsOneFarVertexToTheFirstRow) {
  const int n = 4;
  const TriangleSoup soup = farSourceBumpyPatch(n, 1e6, 3);
  EXPECT_EQ(soup.positions.size(), static_cast<std::size_t>((n + 1) * (n + 1) + 1));
  EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(2 * n * n + n));
  expectWellFormed(soup);
  EXPECT_EQ(soup.positions.back(), Vec3(n / 2.0, -1e6, 0.0));
  for (const Vec3& p : soup.positions) {
    const bool onBoundary = p.x() == 0 || p.x() == n || p.y() == 0 || p.y() == n;
    if (onBoundary || p.y() < 0) EXPECT_EQ(p.z(), 0.0);
    EXPECT_LE(std::abs(p.z()), 0.3);
  }
}

// === Spheres ===================================================================================

TEST(MeshGenerators, Icosphere) {
  for (int s = 0; s <= 3; ++s) {
    const TriangleSoup soup = icosphereMesh(s, 2.0);
    const std::size_t p = std::size_t{1} << (2 * s);  // 4^s
    EXPECT_EQ(soup.positions.size(), 10 * p + 2);
    EXPECT_EQ(soup.faces.size(), 20 * p);
    expectWellFormed(soup);
    expectClosed(soup);
    for (const Vec3& x : soup.positions) EXPECT_NEAR(x.norm(), 2.0, 1e-14);
    for (const auto& f : soup.faces) {
      const Vec3 centroid =
          (soup.positions[f[0]] + soup.positions[f[1]] + soup.positions[f[2]]) / 3.0;
      EXPECT_GT(faceNormal(soup, f).dot(centroid), 0.0) << "face not outward";
    }
  }
}

TEST(MeshGenerators, UvSphere) {
  const int rings = 7, segments = 9;
  const TriangleSoup soup = uvSphereMesh(rings, segments, 1.5);
  EXPECT_EQ(soup.positions.size(), static_cast<std::size_t>(2 + (rings - 1) * segments));
  EXPECT_EQ(soup.faces.size(), static_cast<std::size_t>(2 * segments * (rings - 1)));
  expectWellFormed(soup);
  expectClosed(soup);
  EXPECT_EQ(soup.positions.front(), Vec3(0, 0, 1.5));
  EXPECT_EQ(soup.positions.back(), Vec3(0, 0, -1.5));
  for (const Vec3& x : soup.positions) EXPECT_NEAR(x.norm(), 1.5, 1e-15);
  for (const auto& f : soup.faces) {
    const Vec3 centroid = (soup.positions[f[0]] + soup.positions[f[1]] + soup.positions[f[2]]) / 3.0;
    EXPECT_GT(faceNormal(soup, f).dot(centroid), 0.0) << "face not outward";
  }
  // The smallest: two poles and a triangle around the equator.
  const TriangleSoup bipyramid = uvSphereMesh(2, 3, 1.0);
  EXPECT_EQ(bipyramid.positions.size(), 5u);
  expectClosed(bipyramid);
  EXPECT_THROW(uvSphereMesh(1, 8, 1.0), std::invalid_argument);
}

TEST(MeshGenerators, SplitMixIsDeterministicAndInRange) {
  SplitMix64 a(123), b(123);
  for (int i = 0; i < 1000; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
  }
  // The reference value of splitmix64 seeded with 0 (Vigna's splitmix64.c).
  EXPECT_EQ(SplitMix64(0).next(), 0xe220a8397b1dcdafULL);
}

}  // namespace
}  // namespace geodex::verify
