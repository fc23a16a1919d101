#include "geodex/verify/oracles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "geodex/tolerance.h"

namespace geodex::verify {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Messages are built only when a check fails: these checks run per vertex or face of every
// oracle call, thousands of times a second under the fuzzers.

/// Throws std::invalid_argument unless cond holds; a message given as a callable is built then.
template <typename Message>
void require(bool cond, Message&& message) {
  if (cond) return;
  if constexpr (std::is_invocable_v<Message>) throw std::invalid_argument(message());
  else throw std::invalid_argument(message);
}

void requireVertex(const TriangleSoup& soup, Index v, const char* what) {
  require(v < soup.positions.size(), [&] {
    return std::string(what) + ": vertex " + std::to_string(v) + " out of range (" +
           std::to_string(soup.positions.size()) + " vertices)";
  });
}

void requireFaces(const TriangleSoup& soup, const char* what) {
  for (std::size_t f = 0; f < soup.faces.size(); ++f)
    for (Index v : soup.faces[f])
      require(v < soup.positions.size(), [&] {
        return std::string(what) + ": face " + std::to_string(f) + " references vertex " +
               std::to_string(v) + " out of range";
      });
}

std::uint64_t edgeKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

/// Each undirected edge of the faces once (a < b); faces with a repeated index contribute only
/// their proper edges.
std::vector<std::pair<Index, Index>> uniqueEdges(const TriangleSoup& soup) {
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * soup.faces.size());
  for (const auto& f : soup.faces)
    for (int k = 0; k < 3; ++k)
      if (f[k] != f[(k + 1) % 3]) keys.push_back(edgeKey(f[k], f[(k + 1) % 3]));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(keys.size());
  for (std::uint64_t k : keys)
    edges.emplace_back(static_cast<Index>(k >> 32), static_cast<Index>(k & 0xffffffffULL));
  return edges;
}

std::string formatDouble(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double signedArea(const Polygon2& poly) {
  double twice = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i)
    twice += cross2(poly[i], poly[(i + 1) % poly.size()]);
  return 0.5 * twice;
}

/// Distance from p to the segment ab.
double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

/// Signed distance of x from the line through p with direction u (|u| > 0); positive on the left.
double signedLineDistance(const Vec2& p, const Vec2& u, double uLength, const Vec2& x) {
  return cross2(u, x - p) / uLength;
}

/// Records one comparison in a report.
class ReportBuilder {
 public:
  void pass() { ++report_.checked; }
  /// excess: how far beyond the bound itself; normalizer: |B| + L.
  /// describe() names the failure; it runs only then (a template, not std::function: a
  /// capturing lambda would be copied to the heap at every comparison).
  template <typename Describe>
  void compare(double excess, double allowed, double normalizer, Describe&& describe) {
    ++report_.checked;
    if (excess <= 0.0) return;
    const double relative = normalizer > 0.0 ? excess / normalizer : kInf;
    report_.maxError = std::max(report_.maxError, relative);
    if (excess > allowed) fail(describe());
  }
  void failInfinite(const std::string& what) {
    ++report_.checked;
    report_.maxError = kInf;
    fail(what);
  }
  void failNaN(const std::string& what) {
    ++report_.checked;
    report_.maxError = kInf;
    fail(what);
  }
  CheckReport take() { return std::move(report_); }

 private:
  void fail(const std::string& what) {
    if (report_.failed++ == 0) report_.firstFailure = what;
  }
  CheckReport report_;
};

/// NaN and −inf are never distances.
bool notADistance(double x) { return std::isnan(x) || x == -kInf; }

double largestFinite(std::span<const double> values) {
  double largest = 0.0;
  for (double v : values)
    if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  return largest;
}

void requireSameSize(std::size_t a, std::size_t b, const char* what) {
  require(a == b, [&] {
    return std::string(what) + ": fields of different sizes (" + std::to_string(a) + " and " +
           std::to_string(b) + ")";
  });
}

}  // namespace

// === Surface points ============================================================================

