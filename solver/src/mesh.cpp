#include "geodex/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <sstream>

#include "geodex/error.h"
#include "geodex/tolerance.h"
#include "sort_sides.h"

namespace geodex {
namespace {

// "file:line: " when the soup knows where the element came from, else "".
std::string where(const TriangleSoup& soup, const std::vector<int>& lines, std::size_t i) {
  if (i >= lines.size() || lines[i] <= 0) return soup.fileName.empty() ? "" : soup.fileName + ": ";
  return (soup.fileName.empty() ? std::string("line ") : soup.fileName + ":") +
         std::to_string(lines[i]) + ": ";
}

struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
};

}  // namespace

Mesh::Mesh(TriangleSoup soup) : soup_(std::move(soup)) {
  refuseFacesWithoutUnfolding();
  chooseMeshUnit();
  refuseUncomputableEdgeLengths();
  buildEdges();
  sortEdgesAlongSpace();
  buildFaceFrames();
  measureCornerAngles();
  buildVertexAdjacency();
  sumVertexAngles();
  markBoundaryVertices();
  findPseudoSourceVertices();
  labelComponents();
  measureBoundingBox();
}

// ===  Refusing what has no unfolding  ===========================================================

// Non-finite coordinates, indices out of range, a repeated index in a face, a zero-length edge:
// no frame can be built for such a face.
void Mesh::refuseFacesWithoutUnfolding() const {
  const auto& P = soup_.positions;
  const auto& F = soup_.faces;
  const std::size_t nv = P.size();
  for (std::size_t v = 0; v < nv; ++v) {
    if (!isFinite(P[v])) {
      throw InputError("non-finite-coordinate", where(soup_, soup_.vertexLines, v) + "vertex " +
                                                    std::to_string(v) +
                                                    " has a non-finite coordinate");
    }
  }
  for (std::size_t f = 0; f < F.size(); ++f) {
    const auto& t = F[f];
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= nv) {
        throw InputError("index-out-of-range",
                         where(soup_, soup_.faceLines, f) + "face " + std::to_string(f) +
                             " refers to vertex " + std::to_string(t[k]) + " but there are only " +
                             std::to_string(nv) + " vertices");
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      throw InputError("repeated-index", where(soup_, soup_.faceLines, f) + "face " +
                                             std::to_string(f) + " repeats a vertex index");
    }
    for (int k = 0; k < 3; ++k) {
      if (P[t[k]] == P[t[(k + 1) % 3]]) {
        throw InputError("zero-length-edge",
                         where(soup_, soup_.faceLines, f) + "face " + std::to_string(f) +
                             " has a zero-length edge: vertices " + std::to_string(t[k]) +
                             " and " + std::to_string(t[(k + 1) % 3]) +
                             " are at the same position (weld duplicate vertices first)");
      }
    }
  }
}

// The largest coordinate magnitude of a vertex that faces use, to a power of two (MeshUnit).
void Mesh::chooseMeshUnit() {
  double largest = 0.0;
  for (const auto& t : soup_.faces)
    for (Index v : t) largest = std::max(largest, soup_.positions[v].cwiseAbs().maxCoeff());
  unit_ = meshUnitOf(largest);
}

// Every edge length must be one geodex computes with (EdgeLengthProblem): not so short against
// the mesh unit that its lengths times the tolerances underflow, and a normal double in the
// file's units, so that distances scale back.
void Mesh::refuseUncomputableEdgeLengths() const {
  const auto& F = soup_.faces;
  for (std::size_t f = 0; f < F.size(); ++f) {
    const auto& t = F[f];
    for (int k = 0; k < 3; ++k) {
      const double length =
          (positionInMeshUnits(t[(k + 1) % 3]) - positionInMeshUnits(t[k])).norm();
      const EdgeLengthProblem problem = edgeLengthProblem(length, unit_);
      if (problem != EdgeLengthProblem::None) {
        throw InputError(edgeLengthProblemKind(problem),
                         where(soup_, soup_.faceLines, f) + "face " + std::to_string(f) +
                             ": edge " + std::to_string(t[k]) + "-" +
                             std::to_string(t[(k + 1) % 3]) + " " +
                             describeEdgeLengthProblem(problem, length, unit_));
      }
    }
  }
}

