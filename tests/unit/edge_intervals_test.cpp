// Algorithm 2 on one edge. Expected values come from evaluating the two distance functions
// directly (the pointwise minimum), never from the code under test.
#include "geodex/edge_intervals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "geodex/tolerance.h"

namespace geodex {
namespace {

constexpr double kL = 10.0;

Interval make(double b0, double b1, Vec2 source, double sigma) {
  Interval w;
  w.b0 = b0;
  w.b1 = b1;
  w.source = source;
  w.sigma = sigma;
  return w;
}

struct Edge1 {
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  DegeneracyCounters total;
  IntervalList work;
  void insert(const Interval& w) {
    list.insert(w, kL, report, scratch);
    total += report.degeneracies;
  }
  /// Several at once, as the solver merges a batch's children on one edge.
  void insertRun(std::vector<Interval> run) {
    list.insertRun(run, kL, report, scratch, work);
    total += report.degeneracies;
  }
  /// The intervals the last update created or changed that still need propagating: what the
  /// solver queues.
  std::vector<Interval> toQueue() const {
    std::vector<Interval> q;
    const auto all = list.intervals();
    for (std::size_t i = report.first; i < report.last; ++i)
      if ((all[i].flags & Interval::kChanged) && all[i].pending()) q.push_back(all[i]);
    return q;
  }
};

// Sorted, inside [0, L], no overlap, contiguous coverage between first and last.
void expectWellFormed(const EdgeIntervals& e) {
  const auto w = e.intervals();
  for (std::size_t i = 0; i < w.size(); ++i) {
    EXPECT_LT(w[i].b0, w[i].b1);
    EXPECT_GE(w[i].b0, 0.0);
    EXPECT_LE(w[i].b1, kL);
    if (i > 0) EXPECT_EQ(w[i - 1].b1, w[i].b0) << "interval " << i;
  }
}

// The list equals the pointwise minimum of the given functions over [lo, hi].
void expectPointwiseMin(const EdgeIntervals& e, const std::vector<Interval>& functions, double lo,
                        double hi) {
  for (int k = 0; k <= 1000; ++k) {
    const double x = lo + (hi - lo) * k / 1000.0;
    double expected = INFINITY;
    for (const Interval& f : functions)
      if (x >= f.b0 && x <= f.b1) expected = std::min(expected, f.distanceAt(x));
    EXPECT_NEAR(e.distanceAt(x), expected, 1e-12 * (expected + kL)) << "at x = " << x;
  }
}

TEST(Algorithm2, FirstIntervalIsKeptWhole) {
  Edge1 e;
  const Interval a = make(2.0, 7.0, Vec2(4.0, 3.0), 1.0);
  e.insert(a);
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_EQ(e.list.intervals()[0].b0, 2.0);
  EXPECT_EQ(e.list.intervals()[0].b1, 7.0);
  EXPECT_TRUE(e.report.incomingSurvived);
  ASSERT_EQ(e.toQueue().size(), 1u);
}

// Edge 16-25 of corpus/fuzz_solver/regress/vertex-agreement-d1-sliver-of-a-far-source-dropped-
// on-an-empty-edge, in mesh units: a 0.125-long edge, a source 0.75 away. Its window for the first
// 5e-12 (shorter than its ε, 7.5e-12) reaches the empty edge first, then the rest of its window,
// then the window of the far vertex along the edge, 0.885 at x = 0. The source's 0.75 must stay.
TEST(Algorithm2, ASliverOfAFarSourceAloneOnItsEdgeIsKeptUntilItsNeighbourArrives) {
  constexpr double L = 0.125;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Vec2 source(-2.5e-11, 0.75);
  list.insert(make(0.0, 5e-12, source, 0.0), L, report, scratch);
  ASSERT_EQ(list.intervals().size(), 1u) << "the sliver was dropped with no neighbour to take it";
  list.insert(make(5e-12, L, source, 0.0), L, report, scratch);
  const Interval alongTheEdge = make(0.0, L, Vec2(L, 0.0), 0.76034531631604729);
  list.insert(alongTheEdge, L, report, scratch);
  const double direct = make(0.0, L, source, 0.0).distanceAt(0.0);
  ASSERT_LT(direct, alongTheEdge.distanceAt(0.0) - 0.1);
  EXPECT_NEAR(list.distanceAt(0.0), direct, 1e-12);
  EXPECT_NEAR(list.distanceAt(2.5e-12), make(0.0, L, source, 0.0).distanceAt(2.5e-12), 1e-12);
}

// A D1 sliver between a window from far away (its ε 100× the edge's) and a near one goes to the
// far one, the coarser, even when that one was propagated already and the near one was not:
// merged into the near one, the sliver's end would stay a sliver's width from the far window's.
// Here the sliver is what is left of an old window M where a new near window N crosses it 5e-11
// after M's start.
TEST(Algorithm2, AD1SliverBetweenAFarAndANearWindowGoesToTheFarOneWhateverTheirStates) {
  constexpr double delta = 5e-11;
  Interval far = make(0.0, 5.0, Vec2(-1000.0, 0.5), 0.0);
  far.markPropagated();
  const Interval m = make(5.0, kL, Vec2(5.0, 1.0), 1005.0);
  const double meet = 5.0 + delta;  // where N is to cross M
  const Interval n = make(5.0, kL, Vec2(8.0, 1.0), m.distanceAt(meet) - std::hypot(8.0 - meet, 1.0));
  ASSERT_GT(tinyLength(far, kL), 50 * tinyLength(n, kL));
  ASSERT_LT(far.distanceAt(5.0), m.distanceAt(5.0));  // the far window may take the sliver
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  list.assign(std::vector<Interval>{far, m});
  list.insert(n, kL, report, scratch);
  EXPECT_EQ(report.degeneracies[DegeneracyKind::D1], 1u);
  ASSERT_EQ(list.intervals().size(), 2u);
  EXPECT_EQ(list.intervals()[0].source, far.source);
  EXPECT_EQ(list.intervals()[1].source, n.source);
  EXPECT_NEAR(list.intervals()[0].b1, meet, 1e-12) << "the far window grew over the sliver";
}

// Edge 3-13 of corpus/fuzz_solver/regress/vertex-agreement-d1-pieces-of-a-source-near-a-corner-
// merged-into-a-far-g1-window, in mesh units: vertex 3's window along the edge (0.364 at x = 0),
// then a face source's windows in four pieces, two of them shorter than the source's ε (4.4e-12)
// and alone inside the G1 window, which is 0.13 longer there. Each such piece was merged into the
// G1 window beside it, and the edge's end kept 0.6296 where the source gives 0.49999999998.
TEST(Algorithm2, PiecesOfASourceShorterThanItsEpsilonAreNotMergedIntoAFarLongerNeighbour) {
  constexpr double L = 0.2651650429449553;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Vec2 source(-0.088388347631524658, 0.35355339059327379);
  list.insert(make(0.0, L, Vec2(0.0, 0.0), 0.36443449342375822), L, report, scratch);
  for (const auto& [b0, b1] : {std::pair{0.0, 0.26516504293487908},
                               std::pair{0.26516504293935739, 0.26516504294255616},
                               std::pair{0.0, 0.26516504293935739}, std::pair{0.26516504294255622, L}})
    list.insert(make(b0, b1, source, 0.0), L, report, scratch);
  const Interval direct = make(0.0, L, source, 0.0);
  for (const double x : {0.26516504293935739, 0.2651650429410, 0.26516504294255622, L})
    EXPECT_NEAR(list.distanceAt(x), direct.distanceAt(x), 1e-12) << "at x = " << x;
}

// corpus/fuzz_edge_update/regress/no-tiny-interval-step-3-threshold-blind-to-a-far-neighbour-
// outside-the-slice: a sliver kept because no neighbour may take it, 1e-8 before a window from
// 147456 away, whose ray-end precision (1.5e-9) makes the sliver tiny. A new window that ends
// where the sliver starts, and is shorter there, may take it; the update's slice holds the sliver
// but not the far window, and step 3 measured the sliver by its own ε (1e-11) only.
TEST(Algorithm2, ASliverTinyByAFarNeighbourOutsideTheSliceIsTakenByTheNewWindow) {
  constexpr double L = 1.0;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Interval far = make(0.0625 + 1e-8, L, Vec2(-147456.0, 1e-9), 0.0);
  const Interval sliver = make(0.0625, 0.0625 + 2.4e-11, Vec2(0.0, 1e-9), 2.0);
  list.insert(far, L, report, scratch);
  list.insert(sliver, L, report, scratch);
  ASSERT_EQ(list.intervals().size(), 2u) << "no neighbour may take the sliver: it stays";
  ASSERT_LT(sliver.length(), tinyLengthInList(list.intervals(), 0, L));
  list.insert(make(0.0, 0.0625, Vec2(0.0, 0.0), 0.0), L, report, scratch);
  ASSERT_EQ(list.intervals().size(), 2u);
  EXPECT_EQ(list.intervals()[0].b1, sliver.b1) << "the new window grew over the sliver";
  EXPECT_EQ(list.intervals()[1].b0, far.b0);
}

// corpus/fuzz_solver/regress/full-coverage-ties-of-collinear-pseudo-sources-kept-in-arrival-
// order: a source s and a saddle p on one line from it, which crosses the edge at x = 0.5. p's
// window (σ = |p − s|) is never shorter than s's and ties with it within rounding for ~1e-7
// around 0.5; s's window ends there (p's shadow). Either way round, s must keep the tie and the
// two meet at 0.5 itself: a breakpoint left 1e-7 off the line makes their windows on the next
// edge, cast from s and from p, leave a gap.
TEST(Algorithm2, ATieBetweenASourceAndASaddleOnItsLineGoesToTheSourceInEitherOrder) {
  const Vec2 s(0.1, 0.8), p(0.3, 0.4);  // the line s → p reaches y = 0 at x = 0.5
  const Interval direct = make(0.0, 0.5, s, 0.0);
  const Interval saddle = make(0.3, kL, p, (p - s).norm());
  for (const bool saddleFirst : {true, false}) {
    Edge1 e;
    e.insert(saddleFirst ? saddle : direct);
    e.insert(saddleFirst ? direct : saddle);
    expectWellFormed(e.list);
    ASSERT_EQ(e.list.intervals().size(), 2u) << (saddleFirst ? "saddle first" : "source first");
    EXPECT_EQ(e.list.intervals()[0].source, s);
    EXPECT_NEAR(e.list.intervals()[0].b1, 0.5, 1e-12) << (saddleFirst ? "saddle first" : "source first");
  }
}

// Inserts `window` and `strip` in both orders, one update each and as one run. A tie strip stays
// with the window around it (one interval, the window's, over the whole edge); a strip shorter by
// more than the tie tolerance is cut out of it (three intervals, the strip's in the middle).
void expectStripInsideAWindowInEitherOrder(const Interval& window, const Interval& strip,
                                           bool ties) {
  for (const int order : {0, 1, 2, 3}) {
    const bool windowFirst = order % 2 == 0, asRun = order >= 2;
    SCOPED_TRACE(std::string(windowFirst ? "window first" : "strip first") +
                 (asRun ? ", one run" : ", two updates"));
    Edge1 e;
    if (asRun) {
      e.insertRun({windowFirst ? window : strip, windowFirst ? strip : window});
    } else {
      e.insert(windowFirst ? window : strip);
      e.insert(windowFirst ? strip : window);
    }
    expectWellFormed(e.list);
    if (ties) {
      ASSERT_EQ(e.list.intervals().size(), 1u);
      EXPECT_EQ(e.list.intervals()[0].source, window.source);
      EXPECT_EQ(e.list.intervals()[0].b0, 0.0);
      EXPECT_EQ(e.list.intervals()[0].b1, kL);
    } else {
      ASSERT_EQ(e.list.intervals().size(), 3u);
      EXPECT_EQ(e.list.intervals()[1].source, strip.source);
      expectPointwiseMin(e.list, {window, strip}, 0.0, kL);
    }
  }
}

// The same source s and saddle p, but p's window covers the whole edge (the old one, or arriving
// second) and s's is a strip beside the line s → p (x = 0.5), where the two tie to rounding
// (tests/data/regression/couplingdown-part-edge-source-leaves-a-gap.off, edge 12-28). Either way
// round the strip stays p's: cut out of p's window by the tie rule, it left p | s | p, whose rays
// at the strip's far border diverge on the next edges into gaps wider than step 4 sews. A strip
// wide enough that s is shorter by more than the tie tolerance is s's (control).
TEST(Algorithm2, ATieStripInsideAWindowStaysWithThatWindowInEitherOrder) {
  const Vec2 s(0.1, 0.8), p(0.3, 0.4);
  const Interval saddle = make(0.0, kL, p, (p - s).norm());
  for (const double width : {1e-8, 1e-3}) {
    SCOPED_TRACE("strip " + std::to_string(width));
    expectStripInsideAWindowInEitherOrder(saddle, make(0.5, 0.5 + width, s, 0.0), width < 1e-6);
  }
}

// The same with both pseudo-sources on the edge's line: a source s 2 behind the edge's start and
// the vertex at the start, reached from s straight (σ = 0.5 + 2), whose window covers the edge. The
// two distances are equal on all of it, so s's strip ties the vertex's window exactly, and the tie
// is told from the sources' feet on the line instead of a crossing point x*. Either way round the
// strip stays the vertex's; a strip where s is shorter by 1e-3 is s's (control).
TEST(Algorithm2, ATieStripOfTwoSourcesOnTheEdgeLineStaysWithTheWindowAroundItInEitherOrder) {
  const Vec2 s(-2.0, 0.0), vertex(0.0, 0.0);
  const Interval alongTheEdge = make(0.0, kL, vertex, 2.5);
  for (const double shorter : {0.0, 1e-3}) {
    SCOPED_TRACE("s shorter by " + std::to_string(shorter));
    expectStripInsideAWindowInEitherOrder(alongTheEdge, make(4.0, 4.5, s, 0.5 - shorter),
                                          shorter == 0.0);
  }
}

// A run of three children: the second meets the first at x = 2.5 by Eq. 1 (their sources are
// mirror images about it), then the third, from a source on the edge at 0, is shorter over
// [0, 5] and takes the second's piece up to 2.5. The breakpoint now joins the third child to the
// first, which Eq. 1 never made equal: the update must not report it
// (corpus/fuzz_edge_update/regress/continuous-at-eq1-run-breakpoint-of-an-earlier-child-taken-by-
// a-later-one: reported, the checker found 2.5 against 3.37 there).
TEST(Algorithm2, ARunsLaterChildTakingAnEarlierOnesEq1BreakpointLeavesNoBreakpointThere) {
  Edge1 e;
  e.insertRun({make(0.0, 5.0, Vec2(5.625, 1.25), 0.0), make(1.25, 7.5, Vec2(-0.625, 1.25), 0.0),
               make(0.0, 2.5, Vec2(0.0, 0.0), 0.0)});
  expectWellFormed(e.list);
  const auto list = e.list.intervals();
  for (const double x : e.report.eq1Breakpoints) {
    for (std::size_t i = 0; i + 1 < list.size(); ++i) {
      if (list[i].b1 != x || list[i + 1].b0 != x) continue;
      EXPECT_NEAR(list[i].distanceAt(x), list[i + 1].distanceAt(x), 1e-12) << "breakpoint " << x;
    }
  }
  // The pieces as the three distances order them: the third up to 2.5, the first, the second.
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].source, Vec2(0.0, 0.0));
  EXPECT_EQ(list[1].source, Vec2(5.625, 1.25));
  EXPECT_EQ(list[2].source, Vec2(-0.625, 1.25));
}

