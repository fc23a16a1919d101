#include "geodex/verify/invariant_checker.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "geodex/tolerance.h"

namespace geodex::verify {
namespace {

const char* const kNames[] = {"sorted",          "in-range",          "no-overlap",
                              "no-tiny-gap",     "no-tiny-interval",  "finite-non-negative",
                              "real-source",     "continuous-at-eq1", "pointwise-min",
                              "full-coverage",   "vertex-agreement",  "wavefront-exhausted",
                              "dropped-window-dominated"};

std::string describe(const Interval& w) {
  std::ostringstream os;
  os << std::setprecision(17) << "[" << w.b0 << ", " << w.b1 << "] s=(" << w.source.x() << ", "
     << w.source.y() << ") sigma=" << w.sigma << " side=" << int(w.side);
  return os.str();
}

// Index of the last interval with b0 <= x (lists are sorted by b0), or -1.
std::ptrdiff_t lastStartingBefore(std::span<const Interval> list, double x) {
  const auto it = std::upper_bound(list.begin(), list.end(), x,
                                   [](double v, const Interval& w) { return v < w.b0; });
  return (it - list.begin()) - 1;
}

// The smallest distance the intervals covering x give. Only the interval starting last before x
// and its left neighbour can cover x in a sorted list (neighbours share at most an endpoint); a
// list that is not sorted (a violation reported elsewhere) is scanned whole.
double listDistance(std::span<const Interval> list, double x) {
  double best = INFINITY;
  const std::ptrdiff_t k = lastStartingBefore(list, x);
  for (std::ptrdiff_t i = std::max<std::ptrdiff_t>(0, k - 1); i <= k; ++i)
    if (x >= list[i].b0 && x <= list[i].b1) best = std::min(best, list[i].distanceAt(x));
  return best;
}

// |(x, 0) − source| of w, as Interval::d0 / d1 compute it for x = b0 / b1. Those use std::hypot,
// which is a tenth of a cheap-tier solve; the plain root is as accurate (one rounding more) where
// the squares cannot overflow or underflow, which is every list of a real solve (mesh units).
double sourceDistance(const Interval& w, double x) {
  const double dx = std::abs(x - w.source.x()), dy = w.source.y();
  constexpr double kLarge = 1e150, kSmall = 1e-150;
  if (dx < kLarge && dy < kLarge && (dx > kSmall || dy > kSmall)) return std::sqrt(dx * dx + dy * dy);
  return std::hypot(dx, dy);
}

// The range [lo, hi] the incoming intervals of an update span together.
struct Hull {
  double lo, hi;
};
Hull incomingHull(const EdgeUpdateEvent& e) {
  Hull h{INFINITY, -INFINITY};
  for (const Interval& w : e.incoming) h.lo = std::min(h.lo, w.b0), h.hi = std::max(h.hi, w.b1);
  return h;
}

// The same distance function: distanceAt gives the same value at every x, to the bit.
bool sameFunction(const Interval& a, const Interval& b) {
  return a.source == b.source && a.sigma == b.sigma;
}

// The one interval of list[first, last] (clamped to the list) whose closed range holds x, or
// nullptr when none or several do.
const Interval* coveringOnly(std::span<const Interval> list, std::ptrdiff_t first,
                             std::ptrdiff_t last, double x) {
  const Interval* found = nullptr;
  for (std::ptrdiff_t i = std::max<std::ptrdiff_t>(0, first);
       i <= std::min<std::ptrdiff_t>(last, std::ssize(list) - 1); ++i) {
    if (!(list[i].b0 <= x && x <= list[i].b1)) continue;
    if (found != nullptr) return nullptr;
    found = &list[i];
  }
  return found;
}

// The same interval: everything the invariants read, and the propagation state.
// The solver moves the intervals it does not rewrite as whole objects, so those are the same
// bytes, compared at once; bytes that differ (padding, a flag no invariant reads, -0.0) are left to
// the fields. Equal bytes holding a NaN count as the same here: a NaN is reported by the update
// that writes it, whose bytes differ.
bool sameInterval(const Interval& a, const Interval& b) {
  if (std::memcmp(&a, &b, sizeof(Interval)) == 0) return true;
  return a.b0 == b.b0 && a.b1 == b.b1 && a.source == b.source && a.sigma == b.sigma &&
         a.origin == b.origin && a.side == b.side && a.pending() == b.pending();
}

// sameInterval for a[0, n) and b[0, n): the whole run's bytes in one memcmp first (comparing the
// unchanged ends of a list field by field was a tenth of the cheap tier).
bool sameIntervals(const Interval* a, const Interval* b, std::size_t n) {
  if (n == 0 || std::memcmp(a, b, n * sizeof(Interval)) == 0) return true;
  for (std::size_t i = 0; i < n; ++i)
    if (!sameInterval(a[i], b[i])) return false;
  return true;
}

}  // namespace

InvariantChecker::InvariantChecker(CheckLevel level, bool throwOnViolation)
    : level_(level), throw_(throwOnViolation) {
  tallies_.reserve(std::size(kNames));
  for (const char* n : kNames) tallies_.push_back({n});
}

std::uint64_t InvariantChecker::violations() const {
  std::uint64_t n = 0;
  for (const auto& t : tallies_) n += t.violated;
  return n;
}

void InvariantChecker::record(Id id, bool ok, double error, const std::string& why,
                              const EdgeUpdateEvent* e) {
  InvariantTally& t = tallies_[id];
  ++t.checked;
  t.worst = std::max(t.worst, error);
  if (ok) return;
  ++t.violated;
  if (first_ && !throw_) return;
  auto v = std::make_unique<InvariantViolation>(kNames[id], std::string("invariant '") + kNames[id] + "' violated: " + why);
  if (e != nullptr) {
    v->edge = e->edge;
    v->edgeLength = e->edgeLength;
    v->before.assign(e->before.begin(), e->before.end());
    v->after.assign(e->after.begin(), e->after.end());
    v->incoming.assign(e->incoming.begin(), e->incoming.end());
    v->branch = e->branches.empty() ? "source" : std::string(name(e->branches.front()));
  }
  if (throw_) throw *v;
  first_ = std::move(v);
}

std::string InvariantChecker::checkList(std::span<const Interval> list, double L, std::string& why) {
  return checkListRange(list, 0, list.size(), L, why);
}

std::string InvariantChecker::checkListRange(std::span<const Interval> list, std::size_t lo,
                                             std::size_t hi, double L, std::string& why) {
  // The message is written only for the invariant that fails (this runs at every edge update).
  const auto fail = [&why](const char* invariant, const auto& write) {
    std::ostringstream os;
    os << std::setprecision(17);
    write(os);
    why = os.str();
    return std::string(invariant);
  };
  hi = std::min(hi, list.size());
  for (std::size_t i = lo; i < hi; ++i) {
    const Interval& w = list[i];
    if (!(std::isfinite(w.b0) && std::isfinite(w.b1) && std::isfinite(w.sigma) && w.sigma >= 0.0 &&
          isFinite(w.source))) {
      return fail("finite-non-negative", [&](std::ostream& os) {
        os << "interval " << i << " " << describe(w) << " has a non-finite or negative value";
      });
    }
    // (An interval with no length is no range: Algorithm 2 takes the list as a partition of the
    // edge, and one with b1 < b0 came through as a fuzzed list before, an overlap with itself.)
    if (!(w.b0 >= 0.0 && w.b0 < w.b1 && w.b1 <= L)) {
      return fail("in-range", [&](std::ostream& os) {
        os << "interval " << i << " " << describe(w) << " is not a range 0 <= b0 < b1 <= " << L;
      });
    }
    const double tiny = tinyLengthInList(list, i, L);
    // (A sliver no neighbour can grow over is kept by step 3, as the whole interval of an edge
    // shorter than ε. Whether one can is asked only of a sliver: it evaluates the distances.)
    const auto takeable = [&] {
      return (i > 0 && canTakeSliver(list[i - 1], w, L)) ||
             (i + 1 < list.size() && canTakeSliver(list[i + 1], w, L));
    };
    if (w.b1 - w.b0 < tiny && !(w.b0 == 0.0 && w.b1 == L) && takeable()) {
      return fail("no-tiny-interval", [&](std::ostream& os) {
        os << "interval " << i << " " << describe(w) << " is shorter than epsilon = " << tiny;
      });
    }
    const double d0 = sourceDistance(w, w.b0), d1 = sourceDistance(w, w.b1);
    const double rounding = tol::kRoundingRel * std::max(d0, d1);
    if (w.source.y() < 0.0 || std::abs(d0 - d1) > (w.b1 - w.b0) + tiny + rounding) {
      return fail("real-source", [&](std::ostream& os) {
        os << "interval " << i << " " << describe(w) << " has no real unfolded source (|d0-d1| = "
           << std::abs(d0 - d1) << ")";
      });
    }
    if (i == lo) continue;
    const Interval& p = list[i - 1];
    if (w.b0 < p.b0) {
      return fail("sorted", [&](std::ostream& os) {
        os << "intervals " << i - 1 << " and " << i << " are not sorted by b0";
      });
    }
    if (w.b0 < p.b1) {
      return fail("no-overlap", [&](std::ostream& os) {
        os << "intervals " << i - 1 << " " << describe(p) << " and " << i << " " << describe(w) << " overlap by " << p.b1 - w.b0;
      });
    }
    // A gap is step 4's when below the sewing length of the two intervals beside it.
    if (w.b0 > p.b1 && w.b0 - p.b1 < std::max(sewLength(w, L), sewLength(p, L))) {
      return fail("no-tiny-gap", [&](std::ostream& os) {
        os << "gap of " << w.b0 - p.b1 << " < epsilon between intervals " << i - 1 << " and " << i << " left unsewn";
      });
    }
  }
  if (lo < hi && ((lo == 0 && list.front().b0 > 0.0 && list.front().b0 < sewLength(list.front(), L)) ||
                  (hi == list.size() && list.back().b1 < L && L - list.back().b1 < sewLength(list.back(), L)))) {
    why = "gap below epsilon left unsewn at an end of the edge";
    return "no-tiny-gap";
  }
  return "";
}

// ===  One edge update ============================================================================

// What an update rewrote: after[afterLo, afterHi) in place of before[beforeLo, beforeHi), the
// intervals outside being the same ones in both lists. Taken from the report's [first, last) and
// then verified interval by interval (a comparison, far cheaper than the invariants), so that a
// bug writing outside the range it reports is still seen: it gets the whole lists.
struct InvariantChecker::ChangedRange {
  std::size_t afterLo, afterHi, beforeLo, beforeHi;
  // Of those, the part that differs: after[diffAfterLo, diffAfterHi) in place of
  // before[diffBeforeLo, diffBeforeHi), the intervals around it in the range being the same ones
  // in both lists (compared).
  std::size_t diffAfterLo, diffAfterHi, diffBeforeLo, diffBeforeHi;
};

namespace {

// [beforeLo, beforeHi) of the old list and [afterLo, afterHi) of the new one.
struct ListRanges {
  std::size_t afterLo, afterHi, beforeLo, beforeHi;
};

// The ranges moved inwards past the intervals the same in both lists: at the front while
// `atFront` holds of the old one there, at the back while `atBack` does.
ListRanges pastSameIntervals(const EdgeUpdateEvent& e, ListRanges r, auto atFront, auto atBack) {
  while (r.afterLo < r.afterHi && r.beforeLo < r.beforeHi && atFront(e.before[r.beforeLo]) &&
         sameInterval(e.before[r.beforeLo], e.after[r.afterLo]))
    ++r.afterLo, ++r.beforeLo;
  while (r.afterLo < r.afterHi && r.beforeLo < r.beforeHi && atBack(e.before[r.beforeHi - 1]) &&
         sameInterval(e.before[r.beforeHi - 1], e.after[r.afterHi - 1]))
    --r.afterHi, --r.beforeHi;
  return r;
}

// The range the solver reports, verified: the whole lists when the intervals outside it differ.
ListRanges reportedRange(const EdgeUpdateEvent& e) {
  const ListRanges whole{0, e.after.size(), 0, e.before.size()};
  const std::size_t first = e.report.first, last = e.report.last;
  if (first > last || last > e.after.size()) return whole;
  const std::size_t suffix = e.after.size() - last;
  if (first + suffix > e.before.size()) return whole;
  const std::size_t beforeHi = e.before.size() - suffix;
  if (!sameIntervals(e.before.data(), e.after.data(), first) ||
      !sameIntervals(e.before.data() + beforeHi, e.after.data() + last, suffix))
    return whole;
  // The solver's range may begin or end with intervals it wrote back as they were, away from the
  // incoming range: they are left out too (the minimum holds there by itself). Those the incoming
  // range meets stay, as the pieces its samples need.
  const Hull in = incomingHull(e);
  return pastSameIntervals(
      e, {first, last, first, beforeHi}, [&](const Interval& w) { return w.b1 < in.lo; },
      [&](const Interval& w) { return w.b0 > in.hi; });
}

}  // namespace

InvariantChecker::ChangedRange InvariantChecker::changedRange(const EdgeUpdateEvent& e) {
  const ListRanges r = reportedRange(e);
  const auto always = [](const Interval&) { return true; };
  const ListRanges d = pastSameIntervals(e, r, always, always);
  return {r.afterLo, r.afterHi, r.beforeLo, r.beforeHi,
          d.afterLo, d.afterHi, d.beforeLo, d.beforeHi};
}

void InvariantChecker::onEdgeUpdate(const EdgeUpdateEvent& e) {
  // What the update rewrote, with one neighbour on each side: an interval's ε and the pairs it
  // forms involve its neighbours, so those are checked again too.
  const ChangedRange changed = changedRange(e);
  const std::size_t lo = changed.afterLo >= 1 ? changed.afterLo - 1 : 0;
  const std::size_t hi = std::min(changed.afterHi + 1, e.after.size());

  // The list checks read an interval and its two neighbours. The intervals of the rewritten part
  // written back as they were, around the part that differs, and their neighbours are as the
  // update that wrote them left them, and were checked then: these checks take the part that
  // differs, with one neighbour on each side (a third fewer instructions in them on bunny00). A
  // list the same as before is checked already.
  const std::size_t a0 = changed.diffAfterLo, a1 = changed.diffAfterHi;
  if (a0 == a1 && changed.diffBeforeLo == changed.diffBeforeHi)
    checkWellFormed(e, a0, a0);
  else
    checkWellFormed(e, a0 >= 1 ? a0 - 1 : 0, std::min(a1 + 1, e.after.size()));
  checkContinuityAtEq1(e, lo, hi);
  if (level_ != CheckLevel::Full) return;
  checkPointwiseMin(e, changed, lo, hi);
}

// Cheap tier: the list is well formed (sorted, in range, no overlap, no tiny gap or interval,
// finite, a real source).
void InvariantChecker::checkWellFormed(const EdgeUpdateEvent& e, std::size_t lo, std::size_t hi) {
  std::string why;
  const std::string broken = checkListRange(e.after, lo, hi, e.edgeLength, why);
  // The broken invariant's name is looked up once, only when there is one: comparing it with all
  // seven names at every update was a seventh of the cheap tier's instructions.
  int brokenId = -1;
  if (!broken.empty())
    for (int id = Sorted; id <= RealSource; ++id)
      if (broken == kNames[id]) brokenId = id;
  // A pass is tallied in place, as record would with an error of 0 (which leaves `worst` as it
  // is: it starts at 0 and only grows); a call to record for each of the seven was another sixth.
  for (int id = Sorted; id <= RealSource; ++id) {
    if (id == brokenId)
      record(static_cast<Id>(id), false, 0.0, why, &e);
    else
      ++tallies_[id].checked;
  }
}

// Cheap tier: the two neighbours agree at every Eq. 1 breakpoint.
void InvariantChecker::checkContinuityAtEq1(const EdgeUpdateEvent& e, std::size_t lo,
                                            std::size_t hi) {
  for (double x : e.report.eq1Breakpoints) {
    // Find the two intervals meeting at x (if steps 3–5 moved or merged the breakpoint away,
    // there is nothing left to compare). Eq. 1 solves inside the incoming range, which the
    // rewritten part holds.
    for (std::size_t i = lo; i + 1 < hi; ++i) {
      if (e.after[i].b1 != x || e.after[i + 1].b0 != x) continue;
      const double a = e.after[i].distanceAt(x), b = e.after[i + 1].distanceAt(x);
      const double scale = std::max(a, b) + e.edgeLength;
      const double err = std::abs(a - b) / scale;
      const bool ok = err <= tol::kContinuityRel;
      std::string why;
      if (!ok) {
        std::ostringstream os;
        os << std::setprecision(17) << "at the Eq. 1 breakpoint x = " << x << " the distances are " << a << " and " << b;
        why = os.str();
      }
      record(ContinuousAtEq1, ok, err, why, &e);
    }
  }
}

// ===  Full tier: the pointwise minimum ===========================================================

namespace {

// Each function counts where it covers x up to the slack step 4 may sew (ε): a sewn end is
// part of the repaired list by contract.
// Step 4 sews up to sewLength, which exceeds ε by the ray-end precision
// (corpus/fuzz_edge_update/regress/pointwise-min-end-gap-sewn-up-to-the-ray-end-precision).
// The slack is the largest ε of the intervals step 4 could sew with: it sews a gap below the ε
// of either interval beside it, so a near window's end is carried across a gap as wide as a
// far neighbour's ε (corpus/fuzz_edge_update/regress/pointwise-min-gap-sewn-by-the-far-neighbours-epsilon).
// Steps 3–5 work on the rewritten part and its neighbours, which beforeNear holds.
double sewingSlack(const EdgeUpdateEvent& e, std::span<const Interval> beforeNear) {
  double tiny = tol::kTinyIntervalRel * e.edgeLength;
  for (const Interval& w : beforeNear)
    tiny = std::max({tiny, tinyLength(w, e.edgeLength), sewLength(w, e.edgeLength)});
  for (const Interval& w : e.incoming)
    tiny = std::max({tiny, tinyLength(w, e.edgeLength), sewLength(w, e.edgeLength)});
  return tiny;
}

// Where the difference of two distance functions along the edge can be largest inside the span
// (lo, hi), besides its ends: where their slopes (x − a) / r agree, which squared is
// (x − a) d = (x − b) c for sources (a, c) and (b, d) (the other sign makes the slopes opposite),
// and the kink of a function whose source is on the edge. Infinity where there is none: no NaN
// and no division that could overflow or divide by zero (the debug tests trap those).
std::array<double, 3> largestDifferenceAt(const Interval& f, const Interval& g, double lo,
                                          double hi) {
  const double a = f.source.x(), c = std::abs(f.source.y());
  const double b = g.source.x(), d = std::abs(g.source.y());
  const double num = a * d - b * c, den = d - c;
  const bool inSpan =
      den != 0.0 && std::abs(num) <= std::abs(den) * std::max(std::abs(lo), std::abs(hi));
  return {inSpan ? num / den : INFINITY, c == 0.0 ? a : INFINITY, d == 0.0 ? b : INFINITY};
}

// Appends to `out` the points of (lo, hi) where g can lie furthest below f (largestDifferenceAt),
// those where it does lie below: a dip of g narrower than the uniform sample spacing is at one of
// them. For the walks that otherwise sample a piece only uniformly; out of line, so that the
// common walk is compiled as it was without them.
[[gnu::noinline]] void appendWhereBelow(const Interval& f, const Interval& g, double lo, double hi,
                                        std::vector<double>& out) {
  for (const double x : largestDifferenceAt(f, g, lo, hi))
    if (x > lo && x < hi && g.distanceAt(x) < f.distanceAt(x)) out.push_back(x);
}

// Where a walk does not know which intervals cover a piece: appendWhereBelow for every two
// functions of `runs` (the old list's, the new one's and the incoming ones), over the stretch of
// [from, to] both reach.
[[gnu::noinline]] void appendWhereAnyIsBelow(std::span<const std::span<const Interval>> runs,
                                             double from, double to, std::vector<double>& out) {
  const auto pair = [&](const Interval& f, const Interval& g) {
    const double lo = std::max({f.b0, g.b0, from}), hi = std::min({f.b1, g.b1, to});
    if (!(lo < hi)) return;
    appendWhereBelow(f, g, lo, hi, out);
    appendWhereBelow(g, f, lo, hi, out);
  };
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (const Interval& w : runs[r])
      for (std::size_t t = r; t < runs.size(); ++t)
        for (const Interval& v : runs[t])
          if (&v > &w || t > r) pair(w, v);
}

// Merges `extra` (in no order) into the sorted `xs`.
[[gnu::noinline]] void mergeInto(std::vector<double>& xs, std::vector<double>& extra) {
  std::sort(extra.begin(), extra.end());
  const auto walked = std::ssize(xs);
  xs.insert(xs.end(), extra.begin(), extra.end());
  std::inplace_merge(xs.begin(), xs.begin() + walked, xs.end());
}

}  // namespace

// The largest relative error of the list after against min(before, incoming) over the samples,
// and the first sample (in x order) where it is reached.
struct InvariantChecker::PointwiseMinError {
  double worst = 0.0;
  std::array<double, 4> at{};  // x, the list's value, the strict and the loose minimum

