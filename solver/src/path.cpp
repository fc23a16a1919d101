// Geodesic path tracing: from a surface point back to the nearest source, by following, at each
// step, the window that gives the point its distance, straight across the face towards the
// window's unfolded pseudo-source, until the pseudo-source itself is reached; a pseudo-source at
// a saddle or boundary vertex continues from that vertex.

#include <algorithm>
#include <cmath>
#include <optional>

#include "geodex/check.h"
#include "geodex/geodesic_solver.h"
#include "geodex/predicates.h"
#include "geodex/tolerance.h"

namespace geodex {
namespace {

enum class At { Vertex, Edge, Face, Source };

struct State {
  At at;
  Index element;  // vertex, edge, face, or source number
  double x = 0.0; // position on the edge
  Vec3 position;
};

PathPoint toPathPoint(const Mesh& mesh, const State& s, std::span<const ResolvedPoint> sources) {
  switch (s.at) {
    case At::Vertex: return {SurfacePoint::atVertex(s.element), s.position};
    case At::Edge: {
      const Edge& E = mesh.edge(s.element);
      return {SurfacePoint::onEdge(E.vertex[0], E.vertex[1], s.x / E.length), s.position};
    }
    case At::Face: {
      return {SurfacePoint::inFace(s.element, 1.0 / 3, 1.0 / 3, 1.0 / 3), s.position};
    }
    case At::Source: {
      const ResolvedPoint& r = sources[s.element];
      if (r.kind == SurfacePoint::Kind::Vertex) return {SurfacePoint::atVertex(r.element), r.position};
      if (r.kind == SurfacePoint::Kind::Edge) {
        const Edge& E = mesh.edge(r.element);
        return {SurfacePoint::onEdge(E.vertex[0], E.vertex[1], r.t / E.length), r.position};
      }
      return {SurfacePoint::inFace(r.element, r.bary[0], r.bary[1], r.bary[2]), r.position};
    }
  }
  return {};
}

Vec3 edgePoint(const Mesh& mesh, Index e, double x) {
  const Edge& E = mesh.edge(e);
  const double t = x / E.length;
  return (1.0 - t) * mesh.position(E.vertex[0]) + t * mesh.position(E.vertex[1]);
}

}  // namespace

GeodesicPath GeodesicSolver::path(const SurfacePoint& target) const {
  const ResolvedPoint t = resolve(mesh_, target);
  GeodesicPath result;
  if (!std::isfinite(resolvedDistance(t))) return result;

  State cur{t.kind == SurfacePoint::Kind::Vertex ? At::Vertex
            : t.kind == SurfacePoint::Kind::Edge ? At::Edge
                                                 : At::Face,
            t.element, t.t, t.position};
  if (cur.at == At::Face) {
    // Keep the real barycentrics for the first point.
    result.points.push_back({target, t.position});
  } else {
    result.points.push_back(toPathPoint(mesh_, cur, sources_));
  }

  // Is `s` a source point, and which one?
  auto sourceAtVertex = [&](Index v) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < sources_.size(); ++i)
      if (sources_[i].kind == SurfacePoint::Kind::Vertex && sources_[i].element == v) return i;
    return std::nullopt;
  };

  // Go from `from` (a point on edge `e` at x, or its vertex) into face g towards window w's
  // source; returns the next state (the exit point on another edge of g, or the pseudo-source).
  auto walk = [&](Index e, double x, Index g, const Interval& w) -> std::optional<State> {
    const FaceFrame& fr = mesh_.frame(g, e);
    const Edge& E = mesh_.edge(e);
    const double scale = std::max(E.length, fr.apexPos.norm());
    if (w.source.y() <= tol::kCoincideRel * scale) {
      // The source is on the edge's own line (G1, G4, G5 windows): the path runs along the edge.
      if (w.source.x() <= tol::kCoincideRel * scale && x > 0.0)
        return State{At::Vertex, E.vertex[0], 0.0, mesh_.position(E.vertex[0])};
      if (w.source.x() >= E.length - tol::kCoincideRel * scale && x < E.length)
        return State{At::Vertex, E.vertex[1], 0.0, mesh_.position(E.vertex[1])};
    }
    const Vec2 p(x, 0.0), s(w.source.x(), w.source.y());  // source on g's side: above the axis
    const Vec2 v0(0.0, 0.0), v1 = fr.apexPos, v2(E.length, 0.0);
    const Vec2 d = s - p;
    double bestU = 1.0;
    int exitEdge = 0;
    double exitT = 0.0;
    const Vec2 segA[2] = {v0, v1}, segB[2] = {v1, v2};
    for (int k = 0; k < 2; ++k) {
      const Vec2 a = segA[k], b = segB[k];
      const double denom = pred::cross(d, b - a);
      if (denom == 0.0) continue;
      const double u = pred::cross(a - p, b - a) / denom;
      const double tt = pred::cross(a - p, d) / denom;
      if (u > 1e-12 && u < bestU && tt >= -1e-9 && tt <= 1.0 + 1e-9) {
        bestU = u;
        exitEdge = k + 1;
        exitT = std::clamp(tt, 0.0, 1.0);
      }
    }
    if (exitEdge == 0 || bestU >= 1.0 - 1e-12) {
      // The pseudo-source must then be in (or on) face g; if it is not, the direction towards it
      // leaves g at once (a window that covers this point but does not see it through g).
      const double tolIn = -1e-9 * scale;
      const bool inside = pred::cross(v1 - v0, s - v0) <= -tolIn * scale &&
                          pred::cross(v2 - v1, s - v1) <= -tolIn * scale && s.y() >= tolIn;
      if (!inside) return std::nullopt;
      if (w.origin < 0) {
        const std::size_t n = static_cast<std::size_t>(-(w.origin + 1));
        return State{At::Source, static_cast<Index>(n), 0.0, sources_[n].position};
      }
      return State{At::Vertex, static_cast<Index>(w.origin), 0.0, mesh_.position(w.origin)};
    }
    const Index ex = exitEdge == 1 ? fr.edgeToV0 : fr.edgeToV2;
    const Index from = exitEdge == 1 ? E.vertex[0] : fr.apex;
    const Edge& X = mesh_.edge(ex);
    const double along = X.vertex[0] == from ? exitT : 1.0 - exitT;
    const double snap = tol::kCoincideRel * 1e3;
    if (along <= snap) return State{At::Vertex, X.vertex[0], 0.0, mesh_.position(X.vertex[0])};
    if (along >= 1.0 - snap) return State{At::Vertex, X.vertex[1], 0.0, mesh_.position(X.vertex[1])};
    return State{At::Edge, ex, along * X.length, edgePoint(mesh_, ex, along * X.length)};
  };

  Index cameFromFace = kNoIndex;
  const std::size_t maxSteps = 8 * (mesh_.numFaces() + mesh_.numVertices()) + 16;
  for (std::size_t step = 0; step < maxSteps; ++step) {
    State next{At::Source, 0, 0.0, {}};
    Index nextFace = kNoIndex;  // the face crossed to reach `next`: not to be re-entered from it
    double best = kInfinity;
    // Candidate: continue with window w of edge e from position x on it (x at an end for a vertex).
    auto consider = [&](Index e, double x, const Interval& w, Index excludeVertex) {
      const Index g = mesh_.edge(e).face[w.side];
      if (g == kNoIndex || g == cameFromFace) return;
      if (x < w.b0 - 1e-12 * mesh_.edge(e).length || x > w.b1 + 1e-12 * mesh_.edge(e).length) return;
      if (w.origin >= 0 && static_cast<Index>(w.origin) == excludeVertex) return;
      const double value = w.distanceAt(x);
      if (value < best) {
        if (const auto step = walk(e, x, g, w)) {
          best = value;
          next = *step;
          nextFace = g;
        }
      }
    };
    switch (cur.at) {
      case At::Source:
        result.length = 0.0;
        for (std::size_t k = 1; k < result.points.size(); ++k)
          result.length += (result.points[k].position - result.points[k - 1].position).norm();
        return result;
      case At::Vertex: {
        if (auto src = sourceAtVertex(cur.element)) {
          next = {At::Source, static_cast<Index>(*src), 0.0, cur.position};
          best = 0.0;
          break;
        }
        for (Index e : mesh_.vertexEdges(cur.element)) {
          const Edge& E = mesh_.edge(e);
          const double x = E.vertex[0] == cur.element ? 0.0 : E.length;
          for (const Interval& w : edges_[e].intervals()) consider(e, x, w, cur.element);
          const Index u = E.vertex[0] == cur.element ? E.vertex[1] : E.vertex[0];
          if (vertexDistance_[u] + E.length < best) {
            best = vertexDistance_[u] + E.length;
            next = {At::Vertex, u, 0.0, mesh_.position(u)};
            nextFace = kNoIndex;
          }
        }
        break;
      }
      case At::Edge: {
        const Edge& E = mesh_.edge(cur.element);
        for (const Interval& w : edges_[cur.element].intervals()) consider(cur.element, cur.x, w, kNoIndex);
        for (int k = 0; k < 2; ++k) {
          const double dv = vertexDistance_[E.vertex[k]] + (k == 0 ? cur.x : E.length - cur.x);
          if (dv < best) {
            best = dv;
            next = {At::Vertex, E.vertex[k], 0.0, mesh_.position(E.vertex[k])};
            nextFace = kNoIndex;
          }
        }
        for (std::size_t i = 0; i < sources_.size(); ++i) {
          const ResolvedPoint& src = sources_[i];
          if (src.kind == SurfacePoint::Kind::Edge && src.element == cur.element &&
              std::abs(src.t - cur.x) < best) {
            best = std::abs(src.t - cur.x);
            next = {At::Source, static_cast<Index>(i), 0.0, src.position};
            nextFace = kNoIndex;
          }
        }
        break;
      }
      case At::Face: {
        const Index f = cur.element;
        for (Index v : mesh_.face(f)) {
          const double dv = vertexDistance_[v] + (mesh_.position(v) - cur.position).norm();
          if (dv < best) {
            best = dv;
            next = {At::Vertex, v, 0.0, mesh_.position(v)};
            nextFace = f;
          }
        }
        for (std::size_t i = 0; i < sources_.size(); ++i) {
          const ResolvedPoint& src = sources_[i];
          const bool touches =
              (src.kind == SurfacePoint::Kind::Face && src.element == f) ||
              (src.kind == SurfacePoint::Kind::Edge && mesh_.localEdgeIndex(f, src.element) >= 0);
          const double dv = (src.position - cur.position).norm();
          if (touches && dv < best) {
            best = dv;
            next = {At::Source, static_cast<Index>(i), 0.0, src.position};
          }
        }
        for (Index e : mesh_.faceEdges(f)) {
          const Edge& E = mesh_.edge(e);
          const Vec3 o = mesh_.position(E.vertex[0]);
          const Vec3 dir = (mesh_.position(E.vertex[1]) - o) / E.length;
          const Vec3 rel = cur.position - o;
          const Vec2 q(rel.dot(dir), rel.cross(dir).norm());
          for (const Interval& w : edges_[e].intervals()) {
            const Vec2 s(w.source.x(), -w.source.y());
            const double u = (q.y() - s.y()) > 0 ? -s.y() / (q.y() - s.y()) : 0.0;
            const double cx = std::clamp(s.x() + u * (q.x() - s.x()), w.b0, w.b1);
            const Vec2 c(cx, 0.0);
            const double value = w.sigma + (c - s).norm() + (q - c).norm();
            if (value < best) {
              best = value;
              next = {At::Edge, e, cx, edgePoint(mesh_, e, cx)};
              nextFace = f;
            }
          }
        }
        break;
      }
    }
    GEODEX_REQUIRE(std::isfinite(best), "path tracing lost its way at step " << step);
    if (next.at == At::Edge) {
      const Edge& X = mesh_.edge(next.element);
      if (next.x <= 0.0) next = {At::Vertex, X.vertex[0], 0.0, mesh_.position(X.vertex[0])};
      else if (next.x >= X.length) next = {At::Vertex, X.vertex[1], 0.0, mesh_.position(X.vertex[1])};
    }
    cameFromFace = nextFace;
    cur = next;
    result.points.push_back(toPathPoint(mesh_, cur, sources_));
  }
  GEODEX_REQUIRE(false, "path tracing did not reach a source within " << maxSteps << " steps");
  return result;
}

}  // namespace geodex
