// validateMesh (mesh_io.h): the rules a soup is checked against, one function each, named after
// what the report calls its finding: the rule zeroAreaFace reports "zero-area-face", and
// `geodex info` lists it as "warning: [zero-area-face] ...".

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

#include "../sort_sides.h"
#include "geodex/mesh_io.h"
#include "geodex/tolerance.h"
#include "text_input.h"

namespace geodex {
namespace {

using detail::where;

// ===  Naming elements in messages  ==============================================================

std::string formatPosition(const Vec3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g, %.17g)", p.x(), p.y(), p.z());
  return buffer;
}

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

// ===  What a rule finds  ========================================================================

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

// ===  What several rules need  ==================================================================

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
  /// The smaller root becomes the root: a set's root is its smallest element whatever the order
  /// of the unions, so the elements a message names from roots are always the same.
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    if (b < a) parent_[a] = b;
  }

 private:
  std::vector<std::size_t> parent_;
};

/// One side of an edge in a face: the edge from face[local] to face[(local+1)%3].
struct HalfEdge {
  std::uint64_t key;  ///< smaller vertex << 32 | larger vertex
  Index face;
  std::uint8_t local;
  bool forward;  ///< runs from the smaller vertex to the larger
};

Index smallerVertex(std::uint64_t key) { return static_cast<Index>(key >> 32); }
Index largerVertex(std::uint64_t key) { return static_cast<Index>(key & 0xffffffffu); }

/// What several rules need to know about a soup, found once before any rule runs.
struct SoupFacts {
  explicit SoupFacts(const TriangleSoup& soup);

  const std::vector<Vec3>& positions;
  const std::vector<std::array<Index, 3>>& faces;
  std::size_t numVertices;
  std::size_t numFaces;
  Namer name;
  std::vector<std::uint8_t> finite;  ///< per vertex: every coordinate is finite
  /// Per face: its indices are in range and distinct, so the rules may index with them.
  std::vector<std::uint8_t> usable;
  /// The mesh units Mesh will measure in (MeshUnit): from the finite vertices of the faces whose
  /// indices are in range, as Mesh has it.
  MeshUnit unit;
  /// Per face: the side firstSideLengthProblem finds, or -1 when it finds none or the face has no
  /// measurable sides (hasMeasurableSides). Found once, as three rules ask.
  std::vector<std::int8_t> uncomputableSide;
  /// The sides of the usable faces' edges, sorted by edge and then face: equal keys are the
  /// sides of one edge.
  std::vector<HalfEdge> sides;
};

// The geometric face rules zeroLengthEdge, edgeLengthOutOfRange / edgeLengthSpread and
// zeroAreaFace look at the usable faces whose corners are finite (the others are reported by
// nonFiniteCoordinate), each only at the faces the ones before it passed: a face's edge lengths
// mean nothing when two corners coincide, nor its area when an edge length is out of range. So a
// face is reported once, by the first of them it breaks.

bool hasFiniteCorners(const SoupFacts& facts, std::size_t f) {
  const auto& t = facts.faces[f];
  return facts.finite[t[0]] && facts.finite[t[1]] && facts.finite[t[2]];
}

/// The side k of face f whose two ends have the same position (the first), or -1. Positions
/// compare with -0 == +0.
int zeroLengthSide(const SoupFacts& facts, std::size_t f) {
  const auto& t = facts.faces[f];
  for (int k = 0; k < 3; ++k) {
    if (facts.positions[t[k]] == facts.positions[t[(k + 1) % 3]]) return k;
  }
  return -1;
}

/// The first side of a face whose length geodex cannot compute with, and why.
struct SideLengthProblem {
  int side = -1;  ///< -1: none
  double length = 0.0;  ///< in mesh units
  EdgeLengthProblem problem = EdgeLengthProblem::None;
};

SideLengthProblem firstSideLengthProblem(const SoupFacts& facts, std::size_t f) {
  const auto& t = facts.faces[f];
  for (int k = 0; k < 3; ++k) {
    const Vec3& a = facts.positions[t[k]];
    const Vec3& b = facts.positions[t[(k + 1) % 3]];
    const double length = ((b - a) * facts.unit.inverse).norm();
    const EdgeLengthProblem problem = edgeLengthProblem(length, facts.unit);
    if (problem != EdgeLengthProblem::None) return {k, length, problem};
  }
  return {};
}

/// A usable face with finite corners and no zero-length edge: its edge lengths can be measured.
bool hasMeasurableSides(const SoupFacts& facts, std::size_t f) {
  return facts.usable[f] && hasFiniteCorners(facts, f) && zeroLengthSide(facts, f) < 0;
}