// The same three children after two that crossed old intervals at 8.125 and 9.375 (each pair of
// sources mirror images about the crossing): the run's earlier breakpoints are then 8.125, 9.375
// and 2.5, in that order of arrival, and the last child must still find 2.5 among them. They are
// searched sorted; left in arrival order, the search from 0 to 2.5 stopped at 8.125 and 2.5 stayed
// reported.
TEST(Algorithm2, ARunsLaterChildFindsAnEarlierBreakpointWhateverOrderTheyCameIn) {
  Edge1 e;
  e.insert(make(7.5, 8.75, Vec2(11.125, 1.25), 0.0));
  e.insert(make(8.75, kL, Vec2(12.375, 1.25), 0.0));
  e.insertRun({make(7.5, 8.75, Vec2(5.125, 1.25), 0.0), make(8.75, kL, Vec2(6.375, 1.25), 0.0),
               make(0.0, 5.0, Vec2(5.625, 1.25), 0.0), make(1.25, 7.5, Vec2(-0.625, 1.25), 0.0),
               make(0.0, 2.5, Vec2(0.0, 0.0), 0.0)});
  expectWellFormed(e.list);
  const auto list = e.list.intervals();
  ASSERT_EQ(list.size(), 7u);
  EXPECT_EQ(list[0].source, Vec2(0.0, 0.0));
  ASSERT_EQ(e.report.eq1Breakpoints.size(), 2u);
  EXPECT_NEAR(e.report.eq1Breakpoints[0], 8.125, 1e-12);
  EXPECT_NEAR(e.report.eq1Breakpoints[1], 9.375, 1e-12);
}

// Which of `run` the update charged a repair to (forEachRepairedIncoming), 1 or 0 each.
std::vector<std::uint8_t> repairedChildren(const EdgeUpdateReport& r,
                                           std::span<const Interval> run) {
  std::vector<std::uint8_t> repaired(run.size(), 0);
  forEachRepairedIncoming(r, run, [&](std::size_t k) { repaired[k] = 1; });
  return repaired;
}

// Steps 3–5 run once for a run, but each repair is charged to the child it was made at
// (forEachRepairedIncoming), as when each child was an update of its own: the first child overlaps
// the old interval by a D2 rounding overlap, the third leaves a D3 gap after the second, which is
// charged to the third (one update after another, the third's met it), and the second has nothing
// repaired. Charged to the whole run, all three cases counted as degenerate (libcgal-demo's
// fandisk.off read 90.4 % where one update per child read 38.5 %).
TEST(Algorithm2, ARunChargesEachRepairToTheChildItWasMadeAt) {
  const double tiny = 0.2 * tol::kTinyIntervalRel * kL;
  const Interval old = make(0.0, 2.0, Vec2(1.0, 1.0), 0.0);
  const std::vector<Interval> run = {make(2.0 - tiny, 4.0, Vec2(3.0, 1.0), 0.0),
                                     make(4.0, 7.0, Vec2(5.5, 1.0), 0.0),
                                     make(7.0 + tiny, kL, Vec2(8.5, 1.0), 0.0)};
  const std::vector<std::uint8_t> expected = {1, 0, 1};
  Edge1 e;
  e.insert(old);
  e.insertRun(run);
  expectWellFormed(e.list);
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D2], 1u);
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D3], 1u);
  EXPECT_EQ(repairedChildren(e.report, run), expected);
  // The same children one update each: each is charged what its own update repaired.
  Edge1 one;
  one.insert(old);
  for (std::size_t k = 0; k < run.size(); ++k) {
    one.insert(run[k]);
    EXPECT_EQ(repairedChildren(one.report, std::span<const Interval>(&run[k], 1)),
              std::vector<std::uint8_t>{expected[k]})
        << "child " << k;
  }
}

// A run of four children on an edge of about 2^20: a source on the edge's line at 512, then three
// nearly the same geodesic from the edge's start (a source 0.5 and 2e-5 above it, one on it). The
// later ones tie the earlier ones' pieces between their own, and the tie strip pass erased an
// earlier child's Eq. 1 breakpoint, which left the run's count of earlier breakpoints past the
// end of the list: erasing up to it was out of bounds (AddressSanitizer: negative-size-param;
// corpus/fuzz_edge_update/regress/negative-size-param-run-tie-strip-erased-an-earlier-childs-
// breakpoint). The update must stay in bounds, leave the list well formed and report only
// breakpoints where the two distances agree.
TEST(Algorithm2, ATieStripPassInARunMayEraseAnEarlierChildsBreakpoint) {
  const double length = 1048575.9999934464;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  IntervalList work;
  const std::vector<Interval> run = {make(0.0, 1024.0, Vec2(512.0, 0.0), 0.0),
                                     make(0.0, length, Vec2(0.0001677721599989514, 0.5), 0.0),
                                     make(0.0, 1048320.5, Vec2(0.0, 2.0971519999868925e-05), 0.0),
                                     make(0.0, 256.0, Vec2(0.0, 0.0), 0.0)};
  list.insertRun(run, length, report, scratch, work);
  const auto w = list.intervals();
  ASSERT_FALSE(w.empty());
  EXPECT_EQ(w.front().b0, 0.0);
  EXPECT_EQ(w.back().b1, length);
  for (std::size_t i = 0; i + 1 < w.size(); ++i) EXPECT_EQ(w[i].b1, w[i + 1].b0);
  for (const double x : report.eq1Breakpoints) {
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
      if (w[i].b1 != x || w[i + 1].b0 != x) continue;
      EXPECT_NEAR(w[i].distanceAt(x), w[i + 1].distanceAt(x), 1e-9 * (x + 1.0))
          << "breakpoint " << x;
    }
  }
}

