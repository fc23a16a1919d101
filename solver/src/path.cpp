// Geodesic path tracing: from a surface point back to the nearest source, one face at a time,
// always taking the step along which the distance field descends.
//
// The current point lies on one or more faces (a face point on its face, an edge point on the
// edge's one or two faces, a vertex on its fan). For each such face g, every way of going on
// through g is priced, in g unfolded onto one of its edges, with the formula distance() uses for a
// point inside a face (geodesic_solver.cpp, resolvedDistance):
//   - across g to a point c of an edge e of g that the point is not on, and on from c along a
//     window w of e whose source lies beyond e: σ + |c − s'| + |q − c|, q the point and s' w's
//     source reflected below e, c the point of [b0, b1] nearest the segment q → s' crossing e;
//   - to a corner u of g, and on from u: D(u) + |u − q| (a pseudo-source, or the path runs
//     through a vertex or along an edge);
//   - to a source in g (inside, on an edge or at a corner): |src − q|.
// The cheapest is taken and the tracer moves to its end. Each step joins two points of one face,
// so the path lies on the surface by construction: no window is followed out of the face it
// covers (walking from the point towards a window's source, with a tolerance deciding whether
// that source is inside the face, cuts through the air beside long thin triangles:
// tests/property/regressions_test.cpp case 7).
//
// Why the steps add up to the distance: a window w of edge e covering c got there through the
// face beyond e from a window on another edge of that face (propagate.cpp), or from a corner
// pseudo-source or a source in that face; the edges' distance functions only decreased since
// (Algorithm 2 keeps the pointwise minimum). So at c some step of the next round costs at most
// w's value at c, which is the value just paid for minus the step's length: values never grow
// along the path, and its length is the distance at the target up to the solver's tolerances.
// The cheapest step at a point is straight on across an edge (the ray of the window giving its
// distance), so the path bends only where windows end: at pseudo-sources, the corners they start
// from.
//
// Zero-length steps. Several points of the mesh can lie at one position: a corner of a zero-area
// face and the point of the face's long edge there, two vertices at one position joined through
// such faces, a crossing exactly at a vertex. They are one place for the path, with one distance,
// and the way on may leave from any of them: a window that passes through a zero-area face
// (propagate.cpp, passThroughZeroAreaFace) reaches the point of the far edge at the same position,
// and the path goes on from there. So at each step the tracer first gathers the points at the
// current position (reached from it, through any face at any of them, by a step shorter than
// tol::kPathSamePointRel × that face's longest edge), then takes the cheapest step from any of
// them that moves, or ends at a source, and walks the zero-length steps to where it leaves from.
// A zero-length step is never priced as a step: its value is the distance at the position itself,
// which can come from the very point it leaves (a pseudo-source at the same position whose
// distance was taken from that point), and it ties with the step that really goes on up to
// rounding: priced, it can win by rounding and lead the path to a point at the same position
// from which only an uphill way is left, and back
// (corpus/fuzz_solver/regress/path-length-non-manifold-vertex-beside-a-duplicate-walks-back).
// Every step moves the path by more than kPathSamePointRel × its face's longest edge, and its
// value, the length of a real path, is the smallest over the whole place: values never grow along
// the path, so it never comes back to a place it has left.

#include <algorithm>
#include <cmath>
#include <vector>

#include "geodex/check.h"
#include "geodex/geodesic_solver.h"
#include "geodex/tolerance.h"