Vec3 surfacePointPosition(const TriangleSoup& soup, const SurfacePoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      requireVertex(soup, p.vertex, "surfacePointPosition");
      return soup.positions[p.vertex];
    case SurfacePoint::Kind::Edge: {
      requireVertex(soup, p.vertex, "surfacePointPosition");
      requireVertex(soup, p.toVertex, "surfacePointPosition");
      require(std::isfinite(p.t) && p.t >= 0.0 && p.t <= 1.0,
              "surfacePointPosition: edge parameter outside [0, 1]");
      const bool isEdge = std::any_of(soup.faces.begin(), soup.faces.end(), [&](const auto& f) {
        return std::count(f.begin(), f.end(), p.vertex) && std::count(f.begin(), f.end(), p.toVertex);
      });
      require(isEdge && p.vertex != p.toVertex, [&] {
        return "surfacePointPosition: vertices " + std::to_string(p.vertex) + " and " +
               std::to_string(p.toVertex) + " share no face";
      });
      return (1.0 - p.t) * soup.positions[p.vertex] + p.t * soup.positions[p.toVertex];
    }
    case SurfacePoint::Kind::Face: {
      require(p.face < soup.faces.size(),
              [&] { return "surfacePointPosition: face " + std::to_string(p.face) + " out of range"; });
      const auto& f = soup.faces[p.face];
      for (Index v : f) requireVertex(soup, v, "surfacePointPosition");
      // The same acceptance as geodex::resolve documents: non-negative, summing to 1 within 1e-9.
      const double sum = p.bary[0] + p.bary[1] + p.bary[2];
      require(std::all_of(p.bary.begin(), p.bary.end(),
                          [](double b) { return std::isfinite(b) && b >= -1e-9; }) &&
                  std::abs(sum - 1.0) <= 1e-9,
              "surfacePointPosition: barycentric coordinates not in the face");
      return p.bary[0] * soup.positions[f[0]] + p.bary[1] * soup.positions[f[1]] +
             p.bary[2] * soup.positions[f[2]];
    }
  }
  throw std::invalid_argument("surfacePointPosition: unknown kind");
}

// === Euclidean lower bound =====================================================================

TriangleSoup soupInMeshUnits(const Mesh& mesh) {
  TriangleSoup soup = mesh.soup();
  for (Vec3& p : soup.positions) {
    p *= mesh.meshUnit().inverse;
    if (!isFinite(p)) p = Vec3::Zero();
  }
  return soup;
}

std::vector<double> euclideanDistances(std::span<const Vec3> positions, const Vec3& source) {
  std::vector<double> d(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) d[i] = (positions[i] - source).norm();
  return d;
}

std::vector<double> euclideanDistances(std::span<const Vec3> positions,
                                       std::span<const Vec3> sources) {
  require(!sources.empty(), "euclideanDistances: no source");
  std::vector<double> d(positions.size(), kInf);
  for (const Vec3& s : sources)
    for (std::size_t i = 0; i < positions.size(); ++i)
      d[i] = std::min(d[i], (positions[i] - s).norm());
  return d;
}

// === Edge-graph upper bound ====================================================================

std::vector<double> edgeGraphDijkstra(const TriangleSoup& soup,
                                      const std::vector<std::pair<Index, double>>& sourceVertices) {
  requireFaces(soup, "edgeGraphDijkstra");
  const std::size_t n = soup.positions.size();
  // Adjacency in compressed rows, from the unique edges.
  const auto edges = uniqueEdges(soup);
  std::vector<std::size_t> start(n + 1, 0);
  for (const auto& [a, b] : edges) {
    ++start[a + 1];
    ++start[b + 1];
  }
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::pair<Index, double>> adjacent(start[n]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (const auto& [a, b] : edges) {
      const double length = (soup.positions[a] - soup.positions[b]).norm();
      adjacent[fill[a]++] = {b, length};
      adjacent[fill[b]++] = {a, length};
    }
  }
  std::vector<double> d(n, kInf);
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (const auto& [v, d0] : sourceVertices) {
    requireVertex(soup, v, "edgeGraphDijkstra");
    require(std::isfinite(d0) && d0 >= 0.0,
            "edgeGraphDijkstra: initial distance must be finite and >= 0");
    // A source on a vertex no face uses is a point at distance 0 from itself, as the solver
    // has it; with no edge, it reaches nothing else.
    if (d0 < d[v]) {
      d[v] = d0;
      queue.emplace(d0, v);
    }
  }
  while (!queue.empty()) {
    const auto [dv, v] = queue.top();
    queue.pop();
    if (dv > d[v]) continue;  // stale entry
    for (std::size_t k = start[v]; k < start[v + 1]; ++k) {
      const auto [w, length] = adjacent[k];
      const double candidate = dv + length;
      if (candidate < d[w]) {
        d[w] = candidate;
        queue.emplace(candidate, w);
      }
    }
  }
  return d;
}

