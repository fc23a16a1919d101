// validateMesh (mesh_io.h): every check of a soup, errors first, then warnings.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "geodex/mesh_io.h"
#include "geodex/tolerance.h"
#include "text_input.h"

namespace geodex {
namespace {

using detail::where;

std::string formatPosition(const Vec3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g, %.17g)", p.x(), p.y(), p.z());
  return buffer;
}

class UnionFind {
 public:
  explicit UnionFind(std::size_t size) : parent_(size) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];  // path halving
      x = parent_[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    if (b < a) parent_[a] = b;
  }

 private:
  std::vector<std::size_t> parent_;
};

/// Names elements of a soup in messages, with their file lines when the soup has them.
class Namer {
 public:
  explicit Namer(const TriangleSoup& soup)
      : soup_(soup),
        hasFaceLines_(soup.faceLines.size() == soup.faces.size()),
        hasVertexLines_(soup.vertexLines.size() == soup.positions.size()) {}

  /// "FILE:LINE: " for the start of a message about face f.
  std::string atFace(std::size_t f) const {
    return where(soup_.fileName, hasFaceLines_ ? soup_.faceLines[f] : 0);
  }
  std::string atVertex(std::size_t v) const {
    return where(soup_.fileName, hasVertexLines_ ? soup_.vertexLines[v] : 0);
  }
  /// "face 12 (line 34)", or "face 12" when the line is unknown.
  std::string face(std::size_t f) const {
    return "face " + std::to_string(f) + lineNote(hasFaceLines_ ? soup_.faceLines[f] : 0);
  }
  std::string vertex(std::size_t v) const {
    return "vertex " + std::to_string(v) +
           lineNote(hasVertexLines_ ? soup_.vertexLines[v] : 0);
  }

 private:
  static std::string lineNote(int line) {
    return line > 0 ? " (line " + std::to_string(line) + ")" : std::string();
  }
  const TriangleSoup& soup_;
  bool hasFaceLines_;
  bool hasVertexLines_;
};

/// Every occurrence of one kind of problem, reported as one issue: the first in a full sentence,
/// a few more by name, and the count (a dirty scan has thousands of some kinds).
class Finding {
 public:
  static constexpr std::size_t kExamples = 5;

  /// `describe(true)` gives the full first sentence, `describe(false)` a short example; neither
  /// is called once enough examples are known, so counting stays cheap.
  template <class Describe>
  void add(Describe&& describe) {
    if (count_ == 0) {
      first_ = describe(true);
    } else if (count_ < kExamples) {
      more_.push_back(describe(false));
    }
    ++count_;
  }
  std::size_t count() const { return count_; }

  void report(std::vector<MeshIssue>& issues, Severity severity, const char* kind,
              const char* noun) const {
    if (count_ == 0) return;
    std::string message = first_;
    if (count_ > 1) {
      message += " [" + std::to_string(count_) + " " + noun + " in all; also ";
      for (std::size_t i = 0; i < more_.size(); ++i) message += (i ? ", " : "") + more_[i];
      if (count_ > kExamples) message += ", ...";
      message += "]";
    }
    issues.push_back({severity, kind, message});
  }

 private:
  std::size_t count_ = 0;
  std::string first_;
  std::vector<std::string> more_;
};

/// One side of an edge in a face: the edge from face[local] to face[(local+1)%3].
struct HalfEdge {
  std::uint64_t key;  ///< smaller vertex << 32 | larger vertex
  Index face;
  std::uint8_t local;
  bool forward;  ///< runs from the smaller vertex to the larger
};

/// Positions compare with -0 == +0, like the zero-length-edge test.
bool positionLess(const Vec3& a, const Vec3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

}  // namespace

