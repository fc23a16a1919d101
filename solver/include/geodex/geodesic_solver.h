#pragma once
// Exact geodesic distances and paths on a triangle mesh: MMP window propagation (Surazhsky et al.
// 2005) with the degenerate cases of Liu, Zhou & Hu 2007 handled by the Fig. 6 decision tree
// (propagate.h) and Algorithm 2 (edge_intervals.h).
//
//   std::vector<double> d = geodex::exactGeodesicDistance(mesh, {SurfacePoint::atVertex(0)});
//
//   geodex::GeodesicSolver solver(mesh);
//   solver.solve({SurfacePoint::atVertex(0), SurfacePoint::inFace(7, 0.2, 0.3, 0.5)});
//   double d = solver.distance(SurfacePoint::onEdge(3, 4, 0.25));
//   GeodesicPath p = solver.path(SurfacePoint::atVertex(42));

#include <array>
#include <atomic>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "geodex/bucket_queue.h"
#include "geodex/degeneracy.h"
#include "geodex/edge_intervals.h"
#include "geodex/mesh.h"
#include "geodex/observer.h"
#include "geodex/surface_point.h"

namespace geodex {
namespace detail {
class HelperThread;
}

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct SolveOptions {
  /// Stop once the wavefront has passed this distance. Every vertex within it gets its exact
  /// distance; every vertex beyond it gets +inf.
  double stopDistance = kInfinity;
  /// Stop as soon as the distance of every target is final (the wavefront has passed the
  /// largest of them). Vertices whose distance is not final at that point get +inf.
  /// With both options set, the solve stops at whichever comes first.
  std::vector<SurfacePoint> targets;
  /// Only the vertex distances will be read: the lists of the edges the wavefront has left
  /// behind go back to the pool during the solve, so memory follows the wavefront rather than the
  /// mesh (bunny00 from a vertex: 119 MB → 39 MB). The vertex distances are those of a solve that
  /// keeps every list, to the bit: should a window reach a released edge after all, the solve is
  /// done again keeping them (SolveStats::releaseUndone). Afterwards distance() at an edge or face
  /// point, path() and edgeIntervals() refuse. Ignored with targets, or with an observer that
  /// reads the lists (SolverObserver::readsIntervalLists).
  bool vertexDistancesOnly = false;
  /// Threads for the wavefront: 1, or 2 to share the batches of each round between the thread
  /// that called solve() and a helper thread (a round: the batch of windows taken from the queue
  /// and up to eleven from just behind it that touch none of its edges nor each other's). The
  /// rounds are the same whatever the threads, so the results are the same to the bit. More than
  /// 2 counts as 2. An observer's events all come from the thread that called solve(), in the
  /// same order.
  unsigned threads = 1;
};

struct SolveStats {
  std::uint64_t intervalsCreated = 0;     ///< intervals handed to Algorithm 2
  std::uint64_t intervalsPropagated = 0;  ///< windows popped and propagated across a face
  std::uint64_t pseudoSourceEvents = 0;   ///< saddle/boundary vertices turned into pseudo-sources
  std::uint64_t maxIntervalsPerEdge = 0;
  std::uint64_t intervalsAtEnd = 0;
  /// Thin gaps closed once the wavefront had passed (tol::kShadowSewRel;
  /// EdgeIntervals::closeShadows).
  std::uint64_t shadowsClosed = 0;
  /// Pseudo-source windows dropped before Algorithm 2: a path through an end of their edge is
  /// shorter on all of them (the edge-end rule, GeodesicSolver::dominatedAtAnEdgeEnd).
  std::uint64_t windowsDroppedAtEdgeEnd = 0;
  /// Pseudo-source windows along the source's own edges dropped before Algorithm 2: the edge's
  /// list covers the edge and no interval of it is longer than the window, so it is nowhere above
  /// it (the along-edge rule, GeodesicSolver::dominatedAlongItsEdge, EdgeIntervals::nowhereAbove).
  std::uint64_t windowsDroppedAlongEdge = 0;
  /// SolveOptions::vertexDistancesOnly: edges whose list went back to the pool once the wavefront
  /// had passed them, and whether a window reached one after all, so that the solve was done
  /// again keeping every list (the counts above are then the second solve's).
  std::uint64_t edgesReleased = 0;
  bool releaseUndone = false;
  /// Batches run beside the one taken from the queue's front, in its round (SolveOptions::threads):
  /// the work a second thread can share. The same whatever the threads.
  std::uint64_t batchesBesideTheFront = 0;
  double radius = kInfinity;  ///< distances up to this are final (inf: ran to the end), file units
};

/// One point of a geodesic path.
struct PathPoint {
  SurfacePoint where;  ///< vertex, or edge point (`vertex` → `toVertex` at fraction t), or face
  Vec3 position;       ///< in the mesh file's units
};

struct GeodesicPath {
  std::vector<PathPoint> points;  ///< from the target back to the nearest source
  double length = kInfinity;      ///< sum of segment lengths (file units); equals the distance
};

class GeodesicSolver {
 public:
  explicit GeodesicSolver(const Mesh& mesh);
  ~GeodesicSolver();
  GeodesicSolver(const GeodesicSolver&) = delete;
  GeodesicSolver& operator=(const GeodesicSolver&) = delete;