std::vector<double> edgeGraphDijkstra(const Mesh& mesh,
                                      const std::vector<std::pair<Index, double>>& sourceVertices) {
  return edgeGraphDijkstra(mesh.soup(), sourceVertices);
}

std::vector<double> edgeGraphDijkstra(const TriangleSoup& soup,
                                      const std::vector<SurfacePoint>& sources) {
  std::vector<std::pair<Index, double>> seeds;
  for (const SurfacePoint& p : sources) {
    const Vec3 x = surfacePointPosition(soup, p);
    auto seed = [&](Index v) { seeds.emplace_back(v, (soup.positions[v] - x).norm()); };
    switch (p.kind) {
      case SurfacePoint::Kind::Vertex:
        seeds.emplace_back(p.vertex, 0.0);
        break;
      case SurfacePoint::Kind::Edge:
        // Every corner of every face on the edge: the segment to it stays in that face.
        for (const auto& f : soup.faces)
          if (std::count(f.begin(), f.end(), p.vertex) && std::count(f.begin(), f.end(), p.toVertex))
            for (Index v : f) seed(v);
        break;
      case SurfacePoint::Kind::Face:
        for (Index v : soup.faces[p.face]) seed(v);
        break;
    }
  }
  return edgeGraphDijkstra(soup, seeds);
}

std::vector<double> edgeGraphDijkstra(const Mesh& mesh, const std::vector<SurfacePoint>& sources) {
  return edgeGraphDijkstra(mesh.soup(), sources);
}

// === Planar polygonal domains ==================================================================

PlanarDomain::PlanarDomain(std::vector<Polygon2> loops) {
  require(!loops.empty(), "PlanarDomain: no boundary");
  // Drop consecutive repeats (including last == first), then orient: outer CCW, holes CW.
  for (Polygon2& loop : loops) {
    Polygon2 cleaned;
    for (const Vec2& p : loop) {
      require(std::isfinite(p.x()) && std::isfinite(p.y()), "PlanarDomain: non-finite vertex");
      if (cleaned.empty() || cleaned.back() != p) cleaned.push_back(p);
    }
    while (cleaned.size() > 1 && cleaned.back() == cleaned.front()) cleaned.pop_back();
    require(cleaned.size() >= 3, "PlanarDomain: a loop has fewer than 3 distinct vertices");
    loop = std::move(cleaned);
  }
  std::size_t outer = 0;
  for (std::size_t i = 1; i < loops.size(); ++i)
    if (std::abs(signedArea(loops[i])) > std::abs(signedArea(loops[outer]))) outer = i;
  std::swap(loops[0], loops[outer]);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const bool wantCounterClockwise = i == 0;
    if ((signedArea(loops[i]) > 0.0) != wantCounterClockwise)
      std::reverse(loops[i].begin(), loops[i].end());
  }
  loops_ = std::move(loops);

  Eigen::AlignedBox2d box;
  for (const Polygon2& loop : loops_) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec2& prev = loop[(i + loop.size() - 1) % loop.size()];
      const Vec2& v = loop[i];
      const Vec2& next = loop[(i + 1) % loop.size()];
      edges_.emplace_back(v, next);
      vertices_.push_back(v);
      box.extend(v);
      // The domain is on the left of every edge: a right turn at v is a reflex corner.
      const Vec2 in = v - prev, out = next - v;
      const double sine = cross2(in, out) / (in.norm() * out.norm());
      if (sine < -kReflexSin) reflex_.push_back(v);
    }
  }
  eps_ = kTouchRel * box.diagonal().norm();
}

bool PlanarDomain::onBoundary(const Vec2& p) const {
  return std::any_of(edges_.begin(), edges_.end(), [&](const auto& e) {
    return pointSegmentDistance(p, e.first, e.second) <= eps_;
  });
}

