#pragma once
// Independent oracles for distance fields (DESIGN.md, "Oracles"). Nothing here uses the solver's
// algorithm, its connectivity (geodex::Mesh is only read through its soup) or its tolerances:
// each oracle is an independent computation, so that agreement with the solver means something.
//
//  - euclideanDistances   straight 3-D distance: a lower bound of the geodesic distance on any
//                         mesh, and *the* distance on planar convex meshes.
//  - edgeGraphDijkstra    shortest paths along mesh edges: an upper bound on any mesh.
//  - PlanarDomain         exact shortest paths in a planar polygonal domain with holes (the
//                         visibility graph of its reflex vertices): the distance on planar
//                         non-convex meshes, independent of how they are triangulated.
//  - check*               bound checks over a whole distance field, returning a CheckReport.
//
// Conventions: distance fields have one entry per vertex of the soup (#V), +inf for unreachable
// or unreferenced vertices. Invalid arguments (sizes, indices, points outside a domain) throw
// std::invalid_argument.

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/surface_point.h"

namespace geodex::verify {

// === Surface points ============================================================================

/// The 3-D position of p, computed directly from the soup's positions (p.t along the edge from
/// p.vertex to p.toVertex; p.bary over face(p.face)[0..2]). Checks indices and that an edge
/// point's two vertices share a face; does not snap or otherwise interpret p.
Vec3 surfacePointPosition(const TriangleSoup& soup, const SurfacePoint& p);

/// The mesh's soup in its mesh units (Mesh::unit(), exact), to compare with the solver's
/// distances in mesh units: an oracle's own squares then neither under- nor overflow at any
/// scale the solver accepts. A vertex no face uses and whose position leaves the range of doubles
/// that way goes to the origin (it is no part of the geometry; its distance is +inf).
TriangleSoup soupInMeshUnits(const Mesh& mesh);

// === Euclidean lower bound =====================================================================

/// Straight-line distance from `source` to each of `positions`.
/// @return #positions distances
std::vector<double> euclideanDistances(std::span<const Vec3> positions, const Vec3& source);
/// Distance to the nearest of several sources (≥ 1).
std::vector<double> euclideanDistances(std::span<const Vec3> positions,
                                       std::span<const Vec3> sources);

// === Edge-graph upper bound ====================================================================

/// Dijkstra along the mesh edges (3-D edge lengths), started from the given vertices with the
/// given initial distances (vertex index, distance ≥ 0). Every edge path is a path on the
/// surface, so the result bounds the geodesic distance from above.
/// @param[in] sourceVertices  any number of (vertex, initial distance) pairs
/// @return #V distances; +inf for vertices no source reaches and for unreferenced vertices
///         (an unreferenced source vertex reaches nothing, not even itself)
std::vector<double> edgeGraphDijkstra(const TriangleSoup& soup,
                                      const std::vector<std::pair<Index, double>>& sourceVertices);
std::vector<double> edgeGraphDijkstra(const Mesh& mesh,
                                      const std::vector<std::pair<Index, double>>& sourceVertices);

/// The same from surface points: a vertex source starts at distance 0; an edge point is joined
/// by straight segments to the edge's endpoints and to the opposite corner of every face on that
/// edge; a face point is joined to the face's three corners. Those segments lie on the surface,
/// so the result is still an upper bound.
std::vector<double> edgeGraphDijkstra(const TriangleSoup& soup,
                                      const std::vector<SurfacePoint>& sources);
std::vector<double> edgeGraphDijkstra(const Mesh& mesh, const std::vector<SurfacePoint>& sources);

// === Planar polygonal domains ==================================================================

/// A closed polygon as its vertices in order (not repeating the first at the end).
using Polygon2 = std::vector<Vec2>;

/// A closed planar domain bounded by polygons: one outer boundary and any number of holes, none
/// crossing another. Points on the boundary belong to the domain.
///
/// Shortest paths in such a domain are polylines that bend only at reflex boundary vertices, so
/// the distance from s to q is the shortest path from s to q in the visibility graph over
/// {s, reflex vertices, q}. A segment is *admissible* (in the visibility graph) when all of it
/// lies in the closed domain: it may touch reflex vertices and run along boundary edges.
///
/// Robustness: all decisions use one tolerance, kTouchRel × the diagonal of the boundary's
/// bounding box. A point within it of the boundary is on the boundary; a segment passing within
/// it of a boundary vertex touches the vertex. The distances are exact up to a few times that
/// tolerance (a path may graze a reflex vertex by up to it), far below the solver's 1e-9.
class PlanarDomain {
 public:
  /// Touch tolerance relative to the bounding-box diagonal: 10^4 above the ~1e-16 relative error
  /// of the signed distances it compares (computed from differences of nearby points), 10^3
  /// below the accuracy the solver is held to.
  static constexpr double kTouchRel = 1e-12;
  /// A boundary vertex is reflex when the sine of its turn is below −kReflexSin. Near-straight
  /// vertices need not be nodes: a path through them does not bend there.
  static constexpr double kReflexSin = 1e-12;

  /// @param[in] loops  the boundary polygons in any orientation; the one of largest |area| is
  ///                   the outer boundary, the others are holes. Consecutive repeated vertices
  ///                   are dropped. Each loop needs ≥ 3 distinct vertices.
  explicit PlanarDomain(std::vector<Polygon2> loops);

  /// p is inside the domain or within the tolerance of its boundary.
  bool contains(const Vec2& p) const;
  /// Every point of the segment pq lies in the closed domain (see the class comment).
  bool segmentInside(const Vec2& p, const Vec2& q) const;