namespace geodex {
namespace {

constexpr std::size_t kNoSource = ~std::size_t{0};

// Where the tracer can go next, and what it costs from the current position to the source that
// way.
struct Step {
  double value = kInfinity;            // the step's length plus the distance left after it
  ResolvedPoint to{SurfacePoint::Kind::Vertex, kNoIndex, 0.0, {}, Vec3::Zero()};  // where it ends
  std::size_t source = kNoSource;      // it ends at this source (`to` is then that source)
  std::size_t from = 0;                // the Place it leaves from
};

// A point at the current position of the path: the current point itself (the first Place), or
// one reached from an earlier Place by a zero-length step (see the top of the file).
struct Place {
  ResolvedPoint point;
  std::size_t reachedFrom = 0;  // the Place before it on the zero-length steps from the first
};

ResolvedPoint vertexPoint(const Mesh& mesh, Index v) {
  return {SurfacePoint::Kind::Vertex, v, 0.0, {}, mesh.position(v)};
}

// The point at x (length units from edge(e).vertex[0]) of edge e; within tol::kPathSamePointRel
// of an end, that end's vertex.
ResolvedPoint edgePoint(const Mesh& mesh, Index e, double x) {
  const Edge& E = mesh.edge(e);
  const double snap = tol::kPathSamePointRel * E.length;
  if (x <= snap) return vertexPoint(mesh, E.vertex[0]);
  if (x >= E.length - snap) return vertexPoint(mesh, E.vertex[1]);
  const double t = x / E.length;
  const Vec3 at = (1.0 - t) * mesh.position(E.vertex[0]) + t * mesh.position(E.vertex[1]);
  return {SurfacePoint::Kind::Edge, e, x, {}, at};
}

PathPoint toPathPoint(const Mesh& mesh, const ResolvedPoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return {SurfacePoint::atVertex(p.element), p.position};
    case SurfacePoint::Kind::Edge: {
      const Edge& E = mesh.edge(p.element);
      return {SurfacePoint::onEdge(E.vertex[0], E.vertex[1], p.t / E.length), p.position};
    }
    case SurfacePoint::Kind::Face:
      return {SurfacePoint::inFace(p.element, p.bary[0], p.bary[1], p.bary[2]), p.position};
  }
  return {};
}

// Whether p lies on edge e (p is then no place to cross e from).
bool isOnEdge(const Mesh& mesh, const ResolvedPoint& p, Index e) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      return mesh.edge(e).vertex[0] == p.element || mesh.edge(e).vertex[1] == p.element;
    case SurfacePoint::Kind::Edge: return p.element == e;
    case SurfacePoint::Kind::Face: return false;
  }
  return false;
}

// Whether source point src lies on face g: inside it, on one of its edges, or at a corner.
bool isOnFace(const Mesh& mesh, const ResolvedPoint& src, Index g) {
  switch (src.kind) {
    case SurfacePoint::Kind::Vertex: {
      const auto& corners = mesh.face(g);
      return std::find(corners.begin(), corners.end(), src.element) != corners.end();
    }
    case SurfacePoint::Kind::Edge: return mesh.localEdgeIndex(g, src.element) >= 0;
    case SurfacePoint::Kind::Face: return src.element == g;
  }
  return false;
}

class Tracer {
 public:
  explicit Tracer(const GeodesicSolver& solver)
      : mesh_(solver.mesh()),
        edges_(solver.edgeIntervals()),
        vertexDistance_(solver.vertexDistancesInMeshUnits()),
        sources_(solver.sources()) {}

  // The cheapest step that moves the path on from `at`, or ends it at a source. `places` receives
  // the points at `at`'s position the step may leave from: `at` first, then those reached from
  // it by zero-length steps, each after the one it was reached from (the step's `from`).
  Step cheapestStep(const ResolvedPoint& at, std::vector<Place>& places) const {
    places.assign(1, Place{at, 0});
    Step best;
    if (at.kind == SurfacePoint::Kind::Vertex) {
      if (const std::size_t source = sourceAtVertex(at.element); source != kNoSource)
        return {0.0, at, source, 0};
    }
    // places grows as the faces at each Place are searched: a breadth-first search of the points
    // at this position.
    for (std::size_t k = 0; k < places.size(); ++k) {
      const ResolvedPoint p = places[k].point;  // a copy: stepsThrough may grow places
      for (Index g : facesAt(p)) stepsThrough(p, k, g, places, best);
    }
    return best;
  }