bool PlanarDomain::contains(const Vec2& p) const {
  if (onBoundary(p)) return true;
  // Crossing number of a ray towards +x: odd inside the outer loop and outside every hole.
  // p is farther than eps from every edge, so the half-open rule decides every crossing cleanly.
  bool inside = false;
  for (const auto& [a, b] : edges_) {
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x > p.x()) inside = !inside;
    }
  }
  return inside;
}

bool PlanarDomain::properlyCrossesBoundary(const Vec2& p, const Vec2& q) const {
  const Vec2 u = q - p;
  const double uLength = u.norm();
  for (const auto& [a, b] : edges_) {
    const double da = signedLineDistance(p, u, uLength, a);
    const double db = signedLineDistance(p, u, uLength, b);
    if (!((da > eps_ && db < -eps_) || (da < -eps_ && db > eps_))) continue;
    const Vec2 w = b - a;
    const double wLength = w.norm();
    const double dp = signedLineDistance(a, w, wLength, p);
    const double dq = signedLineDistance(a, w, wLength, q);
    if ((dp > eps_ && dq < -eps_) || (dp < -eps_ && dq > eps_)) return true;
  }
  return false;
}

bool PlanarDomain::segmentInside(const Vec2& p, const Vec2& q) const {
  if (!contains(p) || !contains(q)) return false;
  const Vec2 u = q - p;
  const double length = u.norm();
  if (length <= eps_) return true;
  // A proper crossing of a boundary edge always leaves the domain.
  if (properlyCrossesBoundary(p, q)) return false;
  // Otherwise the segment meets the boundary only where it touches boundary vertices (and at
  // its ends): between two consecutive touches it is entirely inside or entirely outside, so
  // the midpoint of each piece decides. Runs along boundary edges are pieces on the boundary,
  // hence inside.
  std::vector<double> touches{0.0, 1.0};
  for (const Vec2& v : vertices_) {
    if (pointSegmentDistance(v, p, q) <= eps_)
      touches.push_back(std::clamp((v - p).dot(u) / (length * length), 0.0, 1.0));
  }
  std::sort(touches.begin(), touches.end());
  for (std::size_t i = 0; i + 1 < touches.size(); ++i) {
    if ((touches[i + 1] - touches[i]) * length <= eps_) continue;
    if (!contains(p + 0.5 * (touches[i] + touches[i + 1]) * u)) return false;
  }
  return true;
}

std::vector<double> PlanarDomain::distances(const Vec2& source,
                                            std::span<const Vec2> queries) const {
  require(contains(source), "PlanarDomain::distances: the source is outside the domain");
  // Nodes: the source and the reflex vertices. Dense Dijkstra: there are few of them.
  std::vector<Vec2> nodes{source};
  nodes.insert(nodes.end(), reflex_.begin(), reflex_.end());
  const std::size_t n = nodes.size();
  std::vector<double> nodeDistance(n, kInf);
  std::vector<std::uint8_t> done(n, 0);
  nodeDistance[0] = 0.0;
  for (std::size_t round = 0; round < n; ++round) {
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i] && std::isfinite(nodeDistance[i]) &&
          (best == n || nodeDistance[i] < nodeDistance[best]))
        best = i;
    if (best == n) break;
    done[best] = 1;
    for (std::size_t i = 0; i < n; ++i) {
      if (done[i]) continue;
      const double candidate = nodeDistance[best] + (nodes[i] - nodes[best]).norm();
      if (candidate < nodeDistance[i] && segmentInside(nodes[best], nodes[i]))
        nodeDistance[i] = candidate;
    }
  }

  std::vector<double> result(queries.size(), kInf);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const Vec2& q = queries[k];
    require(contains(q), [&] {
      return "PlanarDomain::distances: query " + std::to_string(k) + " (" + formatDouble(q.x()) + ", " +
             formatDouble(q.y()) + ") is outside the domain";
    });
    // Try the nodes by increasing candidate distance; the first visible one is the answer.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const double da = nodeDistance[a] + (q - nodes[a]).norm();
      const double db = nodeDistance[b] + (q - nodes[b]).norm();
      return da < db;
    });
    for (std::size_t i : order) {
      if (!std::isfinite(nodeDistance[i])) break;
      if (segmentInside(nodes[i], q)) {
        result[k] = nodeDistance[i] + (q - nodes[i]).norm();
        break;
      }
    }
  }
  return result;
}

