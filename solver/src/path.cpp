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
// covers (the old tracer walked from the point towards a window's source and asked whether that
// source was inside the face, with a tolerance in absolute cross-product units; beside 1e5-long
// thin triangles it accepted a source 1.58 outside one and cut through the air,
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
// from. A window that passes through a zero-area face (propagate.cpp, passThroughZeroAreaFace)
// is followed the same way: seen from a point of one edge of such a face, the other two lie on
// the same line, and the crossing is the same point (a step of length zero along that line).

#include <algorithm>
#include <cmath>
#include <vector>

#include "geodex/check.h"
#include "geodex/geodesic_solver.h"
#include "geodex/tolerance.h"

namespace geodex {
namespace {

constexpr std::size_t kNoSource = ~std::size_t{0};

// Where the tracer can go next, and what it costs from the current point to the source that way.
struct Step {
  double value = kInfinity;            // the step's length plus the distance left after it
  ResolvedPoint to{SurfacePoint::Kind::Vertex, kNoIndex, 0.0, {}, Vec3::Zero()};  // where it ends
  std::size_t source = kNoSource;      // it ends at this source (`to` is then that source)
  Index through = kNoIndex;            // the face it crosses
  bool moves = true;                   // false: it stays at the point (zero-area faces)
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
        vertexDistance_(solver.vertexDistances()),
        sources_(solver.sources()) {}

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

  // The source at vertex v, or kNoSource.
  std::size_t sourceAtVertex(Index v) const {
    for (std::size_t i = 0; i < sources_.size(); ++i)
      if (sources_[i].kind == SurfacePoint::Kind::Vertex && sources_[i].element == v) return i;
    return kNoSource;
  }

  // Offers `best` every step from p (on face g) through g: to a corner, to a source on g, across
  // g to another edge (see the top of the file).
  void stepsThrough(const ResolvedPoint& p, Index g, Step& best) const {
    const auto& edges = mesh_.faceEdges(g);
    double scale = 0.0;  // the face's longest edge
    for (Index e : edges) scale = std::max(scale, mesh_.edge(e).length);
    const double still = tol::kPathSamePointRel * scale;
    auto offer = [&](double value, const ResolvedPoint& to, std::size_t source, double length) {
      if (value < best.value) best = {value, to, source, g, length > still};
    };

    // Sources and corners: straight lines in g, measured in g unfolded onto its first edge.
    // Sources first: a source beyond a corner on the same line (a zero-area face) ties with the
    // corner, and going straight there ends the path.
    const Vec2 q = pointInFaceFrame(mesh_, p, g, edges[0]);
    for (std::size_t i = 0; i < sources_.size(); ++i) {
      if (!isOnFace(mesh_, sources_[i], g)) continue;
      const double length = (pointInFaceFrame(mesh_, sources_[i], g, edges[0]) - q).norm();
      offer(length, sources_[i], i, length);
    }
    for (Index u : mesh_.face(g)) {
      if (p.kind == SurfacePoint::Kind::Vertex && p.element == u) continue;
      if (!std::isfinite(vertexDistance_[u])) continue;
      const ResolvedPoint corner = vertexPoint(mesh_, u);
      const double length = (pointInFaceFrame(mesh_, corner, g, edges[0]) - q).norm();
      offer(vertexDistance_[u] + length, corner, kNoSource, length);
    }

    // Across g onto each edge e that p is not on, then along one of e's windows from beyond e.
    for (Index e : edges) {
      if (isOnEdge(mesh_, p, e)) continue;
      const Edge& E = mesh_.edge(e);
      const Vec2 qe = pointInFaceFrame(mesh_, p, g, e);  // g above e: qe.y() >= 0
      double value = kInfinity, at = 0.0, length = 0.0;
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
        const double toC = (qe - c).norm();
        const double v = w.sigma + (c - s).norm() + toC;
        if (v < value) {
          value = v;
          at = cx;
          length = toC;
        }
      }
      if (value < best.value) offer(value, edgePoint(mesh_, e, at), kNoSource, length);
    }
  }

 private:
  const Mesh& mesh_;
  std::span<const EdgeIntervals> edges_;
  std::span<const double> vertexDistance_;
  std::span<const ResolvedPoint> sources_;
};

}  // namespace

GeodesicPath GeodesicSolver::path(const SurfacePoint& target) const {
  const ResolvedPoint start = resolve(mesh_, target);
  GeodesicPath result;
  if (!std::isfinite(resolvedDistance(start))) return result;

  // The first point is the target as given (a face point keeps its barycentrics unnormalised).
  result.points.push_back(start.kind == SurfacePoint::Kind::Face ? PathPoint{target, start.position}
                                                                 : toPathPoint(mesh_, start));
  const Tracer tracer(*this);
  ResolvedPoint cur = start;
  // Faces crossed since the path last moved: not entered again from the same point. A window
  // through a zero-area face is followed by a step of length zero (see the top of the file);
  // without this, two such faces on one line could hand the point back and forth for ever. After
  // a step of positive length no face needs barring: going back into the face just crossed is
  // never cheaper (the triangle inequality in that face), and barring it would also bar a face
  // the step only ran along the edge of (a source further along a zero-area face's line).
  std::vector<Index> crossedHere;
  const std::size_t maxSteps = 8 * (mesh_.numFaces() + mesh_.numVertices()) + 16;
  for (std::size_t step = 0; step < maxSteps; ++step) {
    Step best;
    if (cur.kind == SurfacePoint::Kind::Vertex) {
      if (const std::size_t source = tracer.sourceAtVertex(cur.element); source != kNoSource)
        best = {0.0, cur, source};
    }
    if (best.source == kNoSource) {
      for (Index g : tracer.facesAt(cur))
        if (std::find(crossedHere.begin(), crossedHere.end(), g) == crossedHere.end())
          tracer.stepsThrough(cur, g, best);
    }
    GEODEX_REQUIRE(std::isfinite(best.value), "path tracing lost its way at step " << step);
    // A step to a source vertex (its corner, or a crossing at it) ends there.
    if (best.source == kNoSource && best.to.kind == SurfacePoint::Kind::Vertex)
      best.source = tracer.sourceAtVertex(best.to.element);
    if (best.source != kNoSource) {
      result.points.push_back(toPathPoint(mesh_, sources_[best.source]));
      result.length = 0.0;
      for (std::size_t k = 1; k < result.points.size(); ++k)
        result.length += (result.points[k].position - result.points[k - 1].position).norm();
      return result;
    }
    if (best.moves) crossedHere.clear();
    else crossedHere.push_back(best.through);
    cur = best.to;
    result.points.push_back(toPathPoint(mesh_, cur));
  }
  GEODEX_REQUIRE(false, "path tracing did not reach a source within " << maxSteps << " steps");
  return result;
}

}  // namespace geodex