// A saddle s' 5.7e4 from the edge and a source s 1 behind it on its line to x = 5, σ = σ' − 1 plus
// the tie tolerance (6.1e-10 there; found by a search over such pairs): on s's strip
// [5 − 1/128, 5 + 1/128] s is longer than the saddle's window by the tolerance itself, and one ulp
// of the two distances (7e-12) decides, point by point, between a tie s wins by its smaller σ and
// a loss. The saddle's window is then cut into several pieces, not one strip; nowhere shorter by
// more than the tolerance, s gets none of them, and the saddle's window stays whole.
TEST(Algorithm2, AStripNowhereShorterByMoreThanTheTieToleranceLeavesTheWindowAroundItWhole) {
  const Vec2 saddleSource(31041.0, 47863.0);
  const Interval saddle = make(0.0, kL, saddleSource, 4074.0);
  const Interval strip = make(5.0 - 0.0078125, 5.0 + 0.0078125,
                              Vec2(31041.544064377402, 47863.839043475178), 4073.000000000618);
  ASSERT_LT(strip.sigma, saddle.sigma);
  bool tiesSomewhere = false, losesSomewhere = false;
  for (int k = 0; k <= 1000; ++k) {
    const double x = strip.b0 + (strip.b1 - strip.b0) * k / 1000.0;
    const double f = strip.distanceAt(x), g = saddle.distanceAt(x);
    ASSERT_GE(f, g - tol::kTieRel * g) << "s is clearly shorter at x = " << x;
    (f <= g + tol::kTieRel * g ? tiesSomewhere : losesSomewhere) = true;
  }
  ASSERT_TRUE(tiesSomewhere && losesSomewhere) << "the rounding does not split the verdict";
  Edge1 e;
  e.insert(saddle);
  e.insert(strip);
  expectWellFormed(e.list);
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_EQ(e.list.intervals()[0].source, saddleSource);
  EXPECT_EQ(e.list.intervals()[0].b0, 0.0);
  EXPECT_EQ(e.list.intervals()[0].b1, kL);
}

// Two pseudo-sources on the edge line at or behind its start, the far one reaching the near one
// straight (σ_near = σ_far + their distance): their distances tie on the whole window, up to
// rounding, and the far one (σ smaller) keeps it in either order. The near one's window is a
// pseudo-source's window along its own edge; the far one arriving second may round a few ulps
// longer at the start, which must not make it lose there without the tie rule being asked.
TEST(Algorithm2, TwoSourcesOnTheEdgeLineTieToTheFarOneInEitherOrder) {
  int roundedLonger = 0;
  for (int k = 0; k < 400; ++k) {
    const double a = 0.37 + 0.0173 * k, sigmaFar = 0.11 * (k % 37) + 0.3, start = 0.01 * (k % 53);
    const Interval far = make(start, kL, Vec2(-a, 0.0), sigmaFar);
    const Interval near = make(start, kL, Vec2(0.0, 0.0), sigmaFar + a);
    if (far.distanceAt(start) > near.distanceAt(start)) ++roundedLonger;
    for (const bool nearFirst : {true, false}) {
      Edge1 e;
      e.insert(nearFirst ? near : far);
      e.insert(nearFirst ? far : near);
      expectWellFormed(e.list);
      ASSERT_EQ(e.list.intervals().size(), 1u) << "a = " << a;
      EXPECT_EQ(e.list.intervals()[0].source, far.source)
          << "a = " << a << (nearFirst ? ", near first" : ", far first");
    }
  }
  EXPECT_GT(roundedLonger, 0) << "no case where rounding makes the far source longer at the start";
}

// corpus/fuzz_edge_update/regress/no-tiny-interval-step-5-merge-makes-a-sliver-takeable-after-
// step-3: two windows of near-equal sources (σ 4e-11 and 5e-11) side by side, then a 9e-11 gap
// and a 9e-11 sliver of a third near-equal one; a window from 49888 away, long everywhere, fills
// the gap and makes the sliver tiny (its ray-end precision, 5e-10). In step 3 the second window
// grew over the gap but could not take the sliver (longer by just over the slack there); step 5
// then merged it into the first, whose σ is 1e-11 smaller and which may take it. It was left.
TEST(Algorithm2, ASliverANeighbourMayTakeOnlyAfterStep5MergedItIsTaken) {
  constexpr double L = 1.9999999997875;
  const Interval sliver = make(1.8557205201895313, 1.8557205202795313,
                               Vec2(0.10937499999000001, 3.998054501964531), 4.9999999994687499e-11);
  EdgeIntervals list;
  list.assign({make(0.0, 1.8554763794345313, Vec2(0.10937500008000001, 3.9980545020545311),
                    3.9999999995749995e-11),
               make(1.8554763794345313, 1.8557205200995313,
                    Vec2(0.10937500007875001, 3.9980545020545311), 4.9999999994687499e-11),
               sliver, make(1.9357986433595313, L, Vec2(0.0, 3.9980545052145313), 0.0)});
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  list.insert(make(0.0, L, Vec2(49888.0, 1.2874999998632031e-10), 0.0), L, report, scratch);
  for (const Interval& w : list.intervals())
    EXPECT_FALSE(w.b0 == sliver.b0 && w.b1 == sliver.b1) << "the sliver is still there";
}

// A sliver of another source ending at a vertex, meeting a window that covers it where the two
// are equal at the vertex (two sources on one line through it): the sliver's rays beyond the
// vertex may fan out wider than the window's. When step 3 removes such a sliver into the window,
// the update reports the fan lost at that vertex (the solver has it relay the fan); a sliver that
// loses outright to the window, arriving after it, now reports it too. Before, only the first did,
// and a source's shadow behind a hole's corner was left uncovered in the order where the sliver
// came second (corpus/fuzz_solver/regress/full-coverage-source-ray-along-a-line-of-vertices-shadow-
// left-by-batch-order).
TEST(Algorithm2, ASliverOfAnotherSourceLostAtAVertexRelaysItsFanAsOneStep3Removes) {
  const Interval window = make(0.0, kL, Vec2(5.0, 3.0), 0.0);
  const Vec2 far(12.0, 1.0);
  // σ so that the two are equal at x = L (the sliver longer inside its range); 5e-11 long, below
  // the sliver's ε (1e-11 × 13).
  const double sigma = window.distanceAt(kL) - (far - Vec2(kL, 0.0)).norm();
  {  // lost outright: the new report
    Edge1 e;
    e.insert(window);
    e.insert(make(kL - 5e-11, kL, far, sigma));
    EXPECT_FALSE(e.report.incomingSurvived);
    EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D1], 0u);
    EXPECT_EQ(e.report.fanLostAtVertex, 2);  // at the edge's end: its vertex[1]
  }
  {  // shorter by 1e-12 at the vertex, there first: step 3 removes it (the report it always made)
    Edge1 e;
    e.insert(make(kL - 5e-11, kL, far, sigma - 1e-12));
    e.insert(window);
    EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D1], 1u);
    EXPECT_EQ(e.report.fanLostAtVertex, 2);
  }
  {  // lost outright in a run, as a batch's children reach their edge, at both ends
    Edge1 e;
    e.insert(window);
    const Vec2 before(-2.0, 1.0);
    const double sigma0 = window.distanceAt(0.0) - before.norm();
    e.insertRun({make(0.0, 5e-11, before, sigma0), make(kL - 5e-11, kL, far, sigma)});
    EXPECT_EQ(e.report.fanLostAtVertex, 3);
  }
  {  // not when the window is the sliver's own source, nor away from a vertex, nor for more than
     // a sliver
    Edge1 same, away, longer;
    same.insert(window);
    same.insert(make(kL - 5e-11, kL, window.source, 0.0));
    EXPECT_EQ(same.report.fanLostAtVertex, 0);
    away.insert(window);
    const double mid = 5.0;
    const double sigmaMid = window.distanceAt(mid) - (far - Vec2(mid, 0.0)).norm();
    away.insert(make(mid - 5e-11, mid, far, sigmaMid));
    EXPECT_EQ(away.report.fanLostAtVertex, 0);
    longer.insert(window);
    longer.insert(make(kL - 1.0, kL, far, sigma + 1.0));
    EXPECT_FALSE(longer.report.incomingSurvived);
    EXPECT_EQ(longer.report.fanLostAtVertex, 0);
  }
}

TEST(Algorithm2, BetterEverywhereReplacesOld) {
  Edge1 e;
  e.insert(make(0.0, kL, Vec2(5.0, 3.0), 2.0));
  e.insert(make(0.0, kL, Vec2(5.0, 3.0), 1.0));
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_EQ(e.list.intervals()[0].sigma, 1.0);
}

TEST(Algorithm2, WorseEverywhereIsRejected) {
  Edge1 e;
  e.insert(make(0.0, kL, Vec2(5.0, 3.0), 1.0));
  e.insert(make(2.0, 8.0, Vec2(5.0, 3.0), 2.0));
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_FALSE(e.report.incomingSurvived);
}

TEST(Algorithm2, CrossingFunctionsSplitWhereEqual) {
  // Two sources left and right: the split is on the perpendicular bisector, x = 5.
  Edge1 e;
  const Interval a = make(0.0, kL, Vec2(2.0, 1.0), 0.0);
  const Interval b = make(0.0, kL, Vec2(8.0, 1.0), 0.0);
  e.insert(a);
  e.insert(b);
  expectWellFormed(e.list);
  ASSERT_EQ(e.list.intervals().size(), 2u);
  EXPECT_NEAR(e.list.intervals()[0].b1, 5.0, 1e-12);
  ASSERT_EQ(e.report.eq1Breakpoints.size(), 1u);
  expectPointwiseMin(e.list, {a, b}, 0.0, kL);
}

TEST(Algorithm2, OldSurvivesInTheMiddleWithTwoRoots) {
  // Old: close to the edge at x = 5 but σ = 1; new: σ = 0 but 2 away. Near x = 5 the old is
  // shorter (1.1 < 2), far from it the new one is (x = 0: 6.001 > 5.39).
  Edge1 e;
  const Interval old = make(0.0, kL, Vec2(5.0, 0.1), 1.0);
  const Interval in = make(0.0, kL, Vec2(5.0, 2.0), 0.0);
  e.insert(old);
  e.insert(in);
  expectWellFormed(e.list);
  ASSERT_EQ(e.list.intervals().size(), 3u);
  EXPECT_EQ(e.report.eq1Breakpoints.size(), 2u);
  expectPointwiseMin(e.list, {old, in}, 0.0, kL);
  // Both pieces of the new interval need propagating; the middle is the old one's function.
  EXPECT_EQ(e.list.intervals()[1].sigma, 1.0);
  EXPECT_EQ(e.toQueue().size(), 3u) << "two new pieces and the cut old one (still pending)";
}