std::vector<double> planarDomainDistances(const std::vector<Polygon2>& boundary,
                                          const Vec2& source, std::span<const Vec2> queries) {
  return PlanarDomain(boundary).distances(source, queries);
}

std::vector<Polygon2> planarBoundaryPolygons(const TriangleSoup& soup) {
  requireFaces(soup, "planarBoundaryPolygons");
  std::map<std::uint64_t, int> faceCount;  // ordered: deterministic loops
  for (const auto& f : soup.faces)
    for (int k = 0; k < 3; ++k)
      if (f[k] != f[(k + 1) % 3]) ++faceCount[edgeKey(f[k], f[(k + 1) % 3])];
  // Boundary edges per vertex (undirected, so face winding does not matter).
  std::map<Index, std::vector<Index>> neighbours;
  for (const auto& [key, count] : faceCount) {
    require(count <= 2, "planarBoundaryPolygons: an edge has more than two faces");
    if (count != 1) continue;
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffULL);
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  for (const auto& entry : neighbours)  // not a structured binding: clang 14 cannot capture one
    require(entry.second.size() == 2, [&] {
      return "planarBoundaryPolygons: vertex " + std::to_string(entry.first) + " has " +
             std::to_string(entry.second.size()) + " boundary edges (a pinch)";
    });

  std::vector<Polygon2> loops;
  std::map<Index, bool> visited;
  for (const auto& [first, unused] : neighbours) {
    if (visited[first]) continue;
    Polygon2 loop;
    Index prev = kNoIndex, v = first;
    do {
      visited[v] = true;
      loop.push_back(soup.positions[v].head<2>());
      const auto& adjacent = neighbours[v];
      const Index next = adjacent[0] != prev ? adjacent[0] : adjacent[1];
      prev = v;
      v = next;
    } while (v != first);
    loops.push_back(std::move(loop));
  }
  std::stable_sort(loops.begin(), loops.end(), [](const Polygon2& a, const Polygon2& b) {
    return std::abs(signedArea(a)) > std::abs(signedArea(b));
  });
  return loops;
}

namespace {

/// The segments pq and ab share a point, or come within eps of each other at an end.
bool segmentsMeet(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b, double eps) {
  const double pqa = cross2(q - p, a - p), pqb = cross2(q - p, b - p);
  const double abp = cross2(b - a, p - a), abq = cross2(b - a, q - a);
  if (((pqa < 0.0 && pqb > 0.0) || (pqa > 0.0 && pqb < 0.0)) &&
      ((abp < 0.0 && abq > 0.0) || (abp > 0.0 && abq < 0.0)))
    return true;
  return pointSegmentDistance(a, p, q) <= eps || pointSegmentDistance(b, p, q) <= eps ||
         pointSegmentDistance(p, a, b) <= eps || pointSegmentDistance(q, a, b) <= eps;
}

}  // namespace

bool coversItsDomainOnce(const TriangleSoup& soup, const std::vector<Polygon2>& loops) {
  if (loops.empty()) return false;
  double faces = 0.0;
  for (const auto& f : soup.faces) {
    const Vec2 a = soup.positions[f[0]].head<2>(), b = soup.positions[f[1]].head<2>(),
               c = soup.positions[f[2]].head<2>();
    faces += 0.5 * std::abs(cross2(b - a, c - a));
  }
  // Each loop's area about its own first vertex: about the origin, the shoelace of a mesh far from
  // it cancels its terms down to rounding (a loop 2e-9 across at 1.95 keeps no digit).
  const auto area = [](const Polygon2& loop) {
    double twice = 0.0;
    for (std::size_t i = 1; i + 1 < loop.size(); ++i)
      twice += cross2(loop[i] - loop[0], loop[i + 1] - loop[0]);
    return 0.5 * std::abs(twice);
  };
  double domain = area(loops[0]);
  for (std::size_t i = 1; i < loops.size(); ++i) domain -= area(loops[i]);
  if (!(std::abs(faces - domain) <= tol::kPlanarCoverRel * faces)) return false;
  // Equal areas still allow a loop wound twice around a double cover: the loops must be simple.
  struct Segment {
    Vec2 p, q;
    std::size_t loop, index;
  };
  std::vector<Segment> segments;
  Eigen::AlignedBox2d box;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t i = 0; i < loops[l].size(); ++i) {
      segments.push_back({loops[l][i], loops[l][(i + 1) % loops[l].size()], l, i});
      box.extend(loops[l][i]);
    }
  const double eps = PlanarDomain::kTouchRel * box.diagonal().norm();  // as PlanarDomain touches
  for (std::size_t i = 0; i < segments.size(); ++i)
    for (std::size_t j = i + 1; j < segments.size(); ++j) {
      const Segment &s = segments[i], &t = segments[j];
      if (s.loop == t.loop) {
        const std::size_t n = loops[s.loop].size();
        if (t.index == s.index + 1 || (s.index == 0 && t.index == n - 1))
          continue;  // neighbours share an end
      }
      if (segmentsMeet(s.p, s.q, t.p, t.q, eps)) return false;
    }
  return true;
}