// ===  Edges and face frames  ====================================================================

// One edge per vertex pair, from the faces' sides sorted by pair; refuses an edge with more than
// two faces, which has no single face across it to unfold into.
void Mesh::buildEdges() {
  const auto& F = soup_.faces;
  const std::size_t nf = F.size();
  struct HalfEdge {
    Index a, b, face;
    int local;
  };
  std::vector<HalfEdge> half;
  half.reserve(3 * nf);
  for (Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      Index a = F[f][k], b = F[f][(k + 1) % 3];
      if (a > b) std::swap(a, b);
      half.push_back({a, b, f, k});
    }
  }
  detail::sortSidesByVertexPair(
      half, soup_.positions.size(), [](const HalfEdge& h) { return h.a; },
      [](const HalfEdge& x, const HalfEdge& y) {
        return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.face < y.face);
      });
  faceEdges_.assign(nf, {kNoIndex, kNoIndex, kNoIndex});
  std::size_t numEdges = 0;  // (reserved: one allocation, not one per doubling)
  for (std::size_t i = 0; i < half.size(); ++i)
    numEdges += i == 0 || half[i].a != half[i - 1].a || half[i].b != half[i - 1].b;
  edges_.reserve(numEdges);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].a == half[i].a && half[j].b == half[i].b) ++j;
    if (j - i > 2) {
      std::ostringstream os;
      os << where(soup_, soup_.faceLines, half[i].face) << "non-manifold edge " << half[i].a
         << "-" << half[i].b << " is shared by " << (j - i) << " faces (";
      for (std::size_t k = i; k < j && k < i + 5; ++k) os << (k > i ? ", " : "") << half[k].face;
      os << (j - i > 5 ? ", ...)" : ")");
      throw InputError("non-manifold-edge", os.str());
    }
    const Index e = static_cast<Index>(edges_.size());
    Edge edge{{half[i].a, half[i].b},
              {half[i].face, j - i == 2 ? half[i + 1].face : kNoIndex},
              (positionInMeshUnits(half[i].b) - positionInMeshUnits(half[i].a)).norm()};
    edges_.push_back(edge);
    for (std::size_t k = i; k < j; ++k) faceEdges_[half[k].face][half[k].local] = e;
    i = j;
  }
}

// Each face unfolded onto each of its edges (Fig. 3): the edge on the x-axis, the apex above it.
void Mesh::buildFaceFrames() {
  const auto& F = soup_.faces;
  const std::size_t nf = F.size();
  frames_.resize(3 * nf);
  for (Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const Index e = faceEdges_[f][k];
      const Edge& edge = edges_[e];
      const Index apex = F[f][(k + 2) % 3];
      const Vec3 origin = positionInMeshUnits(edge.vertex[0]);
      const Vec3 dir = (positionInMeshUnits(edge.vertex[1]) - origin) / edge.length;
      const Vec3 rel = positionInMeshUnits(apex) - origin;
      const double x = rel.dot(dir);
      const double y = rel.cross(dir).norm();
      FaceFrame& fr = frames_[3 * f + k];
      fr.edge = e;
      fr.apex = apex;
      fr.apexPos = Vec2(x, y);
      // e1 joins edge.vertex[0] (v0) and the apex, e2 the apex and edge.vertex[1] (v2).
      const Index kNext = faceEdges_[f][(k + 1) % 3], kPrev = faceEdges_[f][(k + 2) % 3];
      const bool nextHasV0 = edges_[kNext].vertex[0] == edge.vertex[0] ||
                             edges_[kNext].vertex[1] == edge.vertex[0];
      fr.edgeToV0 = nextHasV0 ? kNext : kPrev;
      fr.edgeToV2 = nextHasV0 ? kPrev : kNext;
    }
  }
}