TEST(Algorithm2, PartialOverlapSplitsTheOldAtTheNewEnds) {
  Edge1 e;
  const Interval old = make(0.0, kL, Vec2(5.0, 4.0), 3.0);
  const Interval in = make(3.0, 6.0, Vec2(4.5, 1.0), 0.5);
  e.insert(old);
  e.insert(in);
  expectWellFormed(e.list);
  expectPointwiseMin(e.list, {old, in}, 0.0, kL);
}

TEST(Algorithm2, GapsBetweenOldIntervalsGoToTheNewOne) {
  Edge1 e;
  const Interval a = make(0.0, 2.0, Vec2(1.0, 1.0), 0.0);
  const Interval b = make(8.0, kL, Vec2(9.0, 1.0), 0.0);
  const Interval in = make(0.0, kL, Vec2(5.0, 1.0), 0.0);
  e.insert(a);
  e.insert(b);
  e.insert(in);
  expectWellFormed(e.list);
  expectPointwiseMin(e.list, {a, b, in}, 0.0, kL);
  EXPECT_EQ(e.list.intervals().front().b0, 0.0);
  EXPECT_EQ(e.list.intervals().back().b1, kL);
}

TEST(Algorithm2, D1TinyIntervalIsMergedIntoItsNeighbour) {
  Edge1 e;
  e.insert(make(0.0, 5.0, Vec2(2.0, 1.0), 0.0));
  const Vec2 right(8.0, 1.0);
  e.insert(make(5.0, kL, right, 0.0));
  // A new interval on a sliver far below ε at x = 5, from another source (3e-9 away, beyond
  // kSameSourceRel) that is nearer x by 5e-11, less than ε: the right neighbour may take the
  // sliver (canTakeSliver).
  const Vec2 at(5.0, 0.0);
  const Vec2 toOld = right - at;
  const double turn = 1e-9, nearer = 5e-11;
  const Vec2 turned(toOld.x() * std::cos(turn) - toOld.y() * std::sin(turn),
                    toOld.x() * std::sin(turn) + toOld.y() * std::cos(turn));
  const Vec2 source = at + turned.normalized() * (toOld.norm() - nearer);
  const double tiny = 0.1 * tol::kTinyIntervalRel * kL;
  const Interval sliver = make(5.0, 5.0 + tiny, source, 0.0);
  ASSERT_LT(sliver.distanceAt(5.0), make(5.0, kL, right, 0.0).distanceAt(5.0));
  e.insert(sliver);
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D1], 1u);
  EXPECT_FALSE(e.report.incomingSurvived);
  expectWellFormed(e.list);
  for (const Interval& w : e.list.intervals()) EXPECT_GE(w.length(), tol::kTinyIntervalRel * kL);
}

TEST(Algorithm2, AnIntervalLongerEverywhereLeavesTheListAsItWas) {
  // Three old intervals cover [0, L]; the new one starts a hair (far below ε) after the second
  // one's start, reaches into the third, and is longer everywhere (its source farther from the
  // edge). Cutting the second one there would leave a D1 sliver of the old interval itself;
  // nothing of the list may change, and no degeneracy is counted.
  Edge1 e;
  e.insert(make(0.0, 3.0, Vec2(1.5, 1.0), 0.0));
  e.insert(make(3.0, 6.0, Vec2(4.5, 1.0), 0.0));
  e.insert(make(6.0, kL, Vec2(8.0, 1.0), 0.0));
  const std::vector<Interval> before(e.list.intervals().begin(), e.list.intervals().end());
  const Interval longer = make(3.0 + 0.1 * tol::kTinyIntervalRel * kL, 8.0, Vec2(4.0, 5.0), 0.0);
  for (double x = longer.b0; x <= longer.b1; x += 0.01)
    ASSERT_GT(longer.distanceAt(x), e.list.distanceAt(x)) << x;
  e.insert(longer);
  EXPECT_FALSE(e.report.incomingSurvived);
  EXPECT_EQ(e.report.degeneracies.count, DegeneracyCounters{}.count);
  ASSERT_EQ(e.list.intervals().size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(e.list.intervals()[i].b0, before[i].b0);
    EXPECT_EQ(e.list.intervals()[i].b1, before[i].b1);
    EXPECT_EQ(e.list.intervals()[i].source, before[i].source);
  }
}

TEST(Algorithm2, AnIntervalLongerOnAllItsRangeLeavesTheListAsItWasThoughShorterBeyondIt) {
  // As above, but the new window's source lies beyond its end, above the edge's end: its
  // distance function, continued past the window, would be the shorter one there. A window is
  // its range only; longer on all of it, it changes nothing (no cut, no D1 sliver).
  Edge1 e;
  e.insert(make(0.0, 3.0, Vec2(1.5, 1.0), 0.0));
  e.insert(make(3.0, 6.0, Vec2(4.5, 1.0), 0.0));
  e.insert(make(6.0, kL, Vec2(8.0, 1.0), 0.0));
  const std::vector<Interval> before(e.list.intervals().begin(), e.list.intervals().end());
  const Interval longer = make(3.0 + 0.1 * tol::kTinyIntervalRel * kL, 8.0, Vec2(kL, 0.5), 0.0);
  for (double x = longer.b0; x <= longer.b1; x += 0.01)
    ASSERT_GT(longer.distanceAt(x), e.list.distanceAt(x)) << x;
  ASSERT_LT(longer.distanceAt(kL), e.list.distanceAt(kL));
  e.insert(longer);
  EXPECT_FALSE(e.report.incomingSurvived);
  EXPECT_EQ(e.report.degeneracies.count, DegeneracyCounters{}.count);
  ASSERT_EQ(e.list.intervals().size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(e.list.intervals()[i].b0, before[i].b0);
    EXPECT_EQ(e.list.intervals()[i].b1, before[i].b1);
    EXPECT_EQ(e.list.intervals()[i].source, before[i].source);
  }
}

TEST(Algorithm2, AnIntervalShorterOnlyInAGapIsKeptThere) {
  // The same longer interval, but the old ones leave a gap wider than ε: there it is the only
  // distance, and it is kept on exactly the gap.
  Edge1 e;
  e.insert(make(0.0, 3.0, Vec2(1.5, 1.0), 0.0));
  e.insert(make(3.5, kL, Vec2(6.0, 1.0), 0.0));
  e.insert(make(1.0, 6.0, Vec2(4.0, 5.0), 0.0));
  EXPECT_TRUE(e.report.incomingSurvived);
  expectWellFormed(e.list);
  ASSERT_EQ(e.list.intervals().size(), 3u);
  EXPECT_EQ(e.list.intervals()[1].b0, 3.0);
  EXPECT_EQ(e.list.intervals()[1].b1, 3.5);
  EXPECT_EQ(e.list.intervals()[1].source, Vec2(4.0, 5.0));
}

TEST(Algorithm2, D2TinyOverlapMeetsAtTheMidpoint) {
  Edge1 e;
  e.insert(make(0.0, 5.0, Vec2(2.0, 1.0), 0.0));
  const double overlap = 0.2 * tol::kTinyIntervalRel * kL;
  e.insert(make(5.0 - overlap, kL, Vec2(8.0, 1.0), 0.0));
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D2], 1u);
  expectWellFormed(e.list);
  ASSERT_EQ(e.list.intervals().size(), 2u);
  EXPECT_DOUBLE_EQ(e.list.intervals()[0].b1, 5.0 - overlap / 2);
}

TEST(Algorithm2, D2RealOverlapGoesToTheShorterInterval) {
  // Regression (corpus/fuzz_edge_update/regress/pointwise-min-D2-overlap-midpoint-keeps-larger-
  // distance): the new interval starts 3e-11 before the old one ends, below ε, so it is D2, not
  // split by Eq. 1. The two are far apart there (2.83 against 4.47): meeting at the midpoint gave
  // the longer distance half the overlap. The shorter keeps it all.
  Edge1 e;
  const Interval old = make(0.0, 4.0, Vec2(2.0, 2.0), 0.0);
  const Interval in = make(4.0 - 3e-11, kL, Vec2(8.0, 2.0), 0.0);
  e.insert(old);
  e.insert(in);
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D2], 1u);
  ASSERT_EQ(e.list.intervals().size(), 2u);
  EXPECT_EQ(e.list.intervals()[0].b1, 4.0);
  EXPECT_NEAR(e.list.distanceAt(4.0 - 1e-11), old.distanceAt(4.0 - 1e-11), 1e-15);
}

// An edge length near kL on which ε (tinyLength: kTinyIntervalRel × the edge length, for sources
// nearer than it) is a power of two, eps: ends placed eps apart then differ by exactly eps in doubles.
double edgeWithDyadicEpsilon(double& eps) {
  eps = std::exp2(std::round(std::log2(tol::kTinyIntervalRel * kL)));
  double L = eps / tol::kTinyIntervalRel;
  while (tol::kTinyIntervalRel * L < eps) L = std::nextafter(L, INFINITY);
  while (tol::kTinyIntervalRel * L > eps) L = std::nextafter(L, 0.0);
  return L;
}

// `in` overlaps `old` by exactly eps = ε on an edge of length L, and old is shorter on all of the
// overlap: no D2, the two meet at old's end (or start) 5, and at x, inside the overlap, the list
// gives old's distance.
void expectAnOverlapOfExactlyEpsilonSplitByEq1(const Interval& old, const Interval& in, double L,
                                               double eps, double x) {
  ASSERT_EQ(std::max(tinyLength(old, L), tinyLength(in, L)), eps);
  ASSERT_EQ(std::min(old.b1, in.b1) - std::max(old.b0, in.b0), eps);
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  list.insert(old, L, report, scratch);
  list.insert(in, L, report, scratch);
  EXPECT_EQ(report.degeneracies[DegeneracyKind::D2], 0u);
  ASSERT_EQ(list.intervals().size(), 2u);
  EXPECT_EQ(list.intervals()[0].b1, 5.0);
  EXPECT_EQ(list.intervals()[1].b0, 5.0);
  ASSERT_LT(old.distanceAt(x), in.distanceAt(x));
  EXPECT_EQ(list.distanceAt(x), old.distanceAt(x));
}