  /// Attach an observer (verify/ uses this); nullptr detaches. Not owned.
  void setObserver(SolverObserver* observer) { observer_ = observer; }

  /// Computes distances from all `sources` (any number; each a vertex, edge point or face point).
  /// Re-running with other sources gives the same results as a fresh solver.
  /// Throws InputError for a source or target outside the mesh, and 'distance-overflow' when a
  /// distance is beyond the largest double in the file's units; that refusal comes after the
  /// observer's onFinish, and the mesh-unit accessors below still hold the whole solve.
  void solve(std::span<const SurfacePoint> sources, const SolveOptions& options = {});

  /// Per-vertex distances (+inf for unreachable, unreferenced, or beyond a stop), #V entries,
  /// in the mesh file's units. (solve() throws InputError when one overflows a double.)
  std::span<const double> vertexDistances() const {
    return mesh_.unit() == 1.0 ? std::span<const double>(vertexDistance_) : vertexDistanceInFileUnits_;
  }
  /// The same in mesh units (Mesh::unit()), as the intervals and observer events have them; during
  /// a solve, the distances found so far.
  std::span<const double> vertexDistancesInMeshUnits() const { return vertexDistance_; }
  /// Distance at any surface point, in the mesh file's units. Throws InputError if it overflows.
  double distance(const SurfacePoint& p) const;
  /// The same in mesh units.
  double distanceInMeshUnits(const SurfacePoint& p) const;
  /// The geodesic from p back to the nearest source. Empty with length +inf if unreachable.
  GeodesicPath path(const SurfacePoint& p) const;

  const DegeneracyCounters& counters() const { return counters_; }
  const SolveStats& stats() const { return stats_; }
  const Mesh& mesh() const { return mesh_; }
  /// Throws after a solve that released lists (SolveOptions::vertexDistancesOnly).
  std::span<const EdgeIntervals> edgeIntervals() const;
  std::span<const ResolvedPoint> sources() const { return sources_; }

 private:
  /// What the wavefront queue holds: one side of an edge with windows still to propagate, keyed
  /// by the smallest distance among them, or a vertex to turn into a pseudo-source.
  struct QueueEntry {
    double key;  ///< the edge side's pending key when queued, or the vertex's distance
    Index edge;  ///< kNoIndex: a pseudo-source event of vertex `which`
    std::uint32_t which;  ///< the side (Interval::side) of the windows, or the vertex

    static QueueEntry edgeSide(Index edge, std::uint8_t side, double key) { return {key, edge, side}; }
    static QueueEntry pseudoSource(Index v, double d) { return {d, kNoIndex, v}; }
  };