// Corner angle at corner k from atan2(|u × v|, u · v): accurate for needles and caps. The sides
// are normalized first: |u × v| is a product of two lengths, squared by the norm.
void Mesh::measureCornerAngles() {
  const auto& F = soup_.faces;
  const std::size_t nf = F.size();
  cornerAngles_.resize(3 * nf);
  for (Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 corner = positionInMeshUnits(F[f][k]);
      const Vec3 u = (positionInMeshUnits(F[f][(k + 1) % 3]) - corner).normalized();
      const Vec3 v = (positionInMeshUnits(F[f][(k + 2) % 3]) - corner).normalized();
      cornerAngles_[3 * f + k] = std::atan2(u.cross(v).norm(), u.dot(v));
    }
  }
}

// ===  Vertices  =================================================================================

// The faces and the edges around each vertex, in compressed rows (CSR).
void Mesh::buildVertexAdjacency() {
  const auto& F = soup_.faces;
  const std::size_t nv = soup_.positions.size();
  const std::size_t nf = F.size();
  vertexFaceStart_.assign(nv + 1, 0);
  for (const auto& t : F)
    for (Index v : t) ++vertexFaceStart_[v + 1];
  std::partial_sum(vertexFaceStart_.begin(), vertexFaceStart_.end(), vertexFaceStart_.begin());
  vertexFaceList_.resize(3 * nf);
  {
    std::vector<Index> fill(vertexFaceStart_.begin(), vertexFaceStart_.end() - 1);
    for (Index f = 0; f < nf; ++f)
      for (Index v : F[f]) vertexFaceList_[fill[v]++] = f;
  }
  vertexEdgeStart_.assign(nv + 1, 0);
  for (const Edge& e : edges_) {
    ++vertexEdgeStart_[e.vertex[0] + 1];
    ++vertexEdgeStart_[e.vertex[1] + 1];
  }
  std::partial_sum(vertexEdgeStart_.begin(), vertexEdgeStart_.end(), vertexEdgeStart_.begin());
  vertexEdgeList_.resize(2 * edges_.size());
  {
    std::vector<Index> fill(vertexEdgeStart_.begin(), vertexEdgeStart_.end() - 1);
    for (Index e = 0; e < edges_.size(); ++e) {
      vertexEdgeList_[fill[edges_[e].vertex[0]]++] = e;
      vertexEdgeList_[fill[edges_[e].vertex[1]]++] = e;
    }
  }
  longestEdgeAt_.assign(nv, 0.0);
  for (const Edge& e : edges_)
    for (const Index v : e.vertex) longestEdgeAt_[v] = std::max(longestEdgeAt_[v], e.length);
}

void Mesh::sumVertexAngles() {
  const auto& F = soup_.faces;
  angleSums_.assign(soup_.positions.size(), 0.0);
  for (Index f = 0; f < F.size(); ++f)
    for (int k = 0; k < 3; ++k) angleSums_[F[f][k]] += cornerAngles_[3 * f + k];
}

// The ends of every edge with one face.
void Mesh::markBoundaryVertices() {
  boundaryVertex_.assign(soup_.positions.size(), 0);
  for (const Edge& e : edges_) {
    if (e.face[1] == kNoIndex) boundaryVertex_[e.vertex[0]] = boundaryVertex_[e.vertex[1]] = 1;
  }
}

// Where geodesics may bend (isPseudoSourceVertex): boundary vertices, saddles, and vertices
// where several fans meet.
void Mesh::findPseudoSourceVertices() {
  const std::size_t nv = soup_.positions.size();
  pseudoSource_.assign(nv, 0);
  for (Index v = 0; v < nv; ++v) {
    pseudoSource_[v] = boundaryVertex_[v] || joinsSeveralFans(v) ||
                       angleSums_[v] > 2.0 * std::numbers::pi + tol::kFlatVertexAngle;
  }
}

