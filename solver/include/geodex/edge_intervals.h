#pragma once
// The intervals of one edge and Algorithm 2 of Liu, Zhou & Hu 2007 (Sect. 4.2): merging a new
// interval into the edge's sorted set so that every point keeps the smaller distance.
//
//   step 1  split the old intervals at the new one's ends, so each is wholly inside or outside it
//   step 2  for each old interval inside the new one, solve Eq. 1 (where the two distance
//           functions are equal) and keep, on each piece, the one that is shorter
//   step 3  remove tiny intervals (D1)
//   step 4  sew small gaps at their midpoint (D3); overlaps (D2) are resolved the same way
//   step 5  merge neighbours with the same pseudo-source
//   step 6  verification: done by verify/ through the solver's observer (see observer.h)
// D4 (the two distances differ at a shared endpoint made by Eq. 1) is repaired in step 2, by
// polishing the root on the exact difference of the two distance functions.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "geodex/check.h"
#include "geodex/degeneracy.h"
#include "geodex/interval.h"
#include "geodex/interval_pool.h"
#include "geodex/tolerance.h"

namespace geodex {

/// What one insertion did, for the solver (which intervals to queue) and the observer.
struct EdgeUpdateReport {
  /// The index range [first, last) of the list that the update rewrote; the intervals in it with
  /// Interval::kChanged set are new or changed (the solver queues the pending ones).
  std::size_t first = 0, last = 0;
  /// Shared endpoints created by an Eq. 1 split: the two neighbours must agree here (D4).
  std::vector<double> eq1Breakpoints;
  /// Ranges of the tiny intervals step 3 removed (D1): there the list takes a neighbour's values
  /// by contract, so the pointwise minimum is not expected to hold inside them.
  std::vector<std::pair<double, double>> removedTiny;
  /// The gaps step 4 sewed (D3), as they were before: between two neighbours or an edge end.
  std::vector<std::pair<double, double>> sewnGaps;
  /// For a run of two or more incoming intervals (EdgeIntervals::insertRun): whether the steps 1
  /// and 2 of each, in order, repaired a D2 or D4. Empty for a single incoming interval.
  std::vector<std::uint8_t> repairedInStepsOneAndTwo;
  /// Whether any part of the incoming interval survived.
  bool incomingSurvived = false;
  /// Bit k: step 3 removed, at the edge's vertex k, a D1 sliver that a neighbour of another
  /// pseudo-source took (see GeodesicSolver::relayFanThroughVertex).
  std::uint8_t fanLostAtVertex = 0;
  DegeneracyCounters degeneracies;  ///< D1–D4 found in this update
  void clear() {
    first = last = 0;
    eq1Breakpoints.clear();
    removedTiny.clear();
    sewnGaps.clear();
    repairedInStepsOneAndTwo.clear();
    incomingSurvived = false;
    fanLostAtVertex = 0;
    degeneracies = {};
  }
};

/// Calls repaired(k) for each interval k of `incoming` (a run's, EdgeIntervals::insertRun, or one
/// alone) at which the update `r` repaired a D1–D4, as its own update would have, had each been
/// one: its D2 and D4 (steps 1 and 2, run per interval), and each D1 sliver removed or D3 gap sewn
/// by the run's one pass of steps 3–5 charged to the last interval of the run whose range reaches
/// it (one update after another, the one that met it). One alone is charged every repair of its
/// update. k may come more than once. A propagation case counts as degenerate by this
/// (DegeneracyCounters::degenerateCases).
template <typename Repaired>
void forEachRepairedIncoming(const EdgeUpdateReport& r, std::span<const Interval> incoming,
                             Repaired&& repaired) {
  if (r.repairedInStepsOneAndTwo.empty()) {
    if (!incoming.empty() && r.degeneracies.discontinuityTotal() > 0) repaired(std::size_t{0});
    return;
  }
  for (std::size_t k = 0; k < incoming.size(); ++k)
    if (r.repairedInStepsOneAndTwo[k]) repaired(k);
  const auto charge = [&](const std::pair<double, double>& range) {
    for (std::size_t k = incoming.size(); k-- > 0;) {
      if (range.first <= incoming[k].b1 && range.second >= incoming[k].b0) {
        repaired(k);
        return;
      }
    }
  };
  for (const auto& range : r.removedTiny) charge(range);
  for (const auto& range : r.sewnGaps) charge(range);
}

/// The length the ε of D1–D3 is relative to for interval w on an edge of length L (see
/// tol::kTinyIntervalRel): the edge length or, when larger, the distance of the pseudo-source.
inline double intervalLengthScale(const Interval& w, double edgeLength) {
  return std::max(edgeLength, std::abs(w.source.x()) + w.source.y());
}
/// ε for interval w: shorter intervals are D1, shorter gaps next to it D3.
inline double tinyLength(const Interval& w, double edgeLength) {
  return tol::kTinyIntervalRel * intervalLengthScale(w, edgeLength);
}

/// D3: a gap beside w shorter than this is sewn (step 4): ε of the edge itself (kTinyIntervalRel ×
/// its length: a flat vertex's shadow, kFlatVertexAngle × the rays' length past the vertex, is
/// below it) plus how far w's ray-cast end may be off (kRayEndRel × w's scale). Not w's whole ε:
/// for a window from far away that is 1e5× its rounding, and a gap that wide at its end can be
/// the start of a near saddle's shadow; sewn, the far window reached over it and the saddle's own
/// window, arriving later, lost there by rounding and never fanned out into the shadow
/// (tests/data/regression/far-source-sewn-over-a-saddle-shadow.off: 0.41 too much downstream).
/// On an edge shorter than w's own ε, though, w's ends mean nothing at the precision of its
/// source (step 3 keeps it as the edge's last window, lastOnShortEdge): its whole ε counts, and
/// step 4 closes every gap beside it (a window from 4.4e12 away left at [1, 5] of a 6-long edge,
/// alone or beside a near window at [0, 0.5]:
/// corpus/fuzz_edge_update/regress/no-tiny-interval-short-edge-window-not-sewn-*).
inline double sewLength(const Interval& w, double edgeLength) {
  const double epsilon = tinyLength(w, edgeLength);
  if (edgeLength < epsilon) return epsilon;
  return tol::kTinyIntervalRel * edgeLength + tol::kRayEndRel * intervalLengthScale(w, edgeLength);
}

/// How far a neighbour's ray-cast end may be off, for step 3's D1 test (tol::kRayEndRel).
inline double rayEndPrecision(const Interval& w, double edgeLength) {
  return tol::kRayEndRel * intervalLengthScale(w, edgeLength);
}

/// The D1 threshold of t between the intervals prev and next of a sorted list (nullptr: none):
/// its own ε, or, when larger, the ray-end precision of a neighbour it touches (a neighbour counts
/// when it touches or is within its own ε of touching: step 4 will sew it). See step 3 in
/// edge_intervals.cpp.
inline double tinyLengthBetween(const Interval* prev, const Interval& t, const Interval* next,
                                double edgeLength) {
  double tiny = tinyLength(t, edgeLength);
  if (prev != nullptr && prev->b1 >= t.b0 - tinyLength(*prev, edgeLength))
    tiny = std::max(tiny, rayEndPrecision(*prev, edgeLength));
  if (next != nullptr && next->b0 <= t.b1 + tinyLength(*next, edgeLength))
    tiny = std::max(tiny, rayEndPrecision(*next, edgeLength));
  return tiny;
}

/// tinyLengthBetween for the i-th interval of a sorted list.
inline double tinyLengthInList(std::span<const Interval> list, std::size_t i, double edgeLength) {
  return tinyLengthBetween(i > 0 ? &list[i - 1] : nullptr, list[i],
                           i + 1 < list.size() ? &list[i + 1] : nullptr, edgeLength);
}

/// Step 3 (D1): whether the neighbour n may grow over the sliver t, whose end next to n is at x.
/// n must reach to within the slack of t (t's own ε, or n's ray-end precision when larger) and be
/// no longer than t there by more than that slack: then growing over t moves the distance on its
/// range by less than D1 allows anyway (the slack and twice t's length). A neighbour much longer
/// at x is not a window t is the rounding of, but one t's source beats: a source's windows that
/// arrive in pieces each shorter than its ε, each merged into the far window beside it, left that
/// window 0.13 too long at the edge's end (corpus/fuzz_solver/regress/vertex-agreement-d1-pieces-
/// of-a-source-near-a-corner-merged-into-a-far-g1-window). A sliver no neighbour can take is kept:
/// it is the shortest distance on its range, and with no neighbour at all the only coverage there
/// (corpus/fuzz_solver/regress/vertex-agreement-d1-sliver-of-a-far-source-dropped-on-an-empty-
/// edge). Pairwise, so that an update beside one neighbour cannot change the verdict about the
/// other, which it may not see (corpus/fuzz_edge_update/regress/no-tiny-interval-isolated-sliver-
/// rule-sees-a-neighbour-outside-the-update-slice).
inline bool canTakeSliver(const Interval& n, const Interval& t, double edgeLength) {
  const double slack = std::max(tinyLength(t, edgeLength), rayEndPrecision(n, edgeLength));
  const bool before = n.b0 < t.b0;
  const double x = before ? t.b0 : t.b1;
  const double gap = before ? t.b0 - n.b1 : n.b0 - t.b1;
  return gap <= slack && n.distanceAt(x) <= t.distanceAt(x) + slack;
}

/// The first index i of `list` with !before(list[i]), where `before` holds on a prefix of the list
/// (a sorted, non-overlapping list: e.g. "ends before x"). The search starts at `guess` and
/// gallops outwards: it reads a cache line or two when the guess is close, O(log n) lines in any
/// case. (A binary search from the middle misses the cache at each of its steps; on an edge of 32
/// intervals that was most of finding one.)
template <typename Before>
std::size_t partitionFrom(std::span<const Interval> list, std::size_t guess, Before before) {
  const std::size_t n = list.size();
  if (guess > n) guess = n;
  std::size_t lo = 0, hi = n;  // the answer is in [lo, hi]
  if (guess < n && before(list[guess])) {
    lo = guess + 1;
    for (std::size_t step = 1;; step *= 2) {
      const std::size_t probe = guess + step;
      if (probe >= n) break;
      if (!before(list[probe])) {
        hi = probe;
        break;
      }
      lo = probe + 1;
    }
  } else {
    hi = guess;
    for (std::size_t step = 1; step <= guess; step *= 2) {
      const std::size_t probe = guess - step;
      if (before(list[probe])) {
        lo = probe + 1;
        break;
      }
      hi = probe;
    }
  }
  // The gallop found the answer beside the guess: 99 % of the searches for a run's children on
  // bunny00 (each child's guess is where the one before it went).
  if (lo == hi) return lo;
  return static_cast<std::size_t>(
      std::partition_point(list.begin() + static_cast<std::ptrdiff_t>(lo),
                           list.begin() + static_cast<std::ptrdiff_t>(hi), before) -
      list.begin());
}

/// Where in a list of n intervals on an edge of length L the one at x probably is: intervals
/// spread along their edge, so the fraction x / L of the way through the list.
inline std::size_t guessIndex(std::size_t n, double x, double edgeLength) {
  if (n == 0 || !(x > 0.0)) return 0;
  const double f = x / edgeLength * static_cast<double>(n);
  return f >= static_cast<double>(n) ? n - 1 : static_cast<std::size_t>(f);
}

/// The sorted, non-overlapping intervals of one edge.
class EdgeIntervals {
 public:
  /// A list allocating from `pool` (a solver's), or with operator new when null.
  explicit EdgeIntervals(IntervalPool* pool = nullptr) : list_(pool) {}