SoupFacts::SoupFacts(const TriangleSoup& soup)
    : positions(soup.positions),
      faces(soup.faces),
      numVertices(soup.positions.size()),
      numFaces(soup.faces.size()),
      name(soup),
      finite(numVertices, 0),
      usable(numFaces, 0) {
  for (std::size_t v = 0; v < numVertices; ++v) finite[v] = isFinite(positions[v]) ? 1 : 0;

  double largestCoordinate = 0.0;
  for (const auto& t : faces) {
    if (t[0] >= numVertices || t[1] >= numVertices || t[2] >= numVertices) continue;
    for (const Index v : t) {
      if (finite[v]) {
        largestCoordinate = std::max(largestCoordinate, positions[v].cwiseAbs().maxCoeff());
      }
    }
  }
  unit = meshUnitOf(largestCoordinate);

  for (std::size_t f = 0; f < numFaces; ++f) {
    const auto& t = faces[f];
    const bool inRange = t[0] < numVertices && t[1] < numVertices && t[2] < numVertices;
    usable[f] = inRange && t[0] != t[1] && t[1] != t[2] && t[2] != t[0] ? 1 : 0;
  }

  uncomputableSide.assign(numFaces, -1);
  for (std::size_t f = 0; f < numFaces; ++f) {
    if (!hasMeasurableSides(*this, f)) continue;
    uncomputableSide[f] = static_cast<std::int8_t>(firstSideLengthProblem(*this, f).side);
  }

  sides.reserve(3 * numFaces);
  for (std::size_t f = 0; f < numFaces; ++f) {
    if (!usable[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const Index a = faces[f][k];
      const Index b = faces[f][(k + 1) % 3];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      sides.push_back({key, static_cast<Index>(f), static_cast<std::uint8_t>(k), a < b});
    }
  }
  detail::sortSidesByVertexPair(
      sides, numVertices, [](const HalfEdge& h) { return smallerVertex(h.key); },
      [](const HalfEdge& x, const HalfEdge& y) {
        return x.key != y.key ? x.key < y.key : x.face < y.face;
      });
}

/// Calls visit(begin, end) for each edge of the usable faces, whose sides are
/// facts.sides[begin, end).
template <class Visit>
void forEachEdge(const SoupFacts& facts, Visit&& visit) {
  const std::vector<HalfEdge>& sides = facts.sides;
  for (std::size_t begin = 0, end = 0; begin < sides.size(); begin = end) {
    end = begin + 1;
    while (end < sides.size() && sides[end].key == sides[begin].key) ++end;
    visit(begin, end);
  }
}

/// Positions compare with -0 == +0, like the zero-length-edge test.
bool positionLess(const Vec3& a, const Vec3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

// ===  Errors: the rules whose findings the solver refuses  ======================================

Finding nonFiniteCoordinate(const SoupFacts& facts) {
  Finding finding;
  for (std::size_t v = 0; v < facts.numVertices; ++v) {
    if (facts.finite[v]) continue;
    finding.add([&](bool full) {
      return full ? facts.name.atVertex(v) + "vertex " + std::to_string(v) +
                        " has a non-finite coordinate " + formatPosition(facts.positions[v])
                  : facts.name.vertex(v);
    });
  }
  return finding;
}

Finding indexOutOfRange(const SoupFacts& facts) {
  Finding finding;
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    const auto& t = facts.faces[f];
    const auto bad =
        std::find_if(t.begin(), t.end(), [&](Index v) { return v >= facts.numVertices; });
    if (bad == t.end()) continue;
    finding.add([&](bool full) {
      return full ? facts.name.atFace(f) + "face " + std::to_string(f) + " refers to vertex " +
                        std::to_string(*bad) + ", but there are only " +
                        std::to_string(facts.numVertices) + " vertices"
                  : facts.name.face(f) + " -> vertex " + std::to_string(*bad);
    });
  }
  return finding;
}

/// Among the faces whose indices are in range.
Finding repeatedIndex(const SoupFacts& facts) {
  Finding finding;
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    const auto& t = facts.faces[f];
    if (facts.usable[f] || t[0] >= facts.numVertices || t[1] >= facts.numVertices ||
        t[2] >= facts.numVertices) {
      continue;
    }
    const Index twice = t[0] == t[1] || t[0] == t[2] ? t[0] : t[1];
    finding.add([&](bool full) {
      return full ? facts.name.atFace(f) + "face " + std::to_string(f) + " uses vertex " +
                        std::to_string(twice) + " twice (" + std::to_string(t[0]) + ", " +
                        std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")"
                  : facts.name.face(f) + " repeating vertex " + std::to_string(twice);
    });
  }
  return finding;
}