// A vertex where several fans meet (non-manifold vertex) joins surfaces that share only that
// point: geodesics cross from one fan to another through it, so it is a pseudo-source too.
bool Mesh::joinsSeveralFans(Index v) const {
  const auto faces = vertexFaces(v);
  if (faces.size() <= 1) return false;
  std::vector<Index> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto slot = [&](Index f) {
    return static_cast<Index>(std::find(faces.begin(), faces.end(), f) - faces.begin());
  };
  for (Index e : vertexEdges(v)) {
    if (edges_[e].face[1] == kNoIndex) continue;
    parent[find(slot(edges_[e].face[0]))] = find(slot(edges_[e].face[1]));
  }
  Index roots = 0;
  for (Index i = 0; i < faces.size(); ++i) roots += find(i) == i;
  return roots > 1;
}

// Components through shared vertices; unreferenced vertices belong to none (kNoIndex).
void Mesh::labelComponents() {
  const std::size_t nv = soup_.positions.size();
  UnionFind uf(nv);
  for (const auto& t : soup_.faces) {
    uf.unite(t[0], t[1]);
    uf.unite(t[1], t[2]);
  }
  component_.assign(nv, kNoIndex);
  std::vector<Index> label(nv, kNoIndex);
  for (Index v = 0; v < nv; ++v) {
    if (!isReferenced(v)) continue;
    const Index r = uf.find(v);
    if (label[r] == kNoIndex) label[r] = static_cast<Index>(numComponents_++);
    component_[v] = label[r];
  }
}

// The bounding box of the vertices that faces use, in mesh units.
void Mesh::measureBoundingBox() {
  bool any = false;
  Vec3 lo, hi;
  for (Index v = 0; v < soup_.positions.size(); ++v) {
    if (!isReferenced(v)) continue;
    const Vec3 p = positionInMeshUnits(v);
    lo = any ? lo.cwiseMin(p) : p;
    hi = any ? hi.cwiseMax(p) : p;
    any = true;
  }
  bboxDiagonal_ = any ? (hi - lo).norm() : 0.0;
}

namespace {

// Interleaves the low 21 bits of x, y, z (a Morton, or Z-order, code).
std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  auto spread = [](std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  return spread(x) | spread(y) << 1 | spread(z) << 2;
}

}  // namespace

// Edges numbered along a Z-order curve through their midpoints: the wavefront sweeps space, and
// with this order the interval lists, edge records and frames it touches at one time lie close
// together in memory, so the first read of a popped edge's list seldom waits on memory. Edge
// numbers are internal: callers name edges by their vertices.
void Mesh::sortEdgesAlongSpace() {
  if (edges_.empty()) return;
  const auto P = [&](Index v) -> Vec3 { return positionInMeshUnits(v); };
  Vec3 lo = P(edges_[0].vertex[0]), hi = lo;
  for (const Edge& e : edges_)
    for (Index v : e.vertex) {
      lo = lo.cwiseMin(P(v));
      hi = hi.cwiseMax(P(v));
    }
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  std::vector<std::pair<std::uint64_t, Index>> order(edges_.size());
  for (Index e = 0; e < edges_.size(); ++e) {
    const Vec3 m = 0.5 * (P(edges_[e].vertex[0]) + P(edges_[e].vertex[1]));
    const Vec3 q = ((m - lo).cwiseQuotient(extent) * 2097151.0).cwiseMax(0.0).cwiseMin(2097151.0);
    order[e] = {mortonCode(static_cast<std::uint32_t>(q.x()), static_cast<std::uint32_t>(q.y()),
                           static_cast<std::uint32_t>(q.z())),
                e};
  }
  std::sort(order.begin(), order.end());
  std::vector<Index> newIndex(edges_.size());
  std::vector<Edge> sorted(edges_.size());
  for (Index k = 0; k < order.size(); ++k) {
    newIndex[order[k].second] = k;
    sorted[k] = edges_[order[k].second];
  }
  edges_ = std::move(sorted);
  for (auto& fe : faceEdges_)
    for (Index& e : fe) e = newIndex[e];
}