  // The source at vertex v, or kNoSource.
  std::size_t sourceAtVertex(Index v) const {
    for (std::size_t i = 0; i < sources_.size(); ++i)
      if (sources_[i].kind == SurfacePoint::Kind::Vertex && sources_[i].element == v) return i;
    return kNoSource;
  }

 private:
  // The faces p lies on.
  std::vector<Index> facesAt(const ResolvedPoint& p) const {
    switch (p.kind) {
      case SurfacePoint::Kind::Vertex: {
        const auto fan = mesh_.vertexFaces(p.element);
        return {fan.begin(), fan.end()};
      }
      case SurfacePoint::Kind::Edge: {
        std::vector<Index> faces;
        for (Index g : mesh_.edge(p.element).face)
          if (g != kNoIndex) faces.push_back(g);
        return faces;
      }
      case SurfacePoint::Kind::Face: return {p.element};
    }
    return {};
  }

  // Adds `to`, reached from places[from] by a zero-length step, to the places unless it is one
  // already. Reaching a source vertex so ends the path there.
  void addPlace(const ResolvedPoint& to, std::size_t from, std::vector<Place>& places,
                Step& best) const {
    for (const Place& known : places)
      if (known.point.kind == to.kind && known.point.element == to.element) return;
    places.push_back({to, from});
    if (to.kind == SurfacePoint::Kind::Vertex) {
      if (const std::size_t source = sourceAtVertex(to.element); source != kNoSource)
        best = {0.0, to, source, from};
    }
  }

  // Offers `best` every step from p = places[k] (on face g) through g that moves p, or ends at a
  // source: to a corner, to a source on g, across g to another edge (see the top of the file).
  // A corner or an edge of g at p's own position is a zero-length step: it goes to `places`.
  void stepsThrough(const ResolvedPoint& p, std::size_t k, Index g, std::vector<Place>& places,
                    Step& best) const {
    const auto& edges = mesh_.faceEdges(g);
    double scale = 0.0;  // the face's longest edge
    for (Index e : edges) scale = std::max(scale, mesh_.edge(e).length);
    const double still = tol::kPathSamePointRel * scale;
    auto offer = [&](double value, const ResolvedPoint& to, std::size_t source) {
      if (value < best.value) best = {value, to, source, k};
    };

    // Sources and corners: straight lines in g, measured in g unfolded onto its first edge.
    // Sources first: a source beyond a corner on the same line (a zero-area face) ties with the
    // corner, and going straight there ends the path.
    const Vec2 q = pointInFaceFrame(mesh_, p, g, edges[0]);
    for (std::size_t i = 0; i < sources_.size(); ++i) {
      if (!isOnFace(mesh_, sources_[i], g)) continue;
      offer((pointInFaceFrame(mesh_, sources_[i], g, edges[0]) - q).norm(), sources_[i], i);
    }
    for (Index u : mesh_.face(g)) {
      if (p.kind == SurfacePoint::Kind::Vertex && p.element == u) continue;
      const ResolvedPoint corner = vertexPoint(mesh_, u);
      const double length = (pointInFaceFrame(mesh_, corner, g, edges[0]) - q).norm();
      if (length <= still) addPlace(corner, k, places, best);
      else if (std::isfinite(vertexDistance_[u])) offer(vertexDistance_[u] + length, corner, kNoSource);
    }

    // Across g onto each edge e that p is not on, then along one of e's windows from beyond e.
    for (Index e : edges) {
      if (isOnEdge(mesh_, p, e)) continue;
      const Edge& E = mesh_.edge(e);
      const Vec2 qe = pointInFaceFrame(mesh_, p, g, e);  // g above e: qe.y() >= 0
      if (qe.y() <= still && qe.x() >= -still && qe.x() <= E.length + still) {
        // p lies on e (g has zero area, or p is at a corner of e): the crossing is p itself.
        addPlace(edgePoint(mesh_, e, std::clamp(qe.x(), 0.0, E.length)), k, places, best);
        continue;
      }
      double value = kInfinity, at = 0.0;
      for (const Interval& w : edges_[e].intervals()) {
        // A window whose source is on g's side came through g: the geodesic from p does not
        // cross e to follow it (it would come straight back); one of g's other edges, a corner
        // or a source on g carries it.
        if (E.face[w.side] == g) continue;
        const Vec2 s(w.source.x(), -w.source.y());  // unfolded beyond e: below it
        // Where q → s crosses e's line (q and s on either side, or both on it: then at s), kept
        // within the window: the path turns there only when the window ends (at a pseudo-source).
        const double rise = qe.y() - s.y();
        const double u = rise > 0.0 ? -s.y() / rise : 0.0;
        const double cx = std::clamp(s.x() + u * (qe.x() - s.x()), w.b0, w.b1);
        const Vec2 c(cx, 0.0);
        const double v = w.sigma + (c - s).norm() + (qe - c).norm();
        if (v < value) {
          value = v;
          at = cx;
        }
      }
      if (value < best.value) offer(value, edgePoint(mesh_, e, at), kNoSource);
    }
  }