Finding zeroLengthEdge(const SoupFacts& facts) {
  Finding finding;
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (!facts.usable[f] || !hasFiniteCorners(facts, f)) continue;
    const int k = zeroLengthSide(facts, f);
    if (k < 0) continue;
    const Index a = facts.faces[f][k];
    const Index b = facts.faces[f][(k + 1) % 3];
    finding.add([&](bool full) {
      return full ? facts.name.atFace(f) + "face " + std::to_string(f) +
                        " has a zero-length edge: its vertices " + std::to_string(a) + " and " +
                        std::to_string(b) + " have the same position " +
                        formatPosition(facts.positions[a])
                  : facts.name.face(f) + " with edge " + std::to_string(a) + "-" +
                        std::to_string(b);
    });
  }
  return finding;
}

/// The faces whose first side of uncomputable length has a problem of the `spread` kind or not
/// (EdgeLengthProblem::Spread, or Subnormal and Overflow): one face is reported once, for that
/// first side, by edgeLengthOutOfRange or edgeLengthSpread.
Finding sideLengthFinding(const SoupFacts& facts, bool spread) {
  Finding finding;
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (facts.uncomputableSide[f] < 0) continue;
    const SideLengthProblem found = firstSideLengthProblem(facts, f);
    if ((found.problem == EdgeLengthProblem::Spread) != spread) continue;
    const Index a = facts.faces[f][found.side];
    const Index b = facts.faces[f][(found.side + 1) % 3];
    finding.add([&](bool full) {
      return full ? facts.name.atFace(f) + "face " + std::to_string(f) + ": edge " +
                        std::to_string(a) + "-" + std::to_string(b) + " " +
                        describeEdgeLengthProblem(found.problem, found.length, facts.unit)
                  : facts.name.face(f) + " with edge " + std::to_string(a) + "-" +
                        std::to_string(b);
    });
  }
  return finding;
}

/// An edge whose length in the file's units is not a normal double (EdgeLengthProblem::Subnormal
/// or Overflow).
Finding edgeLengthOutOfRange(const SoupFacts& facts) { return sideLengthFinding(facts, false); }

/// An edge shorter than tol::kMinEdgeLengthRel mesh units (EdgeLengthProblem::Spread).
Finding edgeLengthSpread(const SoupFacts& facts) { return sideLengthFinding(facts, true); }

/// Usable faces with equal sorted vertex triples.
Finding duplicateFace(const SoupFacts& facts) {
  std::vector<std::pair<std::array<Index, 3>, Index>> sorted;
  sorted.reserve(facts.numFaces);
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (!facts.usable[f]) continue;
    std::array<Index, 3> t = facts.faces[f];
    std::sort(t.begin(), t.end());
    sorted.push_back({t, static_cast<Index>(f)});
  }
  std::sort(sorted.begin(), sorted.end());
  Finding finding;
  for (std::size_t i = 1, first = 0; i < sorted.size(); ++i) {
    if (sorted[i].first != sorted[first].first) {
      first = i;
      continue;
    }
    const Index f = sorted[i].second;
    const Index g = sorted[first].second;
    finding.add([&](bool full) {
      const auto& t = facts.faces[f];
      return full ? facts.name.atFace(f) + "face " + std::to_string(f) +
                        " has the same vertices {" + std::to_string(t[0]) + ", " +
                        std::to_string(t[1]) + ", " + std::to_string(t[2]) + "} as " +
                        facts.name.face(g)
                  : "faces " + std::to_string(g) + " and " + std::to_string(f);
    });
  }
  return finding;
}

/// An edge with more than two faces.
Finding nonManifoldEdge(const SoupFacts& facts) {
  Finding finding;
  forEachEdge(facts, [&](std::size_t begin, std::size_t end) {
    const std::size_t numSides = end - begin;
    if (numSides <= 2) return;
    const Index a = smallerVertex(facts.sides[begin].key);
    const Index b = largerVertex(facts.sides[begin].key);
    finding.add([&](bool full) {
      std::string text = full ? facts.name.atFace(facts.sides[begin].face) : std::string();
      text += "edge " + std::to_string(a) + "-" + std::to_string(b);
      if (!full) return text;
      text += " has " + std::to_string(numSides) + " faces: ";
      for (std::size_t i = begin; i < end && i < begin + 6; ++i) {
        text += (i > begin ? ", " : "") + facts.name.face(facts.sides[i].face);
      }
      return text + (numSides > 6 ? ", ..." : "");
    });
  });
  return finding;
}