TEST(Algorithm2, AnOverlapOfExactlyEpsilonAtTheNewStartIsARealOverlapSplitByEq1) {
  // D2 is an overlap shorter than ε (the larger of the two intervals' ε); one of exactly ε is
  // real and step 2 splits it by Eq. 1. Here the old interval is shorter on all of it (the
  // bisector lies ε past its end) and keeps it whole. Met at the midpoint as a D2 (the two agree
  // there to kContinuityRel), the longer incoming distance would take half of it; x = 5 − ε/4 is
  // in that half.
  double eps = 0.0;
  const double L = edgeWithDyadicEpsilon(eps);
  expectAnOverlapOfExactlyEpsilonSplitByEq1(make(0.0, 5.0, Vec2(2.0 + eps, 1.0), 0.0),
                                            make(5.0 - eps, L, Vec2(8.0 + eps, 1.0), 0.0), L, eps,
                                            5.0 - eps / 4);
}

TEST(Algorithm2, AnOverlapOfExactlyEpsilonAtTheNewEndIsARealOverlapSplitByEq1) {
  // The mirror image of the case above: the old interval starts exactly ε before the incoming
  // one ends, and is shorter on all of the overlap.
  double eps = 0.0;
  const double L = edgeWithDyadicEpsilon(eps);
  expectAnOverlapOfExactlyEpsilonSplitByEq1(make(5.0, L, Vec2(8.0 - eps, 1.0), 0.0),
                                            make(0.0, 5.0 + eps, Vec2(2.0 - eps, 1.0), 0.0), L, eps,
                                            5.0 + eps / 4);
}

TEST(Algorithm2, AnEq1BreakpointAtARemovedSliverIsNoLongerABreakpoint) {
  // Regression (corpus/fuzz_edge_update/regress/continuous-at-eq1-breakpoint-of-removed-sliver):
  // Eq. 1 splits the short last interval, the piece it gives the incoming one is a sliver (D1),
  // and the first interval grows over it. Its end is now the Eq. 1 point, but it meets an
  // interval Eq. 1 never compared it with (1.36e-4 against 2.34e-4 there): the report must not
  // call that point a breakpoint whose two sides agree.
  const double L = 6.103515625e-05;
  EdgeIntervals list;
  list.assign({make(0.0, 6.1035156246999511e-05, Vec2(0.00012207031250415038, 0.00012207031249584962), 0.0),
               make(6.1035156246999511e-05, L, Vec2(6.103515625e-05, 6.103515625e-05), 0.00017263349149768717)});
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  list.insert(make(0.0, L, Vec2(0.0, 0.0), 0.00017263349150062194), L, report, scratch);
  EXPECT_EQ(report.degeneracies[DegeneracyKind::D1], 1u);
  const auto after = list.intervals();
  for (double x : report.eq1Breakpoints) {
    for (std::size_t i = 0; i + 1 < after.size(); ++i) {
      if (after[i].b1 != x || after[i + 1].b0 != x) continue;
      EXPECT_NEAR(after[i].distanceAt(x), after[i + 1].distanceAt(x),
                  tol::kContinuityRel * (after[i].distanceAt(x) + L))
          << "intervals " << i << " and " << i + 1 << " meet at breakpoint " << x;
    }
  }
}

TEST(Algorithm2, AnEq1RootLeavesRoomForStep5ToMergeItsNeighbour) {
  // Regression (corpus/fuzz_edge_update/regress/continuous-at-eq1-root-accepted-then-neighbour-
  // merged): on a 2^21-long edge, sources on the edge's line 2.1e-5 apart (the same source for
  // step 5: kSameSourceRel × L = 2.1e-5) and an incoming source at 4608. Eq. 1's root between
  // the incoming one and the source at 0 was off by 1.05e-4, which kContinuityRel × L = 2.1e-4
  // accepted; step 5 then merged that neighbour with the source at 2.1e-5, and the distances at
  // the breakpoint differed by 2.3e-4 (over kContinuityRel). Roots are now taken only within
  // kEq1RootRel, which leaves step 5 its margin, else bisected (D4).
  const double L = 2097152.0001664613;
  EdgeIntervals list;
  list.assign({make(2.0971520001664612e-05, 2048.0000419430398, Vec2(4.1943040003329223e-05, 0), 0),
               make(2048.0000419430398, 2051.0000838860797, Vec2(2.0971520001664612e-05, 0), 0),
               make(2051.0001258291195, 2221.0002306867195, Vec2(2.0971520001664612e-05, 0), 0),
               make(2221.0002306867195, 2223.0002936012797, Vec2(0, 0), 0),
               make(2223.0002936012797, 2077360.0002936013, Vec2(0, 0), 0),
               make(2077360.0002936013, 2077872.0006081741, Vec2(0, 0), 0),
               make(2077872.0006081741, L, Vec2(0, 2), 13.000859832320069)});
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Interval in = make(0.0, L, Vec2(4608, 0), 0.00020971520001664612);
  list.insert(in, L, report, scratch);
  const auto after = list.intervals();
  int checked = 0;
  for (double x : report.eq1Breakpoints) {
    for (std::size_t i = 0; i + 1 < after.size(); ++i) {
      if (after[i].b1 != x || after[i + 1].b0 != x) continue;
      const double a = after[i].distanceAt(x), b = after[i + 1].distanceAt(x);
      EXPECT_LE(std::abs(a - b), tol::kContinuityRel * (std::max(a, b) + L)) << "at x = " << x;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  // Where the incoming function meets the one from 0: x = (4608 + σ) / 2.
  const double meet = 0.5 * (4608 + in.sigma);
  EXPECT_NEAR(list.distanceAt(meet), meet, tol::kContinuityRel * (meet + L));
}

TEST(Algorithm2, AnEq1RootOfParallelFunctionsIsNotTaken) {
  // Regression (corpus/fuzz_edge_update/regress/pointwise-min-eq1-root-of-parallel-functions,
  // found by the fuzz smoke of a fresh ./test.sh): two sources 1.3e-10 apart near x = 0.109 on a
  // 2-long edge, the incoming one with σ = 1.3e-10. Beyond them the two distance functions run
  // parallel, the incoming one 2.6e-10 longer: within kEq1RootRel of each other everywhere, so a
  // root of Eq. 1 at x = 1.43 "agreed" and the incoming interval kept [1.2e-10, 1.43]. A root is
  // now taken only where f − g is nearer zero than at the samples around it.
  const double L = 1.9999999997875;
  const Interval old = make(0.0, 1.7500076294345313, Vec2(0.10937500008000001, 1.5999999998299998e-10), 0.0);
  EdgeIntervals list;
  list.assign({old});
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Interval in =
      make(1.1874999998738281e-10, 1.7843856798523436, Vec2(0.10937499995125001, 3.1249999996679667e-11), 1.2874999998632031e-10);
  list.insert(in, L, report, scratch);
  for (double x : {0.125, 0.5, 1.0, 1.4, 1.7}) {
    const double expected = std::min(old.distanceAt(x), in.distanceAt(x));
    EXPECT_NEAR(list.distanceAt(x), expected, tol::kPointwiseMinRel * (expected + L)) << "at x = " << x;
  }
}

TEST(Algorithm2, AFarPseudoSourceDoesNotWidenWhatStep4Sews) {
  // Regression (corpus/fuzz_edge_update/regress/pointwise-min-shadow-width-counted-sigma): step 4
  // used to sew up to kFlatVertexAngle × the whole distance, σ included: with σ = 3.2e12 that is
  // 3.2, and the old interval was stretched over [0, 0.0094), where only the new one reaches (the
  // old one's values there are not paths). A shadow widens along the rays, not with σ.
  const double L = 7864320.0045219837;
  EdgeIntervals list;
  list.assign({make(0.0094371840054263811, 4980736.0094371838,
                    Vec2(-8847360, 524287.99252889602), 3229815406592.0)});
  Interval in = make(0.0, 65536.0, Vec2(-8847360, 5636096.0074711042), 3229815406592.0);
  in.side = 1;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  list.insert(in, L, report, scratch);
  EXPECT_DOUBLE_EQ(list.distanceAt(0.0), in.distanceAt(0.0));
  EXPECT_DOUBLE_EQ(list.distanceAt(0.005), in.distanceAt(0.005));
}

TEST(Algorithm2, AnEdgeShorterThanEpsilonKeepsItsLastInterval) {
  // Regression (corpus/fuzz_two_faces/regress/full-coverage-edge-shorter-than-epsilon-lost-its-
  // last-interval): an edge 1.1e-8 long seen from a source 3.3e5 away has ε = 3.3e-6 > its
  // length, so every window on it is a D1 sliver; step 3 merged them into each other and then
  // removed the last one too, leaving the edge uncovered. The nearer window must be the edge's.
  const double L = 1.1313708498984759e-08;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Interval far = make(0.0, L, Vec2(0.0, 0.0), 327689.0);
  const Interval near = make(0.0, L, Vec2(7.78e-09, 327680.0), 0.0);
  list.insert(far, L, report, scratch);
  list.insert(near, L, report, scratch);
  ASSERT_EQ(list.intervals().size(), 1u);
  EXPECT_EQ(list.intervals()[0].b0, 0.0);
  EXPECT_EQ(list.intervals()[0].b1, L);
  EXPECT_DOUBLE_EQ(list.distanceAt(0.0), near.distanceAt(0.0));
  EXPECT_DOUBLE_EQ(list.distanceAt(L), near.distanceAt(L));
}

TEST(Algorithm2, AWindowAloneOnAnEdgeShorterThanItsEpsilonCoversTheEdge) {
  // Regression (corpus/fuzz_edge_update/regress/no-tiny-interval-short-edge-window-not-sewn-to-
  // its-ends): a window from 4.4e12 away has ε = 44 on a 6-long edge. Step 3 keeps it as the
  // edge's last window; step 4 must then stretch it to both ends, although the gaps of 1 beside
  // it are wider than its ray-end precision (0.044), which is all step 4 sews beside a window.
  const double L = 6.0;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  list.insert(make(1.0, 5.0, Vec2(4.0, 4444444444444.0), 0.0), L, report, scratch);
  ASSERT_EQ(list.intervals().size(), 1u);
  EXPECT_EQ(list.intervals()[0].b0, 0.0);
  EXPECT_EQ(list.intervals()[0].b1, L);
}

TEST(Algorithm2, AFarWindowOnAnEdgeShorterThanItsEpsilonGivesWayToANearNeighbour) {
  // Regression (corpus/fuzz_edge_update/regress/no-tiny-interval-short-edge-window-not-sewn-to-a-
  // near-neighbour): the window of the test above arrives beside a near window at [0, 0.5]. Step 4
  // sews the gap between them at its midpoint; the far window, now touching the near one and
  // shorter than its own ε, must then go (step 3 again), leaving the near window on the whole
  // edge. Steps 3 and 4 ran only once, and the far window stayed at [0.75, 6].
  const double L = 6.0;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  const Interval near = make(0.0, 0.5, Vec2(0.0, 0.0), 0.0);
  list.insert(near, L, report, scratch);
  list.insert(make(1.0, 5.0, Vec2(4.0, 4444444444444.0), 0.0), L, report, scratch);
  ASSERT_EQ(list.intervals().size(), 1u);
  EXPECT_EQ(list.intervals()[0].b0, 0.0);
  EXPECT_EQ(list.intervals()[0].b1, L);
  EXPECT_EQ(list.intervals()[0].source, near.source);
}

TEST(Algorithm2, D3TinyGapIsSewnAtTheMidpoint) {
  Edge1 e;
  e.insert(make(0.0, 5.0, Vec2(2.0, 1.0), 0.0));
  const double gap = 0.2 * tol::kTinyIntervalRel * kL;
  e.insert(make(5.0 + gap, kL, Vec2(8.0, 1.0), 0.0));
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D3], 1u);
  expectWellFormed(e.list);
  EXPECT_DOUBLE_EQ(e.list.intervals()[0].b1, 5.0 + gap / 2);
}

