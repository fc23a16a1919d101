#include "geodex/geodesic_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "geodex/check.h"
#include "geodex/error.h"
#include "geodex/predicates.h"
#include "geodex/tolerance.h"
#include "helper_thread.h"

namespace geodex {
namespace {

// The window edge e gets from a source point p of face f (inside f or on its boundary): the whole
// edge, with p unfolded into e's frame on f's side (pointInFaceFrame: from local lengths only).
Interval windowFromPoint(const Mesh& mesh, Index f, Index e, const ResolvedPoint& p, double sigma,
                         std::int32_t origin) {
  const Vec2 q = pointInFaceFrame(mesh, p, f, e);
  Interval w;
  w.b0 = 0.0;
  w.b1 = mesh.edge(e).length;
  w.source = Vec2(q.x(), std::max(0.0, q.y()));
  w.sigma = sigma;
  w.side = static_cast<std::uint8_t>(mesh.sideOf(e, f));
  w.origin = origin;
  return w;
}

}  // namespace

// The wavefront queue's bucket width (bucket_queue.h), in median edge lengths: a window's
// children lie up to an edge beyond it, so with buckets of half an edge the order stays close
// enough to Dijkstra's that no more windows are made (measured: 0.1% more on bunny00, none on the
// icosphere), at O(1) per entry. The median, not the mean: a few 1e6-long edges must not make
// the buckets coarse for all the others.
constexpr double kQueueBucketEdges = 0.5;
// How far beyond a popped edge side's key its other pending windows are propagated with it
// (runBatch), in median edge lengths: a window's children lie up to an edge beyond it
// anyway. Measured on bunny00 / armadillo / fandisk: 0.1–0.4 % more windows than one by one at
// 0.5, 1 or unbounded, and the solve 8–20 % faster; unbounded was as fast, but would let a far
// window's descendants ride ahead of the front with every batch they share an edge with. With
// the rounds (finishRound), 2 made fewer and larger batches and 0.2–0.4 % fewer windows than 1:
// armadillo's solve 5 % faster on one thread and two, bunny00's 8 %, fandisk's 5 %, the
// icosphere's the same; 3 no faster than 2.
constexpr double kBatchSlackEdges = 2.0;

GeodesicSolver::GeodesicSolver(const Mesh& mesh) : mesh_(mesh) {
  std::vector<double> lengths(mesh_.numEdges());
  for (Index e = 0; e < mesh_.numEdges(); ++e) lengths[e] = mesh_.edge(e).length;
  double median = 1.0;
  if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    median = lengths[lengths.size() / 2];
  }
  const double width = kQueueBucketEdges * median;
  queueBucketWidth_ = width > 0.0 && std::isfinite(width) ? width : 1.0;
  batchSlack_ = queueBucketWidth_ * (kBatchSlackEdges / kQueueBucketEdges);
  // The windows on side s of edge e cross the face edge(e).face[1 − s].
  sides_.resize(2 * mesh_.numEdges());
  for (Index f = 0; f < mesh_.numFaces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const FaceFrame& fr = mesh_.frameByLocal(f, k);
      const auto side = static_cast<std::size_t>(1 - mesh_.sideOf(fr.edge, f));
      EdgeSide& es = sides_[2 * std::size_t{fr.edge} + side];
      es.childEdges = {fr.edgeToV0, fr.edgeToV2};
      es.frame = 3 * f + static_cast<Index>(k);
    }
  }
}

GeodesicSolver::~GeodesicSolver() = default;

void GeodesicSolver::reset() {
  edges_.clear();  // every list back to its pool, which then starts over
  pool_.recycle();
  helperPool_.recycle();
  for (Worker* w : {&solving_, &helping_}) {  // (as runBatch leaves them, also after a throw)
    for (Run& run : w->runs) run.clear();
    w->caseDegenerate.clear();
  }
  for (Batch& b : batches_) {  // (as finishBatch leaves them, also after a solve that threw)
    b.updates[0].incoming = b.updates[1].incoming = 0;
    b.relayApexes.clear();
    b.propagations.clear();
    b.counters = {};
    b.propagated = 0;
    b.frame = nullptr;
  }
  edges_.assign(mesh_.numEdges(), EdgeIntervals(&pool_));
  vertexDistance_.assign(mesh_.numVertices(), kInfinity);
  emitsWindows_.resize(mesh_.numVertices());
  for (Index v = 0; v < mesh_.numVertices(); ++v) emitsWindows_[v] = mesh_.isPseudoSourceVertex(v);
  for (EdgeSide& side : sides_) side.pendingKey = kInfinity;
  sources_.clear();
  queue_.reset(queueBucketWidth_, mesh_.numEdges());  // a ring of at most one bucket per edge
  counters_ = {};
  stats_ = {};
  releasing_ = false;
  releaseBroken_ = false;
}

// ===  Solve ======================================================================================
void GeodesicSolver::solve(std::span<const SurfacePoint> sources, const SolveOptions& options) {
  GEODEX_REQUIRE(!std::isnan(options.stopDistance), "stop distance is NaN");
  // Everything below is in mesh units (Mesh::unit(), a power of two: the division is exact).
  SolveOptions inMeshUnits;
  // A stop beyond the largest double in mesh units stops nothing (tested first: no overflow trap).
  const MeshUnit& unit = mesh_.meshUnit();
  inMeshUnits.stopDistance = inMeshUnitsRange(options.stopDistance, unit) == ScaledRange::Overflow
                                 ? kInfinity
                                 : options.stopDistance * unit.inverse;
  std::vector<ResolvedPoint> resolvedSources, targets;
  for (const SurfacePoint& p : sources) resolvedSources.push_back(resolve(mesh_, p));
  for (const SurfacePoint& p : options.targets) targets.push_back(resolve(mesh_, p));

  // Lists are released only where nothing will read them: not for targets (their distances are
  // read from the lists during the solve) nor for an observer that reads them.
  observerReadsLists_ = hooked() && observer_->readsIntervalLists();
  // The pairs, and so the results, are the same whether a batch's partner runs on the helper
  // thread or after it; an observer's events come from this thread either way (finishBatch).
  useHelper_ = options.threads >= 2;
  if (useHelper_ && helper_ == nullptr) helper_ = std::make_unique<detail::HelperThread>();
  const bool release = options.vertexDistancesOnly && targets.empty() && !observerReadsLists_;
  double radius = kInfinity;
  bool undone = false;
  for (bool releasing = release;; releasing = false) {
    reset();
    if (releasing) startReleasing();
    sources_ = resolvedSources;
    for (std::size_t i = 0; i < sources_.size(); ++i) seedSource(sources_[i], i);
    if (runWavefront(inMeshUnits, targets, radius)) break;
    undone = true;
  }
  stats_.releaseUndone = undone;
  finish(inMeshUnits, radius);
}