std::vector<Vec2> planarPositions(const TriangleSoup& soup) {
  std::vector<Vec2> xy;
  xy.reserve(soup.positions.size());
  for (const Vec3& p : soup.positions) xy.push_back(p.head<2>());
  return xy;
}

double sourcePlacementSlack(const TriangleSoup& soup, std::span<const SurfacePoint> sources) {
  // Where every distance is far below the rounding of the coordinates (a source very close to a
  // vertex of a large mesh) placing alone is more than a relative tolerance of the distances
  // (corpus/fuzz_solver/regress/{euclidean-lower,upper}-bound-source-placed-*); a vertex near a
  // snapped source can come out below the straight line from where it was given
  // (corpus/fuzz_solver/regress/euclidean-lower-bound-face-source-snapped-to-its-edge).
  double largestCoordinate = 0.0;
  for (const Vec3& x : soup.positions)
    largestCoordinate = std::max(largestCoordinate, x.cwiseAbs().maxCoeff());
  const double placing = 2.0 * tol::kPositionRoundingRel * largestCoordinate;
  double slack = placing;
  for (const SurfacePoint& src : sources) {
    double longest = 0.0;
    if (src.kind == SurfacePoint::Kind::Edge) {
      longest = (soup.positions[src.vertex] - soup.positions[src.toVertex]).norm();
    } else if (src.kind == SurfacePoint::Kind::Face) {
      const auto& f = soup.faces[src.face];
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, (soup.positions[f[k]] - soup.positions[f[(k + 1) % 3]]).norm());
    }
    slack = std::max(slack, placing + tol::kSnapParam * longest);
  }
  return slack;
}

// === Bound checks ==============================================================================

std::string CheckReport::summary() const {
  std::ostringstream os;
  os << "checked " << checked << ", failed " << failed << ", maxError " << maxError;
  if (!firstFailure.empty()) os << ": " << firstFailure;
  return os.str();
}

CheckReport checkEuclideanLowerBound(std::span<const double> d, std::span<const double> euclid,
                                     double relTol, double absTol) {
  requireSameSize(d.size(), euclid.size(), "checkEuclideanLowerBound");
  const double scale = largestFinite(euclid);
  ReportBuilder report;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (notADistance(d[i])) {
      report.failNaN("vertex " + std::to_string(i) + ": distance is " + formatDouble(d[i]));
      continue;
    }
    if (!std::isfinite(euclid[i]) || d[i] == kInf) {
      report.pass();
      continue;
    }
    const double normalizer = euclid[i] + scale;
    report.compare(euclid[i] - d[i], relTol * normalizer + absTol, normalizer, [&] {
      return "vertex " + std::to_string(i) + ": distance " + formatDouble(d[i]) +
             " below the Euclidean lower bound " + formatDouble(euclid[i]);
    });
  }
  return report.take();
}

CheckReport checkUpperBound(std::span<const double> d, std::span<const double> upper,
                            double relTol, double absTol) {
  requireSameSize(d.size(), upper.size(), "checkUpperBound");
  const double scale = largestFinite(upper);
  ReportBuilder report;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto vertex = [i] { return "vertex " + std::to_string(i); };
    if (notADistance(d[i]) || notADistance(upper[i])) {
      report.failNaN(vertex() + ": distance " + formatDouble(d[i]) + ", upper bound " +
                     formatDouble(upper[i]));
    } else if (std::isfinite(d[i]) != std::isfinite(upper[i])) {
      report.failInfinite(vertex() + ": distance " + formatDouble(d[i]) + " but upper bound " +
                          formatDouble(upper[i]) + " (one reachable, the other not)");
    } else if (!std::isfinite(d[i])) {
      report.pass();  // both unreachable
    } else {
      const double normalizer = std::abs(upper[i]) + scale;
      report.compare(d[i] - upper[i], relTol * normalizer + absTol, normalizer, [&] {
        return vertex() + ": distance " + formatDouble(d[i]) + " above the upper bound " +
               formatDouble(upper[i]);
      });
    }
  }
  return report.take();
}