TEST(Algorithm2, D3GapAtTheEdgeEndIsSewn) {
  Edge1 e;
  const double gap = 0.2 * tol::kTinyIntervalRel * kL;
  e.insert(make(gap, kL, Vec2(8.0, 1.0), 0.0));
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D3], 1u);
  EXPECT_EQ(e.list.intervals()[0].b0, 0.0);
}

TEST(Algorithm2, D4InaccurateRootIsPolished) {
  // A pseudo-source near the edge with a large σ against a far one with σ = 0 (as on a big mesh
  // with small edges): the quadratic's coefficients cancel badly (c² ~ 1e11) and its root is
  // off; the split is moved to where the two distances agree. (Found by random search.)
  Edge1 e;
  const Interval far = make(0.0, kL, Vec2(106679.50483344488, 350837.94985744485), 0.0);
  const Interval nearby =
      make(0.0, kL, Vec2(0.02921229530964543, 0.031554045793446041), 366698.19360690453);
  e.insert(far);
  e.insert(nearby);
  expectWellFormed(e.list);
  for (double x : e.report.eq1Breakpoints) {
    EXPECT_NEAR(far.distanceAt(x), nearby.distanceAt(x),
                tol::kContinuityRel * (far.distanceAt(x) + kL));
  }
  expectPointwiseMin(e.list, {far, nearby}, 0.0, kL);
  EXPECT_GE(e.total[DegeneracyKind::D4], 1u) << "this configuration was chosen to need D4";
}

// The other side of D4: a root of the quadratic whose two distances agree to the Eq. 1 tolerance is
// the breakpoint as it is, though its coefficients cancelled. A source 6e4 away against a nearby
// one with σ 6e4 (found by random search): the two distances at the root differ by 2.3e-12 of the
// distance, thirty times below tol::kEq1RootRel, and no bisection (no D4) is needed.
TEST(Algorithm2, AnEq1RootAccurateToItsToleranceIsTakenWithoutD4) {
  Edge1 e;
  const Interval far = make(0.0, kL, Vec2(36615.503461284738, 47632.261584772757), 0.0);
  const Interval nearby =
      make(0.0, kL, Vec2(3.9744545441573393, 0.15526435831373697), 60072.05865329571);
  e.insert(far);
  e.insert(nearby);
  expectWellFormed(e.list);
  ASSERT_EQ(e.report.eq1Breakpoints.size(), 1u);
  const double x = e.report.eq1Breakpoints[0];
  const double scale = far.distanceAt(x) + kL;
  const double disagreement = std::abs(far.distanceAt(x) - nearby.distanceAt(x));
  EXPECT_GT(disagreement, 1e-12 * scale) << "the root is no better than the cancellation allows";
  EXPECT_LE(disagreement, tol::kEq1RootRel * scale);
  EXPECT_EQ(e.total[DegeneracyKind::D4], 0u);
  expectPointwiseMin(e.list, {far, nearby}, 0.0, kL);
}

// D4 counts a split of a piece that Eq. 1 could not place, polished by bisection, inside the piece.
// One within ε of the piece's end is the two functions meeting there (e.g. both through the same
// vertex), which Eq. 1 need not resolve. The pair of D4InaccurateRootIsPolished, with the incoming
// range ending just past its crossing: what the far interval keeps beyond the crossing goes on into
// its piece after the incoming range, and is joined to it as the pieces are made (step 3 once took
// it for a D1 sliver and gave it to that same piece).
TEST(Algorithm2, AnUnplacedRootWithinEpsilonOfThePiecesEndIsNoD4) {
  const Interval far = make(0.0, kL, Vec2(106679.50483344488, 350837.94985744485), 0.0);
  Interval nearby =
      make(0.0, kL, Vec2(0.02921229530964543, 0.031554045793446041), 366698.19360690453);
  // Where the two distances cross, found here from the functions themselves: nearby is shorter
  // before it.
  double l = 0.0, h = kL;
  ASSERT_LT(nearby.distanceAt(l), far.distanceAt(l));
  ASSERT_GT(nearby.distanceAt(h), far.distanceAt(h));
  for (int it = 0; it < 200 && h - l > 1e-15; ++it) {
    const double mid = 0.5 * (l + h);
    (nearby.distanceAt(mid) < far.distanceAt(mid) ? l : h) = mid;
  }
  const double pastTheCrossing = 1e-6;
  ASSERT_LT(pastTheCrossing, 0.5 * tinyLength(far, kL)) << "within the far interval's ε";
  nearby.b1 = l + pastTheCrossing;
  Edge1 e;
  e.insert(far);
  e.insert(nearby);
  expectWellFormed(e.list);
  expectPointwiseMin(e.list, {far, nearby}, 0.0, kL);
  EXPECT_EQ(e.total[DegeneracyKind::D4], 0u);
  EXPECT_EQ(e.total[DegeneracyKind::D1], 0u) << "the far interval's piece past the crossing";
  ASSERT_EQ(e.list.intervals().size(), 2u);
  EXPECT_EQ(e.list.intervals()[1].b1, kL);
}

// Step 3 repeats until no interval is a sliver a neighbour may take: a sliver kept because no
// neighbour could take it can become one once a later sliver was merged into it. Here the last
// update's sliver lands inside an interval, neither of whose two pieces beside it may take it;
// the piece after it, a sliver too, is merged into it, and the two together, still shorter than
// their ε, now border the next interval, which is shorter there and takes them. (Five updates
// from a random search over sequences of near-equal distances on one edge.)
TEST(Algorithm2, ASliverGrownByALaterSliverIsRemovedInTheSameUpdate) {
  Edge1 e;
  e.insert(make(0x1.1336a4530195ap+3, 0x1.13f130431fadfp+3,
                Vec2(0x1.f402fc4e75a18p+2, 0x1.01ec566ac1e7ap+0), 0x1.4aae6fa9aa0dcp-2));
  e.insert(make(0x1.1336a45307382p+3, 0x1.25a250047def6p+3,
                Vec2(0x1.10bc6cdaa342ap+2, 0x1.8a715a1b0ff62p+0), 0x1.da6c55a642dfdp-2));
  e.insert(make(0x1.25a25004a67acp+3, 0x1.25a25004a6e45p+3,
                Vec2(0x1.a131f89a39124p+2, 0x1.07e3a653b0e8ep+2), 0x1.b097677a16833p-1));
  e.insert(make(0x1.35d9b129798f6p+2, 0x1.25a25004a69dfp+3,
                Vec2(0x1.a131f89a3bd1fp+2, 0x1.07e3a653b6684p+2), 0x1.0a178252200ddp-1));
  e.insert(make(0x1.1336a452f3fa6p+3, 0x1.1336a453009f5p+3,
                Vec2(0x1.f402fc4e72e1dp+2, 0x1.01ec566aabea2p+0), 0x1.a861f9552b62ap-2));
  expectWellFormed(e.list);
  for (const Interval& w : e.list.intervals())
    EXPECT_GE(w.length(), tinyLength(w, kL)) << "a sliver left at [" << w.b0 << ", " << w.b1 << "]";
}

TEST(Algorithm2, Step5MergesNeighboursWithTheSameSource) {
  Edge1 e;
  e.insert(make(0.0, 4.0, Vec2(5.0, 2.0), 1.0));
  e.insert(make(4.0, kL, Vec2(5.0, 2.0), 1.0));
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_EQ(e.list.intervals()[0].b1, kL);
}

TEST(Algorithm2, SameSourceArrivingAgainKeepsTheOldAndItsPropagation) {
  Edge1 e;
  Interval a = make(0.0, kL, Vec2(5.0, 2.0), 1.0);
  a.markPropagated();
  e.insert(a);
  e.insert(make(0.0, kL, Vec2(5.0, 2.0 + 1e-15), 1.0));
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_TRUE(e.list.intervals()[0].fullyPropagated());
  EXPECT_TRUE(e.toQueue().empty());
}

TEST(Algorithm2, SameSourceReachedAloneInsideALongerIncomingRangeIsKept) {
  // The one old interval the incoming one reaches has its source (σ 5e-11 apart, within
  // kSameSourceRel) and lies inside its range, so the scan stops at the gap before it without
  // asking whether the sources are the same. The one-interval update must ask, or it takes the
  // incoming σ as 5e-11 shorter there and drops the propagated old interval; Algorithm 2 keeps
  // the old one and gives the incoming one the gaps on either side.
  Edge1 e;
  Interval old = make(3.0, 7.0, Vec2(5.0, 2.0), 1.0);
  old.markPropagated();
  e.list.assign(std::vector<Interval>{old});
  const Interval in = make(2.0, 8.0, Vec2(5.0, 2.0), 1.0 - 5e-11);
  e.insert(in);
  expectWellFormed(e.list);
  const auto w = e.list.intervals();
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].b0, 2.0);
  EXPECT_EQ(w[1].b0, 3.0);
  EXPECT_EQ(w[1].b1, 7.0);
  EXPECT_EQ(w[1].sigma, old.sigma);
  EXPECT_TRUE(w[1].fullyPropagated());
  EXPECT_EQ(w[2].b1, 8.0);
  EXPECT_EQ(w[0].sigma, in.sigma);
  EXPECT_EQ(w[2].sigma, in.sigma);
}