  /// Shortest-path distance inside the domain from `source` to each query point.
  /// Throws std::invalid_argument if the source or a query point is outside the domain.
  /// @return #queries distances
  std::vector<double> distances(const Vec2& source, std::span<const Vec2> queries) const;

  /// The boundary, oriented so that the domain lies to the left: outer loop first
  /// (counter-clockwise), then the holes (clockwise).
  const std::vector<Polygon2>& loops() const { return loops_; }
  const std::vector<Vec2>& reflexVertices() const { return reflex_; }
  /// The absolute tolerance, kTouchRel × bounding-box diagonal.
  double tolerance() const { return eps_; }

 private:
  bool onBoundary(const Vec2& p) const;
  bool properlyCrossesBoundary(const Vec2& p, const Vec2& q) const;

  std::vector<Polygon2> loops_;
  std::vector<std::pair<Vec2, Vec2>> edges_;
  std::vector<Vec2> vertices_;
  std::vector<Vec2> reflex_;
  double eps_ = 0.0;
};

/// One call: PlanarDomain(boundary).distances(source, queries).
std::vector<double> planarDomainDistances(const std::vector<Polygon2>& boundary,
                                          const Vec2& source, std::span<const Vec2> queries);

/// The boundary polygons of a planar triangle soup (x, y of the positions; z is ignored): the
/// edges used by exactly one face, chained into loops. The loop of largest |area| comes first
/// (the outer boundary), the others follow (holes). Works for any face winding.
/// Throws std::invalid_argument if a vertex has other than 0 or 2 boundary edges (a pinch)
/// or an edge is used by more than two faces.
std::vector<Polygon2> planarBoundaryPolygons(const TriangleSoup& soup);

/// True if the planar soup (x, y; z is ignored) covers the domain its boundary `loops` enclose
/// (planarBoundaryPolygons) exactly once, which PlanarDomain takes for granted: the loops are
/// simple and do not meet, and the face areas add up to the outer loop's minus the holes'
/// (tol::kPlanarCoverRel). A mesh folded over itself (a face flipped onto its neighbours, a
/// double cover) is intrinsically flat, but its geodesics are not the domain's shortest paths.
bool coversItsDomainOnce(const TriangleSoup& soup, const std::vector<Polygon2>& loops);

/// The x, y of every position (queries for PlanarDomain::distances).
std::vector<Vec2> planarPositions(const TriangleSoup& soup);

/// How far an oracle's sources may be from the solver's, in the soup's units: the rounding of
/// placing them in 3-D (tol::kPositionRoundingRel of the largest coordinate, for the source and
/// for the point it is compared at), and the snap of a source within tol::kSnapParam of a vertex
/// or an edge onto it (surface_point.cpp, resolve), which moves it by up to kSnapParam × its edge
/// or its face's longest edge. The absTol of the bound checks below for a field of those sources.
double sourcePlacementSlack(const TriangleSoup& soup, std::span<const SurfacePoint> sources);

// === Bound checks ==============================================================================

/// The outcome of a check over a distance field.
struct CheckReport {
  std::size_t checked = 0;  ///< how many values (or edges, or pairs) were compared
  std::size_t failed = 0;   ///< how many of them broke the bound beyond the tolerance
  /// Largest relative amount by which a bound was exceeded, comparable with relTol (0 when
  /// every value is within its bound; +inf for finite-versus-infinite mismatches).
  double maxError = 0.0;
  std::string firstFailure;  ///< what broke first, naming the vertex/edge and the numbers

  bool ok() const { return failed == 0; }
  /// One line: "checked N, failed M, maxError E[: first failure]".
  std::string summary() const;
};

// Every check lets a value exceed its bound B by relTol × (|B| + L), where L is a length scale
// of the whole field (given per check below). Relative to B alone, a value near the source
// (B ≈ 0) would be held to an impossible absolute accuracy; relative to L alone, far values
// would get a looser check than the solver promises. NaN always fails.

/// Each bound below allows relTol × (value + L) + absTol, absTol being what the reference owes
/// to points it placed in 3-D (a source point's position: tol::kPositionRoundingRel).
/// d ≥ euclid − tolerance wherever d is finite (an unreachable vertex satisfies a lower bound).
/// L = the largest finite value of euclid. Negative d fails.
CheckReport checkEuclideanLowerBound(std::span<const double> d, std::span<const double> euclid,
                                     double relTol, double absTol = 0.0);

/// d ≤ upper + tolerance, e.g. upper = edgeGraphDijkstra(...). A vertex finite in one field and
/// infinite in the other fails (the edge graph reaches exactly what the surface reaches).
/// L = the largest finite value of upper.
CheckReport checkUpperBound(std::span<const double> d, std::span<const double> upper,
                            double relTol, double absTol = 0.0);

/// |d(u) − d(v)| ≤ |uv| + tolerance on every mesh edge uv with both ends finite (geodesic
/// distance is 1-Lipschitz along the surface). Edges with one infinite end are skipped (a solve
/// with a stop distance leaves those). L = the bounding-box diagonal of the referenced vertices.
CheckReport checkLipschitz(const TriangleSoup& soup, std::span<const double> d, double relTol);
CheckReport checkLipschitz(const Mesh& mesh, std::span<const double> d, double relTol);

/// d(a, b) = d(b, a) within relTol × max(|dab|, |dba|). checked = 1.
CheckReport checkSymmetry(double dab, double dba, double relTol);

/// |d − reference| ≤ tolerance entry by entry (e.g. against the planar-domain or the CGAL
/// oracle); +inf must match +inf. L = the largest finite value of reference.
CheckReport checkAgreement(std::span<const double> d, std::span<const double> reference,
                           double relTol, double absTol = 0.0);

}  // namespace geodex::verify
