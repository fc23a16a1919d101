#pragma once
// The triangle mesh as the solver sees it: positions, faces, edges with their one or two faces,
// corner angles (from atan2 of edge vectors: well-conditioned for needles, unlike acos of the law
// of cosines), vertex angle sums, boundary and pseudo-source (saddle or boundary) flags.
//
// Winding does not matter: edges are keyed by their vertex pair and every unfolding places the
// apex above the edge, so faces with inconsistent orientation are handled as they are.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace geodex {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Index = std::uint32_t;
inline constexpr Index kNoIndex = ~Index{0};

/// True if every coordinate is finite. (Eigen's allFinite() computes x − x, which raises the
/// invalid-operation trap on ±inf in debug test runs; this does not.)
template <typename Vector>
bool isFinite(const Vector& p) {
  for (int i = 0; i < p.size(); ++i)
    if (!std::isfinite(p[i])) return false;
  return true;
}

/// The power of two geodex measures a mesh's lengths in ("mesh units"): 2^exponent, with the
/// exponent of the largest coordinate magnitude among the vertices that faces use, so that in
/// mesh units every such coordinate lies in (-2, 2). Dividing by a power of two is exact: a mesh
/// scaled by 2^k has the same geometry in mesh units bit for bit, hence the same decisions,
/// counters and (scaled back, also exactly) distances, at any scale a double can hold.
/// docs/numerics.md has the argument.
struct MeshUnit {
  int exponent = 0;
  double unit = 1.0;     ///< 2^exponent
  double inverse = 1.0;  ///< 2^-exponent (finite: the exponent is at least -1022)
};
/// The unit for a mesh whose largest coordinate magnitude is `largestCoordinate` (finite, >= 0).
MeshUnit meshUnitOf(double largestCoordinate);
/// Where x (mesh units) lands in the file's units: Overflow beyond the largest double, Subnormal
/// below the smallest normal one (0 and infinities are Normal: they scale to themselves). Decided
/// from the exponents, so the test raises no floating-point exception (debug test runs trap
/// overflow), and exact: multiplying by 2^exponent only moves the exponent.
enum class ScaledRange { Normal, Subnormal, Overflow };
ScaledRange inFileUnitsRange(double x, const MeshUnit& unit);
/// The same for x in the file's units on its way into mesh units (times 2^-exponent).
ScaledRange inMeshUnitsRange(double x, const MeshUnit& unit);

/// Why an edge cannot be computed with, given its length in mesh units (or None).
enum class EdgeLengthProblem {
  None,
  Spread,     ///< shorter than tol::kMinEdgeLengthRel: its lengths times the tolerances would underflow
  Subnormal,  ///< its length in the mesh's own units is below the smallest normal double
  Overflow,   ///< its length in the mesh's own units is beyond the largest double
};
EdgeLengthProblem edgeLengthProblem(double lengthInMeshUnits, const MeshUnit& unit);
/// The error kind ('edge-length-spread', 'edge-length-out-of-range') and the end of a message
/// saying what is wrong with such an edge and what to do, for Mesh and validateMesh alike.
const char* edgeLengthProblemKind(EdgeLengthProblem problem);
std::string describeEdgeLengthProblem(EdgeLengthProblem problem, double lengthInMeshUnits,
                                      const MeshUnit& unit);

/// Triangles and positions before connectivity is built (what the readers produce).
struct TriangleSoup {
  std::vector<Vec3> positions;            ///< #V positions
  std::vector<std::array<Index, 3>> faces;  ///< #F triangles, vertex indices into positions
  /// Optional, same length as positions / faces when present: the 1-based line of the input
  /// file each element came from, so validation errors can say where.
  std::vector<int> vertexLines;
  std::vector<int> faceLines;
  std::string fileName;  ///< for messages; empty when built in memory
};

struct Edge {
  std::array<Index, 2> vertex;  ///< vertex[0] < vertex[1]; edge coordinates run from vertex[0]
  std::array<Index, 2> face;    ///< face[1] == kNoIndex on the boundary
  double length;                ///< in mesh units (Mesh::unit())
};

/// The unfolding of one face onto one of its edges: the edge on the x-axis from its vertex[0]
/// at the origin to vertex[1] at (length, 0), the third vertex (the apex) above it; in mesh units.
struct FaceFrame {
  Index edge;  ///< the edge this frame is built on (e0 of Fig. 3)
  Index edgeToV0;  ///< e1 of Fig. 3: from the edge's vertex[0] (v0) to the apex (v1)
  Index edgeToV2;  ///< e2 of Fig. 3: from the apex (v1) to the edge's vertex[1] (v2)
  Index apex;      ///< v1
  Vec2 apexPos;    ///< apex coordinates, y >= 0 (y == 0 only for zero-area faces)
};

class Mesh {
 public:
  /// Builds connectivity. Throws InputError (naming the element, and the file line when the soup
  /// has it) for what the solver cannot handle: non-finite coordinates, indices out of range,
  /// a repeated index in a face, a zero-length edge inside a face, an edge whose length is not a
  /// normal double or is below tol::kMinEdgeLengthRel of the largest coordinate, an edge with
  /// more than two faces. Everything else (zero-area caps, unreferenced vertices, several components,
  /// non-manifold vertices, inconsistent winding, duplicated positions) is handled.
  explicit Mesh(TriangleSoup soup);