bool GeodesicSolver::runWavefront(const SolveOptions& inMeshUnits,
                                  std::span<const ResolvedPoint> targets, double& radius) {
  radius = kInfinity;
  std::uint64_t pops = 0;
  // The largest distance of the targets, looked at again every `targets.size()` pops (one target
  // a pop, amortized): a solve for a target near the source stops near it, not 256 pops later.
  double targetBound = kInfinity;
  const std::uint64_t targetBoundPeriod = std::max<std::uint64_t>(1, targets.size());
  std::uint64_t nextTargetBoundAt = 0;
  while (!queue_.empty()) {
    const QueueEntry top = queue_.front();  // a copy: pushes below may move the entry
    prefetchAhead();
    // No queued key is below `bound`: distances up to it are final.
    const double bound = queue_.lowerBound();
    if (bound > inMeshUnits.stopDistance) {
      radius = inMeshUnits.stopDistance;
      break;
    }
    if (!targets.empty()) {
      // Distances only decrease, so a bound computed earlier stays an upper bound.
      if (pops >= nextTargetBoundAt) {
        targetBound = targetsMaxDistance(targets);
        nextTargetBoundAt = pops + targetBoundPeriod;
      }
      if (bound >= targetBound) {
        radius = bound;
        break;
      }
    }
    queue_.pop();
    ++pops;
    if (releasing_) releasePassedEdges(bound);
    if (top.key > inMeshUnits.stopDistance) continue;  // beyond the stop, in the last bucket
    if (top.edge == kNoIndex) {  // a pseudo-source event; stale if the vertex improved since
      if (top.key == vertexDistance_[top.which]) {
        createPseudoSourceWindows(top.which, top.key, static_cast<std::int32_t>(top.which));
        if (releaseBroken_) return false;
      }
      continue;
    }
    // Stale: a smaller key was queued for the side since, or a round has run its batch (most of
    // them: 252,022 of the 284,314 entries popped on armadillo from v:0). prepareBatch would find
    // the same.
    if (top.key != pendingKey(top.edge, top.which)) continue;
    runRound(top, inMeshUnits.stopDistance);
    if (releaseBroken_) return false;
#if defined(GEODEX_FUZZING_BUILD_MODE)
    // The fuzzing switch: a wavefront that runs away on a fuzzer's mesh (≤ 64 faces) is reported
    // at once as a bug, not minutes later as a timeout.
    GEODEX_REQUIRE(stats_.intervalsPropagated <= fuzzingWorkLimit(),
                   "work limit of the fuzzing build: more than "
                       << fuzzingWorkLimit() << " windows propagated on " << mesh_.numFaces()
                       << " faces");
#endif
  }
  return true;
}

void GeodesicSolver::seedSource(const ResolvedPoint& p, std::size_t number) {
  const std::int32_t origin = sourceOrigin(number);
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      if (!mesh_.isReferenced(p.element)) {
        vertexDistance_[p.element] = 0.0;  // an isolated point: distance 0 to itself only
        return;
      }
      vertexDistance_[p.element] = 0.0;
      createPseudoSourceWindows(p.element, 0.0, origin);
      return;
    case SurfacePoint::Kind::Edge: {
      const Edge& E = mesh_.edge(p.element);
      // The edge itself: the source on its line (G1), whose rays into either face are exactly
      // the windows made below, so it is created already propagated.
      Interval own;
      own.b0 = 0.0;
      own.b1 = E.length;
      own.source = Vec2(p.t, 0.0);
      own.origin = origin;
      own.markPropagated();
      // The corners of its faces first, the ends and each face's apex: the windows below set
      // their distances too (to rounding).
      seedCorner(E.vertex[0], p.t);
      seedCorner(E.vertex[1], E.length - p.t);
      for (Index f : E.face) {
        if (f == kNoIndex) continue;
        const FaceFrame& fr = mesh_.frame(f, p.element);
        seedCorner(fr.apex, (fr.apexPos - Vec2(p.t, 0.0)).norm());
      }
      seedZeroAreaStrip(p.element, p.t);
      addInterval(p.element, own);
      for (Index f : E.face)
        if (f != kNoIndex) seedFaceFromPoint(f, p, p.element, 0.0, origin);
      return;
    }
    case SurfacePoint::Kind::Face: {
      const Index f = p.element;
      const Index e = mesh_.faceEdges(f)[0];
      const Vec2 q = pointInFaceFrame(mesh_, p, f, e);
      for (Index v : mesh_.face(f)) {  // the corners first: the windows below set them too
        const ResolvedPoint corner{SurfacePoint::Kind::Vertex, v, 0.0, {}, mesh_.position(v)};
        seedCorner(v, (pointInFaceFrame(mesh_, corner, f, e) - q).norm());
      }
      seedFaceFromPoint(f, p, kNoIndex, 0.0, origin);
      return;
    }
  }
}