CheckReport checkLipschitz(const TriangleSoup& soup, std::span<const double> d, double relTol) {
  requireSameSize(d.size(), soup.positions.size(), "checkLipschitz");
  requireFaces(soup, "checkLipschitz");
  Eigen::AlignedBox3d box;
  for (const auto& f : soup.faces)
    for (Index v : f) box.extend(soup.positions[v]);
  const double scale = soup.faces.empty() ? 0.0 : box.diagonal().norm();
  ReportBuilder report;
  for (const auto& ab : uniqueEdges(soup)) {
    // Plain copies, not structured bindings: clang 14 cannot capture those in the lambda below.
    const Index a = ab.first, b = ab.second;
    const auto edge = [a, b] { return "edge " + std::to_string(a) + "-" + std::to_string(b); };
    if (notADistance(d[a]) || notADistance(d[b])) {
      report.failNaN(edge() + ": distances " + formatDouble(d[a]) + " and " + formatDouble(d[b]));
      continue;
    }
    if (!std::isfinite(d[a]) || !std::isfinite(d[b])) continue;  // not checked
    const double length = (soup.positions[a] - soup.positions[b]).norm();
    const double jump = std::abs(d[a] - d[b]);
    const double normalizer = length + scale;
    report.compare(jump - length, relTol * normalizer, normalizer, [&] {
      return edge() + ": distances " + formatDouble(d[a]) + " and " + formatDouble(d[b]) +
             " differ by more than the edge length " + formatDouble(length);
    });
  }
  return report.take();
}

CheckReport checkLipschitz(const Mesh& mesh, std::span<const double> d, double relTol) {
  return checkLipschitz(mesh.soup(), d, relTol);
}

CheckReport checkSymmetry(double dab, double dba, double relTol) {
  ReportBuilder report;
  if (notADistance(dab) || notADistance(dba)) {
    report.failNaN("d(a,b) = " + formatDouble(dab) + ", d(b,a) = " + formatDouble(dba));
  } else if (std::isfinite(dab) != std::isfinite(dba)) {
    report.failInfinite("d(a,b) = " + formatDouble(dab) + " but d(b,a) = " + formatDouble(dba));
  } else if (!std::isfinite(dab)) {
    report.pass();
  } else {
    const double normalizer = std::max(std::abs(dab), std::abs(dba));
    report.compare(std::abs(dab - dba), relTol * normalizer, normalizer, [&] {
      return "d(a,b) = " + formatDouble(dab) + " differs from d(b,a) = " + formatDouble(dba);
    });
  }
  return report.take();
}

CheckReport checkAgreement(std::span<const double> d, std::span<const double> reference,
                           double relTol, double absTol) {
  requireSameSize(d.size(), reference.size(), "checkAgreement");
  const double scale = largestFinite(reference);
  ReportBuilder report;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto vertex = [i] { return "vertex " + std::to_string(i); };
    if (notADistance(d[i]) || notADistance(reference[i])) {
      report.failNaN(vertex() + ": not a distance (distance " + formatDouble(d[i]) + ", reference " +
                     formatDouble(reference[i]) + ")");
    } else if (std::isfinite(d[i]) != std::isfinite(reference[i])) {
      report.failInfinite(vertex() + ": distance " + formatDouble(d[i]) + " but reference " +
                          formatDouble(reference[i]));
    } else if (!std::isfinite(d[i])) {
      report.pass();
    } else {
      const double normalizer = std::abs(reference[i]) + scale;
      report.compare(std::abs(d[i] - reference[i]), relTol * normalizer + absTol, normalizer, [&] {
        return vertex() + ": distance " + formatDouble(d[i]) + " differs from the reference " +
               formatDouble(reference[i]);
      });
    }
  }
  return report.take();
}

}  // namespace geodex::verify