MeshUnit meshUnitOf(double largestCoordinate) {
#ifdef GEODEX_NO_MESH_UNITS  // bench-only build (solver/CMakeLists.txt)
  if (largestCoordinate >= 0.0) return {};
#endif
  // ilogb of a subnormal is below -1022; clamped there the inverse stays finite, and the edges
  // of such a mesh are refused (EdgeLengthProblem::Subnormal) before anything is computed.
  const int exponent =
      largestCoordinate > 0.0 ? std::max(std::ilogb(largestCoordinate), -1022) : 0;
  return {exponent, std::ldexp(1.0, exponent), std::ldexp(1.0, -exponent)};
}

ScaledRange inFileUnitsRange(double x, const MeshUnit& unit) {
  if (x == 0.0 || !std::isfinite(x)) return ScaledRange::Normal;
  const int exponent = std::ilogb(x) + unit.exponent;  // of x × 2^unit.exponent, exactly
  if (exponent > std::numeric_limits<double>::max_exponent - 1) return ScaledRange::Overflow;
  if (exponent < std::numeric_limits<double>::min_exponent - 1) return ScaledRange::Subnormal;
  return ScaledRange::Normal;
}

ScaledRange inMeshUnitsRange(double x, const MeshUnit& unit) {
  return inFileUnitsRange(x, {-unit.exponent, unit.inverse, unit.unit});
}

EdgeLengthProblem edgeLengthProblem(double lengthInMeshUnits, const MeshUnit& unit) {
  if (!(lengthInMeshUnits >= tol::kMinEdgeLengthRel)) return EdgeLengthProblem::Spread;
  switch (inFileUnitsRange(lengthInMeshUnits, unit)) {
    case ScaledRange::Subnormal: return EdgeLengthProblem::Subnormal;
    case ScaledRange::Overflow: return EdgeLengthProblem::Overflow;
    case ScaledRange::Normal: break;
  }
  return std::isfinite(lengthInMeshUnits) ? EdgeLengthProblem::None : EdgeLengthProblem::Overflow;
}

const char* edgeLengthProblemKind(EdgeLengthProblem problem) {
  return problem == EdgeLengthProblem::Spread ? "edge-length-spread" : "edge-length-out-of-range";
}

std::string describeEdgeLengthProblem(EdgeLengthProblem problem, double lengthInMeshUnits,
                                      const MeshUnit& unit) {
  std::ostringstream os;
  os.precision(3);
  switch (problem) {
    case EdgeLengthProblem::None: return "is fine";
    case EdgeLengthProblem::Spread:
      os << "is " << lengthInMeshUnits << " times the mesh's largest coordinate magnitude (2^"
         << unit.exponent << "), shorter than the " << tol::kMinEdgeLengthRel
         << " geodex computes with (its lengths times the tolerances would underflow); remove or "
            "weld the tiny edge";
      break;
    case EdgeLengthProblem::Subnormal:
      os << "has length 2^" << unit.exponent << " x " << lengthInMeshUnits
         << ", below the smallest normal double (2.2e-308): it and the distances along it cannot "
            "be represented to full precision; scale the mesh up";
      break;
    case EdgeLengthProblem::Overflow:
      os << "has length 2^" << unit.exponent << " x " << lengthInMeshUnits
         << ", beyond the largest double (1.8e308); scale the mesh down";
      break;
  }
  return os.str();
}

Index Mesh::findEdge(Index a, Index b) const {
  for (Index e : vertexEdges(a)) {
    const Edge& edge = edges_[e];
    if ((edge.vertex[0] == a && edge.vertex[1] == b) || (edge.vertex[0] == b && edge.vertex[1] == a))
      return e;
  }
  return kNoIndex;
}

int Mesh::localEdgeIndex(Index f, Index e) const {
  for (int k = 0; k < 3; ++k)
    if (faceEdges_[f][k] == e) return k;
  return -1;
}

}  // namespace geodex
