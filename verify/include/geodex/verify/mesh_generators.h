#pragma once
// Synthetic meshes with known properties, for tests, fuzz targets and oracles.
//
// Every generator returns a geodex::TriangleSoup with consistently wound faces (counter-clockwise
// seen from +z for the planar and height-field meshes, from outside for the spheres), no
// duplicated positions and no unreferenced vertices. All are deterministic: the ones that take a
// seed use their own splitmix64 stream, never std::random_device or a global generator, so a seed
// printed by a failing test reproduces the same mesh on every platform.
//
// Grid conventions shared by the grid-based generators: `nx` × `ny` *cells*, so (nx+1) × (ny+1)
// vertices before any are removed; vertex (i, j) sits at (i·width/nx, j·height/ny), the grid's
// lower-left corner at the origin, and (for full grids) has index j·(nx+1) + i.

#include <cstdint>
#include <functional>

#include "geodex/mesh.h"

namespace geodex::verify {

/// How each grid cell is split into two triangles.
enum class DiagonalPattern {
  AllOneWay,    ///< every cell split along its (i,j)–(i+1,j+1) diagonal
  Alternating,  ///< checkerboard: cells with odd i+j use the (i+1,j)–(i,j+1) diagonal instead
};

/// A planar (z = 0) rectangular grid.
/// @param[in] nx, ny   number of cells along x and y, ≥ 1
/// @param[in] width, height  extent along x and y, > 0
/// @return (nx+1)(ny+1) vertices, 2·nx·ny faces
TriangleSoup gridMesh(int nx, int ny, double width, double height,
                      DiagonalPattern pattern = DiagonalPattern::AllOneWay);

/// gridMesh with every interior vertex moved in the plane by a pseudo-random offset of up to
/// jitterFraction × the cell size along each axis. Boundary vertices stay, so the domain is
/// still the (convex) rectangle and planar distances are Euclidean.
/// @param[in] jitterFraction  in [0, 1/6): below 1/6 no triangle can flip (the worst case of
///                            the signed area, (1 − 2f)² − 2f(1 + 2f) = 1 − 6f, stays positive)
/// @param[in] seed            the same seed gives the same mesh
TriangleSoup jitteredGridMesh(int nx, int ny, double width, double height, double jitterFraction,
                              std::uint64_t seed,
                              DiagonalPattern pattern = DiagonalPattern::AllOneWay);

/// A planar fan of thin triangles: vertex 0 is the centre (origin), vertices 1..numNeedles+1 lie
/// on the circle of the given radius at angles k·apexAngle, k = 0..numNeedles, and face k is
/// (0, k+1, k+2). The centre is a corner of every needle; the domain is a circular sector
/// (a convex polygon, since its total angle numNeedles·apexAngle must be ≤ π), so planar
/// distances are Euclidean.
/// @param[in] numNeedles        ≥ 1
/// @param[in] apexAngleRadians  > 0, with numNeedles · apexAngleRadians ≤ π
/// @return numNeedles + 2 vertices, numNeedles faces
TriangleSoup needleFanMesh(int numNeedles, double apexAngleRadians, double radius);

/// A planar L-shaped domain: the square [0, size]² minus its upper-right quadrant
/// (size/2, size]², meshed by an n × n grid of which the n²/4 cells of that quadrant are removed.
/// The reflex corner is the vertex at (size/2, size/2).
/// @param[in] n  cells per side of the full square, even, ≥ 2
/// @return (n+1)² − (n/2)² vertices, 3n²/2 faces
TriangleSoup lShapeMesh(int n, double size, DiagonalPattern pattern = DiagonalPattern::AllOneWay);

/// A planar square [0, size]² minus a centred square hole, meshed by an n × n grid of which the
/// h × h central cells are removed. The hole side is snapped to the grid: h is the integer
/// nearest to holeFraction · n that has the parity of n (so the hole is centred), clamped to
/// [1 or 2, n − 2] (at least one ring of cells stays around the hole).
/// The hole's actual side is h · size / n.
/// @param[in] n  cells per side, ≥ 3
/// @param[in] holeFraction  in (0, 1)
/// @return (n+1)² − (h−1)² vertices, 2(n² − h²) faces
TriangleSoup squareWithHoleMesh(int n, double size, double holeFraction,
                                DiagonalPattern pattern = DiagonalPattern::AllOneWay);

/// The number of hole cells per side squareWithHoleMesh(n, ·, holeFraction) uses.
int squareHoleCells(int n, double holeFraction);

/// A height field over the grid of gridMesh: vertex (x, y) is lifted to z(x, y).
TriangleSoup heightFieldMesh(int nx, int ny, double width, double height,
                             const std::function<double(double, double)>& z,
                             DiagonalPattern pattern = DiagonalPattern::AllOneWay);

/// A terraced height field on the integer grid: vertex (i, j) at (i, j, h) with integer
/// h in [0, levels − 1], h the rounding of a smooth random function (a few sinusoids with
/// seeded frequencies and phases). Rounding makes wide plateaus: many coplanar faces and many
/// flat vertices (angle sum exactly 2π) next to steps, all with exactly representable
/// coordinates.
/// @param[in] levels  ≥ 1 (1 gives a flat grid)
/// @return (nx+1)(ny+1) vertices, 2·nx·ny faces
TriangleSoup quantizedHeightField(int nx, int ny, std::uint64_t seed, int levels);

/// A height field on the integer grid, vertex (i, j) at (i, j, z) with z drawn uniformly from
/// [−amplitude, amplitude] by SplitMix64(seed), row by row: saddles, cones and nearly flat
/// vertices side by side, none of them on purpose.
/// @param[in] nx, ny     cells along x and y, ≥ 1
/// @param[in] amplitude  ≥ 0
/// @return (nx+1)(ny+1) vertices, 2·nx·ny faces
TriangleSoup bumpyHeightField(int nx, int ny, double amplitude, std::uint64_t seed);

/// gridMesh(n, n, n, n) with each interior vertex lifted by a uniform draw from [−0.3, 0.3]
/// (SplitMix64(seed), row by row), whose y = 0 side is joined by n long thin triangles to one vertex (the last) at (n/2, −far, 0):
/// windows from that far vertex reach the patch with σ ≈ far, where Eq. 1's coefficients cancel
/// (D4, tests/unit's far-source test).
/// @param[in] n    cells per side, ≥ 1
/// @param[in] far  > 0, e.g. 1e4–1e7 × n
/// @return (n+1)² + 1 vertices, 2n² + n faces
TriangleSoup farSourceBumpyPatch(int n, double far, std::uint64_t seed);

/// An icosahedron with each face split into 4 `subdivisions` times, vertices projected onto the
/// sphere of the given radius centred at the origin.
/// @return 10·4^s + 2 vertices, 20·4^s faces
TriangleSoup icosphereMesh(int subdivisions, double radius);

/// A latitude/longitude sphere centred at the origin: `rings` latitude bands between the poles
/// (each pole a single vertex, on the ±z axis), `segments` vertices around each of the
/// rings − 1 latitude circles.
/// @param[in] rings ≥ 2, segments ≥ 3
/// @return 2 + (rings − 1)·segments vertices, 2·segments·(rings − 1) faces
TriangleSoup uvSphereMesh(int rings, int segments, double radius);

/// splitmix64 (Steele, Lea & Flood 2014): a tiny, fast, well-mixed deterministic generator.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  /// Uniform in [0, 1).
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::uint64_t state_;
};

}  // namespace geodex::verify