// ===  Warnings: the rules whose findings the solver handles  ====================================

/// Three distinct corners on one line (in mesh units, exactly): a cap the solver unfolds flat.
Finding zeroAreaFace(const SoupFacts& facts) {
  Finding finding;
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (!hasMeasurableSides(facts, f) || facts.uncomputableSide[f] >= 0) continue;
    const auto& t = facts.faces[f];
    const auto at = [&](int k) -> Vec3 { return facts.positions[t[k]] * facts.unit.inverse; };
    const Vec3 normal = (at(1) - at(0)).cross(at(2) - at(0));
    if (!(normal.x() == 0.0 && normal.y() == 0.0 && normal.z() == 0.0)) continue;
    finding.add([&](bool full) {
      return full ? facts.name.atFace(f) + "face " + std::to_string(f) +
                        " has zero area: its three distinct corners " + std::to_string(t[0]) +
                        ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                        " are collinear"
                  : facts.name.face(f);
    });
  }
  return finding;
}

/// Corner 3f + k of every usable face, merged across each shared edge at both of its ends: the
/// corners at a vertex then form one set per edge-connected fan of faces around it.
UnionFind cornerFans(const SoupFacts& facts) {
  UnionFind fans(3 * facts.numFaces);
  const auto cornerAt = [&](Index f, Index v) {
    const auto& t = facts.faces[f];
    return 3 * std::size_t{f} + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  forEachEdge(facts, [&](std::size_t begin, std::size_t end) {
    const Index a = smallerVertex(facts.sides[begin].key);
    const Index b = largerVertex(facts.sides[begin].key);
    for (std::size_t i = begin + 1; i < end; ++i) {
      for (const Index v : {a, b}) {
        fans.unite(cornerAt(facts.sides[begin].face, v), cornerAt(facts.sides[i].face, v));
      }
    }
  });
  return fans;
}

/// A vertex whose faces form more than one fan (Mesh makes it a pseudo-source).
Finding nonManifoldVertex(const SoupFacts& facts) {
  UnionFind fans = cornerFans(facts);
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> firstFan(facts.numVertices, kNone);
  std::vector<std::uint8_t> flagged(facts.numVertices, 0);
  Finding finding;
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (!facts.usable[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const Index v = facts.faces[f][k];
      const std::size_t fan = fans.find(3 * f + k);
      if (firstFan[v] == kNone) firstFan[v] = fan;
      if (firstFan[v] == fan || flagged[v]) continue;
      flagged[v] = 1;
      const std::size_t other = firstFan[v] / 3;
      finding.add([&](bool full) {
        return full ? facts.name.atVertex(v) + "vertex " + std::to_string(v) +
                          " is non-manifold: its faces form more than one fan (" +
                          facts.name.face(other) + " and " + facts.name.face(f) +
                          " meet at it but are not linked through its edges)"
                    : facts.name.vertex(v);
      });
    }
  }
  return finding;
}

/// A vertex no face refers to (counting every in-range index, even of faces with errors).
Finding unreferencedVertex(const SoupFacts& facts) {
  std::vector<std::uint8_t> referenced(facts.numVertices, 0);
  for (const auto& t : facts.faces) {
    for (const Index v : t) {
      if (v < facts.numVertices) referenced[v] = 1;
    }
  }
  Finding finding;
  for (std::size_t v = 0; v < facts.numVertices; ++v) {
    if (referenced[v]) continue;
    finding.add([&](bool full) {
      return full ? facts.name.atVertex(v) + "vertex " + std::to_string(v) +
                        " is used by no face (its distance will be +inf)"
                  : facts.name.vertex(v);
    });
  }
  return finding;
}

/// Finite vertices at the same position: equal neighbours once sorted.
Finding duplicatePosition(const SoupFacts& facts) {
  const auto& positions = facts.positions;
  std::vector<Index> order;
  order.reserve(facts.numVertices);
  for (std::size_t v = 0; v < facts.numVertices; ++v) {
    if (facts.finite[v]) order.push_back(static_cast<Index>(v));
  }
  std::sort(order.begin(), order.end(), [&](Index x, Index y) {
    if (positionLess(positions[x], positions[y])) return true;
    if (positionLess(positions[y], positions[x])) return false;
    return x < y;
  });
  Finding finding;
  for (std::size_t i = 1, first = 0; i < order.size(); ++i) {
    if (positions[order[i]] != positions[order[first]]) {
      first = i;
      continue;
    }
    const Index v = order[i];
    const Index original = order[first];
    finding.add([&](bool full) {
      return full ? facts.name.atVertex(v) + "vertex " + std::to_string(v) +
                        " has the same position " + formatPosition(positions[v]) + " as " +
                        facts.name.vertex(original)
                  : facts.name.vertex(v);
    });
  }
  return finding;
}

/// Two faces that traverse their shared edge in the same direction.
Finding inconsistentWinding(const SoupFacts& facts) {
  Finding finding;
  forEachEdge(facts, [&](std::size_t begin, std::size_t end) {
    if (end - begin != 2 || facts.sides[begin].forward != facts.sides[begin + 1].forward) return;
    const Index a = smallerVertex(facts.sides[begin].key);
    const Index b = largerVertex(facts.sides[begin].key);
    finding.add([&](bool full) {
      const Index f = facts.sides[begin].face;
      const Index g = facts.sides[begin + 1].face;
      return full ? facts.name.atFace(f) + facts.name.face(f) + " and " + facts.name.face(g) +
                        " traverse their shared edge " + std::to_string(a) + "-" +
                        std::to_string(b) +
                        " in the same direction (inconsistent winding; the solver does not"
                        " need a consistent one)"
                  : "faces " + std::to_string(f) + " and " + std::to_string(g);
    });
  });
  return finding;
}

/// More than one connected component, through shared vertices (as Mesh counts them): one finding
/// for the whole mesh, naming where each component starts.
Finding components(const SoupFacts& facts) {
  UnionFind parts(facts.numVertices);
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (!facts.usable[f]) continue;
    parts.unite(facts.faces[f][0], facts.faces[f][1]);
    parts.unite(facts.faces[f][0], facts.faces[f][2]);
  }
  std::vector<std::uint8_t> seen(facts.numVertices, 0);
  std::size_t firstFace = 0;
  std::size_t count = 0;
  std::vector<std::size_t> startFaces;  // first face of each component after the first
  for (std::size_t f = 0; f < facts.numFaces; ++f) {
    if (!facts.usable[f]) continue;
    const std::size_t root = parts.find(facts.faces[f][0]);
    if (seen[root]) continue;
    seen[root] = 1;
    if (count++ == 0) {
      firstFace = f;
    } else if (startFaces.size() < Finding::kExamples) {
      startFaces.push_back(f);
    }
  }
  Finding finding;
  if (count <= 1) return finding;
  finding.add([&](bool) {
    std::string message =
        facts.name.atFace(startFaces[0]) + facts.name.face(startFaces[0]) +
        " is not connected to " + facts.name.face(firstFace) + ": the mesh has " +
        std::to_string(count) +
        " connected components (through shared vertices), and distances between them are "
        "+inf; components start at faces " +
        std::to_string(firstFace);
    for (const std::size_t f : startFaces) message += ", " + std::to_string(f);
    if (count > startFaces.size() + 1) message += ", ...";
    return message;
  });
  return finding;
}

}  // namespace