  const Mesh& mesh_;
  std::span<const EdgeIntervals> edges_;
  std::span<const double> vertexDistance_;
  std::span<const ResolvedPoint> sources_;
};

}  // namespace

GeodesicPath GeodesicSolver::path(const SurfacePoint& target) const {
  requireAllLists("path()");
  const ResolvedPoint start = resolve(mesh_, target);
  GeodesicPath result;
  if (!std::isfinite(resolvedDistance(start))) return result;

  // The first point is the target as given (a face point keeps its barycentrics unnormalised).
  result.points.push_back(start.kind == SurfacePoint::Kind::Face ? PathPoint{target, start.position}
                                                                 : toPathPoint(mesh_, start));
  const Tracer tracer(*this);
  ResolvedPoint cur = start;
  std::vector<Place> places;
  std::vector<std::size_t> zeroLengthSteps;
  // Each step moves the path (or ends it), and by at least kPathSamePointRel × a face's longest
  // edge: the bound only stops a bug from looping for ever.
  const std::size_t maxSteps = 8 * (mesh_.numFaces() + mesh_.numVertices()) + 16;
  for (std::size_t step = 0; step < maxSteps; ++step) {
    Step best = tracer.cheapestStep(cur, places);
    GEODEX_REQUIRE(std::isfinite(best.value), "path tracing lost its way at step " << step);
    // First the zero-length steps to the point the step leaves from, if that is not cur.
    zeroLengthSteps.clear();
    for (std::size_t k = best.from; k != 0; k = places[k].reachedFrom) zeroLengthSteps.push_back(k);
    for (auto k = zeroLengthSteps.rbegin(); k != zeroLengthSteps.rend(); ++k)
      result.points.push_back(toPathPoint(mesh_, places[*k].point));
    // A step to a source vertex (its corner, or a crossing at it) ends there.
    if (best.source == kNoSource && best.to.kind == SurfacePoint::Kind::Vertex)
      best.source = tracer.sourceAtVertex(best.to.element);
    if (best.source != kNoSource) {
      result.points.push_back(toPathPoint(mesh_, sources_[best.source]));
      // Summed in mesh units (exact powers of two apart from the file's): squares of file
      // coordinates overflow beyond 1e154.
      const double inverse = mesh_.meshUnit().inverse;
      double length = 0.0;
      for (std::size_t k = 1; k < result.points.size(); ++k)
        length += ((result.points[k].position - result.points[k - 1].position) * inverse).norm();
      result.length = inFileUnits(length);
      return result;
    }
    cur = best.to;
    result.points.push_back(toPathPoint(mesh_, cur));
  }
  GEODEX_REQUIRE(false, "path tracing did not reach a source within " << maxSteps << " steps");
  return result;
}

}  // namespace geodex