// The zero-area faces along edge e's line next to an edge source at t on it (across e, then across
// their own edges, as long as each next face lies on the line too): their corners lie on the line,
// the path to each along it is straight, so each is a corner of the source at that distance. A
// vertex of such a face a hair from the source has no fan otherwise: the source's rays into the
// faces beyond reach it only at grazing angles, and the patch beyond it was reached the long way
// round (corpus/fuzz_solver/regress/vertex-agreement-edge-source-3e-11-from-a-vertex-on-a-zero-
// area-face-beside-its-own; the apexes of e's own faces are corners already).
void GeodesicSolver::seedZeroAreaStrip(Index e, double t) {
  const Edge& E = mesh_.edge(e);
  const Vec3 a = mesh_.positionInMeshUnits(E.vertex[0]);
  const Vec3 dir = (mesh_.positionInMeshUnits(E.vertex[1]) - a) / E.length;
  const Vec3 source = a + t * dir;
  const auto onLine = [&](Index v) {
    const Vec3 r = mesh_.positionInMeshUnits(v) - a;
    return r.cross(dir).norm() <= tol::kVertexOnEdgeRel * std::max(E.length, r.norm());
  };
  std::array<Index, kMaxVertexOnEdgeDepth + 2> strip{};
  std::size_t count = 0;
  for (Index f : E.face)
    if (f != kNoIndex && count < strip.size() && onLine(mesh_.frame(f, e).apex)) strip[count++] = f;
  const auto ownCorner = [&](Index v) {  // seeded already, in the edge's frames
    for (Index f : E.face) {
      if (f == kNoIndex) continue;
      const auto& c = mesh_.face(f);
      if (std::find(c.begin(), c.end(), v) != c.end()) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < count; ++i) {
    const Index f = strip[i];
    for (Index v : mesh_.face(f))
      if (!ownCorner(v)) seedCorner(v, (mesh_.positionInMeshUnits(v) - source).norm());
    for (Index side : mesh_.faceEdges(f)) {
      const Edge& S = mesh_.edge(side);
      // Only across an edge the source's point lies on: a path into the next face that went
      // along the line to a shorter edge first would turn back, longer than the straight line.
      const double u0 = (mesh_.positionInMeshUnits(S.vertex[0]) - a).dot(dir);
      const double u1 = (mesh_.positionInMeshUnits(S.vertex[1]) - a).dot(dir);
      const double slack = tol::kVertexOnEdgeRel * std::max(E.length, std::abs(t));
      if (t < std::min(u0, u1) - slack || t > std::max(u0, u1) + slack) continue;
      const Index g = S.face[0] == f ? S.face[1] : S.face[0];
      if (g == kNoIndex ||
          std::find(strip.begin(), strip.begin() + count, g) != strip.begin() + count)
        continue;
      if (count < strip.size() && onLine(mesh_.frame(g, side).apex)) strip[count++] = g;
    }
  }
}

// Windows on the edges of face f (but `skip`) from the point p of f (inside it or on its boundary),
// at distance sigma from the source `origin` stands for.
void GeodesicSolver::seedFaceFromPoint(Index f, const ResolvedPoint& p, Index skip, double sigma,
                                       std::int32_t origin) {
  for (Index e : mesh_.faceEdges(f)) {
    if (e == skip) continue;
    Interval w = windowFromPoint(mesh_, f, e, p, sigma, origin);
    if (mesh_.edge(e).face[1 - w.side] == kNoIndex) w.markPropagated();
    addInterval(e, w);
  }
}

// A corner of a source's face (for an edge source, of either face of its edge) at distance d,
// straight inside the face: that is its distance (no path is shorter than the segment), and it
// becomes a pseudo-source now.
// Its windows are real paths (source → corner → point), so they never undercut a distance; what
// they add is the fan of directions at the corner, where a source a hair from the corner has its
// rays' directions only to rounding / distance — 1e-7 rad for a source 4e-10 of an edge from it,
// so decisions at kCollinearSin and crossings at grazing angles went wrong and left edges at that
// corner uncovered (corpus/fuzz_solver/regress: seven findings of a source just outside the
// snapping band, tol::kSnapParam).
void GeodesicSolver::seedCorner(Index v, double d) {
  if (d > vertexDistance_[v]) return;  // another source is nearer
  vertexDistance_[v] = d;
  createPseudoSourceWindows(v, d, static_cast<std::int32_t>(v));
}

// A saddle, boundary or source vertex v at distance sigma becomes a pseudo-source: every edge
// opposite v in a face around v gets a whole-edge window from v (Fig. 3c's additional intervals,
// for all faces at once), and every edge incident to v one from v on its own line (G1; already
// propagated, since its rays into either face are the opposite-edge windows).
void GeodesicSolver::createPseudoSourceWindows(Index v, double sigma, std::int32_t origin,
                                               int depth, Index from) {
  ++stats_.pseudoSourceEvents;
  // The faces, frames and edges below are rarely in cache (a vertex is reached once or twice):
  // asked for at once, their misses overlap instead of following one another.
  for (Index f : mesh_.vertexFaces(v)) {
    __builtin_prefetch(&mesh_.face(f));
    __builtin_prefetch(&mesh_.frameByLocal(f, 0));
    __builtin_prefetch(&mesh_.frameByLocal(f, 2));
  }
  for (Index e : mesh_.vertexEdges(v)) {
    __builtin_prefetch(&mesh_.edge(e));
    __builtin_prefetch(&edges_[e]);
  }
  for (Index f : mesh_.vertexFaces(v)) {
    const auto& corners = mesh_.face(f);
    const int k = corners[0] == v ? 0 : (corners[1] == v ? 1 : 2);
    const FaceFrame& fr = mesh_.frameByLocal(f, (k + 1) % 3);
    Interval w;
    w.b0 = 0.0;
    w.b1 = mesh_.edge(fr.edge).length;
    w.source = fr.apexPos;
    w.sigma = sigma;
    w.side = static_cast<std::uint8_t>(mesh_.sideOf(fr.edge, f));
    w.origin = origin;
    if (mesh_.edge(fr.edge).face[1 - w.side] == kNoIndex) w.markPropagated();
    if (!dominatedAtAnEdgeEnd(fr.edge, w)) addInterval(fr.edge, w);
    seedAcrossVertexOnEdge(v, f, fr, sigma, origin, depth, from);
  }
  for (Index e : mesh_.vertexEdges(v)) {
    const Edge& E = mesh_.edge(e);
    Interval w;
    w.b0 = 0.0;
    w.b1 = E.length;
    w.source = Vec2(E.vertex[0] == v ? 0.0 : E.length, 0.0);
    w.sigma = sigma;
    w.origin = origin;
    w.markPropagated();
    if (!dominatedAlongItsEdge(e, w, v)) addInterval(e, w);
  }
}

// v lies on the edge opposite it in face f (a zero-area face, or one so thin that v's window on
// that edge is a D1 sliver): v is a point of that edge, and its fan into the face across the
// edge (Fig. 3c's additional intervals, for a face v touches geometrically but not in the mesh's
// connectivity) is seeded now, as for an edge-point source. Left to v's window on the edge, it
// was lost: the direct windows through f tie with it at v and are shorter everywhere else, so
// Algorithm 2 cut it to nothing before it was propagated, and the shadow of v across the edge was
// reached the long way round (31 fuzz_solver findings, corpus/fuzz_solver/regress/*zero-area*).
void GeodesicSolver::seedAcrossVertexOnEdge(Index v, Index f, const FaceFrame& fr, double sigma,
                                            std::int32_t origin, int depth, Index from) {
  const Edge& E = mesh_.edge(fr.edge);
  const double scale = std::max(E.length, fr.apexPos.norm());
  if (!(fr.apexPos.y() <= tol::kVertexOnEdgeRel * scale)) return;
  if (!(fr.apexPos.x() > 0.0 && fr.apexPos.x() < E.length)) return;
  seedAcrossPointOnEdge(v, fr.edge, f, fr.apexPos.x(), sigma + fr.apexPos.y(), origin, depth, from);
}

// The point at x along edge e (from its vertex[0]), where the saddle v lies, at distance `at`:
// its fan into the face g across e from f. When g is zero-area too, the point lies on another of
// g's edges and the fan goes on across that one (a stack of zero-area faces along one line has
// no inside to spread in: corpus/fuzz_solver/regress/edge-query-saddle-on-a-stack-of-zero-area-
// faces); when g's apex u is the point itself, u becomes a pseudo-source at the same distance
// (its own angle sum may well read 2π), even where the direct windows have set its distance
// already (to rounding), but not back to where this came from.
void GeodesicSolver::seedAcrossPointOnEdge(Index v, Index e, Index f, double x, double at,
                                           std::int32_t origin, int depth, Index from) {
  const Edge& E = mesh_.edge(e);
  const Index g = E.face[0] == f ? E.face[1] : E.face[0];
  if (g == kNoIndex || g == f) return;
  const FaceFrame& gf = mesh_.frame(g, e);
  const double gScale = std::max(E.length, gf.apexPos.norm());
  if (gf.apexPos.y() <= tol::kVertexOnEdgeRel * gScale) {
    if (depth >= kMaxVertexOnEdgeDepth) return;
    if (std::abs(gf.apexPos.x() - x) <= tol::kCoincideRel * gScale) {
      const Index u = gf.apex;
      if (u != v && u != from && at <= vertexDistance_[u] + tol::kTieRel * at) {
        vertexDistance_[u] = std::min(vertexDistance_[u], at);
        createPseudoSourceWindows(u, at, origin, depth + 1, v);
      }
      return;
    }
    // On the line of g the point lies between v0 and the apex or between the apex and v2.
    const bool onE1 = x < gf.apexPos.x();
    const Index next = onE1 ? gf.edgeToV0 : gf.edgeToV2;
    const Index start = onE1 ? E.vertex[0] : gf.apex;  // the end of `next` the point is measured from
    const double along = onE1 ? x : x - gf.apexPos.x();
    const Edge& N = mesh_.edge(next);
    const double nx = N.vertex[0] == start ? along : N.length - along;
    if (!(nx > 0.0 && nx < N.length)) return;
    seedAcrossPointOnEdge(v, next, g, nx, at, origin, depth + 1, from);
    return;
  }
  const ResolvedPoint p{SurfacePoint::Kind::Edge, e, x, {}, mesh_.position(v)};
  seedFaceFromPoint(g, p, e, at, origin);
}

// ===  One propagation case =======================================================================
// Its children are not added to their edges here: they join the runs runBatch adds to
// each child edge once the batch is done.
void GeodesicSolver::propagate(Batch& b, Worker& worker, Index edge, const Interval& w, Index f,
                               const FaceFrame& fr) {
  const Edge& E = mesh_.edge(edge);
  ++b.propagated;

  const LocalWindow local{E.length, fr.apexPos, w.b0, w.b1, Vec2(w.source.x(), -w.source.y())};
  const LocalPropagation result = propagateLocal(local);
  ++b.counters.cases;
  const auto kind = degeneracyOf(result.branch);
  if (kind) ++b.counters[*kind];
  if (result.branch == Fig6Branch::ZeroAreaFace) ++b.counters.zeroAreaFaces;
  if (result.branch == Fig6Branch::G1Outside) ++b.counters.sourceOnEdgeLineOutside;

  const bool oneLine = childEdgesOnOneLine(local);
  // Each child goes straight into its edge's run (runBatch); an observer is shown them too.
  const auto caseInBatch = static_cast<std::uint32_t>(worker.caseDegenerate.size());
  worker.caseDegenerate.push_back(kind.has_value());
  // (What an observer is shown of this case, in finishBatch: on the solve's own thread.)
  Batch::Propagation* shown = nullptr;
  if (hooked()) shown = &b.propagations.emplace_back(Batch::Propagation{f, edge, w, local, result});
  for (int c = 0; c < result.numChildren; ++c) {
    const LocalChild& child = result.children[c];
    const bool onE1 = child.edge == 1;
    const Index ce = onE1 ? fr.edgeToV0 : fr.edgeToV2;
    const Edge& CE = mesh_.edge(ce);
    const Index start = onE1 ? E.vertex[0] : fr.apex;  // where the directed segment e1 or e2 starts
    const ChildInterval made = childInterval(local, child, {CE.length, CE.vertex[0] == start}, oneLine);
    if (made.outcome == ChildOutcome::SeenFromOutside) ++b.counters.childEdgesSeenFromOutside;
    if (made.outcome != ChildOutcome::Made) continue;
    Run& run = worker.runs[onE1 ? 0 : 1];
    Interval& n = run.incoming.emplace_back(made.interval);
    n.sigma = w.sigma;
    n.side = static_cast<std::uint8_t>(mesh_.sideOf(ce, f));
    n.origin = w.origin;
    if (CE.face[1 - n.side] == kNoIndex) n.markPropagated();
    run.cases.push_back(caseInBatch);
    if (hooked()) {
      run.branches.push_back(result.branch);
      shown->children[shown->numChildren++] = {ce, n};
    }
  }
  // In G2–G5 a window's edge ray runs through the apex, and the far edge's side next to the apex
  // is left to the neighbouring window, which can fan away from this ray there: two sources'
  // boundary, exact on a line through the apex, moved 5e-12 off it when step 3 gave a D1 sliver
  // to the coarser neighbour, and a wedge 2e-11 wide behind the apex was reached by neither
  // (SolverRegression.TwoSourcesMeetingOnARayThroughAFaceApexLeaveNoWedgeBehindIt, G2); an edge
  // source on a line through two vertices lost the fan beyond them the same way
  // (SolverRegression.AnEdgeSourceOnALineThroughTwoVerticesReachesBeyondThem, G4/G5). The apex
  // relays the fan: a path along the ray and on from the apex is a real path (finishBatch).
  if (result.branch == Fig6Branch::G2 || result.branch == Fig6Branch::G3 ||
      result.branch == Fig6Branch::G4 || result.branch == Fig6Branch::G5) [[unlikely]]
    b.relayApexes.push_back(fr.apex);
}

// ===  Batches ====================================================================================
// The windows on one side of an edge are propagated together, as VTP (Qin et al. 2016) propagates
// an edge's window list across its face: all of them whose smallest distance is at most `upTo`
// (kBatchSlackEdges beyond the entry's key), in the list's order. One queue entry per edge side
// then stands for all its pending windows, and none has to be looked for in its list when popped.
// Their children go to the face's other two edges, never to this one, so the list stays as it is
// while they are made; each child edge gets its children as one run: steps 1 and 2 for each in
// turn, steps 3–5 once (EdgeIntervals::insertRun). 83 % of bunny00's updates were a later child
// of the same batch on the same edge, and one update per child cost 8–14 % more of the solve on
// the real meshes (docs/benchmarks.md). The entry is stale when a smaller key was queued for the
// side since, or another entry's batch has run.
void GeodesicSolver::prepareBatch(Batch& b, const QueueEntry& entry, double stopDistance) const {
  b.entry = entry;
  b.done.store(false, std::memory_order_relaxed);  // (published by the round's post)
  b.failed = false;
  b.upTo = std::min(entry.key + batchSlack_, stopDistance);
  b.live = entry.key == sides_[2 * std::size_t{entry.edge} + entry.which].pendingKey;
  const Index frame = sides_[2 * std::size_t{entry.edge} + entry.which].frame;
  b.face = frame == kNoIndex ? kNoIndex : frame / 3;
  b.frame = b.live && frame != kNoIndex ? &mesh_.frameByLocal(b.face, static_cast<int>(frame % 3))
                                        : nullptr;
  if (b.frame != nullptr) {
    // What finishBatch reads on this thread after the batch has run: the child edges' keys
    // (afterUpdate waited on them for a third of its time) and the apex's distance.
    __builtin_prefetch(&sides_[2 * std::size_t{b.frame->edgeToV0}]);
    __builtin_prefetch(&sides_[2 * std::size_t{b.frame->edgeToV2}]);
    __builtin_prefetch(&vertexDistance_[b.frame->apex]);
  }
}

void GeodesicSolver::runBatch(Batch& b, Worker& worker) {
  if (!b.live) return;
  const Index edge = b.entry.edge;
  const auto side = static_cast<std::uint8_t>(b.entry.which);
  double& sideKey = pendingKey(edge, side);
  const Index f = b.face;
  b.rest = kInfinity;
  if (f == kNoIndex) {  // a boundary: nothing to cross (Algorithm 2 may have re-opened a window)
    for (Interval& w : edges_[edge].intervals())
      if (w.side == side) w.markPropagated();
    sideKey = kInfinity;
    return;
  }
  const FaceFrame& fr = *b.frame;
  // The children go to the face's other two edges: their lists are wanted soon.
  __builtin_prefetch(&edges_[fr.edgeToV0]);
  __builtin_prefetch(&edges_[fr.edgeToV2]);
  for (std::size_t i = 0; i < edges_[edge].intervals().size(); ++i) {
    Interval& w = edges_[edge].intervals()[i];
    if (!w.pending() || w.side != side) continue;
    const double key = w.minDistance();
    if (key > b.upTo) {
      b.rest = std::min(b.rest, key);
      continue;
    }
    w.markPropagated();
    const Interval window = w;
    propagate(b, worker, edge, window, f, fr);
  }
  sideKey = b.rest;
  for (int k = 0; k < 2; ++k) {
    Run& run = worker.runs[k];
    ChildEdgeUpdate& u = b.updates[k];
    u.incoming = run.incoming.size();
    if (u.incoming == 0) continue;
    const Index ce = k == 0 ? fr.edgeToV0 : fr.edgeToV2;
    // A released list is not updated: finishBatch has the solve done again keeping every list.
    // (releaseState_ changes only between batches.)
    u.updated = !(releasing_ && releaseState_[ce] == kReleased);
    if (!u.updated) [[unlikely]] {
      run.clear();
      continue;
    }
    EdgeIntervals& list = edges_[ce];
    // The list before the update is copied only for an observer that reads it: the copy cost the
    // CLI's progress line 8 % of bunny00's solve at a terminal.
    if (observerReadsLists_)
      b.shown[k].before.assign(list.intervals().begin(), list.intervals().end());
    list.usePool(worker.pool);
    EdgeUpdateReport& report = worker.report;
    list.insertRun(run.incoming, mesh_.edge(ce).length, report, worker.scratch, worker.work);
    u.first = report.first;
    u.last = report.last;
    u.fanLostAtVertex = report.fanLostAtVertex;
    u.reach = 0.0;
    if (releasing_)
      for (const Interval& w : run.incoming) u.reach = std::max(u.reach, releaseReach(w));
    countRepairs(b.counters, report);
    if (report.degeneracies.discontinuityTotal() > 0) {
      forEachRepairedIncoming(report, run.incoming,
                              [&](std::size_t i) { worker.caseDegenerate[run.cases[i]] = 1; });
    }
    if (hooked()) {
      b.shown[k].incoming.assign(run.incoming.begin(), run.incoming.end());
      b.shown[k].branches.assign(run.branches.begin(), run.branches.end());
      b.shown[k].report = report;
    }
    run.clear();
  }
  for (const std::uint8_t degenerate : worker.caseDegenerate)
    b.counters.degenerateCases += degenerate;
  worker.caseDegenerate.clear();
}

// What the batch's updates mean, in the order it made them: its counts, the apexes that relay a
// fan (G2–G5, propagate), each child edge's update (afterUpdate) and the side queued again for
// its windows left pending. (A case is degenerate when its Fig. 6 leaf is G1–G5 or the update
// repaired a D1–D4 at one of its children, forEachRepairedIncoming in runBatch: where its own
// update would have, had each child been one, not wherever in its batch's run.)
void GeodesicSolver::finishBatch(Batch& b) {
  if (!b.live) return;
  stats_.intervalsPropagated += b.propagated;
  counters_ += b.counters;
  if (hooked()) {
    for (const Batch::Propagation& p : b.propagations) {
      observer_->onPropagation({p.face, p.edge, p.window, p.local, p.result,
                                std::span<const MadeChild>(p.children.data(), p.numChildren)});
    }
    b.propagations.clear();
  }
  for (const Index apex : b.relayApexes) relayFanThroughVertex(apex, counters_.apexFansRelayed);
  for (int k = 0; k < 2 && b.frame != nullptr; ++k) {
    ChildEdgeUpdate& u = b.updates[k];
    if (u.incoming == 0) continue;
    const Index ce = k == 0 ? b.frame->edgeToV0 : b.frame->edgeToV2;
    if (!u.updated) [[unlikely]] {
      releaseBroken_ = true;  // the solve starts again keeping every list
      continue;
    }
    if (releasing_) fileForRelease(ce, u.reach);
    stats_.intervalsCreated += u.incoming;
    afterUpdate(ce, u.first, u.last, u.fanLostAtVertex);
    if (hooked()) {
      const Batch::Shown& shown = b.shown[k];
      const std::span<const Interval> before = observerReadsLists_
                                                   ? std::span<const Interval>(shown.before)
                                                   : std::span<const Interval>();
      observer_->onEdgeUpdate({ce, mesh_.edge(ce).length, before, shown.incoming,
                               edges_[ce].intervals(), shown.report, shown.branches});
    }
  }
  if (b.rest < kInfinity) queue_.push(QueueEntry::edgeSide(b.entry.edge, b.entry.which, b.rest));
  b.updates[0].incoming = b.updates[1].incoming = 0;
  b.relayApexes.clear();
  b.counters = {};
  b.propagated = 0;
  b.frame = nullptr;
}

// How far behind the queue's front runRound looks for batches to run beside the front's.
constexpr std::uint32_t kRoundLookahead = 64;

// A round: the batch of `top`, just taken from the queue, and up to kRoundBatches − 1 more of the
// entries behind it (in its bucket's page) that are live edge sides within the stop and share no
// edge, crossed or child, with any batch of the round before them. Batches with no edge in common
// read and write nothing the others do (runBatch), so they run in any order or at once: each
// thread of the solve takes the round's batches one at a time until none is left
// (claimBatches, finishRound), and this one finishes them in the round's order. The entries of the
// later batches stay in the queue and are stale once they have run (their sides' keys are then
// beyond them). That changes the wavefront's order, not its result: Algorithm 2 keeps the pointwise
// minimum of every window an edge receives, in whatever order, and a vertex reached again at a
// smaller distance emits its windows again. The rounds are the same whatever the threads.
void GeodesicSolver::runRound(const QueueEntry& top, double stopDistance) {
  prepareBatch(batches_[0], top, stopDistance);
  roundSize_ = 1;
  if (batches_[0].frame != nullptr) {
    const FaceFrame& fr = *batches_[0].frame;
    std::array<Index, 3 * kRoundBatches> taken{top.edge, fr.edgeToV0, fr.edgeToV2};
    std::size_t numTaken = 3;
    for (std::uint32_t k = 0; k < kRoundLookahead && roundSize_ < kRoundBatches; ++k) {
      const QueueEntry* e = queue_.peek(k);
      if (e == nullptr) break;
      if (e->edge == kNoIndex || e->key > stopDistance) continue;
      const EdgeSide& side = sides_[2 * std::size_t{e->edge} + e->which];
      if (e->key != side.pendingKey || side.childEdges[0] == kNoIndex) continue;
      const std::array<Index, 3> edges{e->edge, side.childEdges[0], side.childEdges[1]};
      const auto end = taken.begin() + static_cast<std::ptrdiff_t>(numTaken);
      if (std::find_first_of(taken.begin(), end, edges.begin(), edges.end()) != end) continue;
      prepareBatch(batches_[roundSize_++], *e, stopDistance);
      for (const Index x : edges) taken[numTaken++] = x;
    }
  }
  stats_.batchesBesideTheFront += roundSize_ - 1;
  roundNext_.store(0, std::memory_order_relaxed);
  const bool helped = useHelper_ && roundSize_ > 1;
  if (helped) helper_->post(&claimBatchesOnTheHelper, this);
  try {
    finishRound();
  } catch (...) {
    if (helped) {
      try {
        helper_->finish();  // its batches work on the solver too: done before this unwinds
      } catch (...) {       // (this thread's error is the one reported)
      }
    }
    throw;
  }
  if (helped) helper_->finish();  // (rethrows the error of a batch it ran)
}

// This thread's share of the round: it takes the round's batches one at a time, as the helper
// does, and finishes them in the round's order, each as soon as it and those before it have run.
// finishBatch writes nothing a batch of the round reads or writes (the queue, the vertices, the
// counts, the release bookkeeping and its own child edges' flags: no edge is shared), so this
// thread finishes its batches while the helper still runs a later one, instead of waiting for it
// first. An observer's events wait for the whole round: an observer may read the solver.
void GeodesicSolver::finishRound() {
  std::size_t finished = 0;
  const auto finishThoseRun = [&] {
    for (; finished < roundSize_; ++finished) {
      Batch& b = batches_[finished];
      if (!b.done.load(std::memory_order_acquire) || b.failed) return;
      finishBatch(b);
    }
  };
  for (;;) {
    if (!hooked()) finishThoseRun();
    const std::size_t i = roundNext_.fetch_add(1, std::memory_order_relaxed);
    if (i >= roundSize_) break;
    runClaimedBatch(batches_[i], solving_);
  }
  for (std::size_t i = finished; i < roundSize_; ++i) {
    detail::awaitSet(batches_[i].done);
    if (batches_[i].failed) return;  // the helper's error: helper_->finish() rethrows it
  }
  finishThoseRun();
}

// Runs the round's batches not yet taken, one at a time, with `worker`: this thread's pool and
// buffers.
void GeodesicSolver::claimBatches(Worker& worker) {
  for (;;) {
    const std::size_t i = roundNext_.fetch_add(1, std::memory_order_relaxed);
    if (i >= roundSize_) return;
    runClaimedBatch(batches_[i], worker);
  }
}

// Runs batch b and tells the round it has: done, and failed when it threw.
void GeodesicSolver::runClaimedBatch(Batch& b, Worker& worker) {
  try {
    runBatch(b, worker);
  } catch (...) {
    b.failed = true;
    b.done.store(true, std::memory_order_release);
    throw;
  }
  b.done.store(true, std::memory_order_release);
}

void GeodesicSolver::claimBatchesOnTheHelper(void* solver) {
  auto* s = static_cast<GeodesicSolver*>(solver);
  s->claimBatches(s->helping_);
}

// A window is pending on its edge side: the side is queued again when the window's smallest
// distance is below every key queued for it.
void GeodesicSolver::queuePending(Index edge, const Interval& w) {
  const double key = w.minDistance();
  double& sideKey = pendingKey(edge, w.side);
  if (!(key < sideKey)) return;
  sideKey = key;
  queue_.push(QueueEntry::edgeSide(edge, w.side, key));
}

// The entries a few places behind the queue's front will want their edge's interval list and
// edge record: asking for them now hides most of a memory access per batch. Two stages: the
// list's header for the entry further ahead, the start of the list's data for the nearer one, and
// with it the face the batch crosses (its edges, which frame() searches, and its frames): that
// search waited on memory for 1.6 % of bunny00's solve, 0.2 % with it.
void GeodesicSolver::prefetchAhead() const {
  if (const QueueEntry* far = queue_.peek(8); far != nullptr && far->edge != kNoIndex) {
    __builtin_prefetch(&edges_[far->edge]);
    __builtin_prefetch(&mesh_.edge(far->edge));
  }
  if (const QueueEntry* near = queue_.peek(4); near != nullptr && near->edge != kNoIndex) {
    const std::span<const Interval> list = edges_[near->edge].intervals();
    if (!list.empty()) __builtin_prefetch(list.data());
    const Index f = mesh_.edge(near->edge).face[1 - near->which];
    if (f != kNoIndex) {
      __builtin_prefetch(&mesh_.faceEdges(f));
      __builtin_prefetch(&mesh_.frameByLocal(f, 0));
    }
  }
}

// ===  Releasing the lists the wavefront has left behind ==========================================
// For a solve asked for vertex distances only. Measured from vertex 0, the edges that still hold a
// pending window or are within two batch slacks of the queue's front carry at their most 6–8 %
// of all intervals on bunny00, armadillo and the icosphere (docs/benchmarks.md, "Releasing the
// lists the wavefront has left behind"): the rest is the wake, which no update reaches again but
// the lists kept. Exactness does not rest on that: an edge is released only with nothing pending on
// it, and a window that reaches a released edge after all (a vertex relaying its fan long after
// it was reached, a window re-propagated behind the front) makes the solve start again keeping
// every list. A solve that completes released only lists no update read or wrote afterwards, so
// its vertex distances are those of the solve that keeps them, to the bit.

// How far behind the queue's lower bound an edge's reach must be before its list goes, in median
// edge lengths: two batch slacks. (Of the 157 libcgal-demo and regression meshes from vertex 0,
// three start again at that distance: couplingdown, pinion and pinion_small.)
constexpr double kReleaseSlackEdges = 4.0;

void GeodesicSolver::startReleasing() {
  releasing_ = true;
  releaseState_.assign(mesh_.numEdges(), 0);
  releaseBuckets_.clear();
  nextReleaseBucket_ = 0;
}

// w arrives on `edge`: the edge waits in the bucket of w's reach (its distance at b0 plus its
// length bounds its distance on [b0, b1]: it grows at slope at most 1), unless it waits in a later
// one already. A reach not yet passed is all this has to get right to save memory; exactness
// does not depend on it.
void GeodesicSolver::fileForRelease(Index edge, double reach) {
  std::uint32_t& state = releaseState_[edge];
  if (state == kKept) return;
  if (state != 0 && reach < static_cast<double>(state)) return;  // waits in a later bucket
  fileInBucket(edge, reach);
}

// How far w reaches, in bucket widths. (A run's windows file their edge once, at the largest:
// the bucket the edge ends in is the same as when each files it in turn.)
double GeodesicSolver::releaseReach(const Interval& w) const {
  return (w.distanceAt(w.b0) + w.length()) / queueBucketWidth_;
}

// Files `edge` in the bucket of `reach` (in bucket widths) or, when the wavefront's release has
// passed that one, in the next it will look at. At most four buckets an edge (the queue's ring
// has one): an edge reaching beyond is kept rather than the bucket array grown for a few far
// windows.
void GeodesicSolver::fileInBucket(Index edge, double reach) {
  std::uint32_t& state = releaseState_[edge];
  const double buckets = 4.0 * static_cast<double>(mesh_.numEdges()) + 64.0;
  if (!(reach < buckets)) {
    state = kKept;
    return;
  }
  const std::size_t k = std::max(static_cast<std::size_t>(reach), nextReleaseBucket_);
  state = static_cast<std::uint32_t>(k + 1);
  if (k >= releaseBuckets_.size()) releaseBuckets_.resize(k + 1);
  releaseBuckets_[k].push_back(edge);
}

// Releases the lists of the edges filed in buckets the wavefront has passed by the slack, those
// with a pending window excepted (filed again where the wavefront is now).
void GeodesicSolver::releasePassedEdges(double bound) {
  if (!(bound < kInfinity)) return;
  const double slack = queueBucketWidth_ * (kReleaseSlackEdges / kQueueBucketEdges);
  while (nextReleaseBucket_ < releaseBuckets_.size() &&
         static_cast<double>(nextReleaseBucket_ + 1) * queueBucketWidth_ + slack <= bound) {
    std::vector<Index> edges;
    edges.swap(releaseBuckets_[nextReleaseBucket_]);  // (its memory goes with it)
    const std::size_t k = nextReleaseBucket_++;
    for (const Index e : edges) {
      std::uint32_t& state = releaseState_[e];
      if (state != k + 1) continue;  // filed again later, released or kept
      if (pendingKey(e, 0) != kInfinity || pendingKey(e, 1) != kInfinity) {
        fileInBucket(e, bound / queueBucketWidth_);  // to be looked at again from here
        continue;
      }
      edges_[e].clearAndRelease();
      state = kReleased;
      ++stats_.edgesReleased;
    }
  }
}

void GeodesicSolver::requireAllLists(const char* what) const {
  GEODEX_REQUIRE(stats_.edgesReleased == 0,
                 what << " needs the interval lists, which the last solve "
                         "released (SolveOptions::vertexDistancesOnly)");
}

std::span<const EdgeIntervals> GeodesicSolver::edgeIntervals() const {
  requireAllLists("edgeIntervals()");
  return edges_;
}

// ===  Edge updates and vertex distances ==========================================================
void GeodesicSolver::addInterval(Index edge, const Interval& w) {
  if (releasing_) {
    if (releaseState_[edge] == kReleased) [[unlikely]] {
      releaseBroken_ = true;  // the solve starts again keeping every list
      return;
    }
    fileForRelease(edge, releaseReach(w));
  }
  ++stats_.intervalsCreated;
  const double length = mesh_.edge(edge).length;
  EdgeIntervals& list = edges_[edge];
  // The list before the update is copied only for an observer that reads it: the copy cost the
  // CLI's progress line 8 % of bunny00's solve at a terminal.
  if (observerReadsLists_) before_.assign(list.intervals().begin(), list.intervals().end());
  list.insert(w, length, report_, scratch_);
  countRepairs(counters_, report_);
  afterUpdate(edge, report_.first, report_.last, report_.fanLostAtVertex);
  if (hooked()) {
    const std::span<const Interval> before =
        observerReadsLists_ ? std::span<const Interval>(before_) : std::span<const Interval>();
    observer_->onEdgeUpdate({edge, length, before, {&w, 1}, list.intervals(), report_, {}});
  }
}

// The repairs an update of an edge made, into `counters`.
void GeodesicSolver::countRepairs(DegeneracyCounters& counters, const EdgeUpdateReport& report) {
  for (DegeneracyKind k :
       {DegeneracyKind::D1, DegeneracyKind::D2, DegeneracyKind::D3, DegeneracyKind::D4})
    counters[k] += report.degeneracies[k];  // (Algorithm 2 finds only these)
  counters.tieStripsKept += report.degeneracies.tieStripsKept;
}

// What an update of `edge` that rewrote its list's [first, last) means for the queue and the
// vertices (EdgeUpdateReport's fields of the same names).
void GeodesicSolver::afterUpdate(Index edge, std::size_t first, std::size_t last,
                                 std::uint8_t fanLostAtVertex) {
  const double length = mesh_.edge(edge).length;
  EdgeIntervals& list = edges_[edge];

  // Every pending interval that is new or whose smallest distance moved may lower its edge
  // side's key; the others keep theirs, which the side's key is no larger than.
  const std::span<Interval> all = list.intervals();
  for (std::size_t i = first; i < last; ++i) {
    Interval& iv = all[i];
    if (!(iv.flags & Interval::kChanged)) continue;
    iv.flags &= static_cast<std::uint8_t>(~Interval::kChanged);
    if (iv.pending()) queuePending(edge, iv);
  }
  // The edge's ends update their vertices' distances, when the update rewrote them (an interval
  // left as it was gave its value there before).
  const auto intervals = list.intervals();
  if (!intervals.empty()) {
    const Edge& E = mesh_.edge(edge);
    if (fanLostAtVertex != 0) [[unlikely]] {
      for (int k = 0; k < 2; ++k)
        if (fanLostAtVertex & (1 << k)) relayFanThroughVertex(E.vertex[k], counters_.d1FansRelayed);
    }
    if (first == 0 && intervals.front().b0 == 0.0)
      updateVertex(E.vertex[0], intervals.front().distanceAt(0.0));
    if (last == intervals.size() && intervals.back().b1 == length)
      updateVertex(E.vertex[1], intervals.back().distanceAt(length));
  }
}

// The edge-end rule (Xin and Wang 2009's filter; VTP's check with vertices): with an end a of w's
// edge at distance d(a), the path through a and then along the edge is d(a) + |a x| at x. Its
// difference from w's σ + |s x| shrinks away from a (|s x| grows at slope at most 1), so where
// the path through a is shorter at w's far end from a, it is shorter on all of w; and at a point
// q beyond, reached by w's straight ray through x, σ + |s x| + |x q| > d(a) + |a x| + |x q|, the
// length of a real path. w is then nowhere the shortest, on its edge or beyond: it is dropped
// whole, never trimmed, before Algorithm 2 sees it. d(a) is the smallest value a's edges gave at
// a, which may lie below a real path by vertexAgreementTolerance (the rounding along a's longest
// edge: 1.2e-10 on a 1e6-long one, which made the trimming filter removed in 93bcc7e cut windows
// that were needed); only a path shorter by more than that counts. Applied to a pseudo-source's
// windows on the edges across its faces: on bunny00 from v:0, 68,858 of them, which Algorithm 2
// compared with a dozen intervals each to keep none (4 % of the solve's instructions).
bool GeodesicSolver::dominatedAtAnEdgeEnd(Index edge, const Interval& w) {
  const Edge& E = mesh_.edge(edge);
  for (int k = 0; k < 2; ++k) {
    const Index a = E.vertex[k];
    const double viaEnd = vertexDistance_[a] + (k == 0 ? w.b1 : E.length - w.b0);
    const double own = w.distanceAt(k == 0 ? w.b1 : w.b0);
    if (!(viaEnd < own)) continue;
    if (!(viaEnd < own - tol::vertexAgreementTolerance(own, E.length, mesh_.longestEdgeAt(a))))
      continue;
    ++stats_.windowsDroppedAtEdgeEnd;
    if (hooked())
      observer_->onWindowDropped({edge, E.length, w, a, vertexDistance_[a], DropRule::EdgeEnd});
    return true;
  }
  return false;
}

// The along-edge rule: v's window along its own edge, σ + |v x|, is dropped before Algorithm 2
// where the edge's list already covers the edge and no interval of it is longer than the window
// (EdgeIntervals::nowhereAbove): Algorithm 2 would keep none of it, after comparing it with every
// interval of the edge. Already propagated (its rays into either face are the windows on the
// opposite edges), it leaves nothing beyond the edge. On bunny00 from v:0, this drops 63,404 of
// the 103,784 windows along a saddle's edges; the rest meet an edge not yet wholly covered, or a
// list with an interval longer than the window somewhere (mostly at v, where another edge brought
// v its distance).
bool GeodesicSolver::dominatedAlongItsEdge(Index edge, const Interval& w, Index v) {
  const Edge& E = mesh_.edge(edge);
  if (!edges_[edge].nowhereAbove(w, E.vertex[0] == v, E.length)) return false;
  ++stats_.windowsDroppedAlongEdge;
  if (hooked())
    observer_->onWindowDropped({edge, E.length, w, v, vertexDistance_[v], DropRule::AlongEdge});
  return true;
}

void GeodesicSolver::updateVertex(Index v, double d) {
  double& current = vertexDistance_[v];
  const double bar = current == kInfinity ? kInfinity : current - tol::kTieRel * current;
  if (!(d < bar)) return;
  current = d;
  if (emitsWindows_[v]) queue_.push(QueueEntry::pseudoSource(v, d));
}

// Step 3 took a D1 sliver ending at v into a neighbour of another pseudo-source, or such a sliver
// lost there outright to one (reportFanOfALostSliver). On its range the neighbour is as short, to
// D1's slack; beyond v the sliver's source, when nearer, fans out wider
// than the neighbour's rays, and what only it reached is left to longer windows: behind a hole's
// corner, on a line through two more vertices, a thin wedge beyond them came out 9 % too long
// (corpus/fuzz_solver/regress/vertex-agreement-d1-sliver-at-a-vertex-loses-its-fan-beyond-it).
// v emits windows from then on, as a saddle does: a path through v is a real path, and one to
// where the sliver's rays reach is at most twice the sliver's length longer than theirs. propagate
// relays the apex of a G2–G5 window for the same reason; `relayed` counts either kind.
void GeodesicSolver::relayFanThroughVertex(Index v, std::uint64_t& relayed) {
  if (emitsWindows_[v]) return;
  emitsWindows_[v] = 1;
  ++relayed;
  if (vertexDistance_[v] != kInfinity) queue_.push(QueueEntry::pseudoSource(v, vertexDistance_[v]));
}

void GeodesicSolver::finish(const SolveOptions& options, double radius) {
  radius_ = radius;
  const MeshUnit& unit = mesh_.meshUnit();
  // (A radius that overflows in file units is refused below; the observers see a finite one.)
  const bool radiusOverflows = inFileUnitsRange(radius, unit) == ScaledRange::Overflow;
  stats_.radius = radiusOverflows ? std::numeric_limits<double>::max() : radius * unit.unit;
  const double cutoff = std::min(radius, options.stopDistance);
  // The wavefront has passed every distance up to the cutoff: a thin gap left there is a shadow
  // between windows that meet along a ray through a vertex up to rounding (tol::kShadowSewRel).
  const double widest = tol::kShadowSewRel * mesh_.boundingBoxDiagonalInMeshUnits();
  for (EdgeIntervals& e : edges_) stats_.shadowsClosed += e.closeShadows(widest, cutoff);
  for (Index v = 0; v < mesh_.numVertices(); ++v) {
    if (vertexDistance_[v] > cutoff) vertexDistance_[v] = kInfinity;
  }
  std::uint64_t total = 0, most = 0;
  for (const EdgeIntervals& e : edges_) {
    total += e.intervals().size();
    most = std::max<std::uint64_t>(most, e.intervals().size());
  }
  stats_.intervalsAtEnd = total;
  stats_.maxIntervalsPerEdge = most;
  // A distance beyond the largest double in file units is refused only after the observers have
  // checked the solve in mesh units, so a refusal always comes from checked numbers.
  Index overflowing = kNoIndex;
  vertexDistanceInFileUnits_.clear();
  if (unit.unit != 1.0) {
    vertexDistanceInFileUnits_.resize(vertexDistance_.size());
    for (Index v = 0; v < vertexDistance_.size(); ++v) {
      if (inFileUnitsRange(vertexDistance_[v], unit) == ScaledRange::Overflow) {
        if (overflowing == kNoIndex) overflowing = v;
        vertexDistanceInFileUnits_[v] = kInfinity;
        continue;
      }
      vertexDistanceInFileUnits_[v] = vertexDistance_[v] * unit.unit;
    }
  }
  if (hooked()) observer_->onFinish(*this);
  if (overflowing != kNoIndex) throwDistanceOverflow(vertexDistance_[overflowing], overflowing);
  if (radiusOverflows) throwDistanceOverflow(radius, kNoIndex);
}

// ===  Queries ====================================================================================
double GeodesicSolver::distance(const SurfacePoint& p) const {
  return inFileUnits(distanceInMeshUnits(p));
}

double GeodesicSolver::distanceInMeshUnits(const SurfacePoint& p) const {
  return resolvedDistance(resolve(mesh_, p));
}

double GeodesicSolver::inFileUnits(double d) const {
  if (inFileUnitsRange(d, mesh_.meshUnit()) == ScaledRange::Overflow) throwDistanceOverflow(d, kNoIndex);
  return d * mesh_.unit();  // exact, but below the smallest normal double (then rounded)
}

void GeodesicSolver::throwDistanceOverflow(double d, Index vertex) const {
  std::ostringstream os;
  os << (vertex == kNoIndex ? std::string("a distance") : "the distance of vertex " + std::to_string(vertex))
     << " is 2^" << mesh_.meshUnit().exponent << " x " << d
     << ", beyond the largest double (1.8e308); scale the mesh down";
  throw InputError("distance-overflow", os.str());
}

double GeodesicSolver::resolvedDistance(const ResolvedPoint& p) const {
  if (p.kind != SurfacePoint::Kind::Vertex)
    requireAllLists("the distance at an edge or face point");
  double best = kInfinity;
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      return vertexDistance_[p.element];
    case SurfacePoint::Kind::Edge: {
      const Edge& E = mesh_.edge(p.element);
      best = edges_[p.element].distanceAt(p.t);
      best = std::min({best, vertexDistance_[E.vertex[0]] + p.t,
                       vertexDistance_[E.vertex[1]] + (E.length - p.t)});
      break;
    }
    case SurfacePoint::Kind::Face: {
      const Index f = p.element;
      {  // the corners of f, and a source in f or on one of its edges, are seen straight
        const Index e = mesh_.faceEdges(f)[0];
        const Vec2 q = pointInFaceFrame(mesh_, p, f, e);
        for (Index v : mesh_.face(f)) {
          const ResolvedPoint corner{SurfacePoint::Kind::Vertex, v, 0.0, {}, mesh_.position(v)};
          best = std::min(best,
                          vertexDistance_[v] + (pointInFaceFrame(mesh_, corner, f, e) - q).norm());
        }
        for (const ResolvedPoint& src : sources_) {
          const bool touches =
              (src.kind == SurfacePoint::Kind::Face && src.element == f) ||
              (src.kind == SurfacePoint::Kind::Edge && mesh_.localEdgeIndex(f, src.element) >= 0);
          if (touches) best = std::min(best, (pointInFaceFrame(mesh_, src, f, e) - q).norm());
        }
      }
      for (Index e : mesh_.faceEdges(f)) {
        const Vec2 q = pointInFaceFrame(mesh_, p, f, e);
        for (const Interval& w : edges_[e].intervals()) {
          // Any window gives a valid path: to the point c of its range nearest the straight
          // line, then straight to q; with the source reflected below the edge the best c is
          // where the segment s→q crosses the edge, clamped to [b0, b1].
          const Vec2 s(w.source.x(), -w.source.y());
          const double u = (q.y() - s.y()) > 0 ? -s.y() / (q.y() - s.y()) : 0.0;
          const double cx = std::clamp(s.x() + u * (q.x() - s.x()), w.b0, w.b1);
          const Vec2 c(cx, 0.0);
          best = std::min(best, w.sigma + (c - s).norm() + (q - c).norm());
        }
      }
      break;
    }
  }
  return best > radius_ ? kInfinity : best;
}

double GeodesicSolver::targetsMaxDistance(std::span<const ResolvedPoint> targets) const {
  double worst = 0.0;
  for (const ResolvedPoint& t : targets) worst = std::max(worst, resolvedDistance(t));
  return worst;
}

std::vector<double> exactGeodesicDistance(const Mesh& mesh, std::span<const SurfacePoint> sources,
                                          const SolveOptions& options) {
  GeodesicSolver solver(mesh);
  SolveOptions vertexOnly = options;  // nothing else is read from this solver
  vertexOnly.vertexDistancesOnly = true;
  solver.solve(sources, vertexOnly);
  const auto d = solver.vertexDistances();
  return {d.begin(), d.end()};
}

}  // namespace geodex