void validateMesh(const TriangleSoup& soup, std::vector<MeshIssue>& issues) {
  const SoupFacts facts(soup);
  // Each rule's finding is reported under the rule's name; `noun` is what its count counts.
  const auto apply = [&](Finding (*rule)(const SoupFacts&), Severity severity, const char* kind,
                         const char* noun) { rule(facts).report(issues, severity, kind, noun); };

  // Errors first, in the order loadMesh should report them; then warnings.
  apply(nonFiniteCoordinate, Severity::Error, "non-finite-coordinate", "vertices");
  apply(indexOutOfRange, Severity::Error, "index-out-of-range", "faces");
  apply(repeatedIndex, Severity::Error, "repeated-index", "faces");
  apply(zeroLengthEdge, Severity::Error, "zero-length-edge", "faces");
  apply(edgeLengthOutOfRange, Severity::Error, "edge-length-out-of-range", "faces");
  apply(edgeLengthSpread, Severity::Error, "edge-length-spread", "faces");
  apply(duplicateFace, Severity::Error, "duplicate-face", "duplicates");
  apply(nonManifoldEdge, Severity::Error, "non-manifold-edge", "edges");

  apply(zeroAreaFace, Severity::Warning, "zero-area-face", "faces");
  apply(nonManifoldVertex, Severity::Warning, "non-manifold-vertex", "vertices");
  apply(unreferencedVertex, Severity::Warning, "unreferenced-vertex", "vertices");
  apply(duplicatePosition, Severity::Warning, "duplicate-position", "vertices");
  apply(inconsistentWinding, Severity::Warning, "inconsistent-winding", "edges");
  apply(components, Severity::Warning, "components", "components");
}

}  // namespace geodex