  std::size_t numVertices() const { return soup_.positions.size(); }
  std::size_t numFaces() const { return soup_.faces.size(); }
  std::size_t numEdges() const { return edges_.size(); }

  const Vec3& position(Index v) const { return soup_.positions[v]; }
  const std::array<Index, 3>& face(Index f) const { return soup_.faces[f]; }
  const Edge& edge(Index e) const { return edges_[e]; }
  /// faceEdges(f)[k] joins face(f)[k] and face(f)[(k+1)%3].
  const std::array<Index, 3>& faceEdges(Index f) const { return faceEdges_[f]; }
  /// Corner angle of face f at its k-th corner, in [0, π].
  double cornerAngle(Index f, int k) const { return cornerAngles_[3 * f + k]; }
  double angleSum(Index v) const { return angleSums_[v]; }
  bool isBoundaryVertex(Index v) const { return boundaryVertex_[v] != 0; }
  /// Boundary vertex, non-manifold vertex, or angle sum > 2π + tol::kFlatVertexAngle (a saddle):
  /// geodesics may bend here, so the solver makes it a pseudo-source.
  bool isPseudoSourceVertex(Index v) const { return pseudoSource_[v] != 0; }
  bool isReferenced(Index v) const { return vertexFaceStart_[v] != vertexFaceStart_[v + 1]; }

  std::span<const Index> vertexFaces(Index v) const {
    return {vertexFaceList_.data() + vertexFaceStart_[v],
            vertexFaceList_.data() + vertexFaceStart_[v + 1]};
  }
  std::span<const Index> vertexEdges(Index v) const {
    return {vertexEdgeList_.data() + vertexEdgeStart_[v],
            vertexEdgeList_.data() + vertexEdgeStart_[v + 1]};
  }
  /// The length of the longest edge at v (0 at a vertex no edge has).
  double longestEdgeAt(Index v) const { return longestEdgeAt_[v]; }
  /// The edge joining a and b, or kNoIndex.
  Index findEdge(Index a, Index b) const;
  /// Position k (0..2) of edge e in faceEdges(f); -1 if e is not an edge of f.
  int localEdgeIndex(Index f, Index e) const;
  /// The frame of face f unfolded onto its edge e (which must be an edge of f).
  const FaceFrame& frame(Index f, Index e) const { return frames_[3 * f + localEdgeIndex(f, e)]; }
  const FaceFrame& frameByLocal(Index f, int k) const { return frames_[3 * f + k]; }
  /// 0 or 1: which of edge(e).face is f.
  int sideOf(Index e, Index f) const { return edges_[e].face[0] == f ? 0 : 1; }

  /// Positions are in the file's units; edge lengths, frames and everything the solver computes
  /// in mesh units: that length divided by unit(), a power of two (MeshUnit).
  double unit() const { return unit_.unit; }
  const MeshUnit& meshUnit() const { return unit_; }
  /// Position of v in mesh units (exact: position(v) / unit()).
  Vec3 positionInMeshUnits(Index v) const { return soup_.positions[v] * unit_.inverse; }
  /// The diagonal of the bounding box of the vertices faces use, in the file's units (+inf if
  /// that overflows a double) and in mesh units.
  double boundingBoxDiagonal() const { return bboxDiagonal_ * unit_.unit; }
  double boundingBoxDiagonalInMeshUnits() const { return bboxDiagonal_; }
  /// Number of connected components (through shared edges or vertices) with at least one face.
  std::size_t numComponents() const { return numComponents_; }
  Index componentOf(Index v) const { return component_[v]; }
  const TriangleSoup& soup() const { return soup_; }

 private:
  // The build phases of the constructor, in the order it runs them (mesh.cpp).
  void refuseFacesWithoutUnfolding() const;
  void chooseMeshUnit();
  void refuseUncomputableEdgeLengths() const;
  void buildEdges();
  void sortEdgesAlongSpace();
  void buildFaceFrames();
  void measureCornerAngles();
  void buildVertexAdjacency();
  void sumVertexAngles();
  void markBoundaryVertices();
  void findPseudoSourceVertices();
  bool joinsSeveralFans(Index v) const;
  void labelComponents();
  void measureBoundingBox();

  TriangleSoup soup_;
  std::vector<Edge> edges_;
  std::vector<std::array<Index, 3>> faceEdges_;
  std::vector<FaceFrame> frames_;
  std::vector<double> cornerAngles_;
  std::vector<double> angleSums_;
  std::vector<std::uint8_t> boundaryVertex_;
  std::vector<std::uint8_t> pseudoSource_;
  std::vector<Index> vertexFaceStart_, vertexFaceList_;
  std::vector<Index> vertexEdgeStart_, vertexEdgeList_;
  std::vector<double> longestEdgeAt_;
  std::vector<Index> component_;
  std::size_t numComponents_ = 0;
  MeshUnit unit_;
  double bboxDiagonal_ = 0.0;  // in mesh units
};

}  // namespace geodex