TEST(Algorithm2, AnUpdateOfOneIntervalJoinsTheIncomingPieceToItsSameSourceNeighbour) {
  // The incoming interval reaches only b, and wins next to a, which has its source: step 5 joins
  // the two (both pending), whichever path the update takes. Without step 5 the list would keep
  // one geodesic as two intervals, and propagate it twice.
  Edge1 e;
  const Vec2 s(2.0, 1.0);
  const Interval a = make(0.0, 4.0, s, 0.0);
  const Interval b = make(4.0, kL, Vec2(9.0, 3.0), 2.0);
  const Interval in = make(4.0, 8.0, s, 0.0);
  ASSERT_LT(in.distanceAt(4.0), b.distanceAt(4.0));
  ASSERT_GT(in.distanceAt(8.0), b.distanceAt(8.0));
  e.insert(a);
  e.insert(b);
  e.insert(in);
  expectWellFormed(e.list);
  const auto w = e.list.intervals();
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].b0, 0.0);
  EXPECT_EQ(w[0].source, s);
  EXPECT_GT(w[0].b1, 4.0);
  EXPECT_EQ(w[1].source, b.source);
  expectPointwiseMin(e.list, {a, b, in}, 0.0, kL);
}

TEST(Algorithm2, AnUpdateOfOneIntervalRemovesASliverOfAFarSourceBesideIt) {
  // The incoming interval reaches only w; w's neighbour p1 is 5e-8 long, its source 1e4 away
  // (its ε 1e-7), between windows of sources within the edge's length (ε 1e-10). Step 3 over
  // the update's slice, which holds p1, removes it into a neighbour, whichever path the update
  // takes: the bound that decides whether the one-interval path may skip step 3 must take in
  // the neighbours' scales, not only those of w and the incoming interval. (Set as a list.)
  Edge1 e;
  const double sliverEnd = 3.0 + 5e-8;
  const Interval p1 = make(3.0, sliverEnd, Vec2(-1e4, 1.0), 0.0);
  const Vec2 s2(2.0, 1.0), sw(6.0, 1.0);
  const Interval p2 = make(0.0, 3.0, s2, p1.distanceAt(3.0) - (Vec2(3.0, 0.0) - s2).norm());
  const Interval w =
      make(sliverEnd, kL, sw, p1.distanceAt(sliverEnd) - (Vec2(sliverEnd, 0.0) - sw).norm());
  ASSERT_LT(p1.length(), tinyLength(p1, kL));
  ASSERT_GT(p1.length(), 100.0 * tinyLength(w, kL));
  e.list.assign(std::vector<Interval>{p2, p1, w});
  const Interval in = make(5.0, kL, Vec2(8.0, 1.0), w.sigma - 1.0);
  e.insert(in);
  expectWellFormed(e.list);
  for (const Interval& v : e.list.intervals())
    EXPECT_NE(v.source, p1.source) << "the sliver is left at [" << v.b0 << ", " << v.b1 << "]";
  EXPECT_EQ(e.total[DegeneracyKind::D1], 1u);
  expectPointwiseMin(e.list, {p2, p1, w, in}, 0.0, kL);
}

TEST(Algorithm2, APendingIntervalTrimmedAwayFromItsNearestPointKeepsItsQueueEntry) {
  // A pending interval's queue key is its smallest distance, which a trim elsewhere leaves where
  // it was (the distance along an edge is convex): the solver keeps its entry and queues only
  // the new piece. At the old interval's end and, mirrored, at its start.
  struct Case {
    Interval old, in;
    double newB0;
  };
  const Case cases[] = {{make(0.0, kL, Vec2(2.0, 1.0), 0.0), make(8.0, kL, Vec2(9.0, 0.5), 0.0), 8.0},
                        {make(0.0, kL, Vec2(8.0, 1.0), 0.0), make(0.0, 2.0, Vec2(1.0, 0.5), 0.0), 0.0}};
  for (const Case& c : cases) {
    EdgeIntervals list;
    EdgeUpdateReport report;
    std::vector<Interval> scratch;
    list.assign(std::vector<Interval>{c.old});  // as the solver leaves it: queued, pending
    list.insert(c.in, kL, report, scratch);
    ASSERT_EQ(list.intervals().size(), 2u);
    std::vector<Interval> queued;
    for (std::size_t i = report.first; i < report.last; ++i)
      if ((list.intervals()[i].flags & Interval::kChanged) && list.intervals()[i].pending())
        queued.push_back(list.intervals()[i]);
    ASSERT_EQ(queued.size(), 1u) << "new piece from " << c.newB0;
    EXPECT_EQ(queued[0].b0, c.newB0);
    EXPECT_EQ(queued[0].source, c.in.source);
  }
}

TEST(Algorithm2, SameSourceNeighboursInDifferentPropagationStatesStaySeparate) {
  // Step 5 would merge them, but then the propagated part would be propagated a second time.
  Edge1 e;
  Interval a = make(0.0, 4.0, Vec2(5.0, 2.0), 1.0);
  a.markPropagated();
  e.insert(a);
  e.insert(make(4.0, 6.0, Vec2(5.0, 2.0), 1.0));
  ASSERT_EQ(e.list.intervals().size(), 2u);
  EXPECT_TRUE(e.list.intervals()[0].fullyPropagated());
  EXPECT_TRUE(e.list.intervals()[1].pending());
  ASSERT_EQ(e.toQueue().size(), 1u);
  EXPECT_EQ(e.toQueue()[0].b0, 4.0);
}

TEST(Algorithm2, TinyPendingSliverMergedIntoAPropagatedNeighbourMakesItPendingAgain) {
  // The sliver was never propagated; the neighbour taking its range must propagate it.
  Edge1 e;
  Interval a = make(0.0, 5.0, Vec2(2.0, 1.0), 0.0);
  a.markPropagated();
  e.insert(a);
  const double tiny = 0.1 * tol::kTinyIntervalRel * kL;
  e.insert(make(5.0, 5.0 + tiny, Vec2(5.0, std::sqrt(10.0)), 0.0));  // as long as a at x = 5
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D1], 1u);
  ASSERT_EQ(e.list.intervals().size(), 1u);
  EXPECT_EQ(e.list.intervals()[0].b1, 5.0 + tiny);
  EXPECT_TRUE(e.list.intervals()[0].pending());
}

TEST(Algorithm2, D3GapBesideAPropagatedIntervalIsClosedByThePendingSide) {
  Edge1 e;
  Interval a = make(0.0, 5.0, Vec2(2.0, 1.0), 0.0);
  a.markPropagated();
  e.insert(a);
  const double gap = 0.2 * tol::kTinyIntervalRel * kL;
  e.insert(make(5.0 + gap, kL, Vec2(8.0, 1.0), 0.0));
  EXPECT_EQ(e.report.degeneracies[DegeneracyKind::D3], 1u);
  expectWellFormed(e.list);
  EXPECT_EQ(e.list.intervals()[0].b1, 5.0);
  EXPECT_TRUE(e.list.intervals()[0].fullyPropagated());
  EXPECT_EQ(e.list.intervals()[1].b0, 5.0);
}

TEST(Algorithm2, AnUpdateRewritesOnlyTheSliceItReaches) {
  // 40 intervals with sources alternating above them; one new interval over [20.3, 20.7].
  constexpr double L = 40.0;
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  std::vector<Interval> before;
  for (int k = 0; k < 40; ++k) before.push_back(make(k, k + 1.0, Vec2(k + 0.5, 1.0 + k % 3), 0.1 * k));
  list.assign(before);
  list.insert(make(20.3, 20.7, Vec2(20.5, 0.1), 1.0), L, report, scratch);
  EXPECT_GE(report.first, 17u);
  EXPECT_LE(report.last, 25u);
  const auto after = list.intervals();
  ASSERT_EQ(after.size(), before.size() + 2) << "interval 20 is cut in three";
  for (std::size_t i = 0; i < report.first; ++i) EXPECT_EQ(after[i].b0, before[i].b0);
  for (std::size_t i = report.last; i < after.size(); ++i) EXPECT_EQ(after[i].b0, before[i - 2].b0);
  EXPECT_NEAR(list.distanceAt(20.5), 1.1, 1e-15);
}

// The list seen from the edge's other end: what Algorithm 2 does at an interval's start it must do
// at the end of the mirrored one.
Interval mirrored(const Interval& w, double edgeLength) {
  Interval m = w;
  m.b0 = edgeLength - w.b1;
  m.b1 = edgeLength - w.b0;
  m.source.x() = edgeLength - w.source.x();
  return m;
}

// A list installed as it is, seen from the edge's start or (`mirror`) from its end.
void assignSeenFrom(Edge1& e, std::vector<Interval> list, bool mirror) {
  if (mirror) {
    for (Interval& w : list) w = mirrored(w, kL);
    std::reverse(list.begin(), list.end());
  }
  e.list.assign(list);
}

// Step 4 counts the edge's ends as neighbours, and the slice an update rewrites takes in one
// interval beyond those it reaches: a new window reaching only B, the interval after the first, A,
// sews a gap of ε/2 between the edge's start and A. (No update leaves such a gap, step 6's
// 'no-tiny-gap', so the list is installed as it is.) From either end of the edge.
TEST(Algorithm2, AGapBelowEpsilonAtAnEndOfTheEdgeIsSewnByAnUpdateOfTheIntervalBesideTheFirst) {
  const double gap = 0.5 * tol::kTinyIntervalRel * kL;
  const Interval a = make(gap, 5.0, Vec2(2.0, 1.0), 0.0), b = make(5.0, kL, Vec2(8.0, 1.0), 0.0),
                 in = make(6.0, 7.5, Vec2(7.0, 0.1), 0.0);
  ASSERT_LT(gap, sewLength(a, kL));
  for (const bool mirror : {false, true}) {
    SCOPED_TRACE(mirror ? "mirrored" : "as built");
    const auto side = [&](const Interval& w) { return mirror ? mirrored(w, kL) : w; };
    Edge1 e;
    assignSeenFrom(e, {a, b}, mirror);
    e.insert(side(in));
    expectWellFormed(e.list);
    const auto after = e.list.intervals();
    ASSERT_EQ(after.size(), 4u);
    EXPECT_EQ(mirror ? after.back().b1 : after.front().b0, mirror ? kL : 0.0) << "the gap is sewn";
    EXPECT_EQ(e.total[DegeneracyKind::D3], 1u);
    expectPointwiseMin(e.list, {side(a), side(b), side(in)}, mirror ? 0.0 : gap,
                       mirror ? kL - gap : kL);
  }
}