  // The worse of two, each over its own samples: the same as over all of them in x order.
  static PointwiseMinError worse(const PointwiseMinError& a, const PointwiseMinError& b) {
    if (a.worst > b.worst || std::isnan(a.worst)) return a;
    if (b.worst > a.worst || std::isnan(b.worst)) return b;
    return a.worst > 0.0 && a.at[0] > b.at[0] ? b : a;
  }
};

// The samples of the pointwise-minimum check. Those well inside a piece between two consecutive
// endpoints are evaluated here, as the walk over the pieces makes them (it knows the intervals
// over the piece); the others are returned, sorted, so that one sweep over each list
// (worstPointwiseMinError) finds the intervals at every one of them.
std::span<const double> InvariantChecker::pointwiseMinSamples(
    const EdgeUpdateEvent& e, const ChangedRange& changed, std::span<const Interval> beforeNear,
    std::span<const Interval> afterNear, double tiny, PointwiseMinError& interior) {
  // The uniform samples cover where the two lists differ and where the incoming interval reaches.
  // Beyond that the neighbours are the same intervals before and after (changedRange compared
  // them) and no incoming value is there, so the minimum holds by itself (their pieces still get
  // a midpoint below).
  const Hull hull = incomingHull(e);
  double from = hull.lo, to = hull.hi;
  const std::span<const Interval> rewrittenParts[] = {
      e.before.subspan(changed.beforeLo, changed.beforeHi - changed.beforeLo),
      e.after.subspan(changed.afterLo, changed.afterHi - changed.afterLo)};
  for (const auto part : rewrittenParts)
    if (!part.empty()) from = std::min(from, part.front().b0), to = std::max(to, part.back().b1);
  from -= tiny, to += tiny;
  const int uniform = 32;
  // Only the k whose sample can fall in [from, to] are tried (each still tested as it is
  // computed); a range that is not finite tries them all.
  int k = 0, kLast = uniform;
  if (std::isfinite(from) && std::isfinite(to) && e.edgeLength > 0.0) {
    k = static_cast<int>(std::clamp(std::floor(from / e.edgeLength * uniform) - 1.0, 0.0, double(uniform)));
    kLast = static_cast<int>(std::clamp(std::ceil(to / e.edgeLength * uniform) + 1.0, 0.0, double(uniform)));
  }
  const auto uniformAt = [&](int j) { return e.edgeLength * j / uniform; };
  const auto nextUniform = [&] {
    for (; k <= kLast; ++k) {
      const double x = uniformAt(k);
      if (x >= from && x <= to) return ++k, x;
    }
    return double(INFINITY);
  };

  // Inside every piece between consecutive endpoints of the three lists: a D2 overlap or a D1
  // sliver is far shorter than the uniform spacing, and which function wins there is what
  // steps 1–4 decide (otherwise an overlap handed to the longer side goes unseen).
  // The endpoints of a well-formed list are already in order, so the lists' are merged as the
  // walk goes, read straight from the intervals; a list that is not (a violation the cheap tier
  // reports) has its endpoints copied out and sorted. Around the part of the new list that
  // differs from the old (the rewritten part's intervals written back as they were, and its
  // neighbours) the intervals are the same in both lists (changedRange compared them): their ends
  // are taken once, from the old list.
  const std::span<const Interval> rewritten =
      e.after.subspan(changed.diffAfterLo, changed.diffAfterHi - changed.diffAfterLo);
  // (In order as std::is_sorted says of b0, b1, b0, b1, ...: no end below the one before it.)
  const auto endsInOrder = [](std::span<const Interval> run) {
    for (std::size_t j = 0; j < run.size(); ++j)
      if (run[j].b1 < run[j].b0 || (j + 1 < run.size() && run[j + 1].b0 < run[j].b1)) return false;
    return true;
  };
  // (And the incoming range within the near parts' unless they reach the edge's end, as the
  // ranges the solver reports are: the sweep below sees no interval beyond them.)
  // The walk follows one incoming interval: a run of them (EdgeIntervals::insertRun), which may
  // overlap one another, takes the route for lists out of order.
  const Interval& in = e.incoming.front();
  const bool inOrder = e.incoming.size() == 1 && endsInOrder(beforeNear) &&
                       endsInOrder(afterNear) && !(in.b1 < in.b0) &&
                       (changed.beforeLo == 0 || in.b0 >= beforeNear.front().b0) &&
                       (changed.beforeHi == e.before.size() || in.b1 <= beforeNear.back().b1) &&
                       (changed.afterLo == 0 || in.b0 >= afterNear.front().b0) &&
                       (changed.afterHi == e.after.size() || in.b1 <= afterNear.back().b1);
  const std::size_t numEnds = 2 * (beforeNear.size() + rewritten.size() + 1);

  const double reachFrom = hull.lo - tiny, reachTo = hull.hi + tiny;
  const auto incomingNear = [&](double x) { return x >= reachFrom && x <= reachTo; };
  std::vector<double>& xs = samples_;
  xs.clear();
  // Points for the sweep found besides the walk's, in no order with its samples (appendWhereBelow):
  // merged in at the end.
  std::vector<double>& extra = extraSamples_;
  extra.clear();
  const auto withExtra = [&] {
    if (!extra.empty()) mergeInto(xs, extra);
  };

  // The samples of the piece (p, q) (the midpoint and the uniform samples inside), merged in order
  // with the uniform samples: a uniform sample at or before p (an endpoint, or before the first)
  // is always taken. Inside a piece where one interval of each list covers it with the same
  // function, a sample the incoming interval does not reach even with the slack has the old
  // list's values to the bit: every error the sweep computes there is 0 (see
  // worstPointwiseMinError), so it is not taken. (Most of the rewritten range is such: an old
  // interval the incoming one cut shorter, away from the cut.)
  double u = nextUniform();
  // Passes the samples below x, untaken: straight to the index floor(x / spacing), whose samples
  // before are a spacing (less a few roundings) below x, then one by one.
  // (Inlined by request: with the walk's other routes beside it, GCC 12 made it a call, a tenth
  // of the walk's instructions on armadillo.)
  const auto skipTo = [&](double x) __attribute__((always_inline)) {
    if (!(u < x)) return;
    if (std::isfinite(x) && e.edgeLength > 0.0)
      k = std::max(k, static_cast<int>(
                          std::clamp(std::floor(x / e.edgeLength * uniform), 0.0, uniform + 1.0)));
    for (u = nextUniform(); u < x; u = nextUniform()) {
    }
  };
  // The largest sample below `below` and at most `atMost` (−∞ for none), found from its index.
  const auto lastSample = [&](double below, double atMost) {
    int j = kLast;
    const double bound = std::min(below, atMost);
    if (std::isfinite(bound) && e.edgeLength > 0.0)
      j = std::min(j, static_cast<int>(std::clamp(std::ceil(bound / e.edgeLength * uniform) + 1.0,
                                                  -1.0, double(uniform))));
    for (; j >= 0; --j) {
      const double x = uniformAt(j);
      if (x < below && x <= atMost && x <= to) return x >= from ? x : -double(INFINITY);
    }
    return -double(INFINITY);
  };
  const auto samplePiece = [&](double p, double q, bool same, auto&& take) {
    for (; u <= p; u = nextUniform()) xs.push_back(u);
    const double m = 0.5 * (p + q);
    for (; u < m; u = nextUniform())
      if (!same || incomingNear(u)) take(u);
    if (!same || incomingNear(m)) take(m);
    for (; u < q; u = nextUniform())
      if (!same || incomingNear(u)) take(u);
  };
  const auto pushSample = [&](double x) { xs.push_back(x); };

  if (!inOrder) {
    // The endpoints copied out and sorted; the intervals covering a piece found at its midpoint,
    // and every sample left to the sweep.
    std::vector<double>& ends = ends_;
    ends.clear();
    for (const Interval& w : beforeNear) ends.insert(ends.end(), {w.b0, w.b1});
    for (const Interval& w : rewritten) ends.insert(ends.end(), {w.b0, w.b1});
    for (const Interval& w : e.incoming) ends.insert(ends.end(), {w.b0, w.b1});
    std::sort(ends.begin(), ends.end());
    for (std::size_t i = 1; i < ends.size(); ++i)
      if (ends[i] > ends[i - 1]) samplePiece(ends[i - 1], ends[i], false, pushSample);
    for (; std::isfinite(u); u = nextUniform()) xs.push_back(u);
    // Which intervals cover a piece is not known here: every two functions of the update, over
    // the stretch both reach, either way round (mutant b07628e0 of docs/mutation.md sent lists of
    // touching intervals this way, where a dip between two samples went unseen).
    const std::span<const Interval> runs[] = {beforeNear, rewritten, e.incoming};
    appendWhereAnyIsBelow(runs, from, to, extra);
    withExtra();
    return samples_;
  }

  // Lists in order: one sweep over the ends of the three runs, merged as std::merge would order
  // them (the second run's end first only when below the first's), knows which interval of each
  // covers the piece between two consecutive ends: the last one whose start it passed, until
  // it passes that one's end. (So do the old list's intervals beyond beforeNear and the new
  // list's beyond afterNear, for lists sorted as the cheap tier checks them: they lie beyond the
  // neighbours, which are as they were in both lists.)
  std::size_t tb = 0, ta = 0, ti = 0;
  const std::size_t nb = 2 * beforeNear.size(), na = 2 * rewritten.size();
  const auto endOf = [](std::span<const Interval> run, std::size_t t) {
    return (t & 1) != 0 ? run[t >> 1].b1 : run[t >> 1].b0;
  };
  const double incomingEnds[] = {in.b0, in.b1};
  const Interval* oldOne = nullptr;        // of beforeNear
  const Interval* rewrittenOne = nullptr;  // of rewritten
  bool incomingCovers = false;
  // Takes the next end and passes it; returns its value.
  const auto next = [&]() -> double {
    const bool fromB = tb < nb, fromA = ta < na;
    if (fromB || fromA) {
      const bool takeA = !fromB || (fromA && endOf(rewritten, ta) < endOf(beforeNear, tb));
      const double s = takeA ? endOf(rewritten, ta) : endOf(beforeNear, tb);
      if (!(ti < 2 && incomingEnds[ti] < s)) {
        std::size_t& t = takeA ? ta : tb;
        const Interval* w = &(takeA ? rewritten : beforeNear)[t >> 1];
        const Interval*& covering = takeA ? rewrittenOne : oldOne;
        if ((t & 1) == 0)
          covering = w;
        else if (covering == w)
          covering = nullptr;
        ++t;
        return s;
      }
    }
    incomingCovers = ti == 0;
    return incomingEnds[ti++];
  };
  // The new list's interval over the piece: the rewritten one, or an old one outside the part
  // that differs, which the new list holds too.
  const Interval* const diffBegin = e.before.data() + changed.diffBeforeLo;
  const Interval* const diffEnd = e.before.data() + changed.diffBeforeHi;
  const auto keptInNewList = [&](const Interval* w) {
    return w != nullptr && (w < diffBegin || w >= diffEnd);
  };

  // A sample farther than the slack from its piece's ends sees, in worstPointwiseMinError, no
  // function by its slack only: its loose minimum is the strict one, every candidate it matches
  // is one of the functions covering it, and its error comes down to |list − min(old, incoming)|.
  // It is evaluated here, with the sweep's arithmetic term for term (the list's value taken from
  // the old or the incoming function's when it is one of them). Samples nearer the ends go to
  // the sweep, and so do all of an update that removed a D1 sliver (the sweep bounds the list
  // differently over it).
  const bool noSliverRemoved = e.report.removedTiny.empty();
  double p = next();
  for (std::size_t i = 1; i < numEnds; ++i) {
    const Interval* const oldHere = oldOne;
    const Interval* const newHere = rewrittenOne != nullptr ? rewrittenOne
                                    : keptInNewList(oldOne) ? oldOne
                                                            : nullptr;
    const bool incomingHere = incomingCovers;
    const double q = next();
    if (!(q > p)) {
      p = q;
      continue;
    }
    const double m = 0.5 * (p + q);
    if (!(m > p && m < q)) {
      // (A piece one ulp wide: no sample is inside it by the slack; which intervals hold its
      // midpoint, an endpoint, is what the lists say there.)
      const std::ptrdiff_t kBefore = lastStartingBefore(e.before, m);
      const std::ptrdiff_t kAfter = lastStartingBefore(e.after, m);
      const Interval* a = coveringOnly(e.before, kBefore - 1, kBefore + 1, m);
      const Interval* b = coveringOnly(e.after, kAfter - 1, kAfter, m);
      samplePiece(p, q, a != nullptr && b != nullptr && sameFunction(*a, *b), pushSample);
      p = q;
      continue;
    }
    const bool same = oldHere != nullptr && newHere != nullptr && sameFunction(*oldHere, *newHere);
    const int newIs = newHere == nullptr                           ? 0
                      : incomingHere && sameFunction(*newHere, in) ? 1
                      : same                                       ? 2
                                                                   : 0;
    const double inFrom = p + tiny, inTo = q - tiny;
    const auto evaluate = [&](double x) {
      const double incomingValue = incomingHere ? in.distanceAt(x) : INFINITY;
      const double oldValue = oldHere != nullptr ? oldHere->distanceAt(x) : INFINITY;
      const double strict = std::min(incomingValue, oldValue);
      const double got = newHere == nullptr ? INFINITY
                         : newIs == 1       ? incomingValue
                         : newIs == 2       ? oldValue
                                            : newHere->distanceAt(x);
      double err = 0.0;
      if (!std::isfinite(got)) {
        err = std::isfinite(strict) ? INFINITY : 0.0;
      } else if (!std::isfinite(strict)) {
        err = INFINITY;
      } else {
        const double scale = got + e.edgeLength, off = std::abs(got - strict);
        if (off <= interior.worst * scale) return;
        err = off / scale;
      }
      if (!(err <= interior.worst)) interior.worst = err, interior.at = {x, got, strict, strict};
    };
    // Where the new list holds one of the two functions present, the error is how far it lies
    // above the other, which is largest at an end of the span the samples cover or where the two
    // slopes agree (largestDifferenceAt): those points are evaluated, and the samples between
    // stand for that span (found exactly, not at 32 points: a dip narrower than their spacing is
    // seen). The error is relative to the list's value plus L, which moves by at most the span's
    // width along it, so the point found has at least half the largest relative error of the
    // span. Where the new list holds the only function present, the error is 0.
    const Interval* const other = newIs == 1 ? oldHere : newIs == 2 && incomingHere ? &in : nullptr;
    const bool none = (newIs == 1 && oldHere == nullptr) || (newIs == 2 && !incomingHere);
    // The routes below that sample a piece only uniformly also take the points where a function
    // present lies furthest below the one the new list holds.
    const auto whereBelowHere = [&] {
      if (newHere == nullptr) return;  // (no function kept: every sample's error is infinite)
      if (oldHere != nullptr && !same) appendWhereBelow(*newHere, *oldHere, p, q, extra);
      if (incomingHere && newIs != 1) appendWhereBelow(*newHere, in, p, q, extra);
    };
    if (!noSliverRemoved) {
      samplePiece(p, q, same, pushSample);
      whereBelowHere();
    } else if (other == nullptr && !none) {
      samplePiece(p, q, same, [&](double x) {
        if (x > inFrom && x < inTo)
          evaluate(x);
        else
          xs.push_back(x);
      });
      whereBelowHere();
    } else if (!(m > inFrom && m < inTo)) {
      samplePiece(p, q, same, pushSample);  // (no sample is inside by the slack)
    } else {
      // The samples samplePiece takes, with those inside by the slack found at the two ends of
      // their run (where the incoming interval reaches, in a piece where the lists agree) by index.
      const double takenFrom = same ? reachFrom : -INFINITY, takenTo = same ? reachTo : INFINITY;
      const auto taken = [&](double x) { return x >= takenFrom && x <= takenTo; };
      for (; u <= p; u = nextUniform()) xs.push_back(u);
      for (; u <= inFrom; u = nextUniform())
        if (taken(u)) xs.push_back(u);
      double first = INFINITY, last = -INFINITY;
      skipTo(std::min(takenFrom, inTo));
      if (u < inTo && u <= takenTo) first = u, last = std::max(u, lastSample(inTo, takenTo));
      skipTo(inTo);
      if (taken(m)) first = std::min(first, m), last = std::max(last, m);
      for (; u < q; u = nextUniform())
        if (taken(u)) xs.push_back(u);
      if (other != nullptr && first <= last) {
        evaluate(first);
        if (last > first) evaluate(last);
        for (const double x : largestDifferenceAt(*newHere, *other, first, last))
          if (x > first && x < last) evaluate(x);
      }
    }
    p = q;
  }
  for (; std::isfinite(u); u = nextUniform()) xs.push_back(u);
  withExtra();
  return samples_;
}

InvariantChecker::PointwiseMinError InvariantChecker::worstPointwiseMinError(
    const EdgeUpdateEvent& e, std::span<const double> xs, double tiny) {
  // The last interval of each list starting at or before the sample (-1: none), for sorted
  // lists as lastStartingBefore finds it; advanced from one sample to the next.
  std::ptrdiff_t kBefore = xs.empty() ? -1 : lastStartingBefore(e.before, xs.front());
  std::ptrdiff_t kAfter = xs.empty() ? -1 : lastStartingBefore(e.after, xs.front());
  const std::ptrdiff_t numBefore = std::ssize(e.before), numAfter = std::ssize(e.after);
  double worst = 0.0;
  std::array<double, 4> worstAt{};
  auto valueWithSlack = [&](const Interval& w, double x) {
    return x >= w.b0 - tiny && x <= w.b1 + tiny ? w.distanceAt(x) : INFINITY;
  };
  // Every value the repaired list may take at a sample: one per incoming interval and three of the
  // old list at most.
  std::vector<double>& candidates = candidates_;
  std::vector<const Interval*>& candidateOf = candidateOf_;
  candidates.resize(e.incoming.size() + 3);
  candidateOf.resize(candidates.size());
  // Where step 3 removed a D1 sliver, a neighbour grew over it and the gap beside it, one no
  // longer than the sliver at its end by more than the slack (canTakeSliver): with both functions
  // 1-Lipschitz, the list there is above the functions really present by less than the slack and
  // twice the stretch grown over (`reach`): 2 reach + 4 slack bounds it. More is a sliver's
  // distance lost (corpus/fuzz_solver/regress/vertex-agreement-d1-pieces-of-a-source-near-a-
  // corner-merged-into-a-far-g1-window). Below them it may be by more: a neighbour takes slivers
  // one after another (under a far window's ray-end precision), which is D1's own premise; the
  // solve's lower-bound oracles watch that.
  auto removedSliverReach = [&](double x) {
    double reach = 0.0;
    for (const auto& [lo, hi] : e.report.removedTiny)
      if (x >= lo - tiny && x <= hi + tiny) reach = std::max(reach, hi - lo + tiny);
    return reach;
  };
  for (double x : xs) {
    while (kBefore + 1 < numBefore && e.before[kBefore + 1].b0 <= x) ++kBefore;
    while (kAfter + 1 < numAfter && e.after[kAfter + 1].b0 <= x) ++kAfter;
    // The old list is sorted: only intervals next to the one starting last before x can reach x,
    // even with the sewing slack; only the interval starting last before x and its left
    // neighbour can cover x in the new one (listDistance).
    const std::ptrdiff_t beforeFirst = std::max<std::ptrdiff_t>(0, kBefore - 1);
    const std::ptrdiff_t beforeLast = std::min<std::ptrdiff_t>(kBefore + 1, numBefore - 1);
    const std::ptrdiff_t afterFirst = std::max<std::ptrdiff_t>(0, kAfter - 1);
    bool incomingNear = false;
    for (const Interval& w : e.incoming)
      incomingNear = incomingNear || (x >= w.b0 - tiny && x <= w.b1 + tiny);
    // Where the incoming interval does not reach, the minimum is the old list, and where one
    // interval of each list covers x with the same function (source and σ), the new list's
    // value is the old one's to the bit: every error below is 0 there, so nothing is evaluated.
    // (Most samples of an update are such: an old interval the incoming one cut shorter, away
    // from the cut.)
    if (!incomingNear) {
      const Interval* oldOne = coveringOnly(e.before, kBefore - 1, kBefore + 1, x);
      const Interval* newOne = coveringOnly(e.after, kAfter - 1, kAfter, x);
      if (oldOne != nullptr && newOne != nullptr && sameFunction(*oldOne, *newOne)) continue;
    }
    const double reach = removedSliverReach(x);
    // strict: the minimum of the functions where they really are; loose: the minimum with the
    // slack step 4 may sew; candidates: every value the repaired list may take at x (a sewn end
    // is one function's value carried across the gap).
    // (Each function is evaluated once per sample: strict and loose share the value, and an
    // interval of the new list that is an old one's or the incoming one's function, cut to
    // another range, takes the value already computed.)
    double loose = INFINITY, strict = INFINITY;
    std::size_t numCandidates = 0;
    for (const Interval& w : e.incoming) {
      const double v = valueWithSlack(w, x);
      if (!std::isfinite(v)) continue;
      if (w.b0 <= x && x <= w.b1) strict = std::min(strict, v);
      candidateOf[numCandidates] = &w, candidates[numCandidates++] = v;
      loose = std::min(loose, v);
    }
    for (std::ptrdiff_t i = beforeFirst; i <= beforeLast; ++i) {
      const Interval& w = e.before[i];
      const double v = valueWithSlack(w, x);
      if (w.b0 <= x && x <= w.b1) strict = std::min(strict, v);
      if (std::isfinite(v)) candidateOf[numCandidates] = &w, candidates[numCandidates++] = v;
      loose = std::min(loose, v);
    }
    double got = INFINITY;
    for (std::ptrdiff_t i = afterFirst; i <= kAfter; ++i) {
      const Interval& w = e.after[i];
      if (!(x >= w.b0 && x <= w.b1)) continue;
      double v = NAN;
      for (std::size_t c = 0; c < numCandidates && std::isnan(v); ++c)
        if (sameFunction(*candidateOf[c], w)) v = candidates[c];
      got = std::min(got, std::isnan(v) ? w.distanceAt(x) : v);
    }
    double err = 0.0;
    if (!std::isfinite(got)) {
      err = std::isfinite(strict) ? INFINITY : 0.0;  // coverage lost
    } else if (reach > 0.0) {
      // Over a removed sliver: not above the functions there by more than the bound above.
      const double above = std::isfinite(strict) ? got - strict - (2.0 * reach + 4.0 * tiny) : 0.0;
      if (above <= worst * (got + e.edgeLength)) continue;
      err = above / (got + e.edgeLength);
    } else if (!std::isfinite(loose)) {
      err = INFINITY;  // coverage from nowhere
    } else {
      // The list must take one of the candidate values, never below the loose minimum (a
      // distance no function offers) and never above the strict one (a function that is there
      // beats it). Between the two, which sewn value it takes depends on which gap step 4 sewed:
      // an interval's slack reaches an end of the edge only if nothing else covered that end
      // (corpus/fuzz_edge_update/regress/pointwise-min-slack-of-an-interval-the-incoming-one-covered).
      const double scale = got + e.edgeLength;
      double match = INFINITY;
      for (std::size_t i = 0; i < numCandidates; ++i) match = std::min(match, std::abs(got - candidates[i]));
      if (std::isfinite(strict)) match = std::min(match, std::abs(got - strict));
      const double below = std::max(0.0, loose - got);
      const double above = std::isfinite(strict) ? std::max(0.0, got - strict) : 0.0;
      // (Compared before dividing: only a new worst needs the relative error.)
      const double off = std::max({match, below, above});
      if (off <= worst * scale) continue;
      err = off / scale;
    }
    if (!(err <= worst)) worst = err, worstAt = {x, got, strict, loose};
  }
  return {worst, worstAt};
}

// Full tier: the list after is the pointwise minimum of the old list and the incoming interval,
// sampled. Outside the rewritten parts and the incoming range the list after is the list before,
// which is the minimum there: the samples are taken where the two lists differ or the incoming
// interval reaches, with the neighbours on each side.
void InvariantChecker::checkPointwiseMin(const EdgeUpdateEvent& e, const ChangedRange& changed,
                                         std::size_t lo, std::size_t hi) {
  const std::size_t beforeLo = changed.beforeLo >= 1 ? changed.beforeLo - 1 : 0;
  const std::size_t beforeHi = std::min(changed.beforeHi + 1, e.before.size());
  const std::span<const Interval> beforeNear = e.before.subspan(beforeLo, beforeHi - beforeLo);
  const std::span<const Interval> afterNear = e.after.subspan(lo, hi - lo);
  const double tiny = sewingSlack(e, beforeNear);
  PointwiseMinError interior;
  const std::span<const double> xs =
      pointwiseMinSamples(e, changed, beforeNear, afterNear, tiny, interior);
  const PointwiseMinError error =
      PointwiseMinError::worse(interior, worstPointwiseMinError(e, xs, tiny));
  // (The message is written only when it is needed: this runs at every edge update.)
  const bool ok = error.worst <= tol::kPointwiseMinRel;
  std::string where;
  if (!ok) {
    std::ostringstream os;
    os << std::setprecision(17) << "at x = " << error.at[0] << " the list gives " << error.at[1]
       << " but min(before, incoming) is " << error.at[2] << " (" << error.at[3]
       << " with the sewing slack)";
    where = os.str();
  }
  record(PointwiseMin, ok, error.worst, where, &e);
}

// ===  End of the solve ===========================================================================

void InvariantChecker::onWindowDropped(const WindowDroppedEvent& e) {
  if (level_ == CheckLevel::Full)
    dropped_.push_back({e.edge, e.window, e.vertex, e.vertexDistance, e.rule});
}

void InvariantChecker::onFinish(const GeodesicSolver& solver) {
  if (level_ != CheckLevel::Full) return;
  const bool ranToEnd = !std::isfinite(solver.stats().radius);
  checkFinal(solver.mesh(), solver.edgeIntervals(), solver.vertexDistancesInMeshUnits(), solver.sources(),
             ranToEnd);
  if (ranToEnd) checkDroppedWindows(solver);
  dropped_.clear();
}

// The solver dropped these windows as longer everywhere than a path through an end of their edge
// (GeodesicSolver::dominatedAtAnEdgeEnd) or than the edge's list (a pseudo-source's window along
// its own edge, GeodesicSolver::dominatedAlongItsEdge). Whatever the rule's reasoning, the final
// distances must then be nowhere above them: sampled at the window's ends and quarters against the
// edge's final list, and on the ray through its middle a quarter of the way into the face the
// window would have crossed against the solver's distance there (skipped where the ray has left the
// face). One point there, not three: a face query costs about 2,000 instructions, and three per
// drop were 0.28 of an unchecked armadillo solve.
void InvariantChecker::checkDroppedWindows(const GeodesicSolver& solver) {
  const Mesh& mesh = solver.mesh();
  for (const DroppedWindow& dw : dropped_) {
    const Edge& E = mesh.edge(dw.edge);
    const Interval& w = dw.window;
    double longestAtEnd = 0.0;
    for (Index e : mesh.vertexEdges(dw.vertex)) longestAtEnd = std::max(longestAtEnd, mesh.edge(e).length);
    const auto list = solver.edgeIntervals()[dw.edge].intervals();
    const Index f = E.face[1 - w.side];
    const Vec2 s(w.source.x(), -w.source.y());  // in the frame of f, whose apex has y > 0
    // (face: kNoIndex for a point of the edge, else the face beyond it the point is in.)
    auto check = [&](double got, double own, Index face, double x) {
      const double slack = tol::droppedWindowTolerance(own, E.length, longestAtEnd);
      const double error = (got - own) / (own + E.length);
      const bool ok = got <= own + slack;
      std::string why;
      if (!ok) {
        std::ostringstream os;
        os << std::setprecision(17) << "window " << describe(w) << " of edge " << dw.edge << " ("
           << E.vertex[0] << "-" << E.vertex[1] << "), dropped "
           << (dw.rule == DropRule::EdgeEnd ? "as longer than the path through vertex "
                                            : "as longer than the edge's list, from vertex ")
           << dw.vertex << " (at " << dw.vertexDistance << "), is " << own
           << (face == kNoIndex
                   ? " on its edge at x = "
                   : " beyond it in face " + std::to_string(face) + ", on the ray through x = ")
           << x << ", where the solve ends at " << got;
        why = os.str();
      }
      record(DroppedWindowDominated, ok, std::max(0.0, error), why, nullptr);
    };
    for (int i = 0; i <= 4; ++i) {
      const double x = i == 4 ? w.b1 : w.b0 + 0.25 * i * (w.b1 - w.b0);
      check(listDistance(list, x), w.distanceAt(x), kNoIndex, x);
      if (f == kNoIndex || i != 2) continue;
      const FaceFrame& fr = mesh.frame(f, dw.edge);
      const Vec2 p(x, 0.0), ray = p - s;
      if (!(ray.y() > 0.0 && fr.apexPos.y() > 0.0)) continue;
      const Vec2 q = p + (0.25 * fr.apexPos.y() / ray.y()) * ray;
      const double atApex = 0.25, atV2 = (q.x() - atApex * fr.apexPos.x()) / E.length, atV0 = 1.0 - atV2 - atApex;
      if (!(atV0 >= 0.0 && atV2 >= 0.0)) continue;
      std::array<double, 3> bary{};
      const auto& corners = mesh.face(f);
      for (int k = 0; k < 3; ++k)
        bary[k] = corners[k] == E.vertex[0] ? atV0 : (corners[k] == E.vertex[1] ? atV2 : atApex);
      const double got = solver.distanceInMeshUnits(SurfacePoint::inFace(f, bary[0], bary[1], bary[2]));
      check(got, w.sigma + (q - s).norm(), f, x);
    }
  }
}

void InvariantChecker::checkFinal(const Mesh& mesh, std::span<const EdgeIntervals> edges,
                                  std::span<const double> d, std::span<const ResolvedPoint> sources,
                                  bool ranToEnd) {
  std::vector<char> sourceComponent(mesh.numComponents() + 1, 0);
  for (const ResolvedPoint& s : sources) {
    Index v = kNoIndex;
    if (s.kind == SurfacePoint::Kind::Vertex) v = s.element;
    else if (s.kind == SurfacePoint::Kind::Edge) v = mesh.edge(s.element).vertex[0];
    else v = mesh.face(s.element)[0];
    if (mesh.isReferenced(v)) sourceComponent[mesh.componentOf(v)] = 1;
  }
  std::vector<double> longestAt(mesh.numVertices(), 0.0);  // longest incident edge per vertex
  for (Index e = 0; e < mesh.numEdges(); ++e)
    for (Index v : mesh.edge(e).vertex) longestAt[v] = std::max(longestAt[v], mesh.edge(e).length);
  for (Index e = 0; e < mesh.numEdges(); ++e) {
    const Edge& E = mesh.edge(e);
    const auto list = edges[e].intervals();
    if (ranToEnd && sourceComponent[mesh.componentOf(E.vertex[0])]) {
      bool covered = !list.empty() && list.front().b0 == 0.0 && list.back().b1 == E.length;
      for (std::size_t i = 0; covered && i + 1 < list.size(); ++i) covered = list[i].b1 == list[i + 1].b0;
      // (The messages are written only for a failure: formatting them for every edge and vertex
      // cost more than the checks.)
      std::string why;
      if (!covered) {
        std::ostringstream os;
        os << "edge " << e << " (" << E.vertex[0] << "-" << E.vertex[1] << ") is not fully covered by its "
           << list.size() << " intervals";
        why = os.str();
      }
      record(FullCoverage, covered, 0.0, why, nullptr);
    }
    if (ranToEnd) checkExhausted(mesh, e, list);
    for (int k = 0; k < 2; ++k) {
      const Index v = E.vertex[k];
      if (!std::isfinite(d[v]) || list.empty()) continue;
      const double x = k == 0 ? 0.0 : E.length;
      const double got = listDistance(list, x);
      if (!std::isfinite(got)) continue;  // not covered: reported by full-coverage
      const double err = std::abs(got - d[v]) / (d[v] + E.length);
      const double allowed =
          tol::vertexAgreementTolerance(d[v], E.length, longestAt[v]) / (d[v] + E.length);
      std::string why;
      if (!(err <= allowed)) {
        std::ostringstream os;
        os << std::setprecision(17) << "vertex " << v << " has distance " << d[v] << " but edge " << e
           << " gives " << got << " there";
        why = os.str();
      }
      record(VertexAgreement, err <= allowed, err, why, nullptr);
    }
  }
}

// A solve that ran to the end has crossed every face with every window that can cross it: no
// interval with a face on the side it propagates into is still pending. (The solver's queue holds
// edge sides, not windows; this looks at the windows themselves.)
void InvariantChecker::checkExhausted(const Mesh& mesh, Index e, std::span<const Interval> list) {
  const Edge& E = mesh.edge(e);
  for (const Interval& w : list) {
    if (!w.pending() || E.face[1 - w.side] == kNoIndex) continue;
    std::ostringstream os;
    os << std::setprecision(17) << "edge " << e << " (" << E.vertex[0] << "-" << E.vertex[1]
       << "): " << describe(w) << " is still pending at the end of the solve; face "
       << E.face[1 - w.side] << " was never crossed from it";
    record(WavefrontExhausted, false, 0.0, os.str(), nullptr);
    return;
  }
  record(WavefrontExhausted, true, 0.0, "", nullptr);
}

void writeReproducer(const InvariantViolation& v, const std::string& path) {
  std::ofstream out(path);
  out << std::setprecision(17);
  out << "# geodex edge-update reproducer: " << v.what() << "\n";
  out << "geodex-edge-update 1\n";
  out << "invariant " << v.invariant() << "\n";
  out << "branch " << v.branch << "\n";
  out << "edge-length " << v.edgeLength << "\n";
  auto put = [&](const char* tag, const Interval& w) {
    out << tag << " " << w.b0 << " " << w.b1 << " " << w.source.x() << " " << w.source.y() << " "
        << w.sigma << " " << int(w.side) << "\n";
  };
  out << "before " << v.before.size() << "\n";
  for (const Interval& w : v.before) put("interval", w);
  // (A run of children, merged by one update, is one incoming line each, in the update's order.)
  for (const Interval& w : v.incoming) put("incoming", w);
}

}  // namespace geodex::verify
