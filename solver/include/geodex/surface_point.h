#pragma once
// A point on the mesh surface: a vertex, a point on an edge, or a point inside a face.

#include <array>
#include <string>

#include "geodex/mesh.h"

namespace geodex {

struct SurfacePoint {
  enum class Kind { Vertex, Edge, Face };
  Kind kind = Kind::Vertex;
  /// Vertex: the vertex. Edge: the two endpoints as the user named them (from, to).
  /// Face: unused.
  Index vertex = kNoIndex;
  Index toVertex = kNoIndex;
  /// Edge: fraction in [0, 1] from `vertex` to `toVertex`.
  double t = 0.0;
  /// Face: the face and barycentric coordinates of its corners face(f)[0..2], summing to 1.
  Index face = kNoIndex;
  std::array<double, 3> bary{0.0, 0.0, 0.0};

  static SurfacePoint atVertex(Index v) { return {Kind::Vertex, v, kNoIndex, 0.0, kNoIndex, {}}; }
  /// The point at fraction t from vertex `from` to vertex `to` of the edge joining them.
  static SurfacePoint onEdge(Index from, Index to, double t) {
    return {Kind::Edge, from, to, t, kNoIndex, {}};
  }
  static SurfacePoint inFace(Index f, double a, double b, double c) {
    return {Kind::Face, kNoIndex, kNoIndex, 0.0, f, {a, b, c}};
  }
};

/// Parses the CLI's SPEC syntax: `v:I`, `e:I,J,T`, `f:F,A,B,C`. Throws InputError on bad syntax.
SurfacePoint parseSurfacePoint(const std::string& spec);
/// The inverse of parseSurfacePoint, with %.17g numbers.
std::string formatSurfacePoint(const SurfacePoint& p);

/// A surface point resolved against a mesh: a vertex, or an edge id with the parameter measured
/// from edge(e).vertex[0], or a face with barycentrics. Parameters within tol::kSnapParam of an
/// end snap to the vertex or edge they are on.
struct ResolvedPoint {
  SurfacePoint::Kind kind;
  Index element;       ///< vertex, edge or face id
  double t = 0.0;      ///< Edge: position in [0, length] from edge(e).vertex[0]
  std::array<double, 3> bary{};  ///< Face
  Vec3 position;
};

/// Validates p against the mesh (indices in range, the edge exists, parameters finite and in
/// range, barycentrics non-negative and summing to 1 within 1e-9) and resolves it.
/// Throws InputError naming the element otherwise.
ResolvedPoint resolve(const Mesh& mesh, const SurfacePoint& p);

/// Coordinates of p — a corner of face f, a point on one of f's edges, or a point inside f — in
/// the frame of f unfolded onto its edge e (Mesh::frame: e's vertex[0] at the origin, e along +x,
/// the apex above). Computed from p's edge parameter or barycentrics and the frame's corners,
/// never from absolute 3-D positions: a mesh far from the origin keeps the precision of its
/// local lengths (a point 5e6 from the origin is only known to ~1e-9 in absolute coordinates).
/// Requires p to lie on f (a vertex of f, an edge of f, or f itself).
Vec2 pointInFaceFrame(const Mesh& mesh, const ResolvedPoint& p, Index f, Index e);

}  // namespace geodex