  std::span<const Interval> intervals() const { return list_; }
  std::span<Interval> intervals() { return list_; }
  bool empty() const { return list_.empty(); }
  void clear() { list_.clear(); }
  /// Empties the list and hands its memory back (to the pool it was allocated from).
  void clearAndRelease() { list_.clearAndRelease(); }
  /// The list's memory comes from, and goes back to, `pool` from now on (IntervalList::usePool):
  /// only between pools.
  void usePool(IntervalPool* pool) {
    GEODEX_CHECK(list_.pool() != nullptr && pool != nullptr, "a list moved to or from no pool");
    list_.usePool(pool);
  }
  /// For tests and the fuzzers: install a list as it is (no checks; verify/ judges it).
  void assign(const std::vector<Interval>& list) { list_.assign(list); }

  /// Algorithm 2: merge `incoming` (range within [0, edgeLength]) into the list. Only the part
  /// of the list the incoming range reaches (plus two neighbours on each side, which steps 3–5 may
  /// touch) is read and rewritten, so an update costs O(log n + overlap), not O(n). `scratch` is
  /// reused between calls to avoid allocation; what it holds afterwards is unspecified.
  void insert(const Interval& incoming, double edgeLength, EdgeUpdateReport& report,
              std::vector<Interval>& scratch);