  void reset();
  /// One attempt at a solve (seeding and the wavefront loop); false when it released edges' lists
  /// and a window reached one of them, so that it must be done again keeping them.
  bool runWavefront(const SolveOptions& inMeshUnits, std::span<const ResolvedPoint> targets,
                    double& radius);
  void startReleasing();
  void fileForRelease(Index edge, double reach);
  double releaseReach(const Interval& w) const;
  void fileInBucket(Index edge, double reach);
  void releasePassedEdges(double bound);
  void requireAllLists(const char* what) const;
  void seedSource(const ResolvedPoint& p, std::size_t number);
  /// A batch's children on one child edge, in the order they were made, with the Fig. 6 leaf and
  /// the case (its index in the batch) each came from.
  struct Run {
    std::vector<Interval> incoming;
    std::vector<Fig6Branch> branches;  ///< (for an observer only: empty without one)
    std::vector<std::uint32_t> cases;
    void clear() {
      incoming.clear();
      branches.clear();
      cases.clear();
    }
  };
  /// What finishBatch needs of a batch's update of one child edge.
  struct ChildEdgeUpdate {
    std::size_t incoming = 0;         // the run's children (0: none, no update)
    bool updated = false;             // false: the run reached a released list (not updated)
    std::size_t first = 0, last = 0;  // EdgeUpdateReport's
    std::uint8_t fanLostAtVertex = 0;
    double reach = 0.0;  // the run's farthest releaseReach, when releasing
  };
  /// One batch: the pending windows of an edge side up to a distance, propagated across the
  /// face beyond it, their children merged into the face's other two edges (Algorithm 2, one run
  /// per edge). runBatch writes only what the batch holds, the edge side's own windows and key,
  /// and the lists of the two child edges, so that two batches with no edge in common can run at
  /// once; finishBatch then does what they mean for the queue, the vertices and the counts.
  // (On cache lines of its own: two threads write their batches' counts at once.)
  struct alignas(64) Batch {
    QueueEntry entry{};
    double upTo = 0.0;
    bool live = false;  // the entry was not stale
    Index face = kNoIndex;
    const FaceFrame* frame = nullptr;
    double rest = kInfinity;  // the smallest distance of the side's windows left pending
    ChildEdgeUpdate updates[2];  // on the face's edges e1 and e2
    DegeneracyCounters counters;
    std::uint64_t propagated = 0;
    std::vector<Index> relayApexes;  // G2–G5 apexes to relay the fan through
    /// Set by the thread that ran it, once it has (release): finishBatch may then read it.
    std::atomic<bool> done{false};
    bool failed = false;  // its runBatch threw (set before done)
    /// For an observer: each case as propagate saw it (PropagationEvent), shown by finishBatch.
    struct Propagation {
      Index face;
      Index edge;
      Interval window;
      LocalWindow local;
      LocalPropagation result;
      std::array<MadeChild, 2> children{};
      std::size_t numChildren = 0;
    };
    std::vector<Propagation> propagations;
    /// For an observer: each child edge's update as it shows it (EdgeUpdateEvent).
    struct Shown {
      std::vector<Interval> before;  // (for an observer that reads the lists)
      std::vector<Interval> incoming;
      std::vector<Fig6Branch> branches;
      EdgeUpdateReport report;
    };
    Shown shown[2];
  };
  void addInterval(Index edge, const Interval& w);
  /// At most this many batches run in one round (runRound).
  static constexpr std::size_t kRoundBatches = 12;
  void runRound(const QueueEntry& top, double stopDistance);
  /// What a thread of the solve runs batches with: the pool the lists it updates allocate from,
  /// and Algorithm 2's buffers (one set per thread, not per batch: they stay in its cache).
  struct alignas(64) Worker {
    explicit Worker(IntervalPool* p) : pool(p) {}
    IntervalPool* pool;
    std::vector<Interval> scratch;
    IntervalList work;  // (EdgeIntervals::insertRun's copy of a slice)
    /// The children of the batch it runs, on the face's edges e1 and e2, and whether each of its
    /// cases is degenerate so far; and its updates' report.
    Run runs[2];
    std::vector<std::uint8_t> caseDegenerate;
    EdgeUpdateReport report;
  };
  void claimBatches(Worker& worker);
  void runClaimedBatch(Batch& b, Worker& worker);
  void finishRound();
  static void claimBatchesOnTheHelper(void* solver);
  void prepareBatch(Batch& b, const QueueEntry& entry, double stopDistance) const;
  void runBatch(Batch& b, Worker& worker);
  void finishBatch(Batch& b);
  static void countRepairs(DegeneracyCounters& counters, const EdgeUpdateReport& report);
  void afterUpdate(Index edge, std::size_t first, std::size_t last, std::uint8_t fanLostAtVertex);
  void queuePending(Index edge, const Interval& w);
  void prefetchAhead() const;
  void updateVertex(Index v, double d);
  bool dominatedAtAnEdgeEnd(Index edge, const Interval& w);
  bool dominatedAlongItsEdge(Index edge, const Interval& w, Index v);
  void relayFanThroughVertex(Index v, std::uint64_t& relayed);
  void createPseudoSourceWindows(Index v, double sigma, std::int32_t origin, int depth = 0,
                                 Index from = kNoIndex);
  void seedFaceFromPoint(Index f, const ResolvedPoint& p, Index skip, double sigma,
                         std::int32_t origin);
  void seedCorner(Index v, double d);
  void seedZeroAreaStrip(Index e, double t);
  void seedAcrossVertexOnEdge(Index v, Index f, const FaceFrame& fr, double sigma,
                              std::int32_t origin, int depth, Index from);
  void seedAcrossPointOnEdge(Index v, Index e, Index f, double x, double at, std::int32_t origin,
                             int depth, Index from);
  /// Zero-area faces stacked on one point hand it on at most this many times.
  static constexpr int kMaxVertexOnEdgeDepth = 4;
  /// GEODEX_FUZZING_BUILD_MODE (the `fuzz` preset, ClusterFuzzLite) caps a solve at this many
  /// propagated windows: 20 × (faces + 1)², the exact algorithm's quadratic worst case with a wide
  /// margin (a 64-face fuzz mesh propagates a few thousand; the cap is 84,500).
  std::uint64_t fuzzingWorkLimit() const {
    const std::uint64_t f = mesh_.numFaces() + 1;
    return 20 * f * f;
  }
  /// One window of `edge` across face f (the one across from its source), fr: f on `edge`; its
  /// children go into the runs of `worker` (the thread running batch b), its counts into b.
  void propagate(Batch& b, Worker& worker, Index edge, const Interval& w, Index f,
                 const FaceFrame& fr);
  void finish(const SolveOptions& options, double radius);
  /// Whether to build and send observer events. GEODEX_NO_OBSERVER_HOOKS compiles the hooks out
  /// (only for bench/hooks_overhead, which measures what the null check costs a release solve).
#ifdef GEODEX_NO_OBSERVER_HOOKS
  static constexpr bool hooked() { return false; }
#else
  bool hooked() const { return observer_ != nullptr; }
#endif
  double targetsMaxDistance(std::span<const ResolvedPoint> targets) const;
  double resolvedDistance(const ResolvedPoint& p) const;  // mesh units
  /// d (mesh units) in the file's units; throws InputError when a finite d overflows there.
  double inFileUnits(double d) const;
  /// The 'distance-overflow' InputError for d (mesh units), naming `vertex` unless kNoIndex.
  [[noreturn]] void throwDistanceOverflow(double d, Index vertex) const;