void validateMesh(const TriangleSoup& soup, std::vector<MeshIssue>& issues) {
  const Namer name(soup);
  const std::size_t numVertices = soup.positions.size();
  const std::size_t numFaces = soup.faces.size();
  const auto& positions = soup.positions;
  const auto& faces = soup.faces;

  // --- Per vertex and per face ---
  Finding nonFinite;
  std::vector<std::uint8_t> finite(numVertices, 0);
  for (std::size_t v = 0; v < numVertices; ++v) {
    finite[v] = isFinite(positions[v]) ? 1 : 0;
    if (finite[v]) continue;
    nonFinite.add([&](bool full) {
      return full ? name.atVertex(v) + "vertex " + std::to_string(v) +
                        " has a non-finite coordinate " + formatPosition(positions[v])
                  : name.vertex(v);
    });
  }

  // Mesh units (MeshUnit), from the vertices of faces whose indices are in range, as Mesh has it.
  double largestCoordinate = 0.0;
  for (const auto& t : faces) {
    if (t[0] >= numVertices || t[1] >= numVertices || t[2] >= numVertices) continue;
    for (const Index v : t)
      if (finite[v]) largestCoordinate = std::max(largestCoordinate, positions[v].cwiseAbs().maxCoeff());
  }
  const MeshUnit unit = meshUnitOf(largestCoordinate);

  Finding outOfRange, repeatedIndex, zeroLengthEdge, edgeLengthRange, edgeLengthSpread, zeroArea;
  // usable: indices in range and distinct, so everything below may index with them.
  std::vector<std::uint8_t> usable(numFaces, 0);
  std::vector<std::uint8_t> referenced(numVertices, 0);
  for (std::size_t f = 0; f < numFaces; ++f) {
    const auto& t = faces[f];
    const auto bad = std::find_if(t.begin(), t.end(), [&](Index v) { return v >= numVertices; });
    for (const Index v : t) {
      if (v < numVertices) referenced[v] = 1;
    }
    if (bad != t.end()) {
      outOfRange.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) + " refers to vertex " +
                          std::to_string(*bad) + ", but there are only " +
                          std::to_string(numVertices) + " vertices"
                    : name.face(f) + " -> vertex " + std::to_string(*bad);
      });
      continue;
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      const Index twice = t[0] == t[1] || t[0] == t[2] ? t[0] : t[1];
      repeatedIndex.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) + " uses vertex " +
                          std::to_string(twice) + " twice (" + std::to_string(t[0]) + ", " +
                          std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")"
                    : name.face(f) + " repeating vertex " + std::to_string(twice);
      });
      continue;
    }
    usable[f] = 1;
    if (!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;
    const auto sharedPosition = [&](int k) { return positions[t[k]] == positions[t[(k + 1) % 3]]; };
    if (sharedPosition(0) || sharedPosition(1) || sharedPosition(2)) {
      const int k = sharedPosition(0) ? 0 : sharedPosition(1) ? 1 : 2;
      const Index a = t[k];
      const Index b = t[(k + 1) % 3];
      zeroLengthEdge.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) +
                          " has a zero-length edge: its vertices " + std::to_string(a) + " and " +
                          std::to_string(b) + " have the same position " +
                          formatPosition(positions[a])
                    : name.face(f) + " with edge " + std::to_string(a) + "-" +
                          std::to_string(b);
      });
      continue;
    }
    bool lengthsInRange = true;
    for (int k = 0; k < 3 && lengthsInRange; ++k) {
      const Index a = t[k];
      const Index b = t[(k + 1) % 3];
      const double length = ((positions[b] - positions[a]) * unit.inverse).norm();
      const EdgeLengthProblem problem = edgeLengthProblem(length, unit);
      if (problem == EdgeLengthProblem::None) continue;
      lengthsInRange = false;
      Finding& finding = problem == EdgeLengthProblem::Spread ? edgeLengthSpread : edgeLengthRange;
      finding.add([&, a, b, length, problem](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) + ": edge " + std::to_string(a) +
                          "-" + std::to_string(b) + " " +
                          describeEdgeLengthProblem(problem, length, unit)
                    : name.face(f) + " with edge " + std::to_string(a) + "-" + std::to_string(b);
      });
    }
    if (!lengthsInRange) continue;
    const auto at = [&](int k) -> Vec3 { return positions[t[k]] * unit.inverse; };  // mesh units
    const Vec3 normal = (at(1) - at(0)).cross(at(2) - at(0));
    if (normal.x() == 0.0 && normal.y() == 0.0 && normal.z() == 0.0) {
      zeroArea.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) +
                          " has zero area: its three distinct corners " + std::to_string(t[0]) +
                          ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                          " are collinear"
                    : name.face(f);
      });
    }
  }

  // --- Edges: sorted half-edges, equal keys are the sides of one edge ---
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * numFaces);
  for (std::size_t f = 0; f < numFaces; ++f) {
    if (!usable[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const Index a = faces[f][k];
      const Index b = faces[f][(k + 1) % 3];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      halfEdges.push_back({key, static_cast<Index>(f), static_cast<std::uint8_t>(k), a < b});
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  });

  // Corners 3f + k are merged across every shared edge at both of its ends: afterwards the
  // corners at a vertex form one set per edge-connected fan.
  UnionFind fans(3 * numFaces);
  const auto cornerAt = [&](Index f, Index v) {
    const auto& t = faces[f];
    return 3 * std::size_t{f} + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  Finding nonManifoldEdge, inconsistentWinding;
  for (std::size_t begin = 0, end = 0; begin < halfEdges.size(); begin = end) {
    end = begin + 1;
    while (end < halfEdges.size() && halfEdges[end].key == halfEdges[begin].key) ++end;
    const auto a = static_cast<Index>(halfEdges[begin].key >> 32);
    const auto b = static_cast<Index>(halfEdges[begin].key & 0xffffffffu);
    const std::size_t numSides = end - begin;
    if (numSides > 2) {
      nonManifoldEdge.add([&](bool full) {
        std::string text = full ? name.atFace(halfEdges[begin].face) : std::string();
        text += "edge " + std::to_string(a) + "-" + std::to_string(b);
        if (!full) return text;
        text += " has " + std::to_string(numSides) + " faces: ";
        for (std::size_t i = begin; i < end && i < begin + 6; ++i) {
          text += (i > begin ? ", " : "") + name.face(halfEdges[i].face);
        }
        return text + (numSides > 6 ? ", ..." : "");
      });
    }
    if (numSides == 2 && halfEdges[begin].forward == halfEdges[begin + 1].forward) {
      inconsistentWinding.add([&](bool full) {
        const Index f = halfEdges[begin].face;
        const Index g = halfEdges[begin + 1].face;
        return full ? name.atFace(f) + name.face(f) + " and " + name.face(g) +
                          " traverse their shared edge " + std::to_string(a) + "-" +
                          std::to_string(b) +
                          " in the same direction (inconsistent winding; the solver does not"
                          " need a consistent one)"
                    : "faces " + std::to_string(f) + " and " + std::to_string(g);
      });
    }
    for (std::size_t i = begin + 1; i < end; ++i) {
      for (const Index v : {a, b}) {
        fans.unite(cornerAt(halfEdges[begin].face, v), cornerAt(halfEdges[i].face, v));
      }
    }
  }
  halfEdges = {};

  // --- Duplicate faces: equal sorted vertex triples ---
  Finding duplicateFace;
  {
    std::vector<std::pair<std::array<Index, 3>, Index>> sorted;
    sorted.reserve(numFaces);
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      std::array<Index, 3> t = faces[f];
      std::sort(t.begin(), t.end());
      sorted.push_back({t, static_cast<Index>(f)});
    }
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1, first = 0; i < sorted.size(); ++i) {
      if (sorted[i].first != sorted[first].first) {
        first = i;
        continue;
      }
      const Index f = sorted[i].second;
      const Index g = sorted[first].second;
      duplicateFace.add([&](bool full) {
        const auto& t = faces[f];
        return full ? name.atFace(f) + "face " + std::to_string(f) + " has the same vertices {" +
                          std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                          std::to_string(t[2]) + "} as " + name.face(g)
                    : "faces " + std::to_string(g) + " and " + std::to_string(f);
      });
    }
  }

  // --- Non-manifold vertices: corners in more than one fan ---
  Finding nonManifoldVertex;
  {
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> firstFan(numVertices, kNone);
    std::vector<std::uint8_t> flagged(numVertices, 0);
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      for (int k = 0; k < 3; ++k) {
        const Index v = faces[f][k];
        const std::size_t fan = fans.find(3 * f + k);
        if (firstFan[v] == kNone) firstFan[v] = fan;
        if (firstFan[v] == fan || flagged[v]) continue;
        flagged[v] = 1;
        const std::size_t other = firstFan[v] / 3;
        nonManifoldVertex.add([&](bool full) {
          return full ? name.atVertex(v) + "vertex " + std::to_string(v) +
                            " is non-manifold: its faces form more than one fan (" +
                            name.face(other) + " and " + name.face(f) +
                            " meet at it but are not linked through its edges)"
                      : name.vertex(v);
        });
      }
    }
  }

  // --- Unreferenced vertices ---
  Finding unreferenced;
  for (std::size_t v = 0; v < numVertices; ++v) {
    if (referenced[v]) continue;
    unreferenced.add([&](bool full) {
      return full ? name.atVertex(v) + "vertex " + std::to_string(v) +
                        " is used by no face (its distance will be +inf)"
                  : name.vertex(v);
    });
  }

  // --- Duplicated positions: equal neighbours after sorting ---
  Finding duplicatePosition;
  {
    std::vector<Index> order;
    order.reserve(numVertices);
    for (std::size_t v = 0; v < numVertices; ++v) {
      if (finite[v]) order.push_back(static_cast<Index>(v));
    }
    std::sort(order.begin(), order.end(), [&](Index x, Index y) {
      if (positionLess(positions[x], positions[y])) return true;
      if (positionLess(positions[y], positions[x])) return false;
      return x < y;
    });
    for (std::size_t i = 1, first = 0; i < order.size(); ++i) {
      if (positions[order[i]] != positions[order[first]]) {
        first = i;
        continue;
      }
      const Index v = order[i];
      const Index original = order[first];
      duplicatePosition.add([&](bool full) {
        return full ? name.atVertex(v) + "vertex " + std::to_string(v) + " has the same position " +
                          formatPosition(positions[v]) + " as " + name.vertex(original)
                    : name.vertex(v);
      });
    }
  }

  // --- Connected components, through shared vertices (as Mesh counts them) ---
  std::string componentsMessage;
  {
    UnionFind parts(numVertices);
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      parts.unite(faces[f][0], faces[f][1]);
      parts.unite(faces[f][0], faces[f][2]);
    }
    std::vector<std::uint8_t> seen(numVertices, 0);
    std::size_t firstFace = 0;
    std::size_t count = 0;
    std::vector<std::size_t> startFaces;  // first face of each component after the first
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      const std::size_t root = parts.find(faces[f][0]);
      if (seen[root]) continue;
      seen[root] = 1;
      if (count++ == 0) {
        firstFace = f;
      } else if (startFaces.size() < Finding::kExamples) {
        startFaces.push_back(f);
      }
    }
    if (count > 1) {
      std::string& message = componentsMessage;
      message = name.atFace(startFaces[0]) + name.face(startFaces[0]) +
                            " is not connected to " + name.face(firstFace) + ": the mesh has " +
                            std::to_string(count) +
                            " connected components (through shared vertices), and distances "
                            "between them are +inf; components start at faces " +
                            std::to_string(firstFace);
      for (const std::size_t f : startFaces) message += ", " + std::to_string(f);
      if (count > startFaces.size() + 1) message += ", ...";
    }
  }

  // Errors first, in the order loadMesh should report them; then warnings.
  nonFinite.report(issues, Severity::Error, "non-finite-coordinate", "vertices");
  outOfRange.report(issues, Severity::Error, "index-out-of-range", "faces");
  repeatedIndex.report(issues, Severity::Error, "repeated-index", "faces");
  zeroLengthEdge.report(issues, Severity::Error, "zero-length-edge", "faces");
  edgeLengthRange.report(issues, Severity::Error, "edge-length-out-of-range", "faces");
  edgeLengthSpread.report(issues, Severity::Error, "edge-length-spread", "faces");
  duplicateFace.report(issues, Severity::Error, "duplicate-face", "duplicates");
  nonManifoldEdge.report(issues, Severity::Error, "non-manifold-edge", "edges");
  zeroArea.report(issues, Severity::Warning, "zero-area-face", "faces");
  nonManifoldVertex.report(issues, Severity::Warning, "non-manifold-vertex", "vertices");
  unreferenced.report(issues, Severity::Warning, "unreferenced-vertex", "vertices");
  duplicatePosition.report(issues, Severity::Warning, "duplicate-position", "vertices");
  inconsistentWinding.report(issues, Severity::Warning, "inconsistent-winding", "edges");
  if (!componentsMessage.empty()) {
    issues.push_back({Severity::Warning, "components", std::move(componentsMessage)});
  }
}

}  // namespace geodex
