#pragma once
// The differential oracle (DESIGN.md, "Oracles"): CGAL's Surface_mesh_shortest_path, an
// independent exact-geodesic algorithm (Chen–Han / Xin–Wang), with the
// Exact_predicates_inexact_constructions_kernel. Optional: the target geodex_cgal_oracle exists
// only where CGAL is installed, and defines GEODEX_HAVE_CGAL_ORACLE for its users.
//
// Known limits (measured, see DESIGN.md): its constructions are in doubles, so expect ~1e-7
// relative agreement on good meshes and ~1e-5 on large flat grids, where it loses windows; on
// some CAD meshes it is off by up to 1%. Disagreement is a lead, not a verdict.
//
// CGAL 5.5.1 mirrors sources that lie exactly on an edge (weights (a, b) are seeded as (b, a));
// the oracle probes once what the installed CGAL does and compensates, so edge sources and face
// sources with a zero barycentric coordinate land where they should.
//
//   std::vector<double> d = geodex::verify::cgalGeodesicDistances(soup, {SurfacePoint::atVertex(0)});
//
//   geodex::verify::CgalGeodesicOracle oracle(soup);
//   oracle.solve({SurfacePoint::inFace(7, 0.2, 0.3, 0.5)});
//   double d = oracle.distance(SurfacePoint::onEdge(3, 4, 0.25));

#include <memory>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/surface_point.h"

namespace geodex::verify {

/// Wall-clock seconds spent in each phase (std::chrono::steady_clock), for benchmarks.
struct CgalTiming {
  double buildMeshSeconds = 0.0;   ///< soup → CGAL::Surface_mesh and the solver's set-up
  double sequenceTreeSeconds = 0.0;  ///< adding the sources and build_sequence_tree()
  double querySeconds = 0.0;       ///< the distance queries so far
  double totalSeconds() const { return buildMeshSeconds + sequenceTreeSeconds + querySeconds; }
};

/// Keeps the CGAL mesh and sequence tree for repeated queries.
class CgalGeodesicOracle {
 public:
  /// Builds a CGAL::Surface_mesh from the soup: every referenced vertex, every face in soup
  /// order. Throws std::invalid_argument if a face cannot be added (an index out of range, a
  /// repeated index, a non-manifold edge or vertex, or winding inconsistent with its neighbours:
  /// CGAL's halfedge structure needs an oriented 2-manifold, possibly with boundary).
  explicit CgalGeodesicOracle(const TriangleSoup& soup);
  ~CgalGeodesicOracle();
  CgalGeodesicOracle(CgalGeodesicOracle&&) noexcept;
  CgalGeodesicOracle& operator=(CgalGeodesicOracle&&) noexcept;

  /// Replaces the sources (≥ 1; vertices, edge points, face points) and builds the sequence tree.
  /// Throws std::invalid_argument for a source not on the mesh (unreferenced vertex, no face
  /// holding the edge, index out of range).
  void solve(const std::vector<SurfacePoint>& sources);

  /// Distance from the nearest source to every vertex of the soup (#V entries); +inf for
  /// unreferenced vertices and vertices no source reaches.
  std::vector<double> vertexDistances();
  /// Distance from the nearest source to any surface point; +inf if unreachable.
  double distance(const SurfacePoint& p);

  const CgalTiming& timing() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One call: distances from `sources` to every vertex of `soup` (#V entries, +inf where
/// unreachable or unreferenced). Sources are mapped onto CGAL face locations with the
/// barycentric coordinates reordered from soup.faces[f][0..2] to CGAL's halfedge order.
/// @param[out] timing  optional: where the time went
std::vector<double> cgalGeodesicDistances(const TriangleSoup& soup,
                                          const std::vector<SurfacePoint>& sources,
                                          CgalTiming* timing = nullptr);

}  // namespace geodex::verify