  const Mesh& mesh_;
  SolverObserver* observer_ = nullptr;
  IntervalPool pool_;  // before edges_: their lists live in it
  IntervalPool helperPool_;  // (what the helper thread's batches allocate from)
  std::vector<EdgeIntervals> edges_;
  std::vector<double> vertexDistance_;             // mesh units
  // Whether a vertex emits windows when reached: the mesh's pseudo-source vertices, and those
  // relayFanThroughVertex adds during a solve.
  std::vector<std::uint8_t> emitsWindows_;
  std::vector<double> vertexDistanceInFileUnits_;  // the same × mesh_.unit(), when that is not 1
  double radius_ = kInfinity;                      // stats_.radius in mesh units
  std::vector<ResolvedPoint> sources_;
  BucketQueue<QueueEntry> queue_;
  double queueBucketWidth_ = 1.0;
  double batchSlack_ = 1.0;  // kBatchSlackEdges in mesh units
  /// Per edge side (2 × edge + Interval::side): its pending key, no pending window there has a
  /// smallest distance below it (+inf: none pending), the key of its newest queue entry; and the
  /// face's two other edges its batches' children go to (kNoIndex at a boundary) and its frame,
  /// for runRound, which tests up to kRoundLookahead entries a round: one cache line an entry,
  /// not four.
  struct alignas(32) EdgeSide {  // (an edge's two sides on one cache line)
    double pendingKey = kInfinity;
    std::array<Index, 2> childEdges{kNoIndex, kNoIndex};
    Index frame = kNoIndex;  // 3 × face + the edge's place in it (Mesh::frameByLocal)
  };
  std::vector<EdgeSide> sides_;
  double& pendingKey(Index edge, std::uint32_t side) {
    return sides_[2 * std::size_t{edge} + side].pendingKey;
  }
  // SolveOptions::vertexDistancesOnly: edges wait in buckets of the queue's width, by how far the
  // windows they received reach, for the wavefront to leave them behind (releasePassedEdges).
  bool releasing_ = false;      // this attempt releases lists
  bool releaseBroken_ = false;  // a window reached a released edge
  /// Per edge: 0 not filed, k + 1 filed in bucket k, or one of the two below.
  std::vector<std::uint32_t> releaseState_;
  static constexpr std::uint32_t kReleased = 0xffffffff;
  static constexpr std::uint32_t kKept = 0xfffffffe;  // reaches beyond the buckets: never released
  std::vector<std::vector<Index>> releaseBuckets_;
  std::size_t nextReleaseBucket_ = 0;
  EdgeUpdateReport report_;
  /// The attached observer's readsIntervalLists(), read once a solve: without it, edge updates do
  /// not copy the list into before_ (EdgeUpdateEvent::before is then empty).
  bool observerReadsLists_ = false;
  std::vector<Interval> scratch_, before_;
  /// The round's batches: the one taken from the queue's front first (runRound).
  Batch batches_[kRoundBatches];
  std::size_t roundSize_ = 0;
  Worker solving_{&pool_};        // the thread that called solve()
  Worker helping_{&helperPool_};  // the helper thread
  // The next batch of the round a thread may take (claimBatches); apart from the batches.
  alignas(64) std::atomic<std::size_t> roundNext_{0};
  std::unique_ptr<detail::HelperThread> helper_;  // made by the first solve with two threads
  bool useHelper_ = false;                        // this solve runs batches on it
  DegeneracyCounters counters_;
  SolveStats stats_;
};

/// One call: distances from `sources` to every vertex of `mesh` (+inf where unreachable). Solves
/// with SolveOptions::vertexDistancesOnly.
std::vector<double> exactGeodesicDistance(const Mesh& mesh, std::span<const SurfacePoint> sources,
                                          const SolveOptions& options = {});

}  // namespace geodex