  /// Algorithm 2 for a run of incoming intervals (each within [0, edgeLength]), in order: steps 1
  /// and 2 for each on a copy of the slice over all of them, steps 3–5 once, one splice. The list
  /// afterwards is the pointwise minimum of the list before and every interval of the run, with
  /// D1–D4 repaired, as after one update per interval (up to where the repairs fall). A run of
  /// one is insert(). `work` is scratch like `scratch` (a list without a pool: the copy of the
  /// slice the run's children update one after another).
  void insertRun(std::span<const Interval> run, double edgeLength, EdgeUpdateReport& report,
                 std::vector<Interval>& scratch, IntervalList& work);

  /// The smallest distance the list gives at x, or +inf where no interval covers x.
  double distanceAt(double x) const;

  /// Whether the list covers [0, edgeLength] with no gap and no interval of it is longer than
  /// `alongEdge`, a window whose source lies on the edge at its start (`fromStart`) or its end
  /// and which spans the edge: Algorithm 2 would keep none of that window
  /// (GeodesicSolver::dominatedAlongItsEdge).
  bool nowhereAbove(const Interval& alongEdge, bool fromStart, double edgeLength) const;

  /// When the wavefront has passed: closes, at their midpoints, the gaps between neighbours
  /// narrower than `widest` (tol::kShadowSewRel × the bounding-box diagonal) where the distance is
  /// at most `passed` (beyond it the wavefront may not have arrived). Returns how many it closed.
  std::size_t closeShadows(double widest, double passed);

 private:
  IntervalList list_;
};

/// Eq. 1: positions x in (lo, hi) where the two intervals' distance functions are equal, as
/// candidates (roots of the quadratic; spurious ones from squaring are possible and harmless).
/// Returns how many were written to roots (0–2), sorted.
int equalDistanceCandidates(const Interval& a, const Interval& b, double lo, double hi,
                            double roots[2]);

}  // namespace geodex