TEST(Algorithm2, AGapBesideTheUpdateIsSewnWhenTheIntervalNextToItGoesToACoarserWindow) {
  // Near windows A and t with a gap of 2e-10 between them (above ε = 1e-10 of the edge: a real
  // gap), t 1e-9 long and C after it; distances about 1e6 (pseudo-sources reached from far away).
  // A far window X (source 1e6 away, ray ends good to 1e-8) replaces C: beside it t is a D1 sliver
  // of X's rounding and goes to X, and the gap between A and what is now X is below X's sewing
  // length. A lies outside the range X reaches, so only an update that looks one interval further
  // out after t is gone sews it. From either end of the edge.
  const double delta = 1e-9, gap = 2e-10, x1 = 5.0 + delta;
  const Vec2 sX(5.0, 1e6), sC(5.0, 1.0), sT(5.0, 2.0), sA(2.0, 1.0);
  const double dX1 = (Vec2(x1, 0.0) - sX).norm();
  const double sigmaC = dX1 - (Vec2(x1, 0.0) - sC).norm();
  const double sigmaT = dX1 - (Vec2(x1, 0.0) - sT).norm();
  const double sigmaA = sigmaT + (Vec2(5.0, 0.0) - sT).norm() - (Vec2(5.0, 0.0) - sA).norm();
  const Interval a = make(0.0, 5.0 - gap, sA, sigmaA), t = make(5.0, x1, sT, sigmaT),
                 c = make(x1, kL, sC, sigmaC), x = make(x1, kL, sX, 0.0);
  for (const bool mirror : {false, true}) {
    SCOPED_TRACE(mirror ? "mirrored" : "as built");
    const auto side = [&](const Interval& w) { return mirror ? mirrored(w, kL) : w; };
    Edge1 e;
    assignSeenFrom(e, {a, t, c}, mirror);
    e.insert(side(x));
    expectWellFormed(e.list);
    const auto after = e.list.intervals();
    ASSERT_EQ(after.size(), 2u);
    const Interval& far = after[mirror ? 0 : 1];
    EXPECT_EQ(far.source, side(x).source) << "X took t";
    EXPECT_EQ(e.total[DegeneracyKind::D1], 1u);
    EXPECT_EQ(e.total[DegeneracyKind::D3], 1u);
    expectPointwiseMin(e.list, {side(a), side(t), side(c), side(x)}, 0.0, kL);
  }
}

TEST(Algorithm2, ASliverTheNeighbourOutsideTheUpdateTakesIsNotLostWhenTheSameSourceFollows) {
  // Near windows A and t meet at 5; t (1e-9 long) and U, further on, are one source and state,
  // 1e-9 apart (a real gap, above ε = 1e-10). A far window X (source 1e6 away, ray ends good to
  // 1e-8, everywhere longer than t and U) arrives from 5e-10 past t's end: beside it t is a D1
  // sliver only A may take, and X's piece of the gap a sliver that U takes, growing back to X's
  // start. What is now first after A has t's function but not t's start, and only an update one
  // interval further out lets A grow over t
  // (corpus/fuzz_edge_update/regress/pointwise-min-sliver-taken-by-the-outer-neighbour-before-a-
  // gap-to-the-same-source). Not mirrored: step 3 goes through the slice from its start, and
  // from the other end X's piece goes to U before t is looked at, when t is no sliver any more.
  const double delta = 1e-9, eta = 5e-10, uStart = 5.0 + delta + 2.0 * eta;
  const Vec2 sA(2.0, 1.0), sS(5.0, 2.0), sX(5.0, 1e6);
  const double sigmaS = 1e6 - 10.0;
  const double sigmaA = sigmaS + (Vec2(5.0, 0.0) - sS).norm() - (Vec2(5.0, 0.0) - sA).norm();
  const Interval a = make(0.0, 5.0, sA, sigmaA), t = make(5.0, 5.0 + delta, sS, sigmaS),
                 u = make(uStart, kL, sS, sigmaS), x = make(5.0 + delta + eta, kL, sX, 0.0);
  Edge1 e;
  e.list.assign({a, t, u});
  e.insert(x);
  expectWellFormed(e.list);
  const auto after = e.list.intervals();
  ASSERT_EQ(after.size(), 2u);
  EXPECT_EQ(after[0].source, sA) << "A took t and X's piece of the gap";
  EXPECT_EQ(after[1].source, sS);
  EXPECT_EQ(e.total[DegeneracyKind::D1], 2u);
  expectPointwiseMin(e.list, {a, t, u, x}, 0.0, kL);
}

TEST(Algorithm2, ShadowsLeftWhenTheWavefrontHasPassedAreClosedAtTheirMidpoints) {
  // Three intervals of one source with gaps of 1e-9 and 1e-6 between them (edge 10, distances
  // about 3 there): with a widest closable gap of 1e-8, the first closes at its midpoint, the
  // second stays; with the wavefront passed only up to 1, neither closes.
  for (double passed : {100.0, 1.0}) {
    EdgeIntervals list;
    list.assign({make(0.0, 4.0, Vec2(5.0, 3.0), 0.0), make(4.0 + 1e-9, 7.0, Vec2(5.0, 3.0), 0.0),
                 make(7.0 + 1e-6, kL, Vec2(5.0, 3.0), 0.0)});
    const std::size_t closed = list.closeShadows(1e-8, passed);
    const auto w = list.intervals();
    if (passed > 3.0) {
      EXPECT_EQ(closed, 1u);
      EXPECT_EQ(w[0].b1, w[1].b0);
      EXPECT_DOUBLE_EQ(w[0].b1, 4.0 + 0.5e-9);
    } else {
      EXPECT_EQ(closed, 0u);
      EXPECT_LT(w[0].b1, w[1].b0);
    }
    EXPECT_LT(w[1].b1, w[2].b0) << "a gap wider than the widest closable stays";
  }
}

TEST(Algorithm2, NeighboursThatAlreadyMeetLeaveNoShadowToClose) {
  // A shadow is a gap: of three neighbours that meet and a fourth 1e-9 beyond, once the wavefront
  // has passed, only that gap is closed (and counted), and the meeting points stay where they are.
  EdgeIntervals list;
  list.assign({make(0.0, 3.0, Vec2(2.0, 1.0), 0.0), make(3.0, 6.0, Vec2(5.0, 1.0), 0.0),
               make(6.0, 8.0, Vec2(7.0, 1.0), 0.0), make(8.0 + 1e-9, kL, Vec2(9.0, 1.0), 0.0)});
  EXPECT_EQ(list.closeShadows(1e-8, 100.0), 1u);
  const auto w = list.intervals();
  EXPECT_EQ(w[0].b1, 3.0);
  EXPECT_EQ(w[1].b1, 6.0);
  EXPECT_EQ(w[2].b1, w[3].b0);
}

TEST(Eq1, CandidatesIncludeTheBisector) {
  const Interval a = make(0.0, kL, Vec2(2.0, 1.0), 0.0);
  const Interval b = make(0.0, kL, Vec2(8.0, 1.0), 0.0);
  double roots[2];
  const int n = equalDistanceCandidates(a, b, 0.0, kL, roots);
  ASSERT_GE(n, 1);
  EXPECT_NEAR(roots[0], 5.0, 1e-12);
}

// The along-edge rule's test (EdgeIntervals::nowhereAbove, GeodesicSolver::dominatedAlongItsEdge):
// a pseudo-source's window along its own edge is nowhere shorter than a list that covers the edge
// with no interval longer than it. Each verdict is set against the two functions sampled along
// the edge.
namespace along_edge {

// The largest amount by which `along` is shorter than the list anywhere (negative: nowhere).
double largestWin(const EdgeIntervals& e, const Interval& along) {
  double largest = -INFINITY;
  for (int k = 0; k <= 1000; ++k) {
    const double x = kL * k / 1000.0;
    largest = std::max(largest, e.distanceAt(x) - along.distanceAt(x));
  }
  return largest;
}

TEST(AlongEdgeRule, AWindowFromEitherEndLosesToAListItsSourceGetsItsDistanceFrom) {
  Edge1 e;
  const Interval w = make(0.0, kL, Vec2(2.0, 3.0), 0.0);
  e.insert(w);
  const Interval fromStart = make(0.0, kL, Vec2(0.0, 0.0), w.distanceAt(0.0));
  const Interval fromEnd = make(0.0, kL, Vec2(kL, 0.0), w.distanceAt(kL));
  EXPECT_LE(largestWin(e.list, fromStart), 0.0);
  EXPECT_LE(largestWin(e.list, fromEnd), 0.0);
  EXPECT_TRUE(e.list.nowhereAbove(fromStart, true, kL));
  EXPECT_TRUE(e.list.nowhereAbove(fromEnd, false, kL));
}

// The list gives the source its σ, and then steps up where the first window's range ends: the
// window along the edge is shorter beyond the step, as behind a saddle's shadow.
TEST(AlongEdgeRule, AListThatStepsUpBeyondTheSourcesEndIsNotNowhereAbove) {
  Edge1 e;
  e.insert(make(0.0, 5.0, Vec2(2.0, 3.0), 0.0));
  e.insert(make(5.0, kL, Vec2(-5.0, 0.0), 0.0));
  ASSERT_EQ(e.list.intervals().size(), 2u);
  const Interval fromStart = make(0.0, kL, Vec2(0.0, 0.0), e.list.distanceAt(0.0));
  EXPECT_GT(largestWin(e.list, fromStart), 1.0);
  EXPECT_FALSE(e.list.nowhereAbove(fromStart, true, kL));
}

// A gap inside the list, or an end it does not reach, is the window's to fill.
TEST(AlongEdgeRule, AListWithAGapOrShortOfAnEndIsNotNowhereAbove) {
  const Interval near = make(0.0, kL, Vec2(2.0, 3.0), 0.0);
  const Interval fromStart = make(0.0, kL, Vec2(0.0, 0.0), near.distanceAt(0.0));
  Edge1 gap;
  gap.insert(make(0.0, 4.0, near.source, 0.0));
  gap.insert(make(6.0, kL, near.source, 0.0));
  ASSERT_EQ(gap.list.intervals().size(), 2u);
  EXPECT_EQ(gap.list.distanceAt(5.0), INFINITY);
  EXPECT_FALSE(gap.list.nowhereAbove(fromStart, true, kL));
  Edge1 shortOfTheEnd;
  shortOfTheEnd.insert(make(0.0, 9.5, near.source, 0.0));
  EXPECT_EQ(shortOfTheEnd.list.distanceAt(9.75), INFINITY);
  EXPECT_FALSE(shortOfTheEnd.list.nowhereAbove(fromStart, true, kL));
}

}  // namespace along_edge

}  // namespace
}  // namespace geodex
