#pragma once
// The cases `geodex crosscheck` runs another exact-geodesic program on: a mesh and a vertex
// source, made by the generators the property tests and the fuzz targets already use, so that
// every configuration they aim at reaches the other program too:
//
//   two-faces          fuzz_two_faces' seeds: G1, G4, G5 unfolded across one edge, zero-area and
//                      folded pairs, inconsistent winding, scales 1e-6 and 1e+6
//   fuzz-solver-seed   fuzz_solver's seeds: flat grids, holes, saddles, cones, terraces, moved
//                      vertices (needles, zero-area faces), non-manifold vertices, components
//   fuzz-solver        fuzz_solver's decoder on bytes drawn from the seed (what the fuzzer makes)
//   flat-grid          gridMesh: every interior vertex flat (angle sum 2π), rays through
//                      vertices (G2–G5) and along edges (G1); distances are Euclidean
//   near-flat-grid     jitteredGridMesh moved by 1e-13 … 0.15 of a cell: near-collinear rays,
//                      just inside and just outside the tolerances; Euclidean
//   needle-fan         needleFanMesh: apex angles down to 1e-7 π; Euclidean
//   l-shape            lShapeMesh: a boundary with a reflex corner; exact planar paths
//   square-with-hole   squareWithHoleMesh: an inner boundary; exact planar paths
//   terraces           quantizedHeightField: plateaus of flat vertices beside steps
//   bumpy              bumpyHeightField: saddles and cones
//   icosphere          icosphereMesh: a symmetric sphere, many ties
//   uv-sphere          uvSphereMesh: a symmetric sphere with high-valence poles
//   components         a grid beside an icosphere: +inf on the second component
//   far-source         farSourceBumpyPatch: windows from 1e4–1e7 away meet near ones (D4)
//
// Case i is family i mod F at size step i / F, its free parameters drawn from SplitMix64 seeded
// with (seed, i): all families appear within the first F cases, small meshes come first, and the
// same seed gives the same cases in the same order on every platform.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geodex/mesh.h"

namespace geodex::verify {

/// Which exact planar oracle a case's distances can be compared with.
enum class PlanarOracle : std::uint8_t {
  None,    ///< not planar (or not known to be)
  Convex,  ///< planar with a convex domain: distances are Euclidean
  Domain,  ///< planar, non-convex or with holes: shortest paths of the visibility graph
};

/// One case: a mesh and a source vertex, and where they came from.
struct CrossCheckCase {
  std::string family;  ///< one of crossCheckFamilies()
  std::string recipe;  ///< how to rebuild the mesh: a generator call or a seed's name
  TriangleSoup soup;
  Index source = 0;    ///< 0-based, a vertex some face uses
  PlanarOracle planar = PlanarOracle::None;
};

/// The families in the order cases cycle through them.
const std::vector<std::string_view>& crossCheckFamilies();

/// Case `index` of the sequence for `seed` (see the file comment). Deterministic.
CrossCheckCase crossCheckCase(std::uint64_t seed, std::size_t index);

/// The soup without the faces `keep` rejects and without the vertices no kept face uses (the
/// rest keep their order), and `source` renumbered into it; kNoIndex when no kept face uses it.
/// @param[in] keep  #F flags
TriangleSoup keepFaces(const TriangleSoup& soup, const std::vector<bool>& keep, Index& source);

/// The soup as an OFF file, coordinates to 17 significant digits (they read back exactly).
std::string offText(const TriangleSoup& soup);

}  // namespace geodex::verify
