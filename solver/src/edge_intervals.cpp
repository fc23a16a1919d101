#include "geodex/edge_intervals.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "geodex/check.h"
#include "geodex/tolerance.h"

namespace geodex {
namespace {

bool sameSource(const Interval& p, const Interval& q, double edgeLength) {
  const double tol = tol::kSameSourceRel * edgeLength;
  return p.side == q.side && std::abs(p.sigma - q.sigma) <= tol &&
         (p.source - q.source).squaredNorm() <= tol * tol;
}

// Whether the incoming distance f beats the old one g at a point: shorter by more than the tie
// tolerance, or within it and from a pseudo-source reached earlier (σ smaller by more than it).
// The second makes a tie independent of the order the two arrive in: a source and the saddles on
// one straight line from it (σ growing along it) tie within rounding for 1e-7 of the edge around
// where the line crosses it, and whichever came first kept that stretch; the windows on the next
// edge, cast from different sources through a breakpoint off the line, then left gaps of 2e-9 to
// 5e-9 between them (corpus/fuzz_solver/regress/full-coverage-ties-of-collinear-pseudo-sources-
// kept-in-arrival-order). The smaller σ is the one the triangle inequality says is never longer.
bool incomingBeats(double f, double g, const Interval& incoming, const Interval& old) {
  const double tie = tol::kTieRel * g;
  return f < g - tie || (f <= g + tie && incoming.sigma < old.sigma - tie);
}

bool incomingWins(const Interval& incoming, const Interval& old, double x) {
  return incomingBeats(incoming.distanceAt(x), old.distanceAt(x), incoming, old);
}

void markChanged(Interval& w) { w.flags |= Interval::kChanged; }

// A pending interval keeps its queue entry while its point of smallest distance stays where it
// was (then so does the key: the distance along an edge is convex). `piece` is cut from or grown
// out of an interval whose smallest distance was at (x, at).
void keepOrRequeue(Interval& piece, double x, Interval::MinAt at) {
  if (piece.pending() && (piece.argMinDistance() != x || piece.minAt() != at)) markChanged(piece);
}

// D2: `left` reaches over `right`'s start, they overlap on [lo, hi] by less than ε; returns where
// they are to meet. Where the two agree there (a rounding overlap at a shared boundary, the usual
// case) at the midpoint; otherwise the one shorter in the middle keeps the whole overlap: a real
// overlap, only too thin to split by Eq. 1, must not give the longer distance the half it loses
// (corpus/fuzz_edge_update/regress/pointwise-min-D2-overlap-midpoint-keeps-larger-distance).
double overlapMeetingPoint(const Interval& left, const Interval& right, double lo, double hi,
                           double edgeLength) {
  const double mid = 0.5 * (lo + hi);
  const double f = left.distanceAt(mid), g = right.distanceAt(mid);
  if (std::abs(f - g) <= tol::kContinuityRel * (std::min(f, g) + edgeLength)) return mid;
  return f < g ? hi : lo;
}

// Sets w's range (steps 3–5: removal of a tiny neighbour, sewing, merging).
void setRange(Interval& w, double b0, double b1) {
  const double x = w.argMinDistance();
  const Interval::MinAt at = w.minAt();
  w.b0 = b0;
  w.b1 = b1;
  keepOrRequeue(w, x, at);
}

// w's range grows by a part nothing propagated (a tiny neighbour that was still pending, or half
// a sewn gap). An interval carries one pending bit, not a propagated sub-range, so a propagated
// one is propagated again whole; its repeated children tie with the ones it made before and
// Algorithm 2 keeps those (same pseudo-source).
void grewUnpropagated(Interval& w) {
  if (w.regrown >= tol::kMaxRegrowths) return;
  ++w.regrown;
  w.markPending();
  markChanged(w);
}

// Which of the two intervals is shorter at the samples keepShorter (below) decides by on old's
// piece [lo, hi]: lo, the point x* or the feet, hi.
struct SampledWinners {
  double sample[4];
  double f[4], g[4];  // the incoming and the old distance at each sample
  bool wins[4];       // the incoming interval wins there
  int numSamples = 0;
  bool uniform() const {
    for (int k = 1; k < numSamples; ++k)
      if (wins[k] != wins[0]) return false;
    return true;
  }
};

SampledWinners sampleWinners(const Interval& in, const Interval& old, double lo, double hi,
                             double edgeLength) {
  SampledWinners s;
  // (References, not a structured binding: clang 14 cannot capture one in agreeAt.)
  auto& sample = s.sample;
  auto& f = s.f;
  auto& g = s.g;
  auto& wins = s.wins;
  int& numSamples = s.numSamples;
  sample[numSamples++] = lo;
  const double y1 = in.source.y(), y2 = old.source.y();
  if (y1 != y2) {
    const double xStar = (in.source.x() * y2 - old.source.x() * y1) / (y2 - y1);
    if (xStar > lo && xStar < hi) sample[numSamples++] = xStar;
  } else if (y1 == 0.0) {
    for (const double foot : {in.source.x(), old.source.x()})
      if (foot > lo && foot < hi) sample[numSamples++] = foot;
  }
  sample[numSamples++] = hi;
  if (numSamples == 4 && sample[2] < sample[1]) std::swap(sample[1], sample[2]);  // the two feet
  for (int k = 0; k < numSamples; ++k) {
    f[k] = in.distanceAt(sample[k]);
    g[k] = old.distanceAt(sample[k]);
    wins[k] = incomingBeats(f[k], g[k], in, old);
  }
  // Where the two distances agree at an end of the piece up to rounding (both windows through
  // the same point, typically a vertex or a shared boundary ray), the tie there says nothing
  // about the inside: the end takes the verdict of the sample next to it. (Only up to rounding:
  // on a long edge two functions can differ by less than kContinuityRel × the edge length at an
  // end and still cross far inside.)
  auto agreeAt = [&](int k) {
    return std::abs(f[k] - g[k]) <= tol::kRoundingRel * (g[k] + edgeLength);
  };
  if (wins[0] != wins[1] && agreeAt(0)) wins[0] = wins[1];
  if (wins[numSamples - 1] != wins[numSamples - 2] && agreeAt(numSamples - 1))
    wins[numSamples - 1] = wins[numSamples - 2];
  return s;
}

// Step 1's D2 tests for an old interval w the incoming range reaches: w reaches over the incoming
// start (end) by less than `overlapTiny`, ε of the larger of the two, without covering the whole
// incoming range. Shared by step 1 and incomingLosesEverywhere.
bool overlapsStartByD2(const Interval& w, const Interval& in, double overlapTiny) {
  return w.b0 < in.b0 && w.b1 - in.b0 < overlapTiny && w.b1 < in.b1;
}
bool overlapsEndByD2(const Interval& w, const Interval& in, double overlapTiny) {
  return w.b1 > in.b1 && in.b1 - w.b0 < overlapTiny && w.b0 > in.b0;
}

// Whether the incoming interval loses on all of the piece [lo, hi] of an old one, told from one end
// when its source lies on the edge line beside the piece (a pseudo-source's window along its
// own edge, most of the lost updates): its distance grows at slope 1 away from the source and
// no distance grows faster, so f − g is smallest at the end nearest the source. Lost there by
// twice the tie tolerance (rounding is a few ulps, far below it), it is lost, to that tolerance,
// at every sample keepShorter would take: the same verdict, from two square roots.
bool losesFromTheNearEnd(const Interval& in, const Interval& old, double lo, double hi) {
  if (in.source.y() != 0.0) return false;
  double x;
  if (in.source.x() <= lo) {
    x = lo;
  } else if (in.source.x() >= hi) {
    x = hi;
  } else {
    return false;
  }
  const double f = in.distanceAt(x), g = old.distanceAt(x);
  return f - g > 2.0 * tol::kTieRel * (f + g + (hi - lo));
}

// What incomingLosesEverywhere learned of the old intervals `reached` (those overlapping the
// incoming range, in order): on the first `lostPrefix` of them the old one is kept (the incoming
// one wins at no sample of keepShorter, or is the same geodesic), and when `stopSampled`, `stop`
// holds keepShorter's samples for the next one, cut to the incoming range as step 1 cuts it.
// Steps 1 and 2 take these verdicts instead of sampling the same pieces again.
struct ReachedScan {
  std::size_t lostPrefix = 0;
  bool stopSampled = false;
  // Whether the scan found the first reached interval to be neither a D2 overlap at an end of the
  // incoming range nor of the incoming interval's source (false: it found one, or did not get as
  // far): updateOneReached then need not ask again.
  bool firstPlain = false;
  SampledWinners stop;
  // Whether `stop` holds the samples of the reached interval at `reachedIndex`: the scan stopped
  // there having sampled it.
  bool sampled(std::size_t reachedIndex) const { return stopSampled && reachedIndex == lostPrefix; }
};

// Whether the old intervals `reached` leave the incoming interval nothing: they cover its whole
// range, with no D2 overlap at its ends, and on each one's part of it the incoming one wins at no
// sample of keepShorter (or is the same geodesic). Steps 1 and 2 would then cut old intervals at
// the incoming ends only for step 5 to join the pieces again (and step 3 to take a piece cut
// thinner than ε as a D1 sliver).
bool incomingLosesEverywhere(const Interval& in, std::span<const Interval> reached,
                             double edgeLength, ReachedScan& scan) {
  if (reached.empty()) return false;
  double cursor = in.b0;
  for (const Interval& old : reached) {
    if (old.b0 > cursor) return false;  // a gap the incoming interval would fill
    const double overlapTiny = std::max(tinyLength(old, edgeLength), tinyLength(in, edgeLength));
    if (overlapsStartByD2(old, in, overlapTiny) || overlapsEndByD2(old, in, overlapTiny))
      return false;
    if (!sameSource(in, old, edgeLength)) {
      if (&old == &reached.front()) scan.firstPlain = true;
      const double lo = std::max(old.b0, in.b0), hi = std::min(old.b1, in.b1);
      if (!losesFromTheNearEnd(in, old, lo, hi)) {
        scan.stop = sampleWinners(in, old, lo, hi, edgeLength);
        if (!scan.stop.uniform() || scan.stop.wins[0]) {
          scan.stopSampled = true;
          return false;
        }
      }
    }
    ++scan.lostPrefix;
    cursor = old.b1;
  }
  return cursor >= in.b1;
}

// `in` lost everywhere to the intervals `reached` (incomingLosesEverywhere). When it is a sliver
// (shorter than its D1 threshold beside them) ending at a vertex, where another source's interval
// beat it, its rays beyond the vertex can fan out wider than the winner's: the update reports the
// fan lost there, and the solver has the vertex relay it, as for a sliver step 3 removes there
// (removeTinyIntervals). Whether the sliver came before the winner (and step 3 removed it) or
// after (and lost outright) was the order of arrival's: a source's shadow behind a hole's corner,
// 1e-12 wide, was left uncovered in one order (corpus/fuzz_solver/regress/full-coverage-source-
// ray-along-a-line-of-vertices-shadow-left-by-batch-order).
void reportFanOfALostSliver(const Interval& in, std::span<const Interval> reached,
                            double edgeLength, EdgeUpdateReport& report) {
  const Interval& first = reached.front();
  const Interval& last = reached.back();
  if (!(in.length() < tinyLengthBetween(&first, in, &last, edgeLength))) return;
  const double tiny = tinyLength(in, edgeLength);
  if (in.b0 <= tiny && !sameSource(first, in, edgeLength)) report.fanLostAtVertex |= 1;
  if (in.b1 >= edgeLength - tiny && !sameSource(last, in, edgeLength)) report.fanLostAtVertex |= 2;
}

// keepShorter's samples of `old`, the reached interval at `reachedIndex` (cut to the incoming
// range), against `in`: the scan's, when it sampled this one, else new ones written to `fresh`.
// (Referred to, not copied: they are 112 bytes, and most updates have them from the scan.)
const SampledWinners& samplesOf(const Interval& in, const Interval& old, const ReachedScan& scan,
                                std::size_t reachedIndex, SampledWinners& fresh,
                                double edgeLength) {
  if (scan.sampled(reachedIndex)) return scan.stop;
  fresh = sampleWinners(in, old, old.b0, old.b1, edgeLength);
  return fresh;
}

// Where steps 1 and 2 write the slice's new intervals and steps 3–5 work on them: a raw pointer and
// a count over storage the caller sized (piecesBound). Not a vector: writes to the intervals'
// one-byte fields may alias anything, which made every push_back reload the vector's own pointers
// (its capacity checks and copies were a tenth of a solve's instructions).
// Pieces of the incoming interval carry this flag until the end of the update, so that
// report.incomingSurvived can tell whether any of it is left.
constexpr std::uint8_t kFromIncoming = 4;
// Pieces of an earlier interval of a run (insertRun) while a later one's steps 1 and 2 run, and
// of all of them in its steps 3–5, which take either flag for a piece of the incoming intervals.
constexpr std::uint8_t kFromRun = 8;
constexpr std::uint8_t kFromAnyIncoming = kFromIncoming | kFromRun;

struct Pieces {
  Interval* data;
  std::size_t size;
  std::size_t capacity;
  int incomingRuns = 0;  // runs of the incoming interval's pieces (a tie strip needs two)
  // Appends w, or grows the last piece over it where w goes on with the same function in the same
  // state: step 5 would join the two (mergeSameSources), and a later child of a run would cut
  // them apart again first. Step 1 cuts an interval at the incoming ends and step 2 keeps both
  // sides, and most pieces were such halves: on the icosphere steps 1 and 2 of a run made 3.9
  // pieces a child, of which step 5 left one.
  void push(const Interval& w) {
    if (size > 0) {
      Interval& last = data[size - 1];
      if (last.b1 == w.b0 && last.source == w.source && last.sigma == w.sigma &&
          last.side == w.side && last.origin == w.origin && last.pending() == w.pending()) {
        setRange(last, last.b0, w.b1);
        last.flags |= static_cast<std::uint8_t>(w.flags & kFromAnyIncoming);
        return;
      }
    }
    GEODEX_CHECK(size < capacity, "steps 1 and 2 made more than " << capacity << " pieces");
    data[size++] = w;
  }
};
// Steps 1 and 2 make at most seven pieces of an old interval (a piece before the incoming range,
// a gap of the incoming one before it, keepShorter's up to four, the piece after the range) and
// one of the incoming range after the last.
constexpr std::size_t piecesBound(std::size_t sliceSize) { return 7 * sliceSize + 1; }

// ===  Step 2 for one old interval ================================================================
// Where on old's range [old.b0, old.b1] is the incoming interval shorter? findWinners cuts the
// range where the winner changes; keepShorter appends the pieces, in order, to `out`: pieces of the
// old interval (the first keeps old's state; all are marked changed when old was cut) and pieces of
// the incoming one (appended by newPiece).
//
// h = f − g (incoming minus old) has h' = cos θ_in − cos θ_old, zero only where x is collinear
// with the two sources (both lie on one side of the line, heights >= 0): h is monotone on either
// side of that point x*. So the winners at old.b0, x* and old.b1 tell every change of winner,
// at most one between two samples. (A source on the edge line has a kink at its foot, which is
// x* then; two sources on the line add both feet.) Eq. 1's roots only *locate* a change: with σ or
// the source distance many orders above the edge length its coefficients cancel, and a root can
// be off or missing. A root is taken where the two distances really agree there; otherwise (D4)
// the change is located by bisection on the exact difference of the two distance functions.
struct Winners {
  double cut[6];  // cut[0] = old.b0 < cut[1] < ... < cut[m] = old.b1
  bool wins[5];   // the incoming interval is shorter on [cut[k], cut[k + 1]]
  int m = 0;
};

Winners findWinners(const Interval& in, const Interval& old, const SampledWinners& sampled,
                    double edgeLength, EdgeUpdateReport& report) {
  const double lo = old.b0, hi = old.b1;
  const auto& sample = sampled.sample;
  const auto& f = sampled.f;
  const auto& g = sampled.g;
  const auto& wins = sampled.wins;
  const int numSamples = sampled.numSamples;
  Winners out;
  auto& cut = out.cut;
  auto& cutWins = out.wins;
  int& m = out.m;
  cut[0] = lo;
  cutWins[0] = wins[0];
  if (sampled.uniform()) {  // the common case: one of the two is shorter on the whole piece
    cut[1] = hi;
    m = 1;
    return out;
  }

  const double pieceTiny = std::max(tinyLength(in, edgeLength), tinyLength(old, edgeLength));
  const double bisectionResolution = 1e-3 * tol::kTinyIntervalRel * edgeLength;
  double roots[2];
  int numRoots = -1;  // computed on first need
  for (int k = 1; k < numSamples; ++k) {
    if (wins[k] == cutWins[m]) continue;
    const double a = sample[k - 1], b = sample[k];
    if (numRoots < 0) numRoots = equalDistanceCandidates(in, old, lo, hi, roots);
    double x = -1.0;
    // f − g is monotone between the two samples, so a real crossing is nearer zero than f − g at
    // both of them. Where the two functions run parallel within the tolerance (two sources 1e-10
    // apart, one with σ 1e-10), every point "agrees" to kEq1RootRel and a root far from the
    // crossing was taken: the incoming interval kept 1.3 of a 2-long edge it loses everywhere by
    // 2.6e-10 (corpus/fuzz_edge_update/regress/pointwise-min-eq1-root-of-parallel-functions).
    const double edgeDiff = 0.5 * std::min(std::abs(f[k - 1] - g[k - 1]), std::abs(f[k] - g[k]));
    for (int r = 0; r < numRoots; ++r) {
      if (roots[r] <= a || roots[r] >= b) continue;
      const double fr = in.distanceAt(roots[r]), gr = old.distanceAt(roots[r]);
      const double diff = std::abs(fr - gr);
      if (diff <= tol::kEq1RootRel * (gr + edgeLength) && diff <= edgeDiff) x = roots[r];
    }
    if (x < 0.0) {  // no accurate root between two samples with different winners
      double l = a, h = b;
      const bool loWins = wins[k - 1];
      for (int it = 0; it < 200 && h - l > bisectionResolution; ++it) {
        const double mid = 0.5 * (l + h);
        (incomingWins(in, old, mid) == loWins ? l : h) = mid;
      }
      x = 0.5 * (l + h);
      // D4 if the change is a real crossing inside the piece. One within ε of the piece's end
      // is the two functions meeting there (e.g. both through the same vertex), which Eq. 1 need
      // not resolve: the sliver it leaves is step 3's (D1).
      if (x - lo > pieceTiny && hi - x > pieceTiny) ++report.degeneracies[DegeneracyKind::D4];
    }
    report.eq1Breakpoints.push_back(x);
    cut[++m] = x;
    cutWins[m] = wins[k];
  }
  cut[++m] = hi;
  return out;
}

// Whether a sample of keepShorter's in [lo, hi] has the incoming distance f shorter than the old
// one g by more than the tie tolerance.
bool clearlyShorterAtASample(const SampledWinners& sampled, double lo, double hi) {
  for (int k = 0; k < sampled.numSamples; ++k)
    if (sampled.sample[k] >= lo && sampled.sample[k] <= hi &&
        sampled.f[k] < sampled.g[k] - tol::kTieRel * sampled.g[k])
      return true;
  return false;
}

// Whether `in` is nowhere on [lo, hi] shorter than `old` by more than the tie tolerance: where it
// wins there, it wins by the tie rule only (incomingBeats). The difference of the two distances is
// monotone on either side of the point x* (findWinners), so its ends, x* and the feet tell.
bool winsOnlyByTie(const Interval& in, const Interval& old, double lo, double hi,
                   const SampledWinners* sampled = nullptr) {
  // A sample of the whole old range inside [lo, hi] where `in` is clearly shorter settles it with
  // no new distance: most pieces `in` wins, it wins by far more than a tie.
  if (sampled != nullptr && clearlyShorterAtASample(*sampled, lo, hi)) return false;
  const auto clearlyShorterAt = [&](double x) {
    const double g = old.distanceAt(x);
    return in.distanceAt(x) < g - tol::kTieRel * g;
  };
  if (clearlyShorterAt(lo) || clearlyShorterAt(hi)) return false;
  const double y1 = in.source.y(), y2 = old.source.y();
  if (y1 != y2) {
    const double xStar = (in.source.x() * y2 - old.source.x() * y1) / (y2 - y1);
    if (xStar > lo && xStar < hi && clearlyShorterAt(xStar)) return false;
  } else if (y1 == 0.0) {
    for (const double foot : {in.source.x(), old.source.x()})
      if (foot > lo && foot < hi && clearlyShorterAt(foot)) return false;
  }
  return true;
}

// winsOnlyByTie on the whole piece keepShorter sampled, from the samples' distances (the same
// points: its ends, x* or the feet).
bool winsOnlyByTie(const SampledWinners& sampled) {
  constexpr double kAll = std::numeric_limits<double>::infinity();
  return !clearlyShorterAtASample(sampled, -kAll, kAll);
}

// Whether old keeps a piece the incoming interval won: by the tie rule only (`onlyByTie`, asked
// last), with old's function going on before and after it, on the same side of the edge (on the
// other side its rays go into the other face).
template <typename OnlyByTie>
bool tieStripStaysWithOld(const Interval& in, const Interval& old, bool oldBefore, bool oldAfter,
                          OnlyByTie&& onlyByTie) {
  return oldBefore && oldAfter && in.side == old.side && onlyByTie();
}

// A tie strip inside one window: where the incoming interval wins a piece of `old` by the tie rule
// only and old's function goes on on both sides of that piece, old keeps it. Windows of two
// pseudo-sources on one geodesic (a saddle s' on a geodesic from s, σ' = σ + |s s'|) tie along its
// line beyond s'; the tie rule gave s, the smaller σ, a strip cut out of the middle of s''s
// window, and downstream the two sources' rays through the strip's borders diverge: the strip's
// rays fan out less than the hole it leaves in s''s, and the gaps beside it widened past what
// step 4 sews (tests/data/regression/couplingdown-part-edge-source-leaves-a-gap.off). Kept whole,
// old's window goes on in one piece; its distance on the strip is the incoming one's to the tie
// tolerance. `cuts` is findWinners' answer on [old.b0, old.b1]; `oldBefore` (`oldAfter`): old's
// function goes on before (after) that range. The Eq. 1 breakpoints findWinners reported at the
// cuts that go are taken back.
void keepTieStripsInsideOld(Winners& cuts, const Interval& in, const Interval& old,
                            const SampledWinners& sampled, bool oldBefore, bool oldAfter,
                            EdgeUpdateReport& report) {
  bool flipped = false;
  for (int k = 0; k < cuts.m; ++k) {
    if (!cuts.wins[k] ||
        !tieStripStaysWithOld(in, old, k > 0 || oldBefore, k < cuts.m - 1 || oldAfter, [&] {
          return cuts.m == 1 ? winsOnlyByTie(sampled)
                             : winsOnlyByTie(in, old, cuts.cut[k], cuts.cut[k + 1], &sampled);
        }))
      continue;
    cuts.wins[k] = false;
    flipped = true;
    ++report.degeneracies.tieStripsKept;
  }
  if (!flipped) return;
  const int before = cuts.m - 1;  // breakpoints findWinners pushed, the last ones of the report
  report.eq1Breakpoints.resize(report.eq1Breakpoints.size() - static_cast<std::size_t>(before));
  int m = 0;
  for (int k = 1; k < cuts.m; ++k) {
    if (cuts.wins[k] == cuts.wins[m]) continue;
    report.eq1Breakpoints.push_back(cuts.cut[k]);
    cuts.cut[++m] = cuts.cut[k];
    cuts.wins[m] = cuts.wins[k];
  }
  cuts.cut[++m] = cuts.cut[cuts.m];
  cuts.m = m;
}

template <typename NewPiece, typename OldPiece>
void keepShorter(const Interval& in, const Interval& old, const SampledWinners& sampled,
                 double edgeLength, EdgeUpdateReport& report, Pieces& out, NewPiece&& newPiece,
                 OldPiece&& oldPiece, bool oldBefore, bool oldAfter) {
  if (sampled.uniform()) {
    const bool tieStripKept =
        sampled.wins[0] &&
        tieStripStaysWithOld(in, old, oldBefore, oldAfter, [&] { return winsOnlyByTie(sampled); });
    if (tieStripKept) ++report.degeneracies.tieStripsKept;
    if (sampled.wins[0] && !tieStripKept) {
      newPiece(old.b0, old.b1);
    } else {
      out.push(old);  // as the caller cut it
    }
    return;
  }
  Winners cuts = findWinners(in, old, sampled, edgeLength, report);
  keepTieStripsInsideOld(cuts, in, old, sampled, oldBefore, oldAfter, report);
  for (int k = 0; k < cuts.m; ++k) {
    if (cuts.wins[k]) {
      newPiece(cuts.cut[k], cuts.cut[k + 1]);
    } else {
      Interval w = old;
      w.b0 = cuts.cut[k];
      w.b1 = cuts.cut[k + 1];
      oldPiece(w);
      out.push(w);
    }
  }
}

}  // namespace

double EdgeIntervals::distanceAt(double x) const {
  double best = std::numeric_limits<double>::infinity();
  if (list_.empty()) return best;
  const std::size_t first = partitionFrom(list_, guessIndex(list_.size(), x, list_.back().b1),
                                          [x](const Interval& w) { return w.b1 < x; });
  for (std::size_t i = first; i < list_.size() && list_[i].b0 <= x; ++i)
    best = std::min(best, list_[i].distanceAt(x));
  return best;
}

// The window grows at slope 1 away from its source, at its edge's start or end, and no interval's
// distance σ' + |s x| grows faster: an interval no longer than it at its end nearer the source
// is nowhere longer on its range. Each interval is asked, not the list at the source's end only:
// the list steps up where a window's range ends, as at a saddle's shadow, which this window fills
// (SolverRegression.AFaceSourceAHairFromACornerLeavesNoGapDownstream, where the step was 1.3e-9).
bool EdgeIntervals::nowhereAbove(const Interval& alongEdge, bool fromStart,
                                 double edgeLength) const {
  if (list_.empty() || list_.front().b0 != 0.0 || list_.back().b1 != edgeLength) return false;
  for (std::size_t i = 0; i < list_.size(); ++i) {
    const Interval& w = list_[i];
    if (i + 1 < list_.size() && w.b1 != list_[i + 1].b0) return false;  // a gap it would fill
    const double nearSource = fromStart ? w.b0 : w.b1;
    if (!(w.distanceAt(nearSource) <= alongEdge.distanceAt(nearSource))) return false;
  }
  return true;
}

std::size_t EdgeIntervals::closeShadows(double widest, double passed) {
  std::size_t closed = 0;
  for (std::size_t k = 0; k + 1 < list_.size(); ++k) {
    Interval& p = list_[k];
    Interval& q = list_[k + 1];
    const double gap = q.b0 - p.b1;
    if (!(gap > 0.0 && gap < widest)) continue;
    if (std::max(p.distanceAt(p.b1), q.distanceAt(q.b0)) > passed) continue;
    p.b1 = q.b0 = 0.5 * (p.b1 + q.b0);
    ++closed;
  }
  return closed;
}

namespace {

// 2^-⌊log2 x⌋, so that x times it lies in [1, 2): exact to multiply by. From the bits when x is a
// normal double whose inverse is one too (std::ilogb and std::ldexp are library calls, a
// measurable part of Eq. 1); 1 for zero, inf or NaN.
double inversePowerOfTwo(double x) {
  const std::uint64_t biased = (std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff;
  if (biased >= 1 && biased <= 2045) return std::bit_cast<double>((2046 - biased) << 52);
  return x > 0.0 && std::isfinite(x) ? std::ldexp(1.0, -std::ilogb(x)) : 1.0;
}

}  // namespace

// ===  Eq. 1 ======================================================================================
// σa + |x − sa| = σb + |x − sb| for x on the edge line. With c = σb − σa, squaring twice gives
// A x² + B x + C = 0. Coordinates are shifted to the middle of [lo, hi] first, so that the
// squares stay of the size of the configuration rather than of the edge's distance to the origin.
int equalDistanceCandidates(const Interval& a, const Interval& b, double lo, double hi,
                            double roots[2]) {
  const double m = 0.5 * (lo + hi);
  // The coefficients are products of up to six lengths: measured in a power of two of the
  // largest one (exact), they stay of order one at any mesh scale and source distance.
  const double size =
      std::max({std::abs(a.source.x() - m), a.source.y(), std::abs(b.source.x() - m), b.source.y(),
                std::abs(b.sigma - a.sigma), 0.5 * (hi - lo)});
#ifdef GEODEX_NO_MESH_UNITS  // bench-only build (solver/CMakeLists.txt)
  const double k = 1.0;
#else
  const double k = inversePowerOfTwo(size);
#endif
  const double half = 0.5 * (hi - lo) * k;
  const double x1 = (a.source.x() - m) * k, y1 = a.source.y() * k;
  const double x2 = (b.source.x() - m) * k, y2 = b.source.y() * k;
  const double c = (b.sigma - a.sigma) * k;
  const double alpha = 2.0 * (x2 - x1);
  const double beta = x1 * x1 + y1 * y1 - x2 * x2 - y2 * y2 - c * c;
  const double A = alpha * alpha - 4.0 * c * c;
  const double B = 2.0 * alpha * beta + 8.0 * c * c * x2;
  const double C = beta * beta - 4.0 * c * c * (x2 * x2 + y2 * y2);

  double r[2];
  int n = 0;
  const double linearScale = std::abs(B) * half + std::abs(C);
  if (std::abs(A) * half * half <= 1e-14 * linearScale) {
    if (B != 0.0) r[n++] = -C / B;
  } else {
    double disc = B * B - 4.0 * A * C;
    if (disc < 0.0 && disc > -1e-12 * B * B) disc = 0.0;  // a double root (tangent functions)
    if (disc >= 0.0) {
      const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      r[n++] = q / A;
      if (q != 0.0) r[n++] = C / q;
    }
  }
  int kept = 0;
  const double unit = 1.0 / k;  // exact (a power of two): one division where there were two
  for (int i = 0; i < n; ++i) {
    const double x = r[i] * unit + m;
    if (std::isfinite(x) && x > lo && x < hi) roots[kept++] = x;
  }
  if (kept == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return kept;
}

// ===  Algorithm 2 ================================================================================
// EdgeIntervals::insert (at the end) finds the slice of the list an update reads and rewrites,
// runs steps 1 and 2 over it into a buffer, steps 3–5 over the buffer, widens the slice and starts
// again when those changed an interval at its edge, and splices the buffer back. Each step is a
// function of its own below.
namespace {

// ===  Steps 1 and 2 ==============================================================================
// One pass over the slice (the list's intervals [s0, s1), given as `slice`; the first of them
// the incoming range reaches is slice[firstReached]). Step 1 splits each old interval at the new
// one's ends, so that each piece is wholly inside or outside it (an overlap shorter than ε is not
// split off: it is D2, two intervals intersecting by a rounding error, resolved by
// overlapMeetingPoint). Step 2 keeps, on each piece inside, the shorter of the two; the new
// interval fills what no old interval covered. Writes the slice's new intervals, in order, to
// `out`; `scan` holds what incomingLosesEverywhere already decided about the reached ones.
void splitAndKeepShorter(std::span<const Interval> slice, std::size_t firstReached,
                         const Interval& incoming, const ReachedScan& scan, double edgeLength,
                         EdgeUpdateReport& report, Pieces& out) {
  Interval in = incoming;
  in.flags = static_cast<std::uint8_t>((incoming.flags & Interval::kPending) | Interval::kChanged |
                                       kFromIncoming);
  auto newPiece = [&](double lo, double hi) {  // appends the incoming interval's piece [lo, hi]
    out.incomingRuns += out.size == 0 || !(out.data[out.size - 1].flags & kFromIncoming);
    Interval piece = in;
    piece.b0 = lo;
    piece.b1 = hi;
    out.push(piece);
  };
  double cursor = in.b0;      // the incoming range up to here is accounted for
  bool incomingDone = false;  // the incoming interval's pieces are all in `out`
  auto finishIncoming = [&] {
    if (!incomingDone && cursor < in.b1) newPiece(cursor, in.b1);
    incomingDone = true;
  };
  for (std::size_t k = 0; k < slice.size(); ++k) {
    const Interval& before = slice[k];
    if (before.b1 <= in.b0) {  // before the incoming range
      out.push(before);
      continue;
    }
    if (incomingDone || before.b0 >= in.b1) {  // after it
      finishIncoming();
      out.push(before);
      continue;
    }
    Interval w = before;
    // Every piece cut from w is checked against where w's smallest distance was: the piece that
    // still has it keeps w's queue entry, the others (when pending) need their own.
    const double minX = w.argMinDistance();
    const Interval::MinAt minAt = w.minAt();
    auto oldPiece = [&](Interval& piece) { keepOrRequeue(piece, minX, minAt); };
    const double overlapTiny = std::max(tinyLength(w, edgeLength), tinyLength(in, edgeLength));
    if (overlapsStartByD2(w, in, overlapTiny)) {  // D2 at the new one's start
      ++report.degeneracies[DegeneracyKind::D2];
      const double meet = overlapMeetingPoint(w, in, in.b0, w.b1, edgeLength);
      w.b1 = meet;
      in.b0 = cursor = meet;
      oldPiece(w);
      out.push(w);
      continue;
    }
    if (overlapsEndByD2(w, in, overlapTiny)) {  // D2 at the new one's end
      ++report.degeneracies[DegeneracyKind::D2];
      const double meet = overlapMeetingPoint(in, w, w.b0, in.b1, edgeLength);
      w.b0 = meet;
      in.b1 = meet;
      oldPiece(w);
      finishIncoming();
      out.push(w);
      continue;
    }
    if (w.b0 < in.b0) {  // 1.3: separate at interb0
      Interval left = w;
      left.b1 = in.b0;
      oldPiece(left);
      out.push(left);
      w.b0 = in.b0;
    }
    const bool hasRight = w.b1 > in.b1;
    if (hasRight) w.b1 = in.b1;  // 1.4: separate at interb1 (the right piece is added below)
    if (w.b0 > cursor) newPiece(cursor, w.b0);  // a gap: the new one's
    cursor = w.b1;
    if (sameSource(in, w, edgeLength)) {  // the same geodesic arriving again: keep the old
      oldPiece(w);
      out.push(w);
    } else {
      oldPiece(w);  // as cut by step 1; keepShorter may cut it further
      // (The scan saw the same cut: only an interval after a D2 overlap, which ends the scan,
      // is cut differently.)
      const std::size_t reachedIndex = k - firstReached;
      if (reachedIndex < scan.lostPrefix) {
        out.push(w);
      } else {
        SampledWinners fresh;
        keepShorter(in, w, samplesOf(in, w, scan, reachedIndex, fresh, edgeLength), edgeLength,
                    report, out, newPiece, oldPiece, before.b0 < w.b0, hasRight);
      }
    }
    if (hasRight) {  // 1.4's right piece
      incomingDone = true;
      Interval right = before;
      right.b0 = in.b1;
      oldPiece(right);
      out.push(right);
    }
  }
  finishIncoming();
}

// What steps 3–5 work on: the slice's new intervals L[0, m) (through a raw pointer and a count:
// writes to the intervals' one-byte fields may alias anything, which would make every size() and
// [i] of a vector reload the vector's own pointers), and the list's intervals just outside the
// slice, which the steps read but do not change (null at an end of the edge).
struct Slice {
  Interval* L;
  std::size_t m;
  const Interval* outerPrev;
  const Interval* outerNext;
  double edgeLength;
};

// ===  Step 3: remove tiny intervals (D1) =========================================================
// Each is merged into a neighbour that may grow over it (canTakeSliver); one no neighbour may
// take is kept. A neighbour grown this way may itself still be tiny next to a coarser one: repeat
// until nothing is (each pass removes at least one interval, so this ends). An interval's ε
// depends on its pseudo-source only, which merging does not change. Intervals at least
// `sliverBound` long are no D1 at any threshold (see repairSlice).
void removeTinyIntervals(Slice& s, double sliverBound, EdgeUpdateReport& report) {
  Interval* const L = s.L;
  const double edgeLength = s.edgeLength;
  for (bool removed = true; removed;) {
    removed = false;
    std::size_t w = 0;
    for (std::size_t r = 0; r < s.m; ++r) {
      const double length = L[r].length();
      if (length >= sliverBound) {  // no D1 threshold reaches this far (see sliverBound)
        if (w != r) L[w] = L[r];
        ++w;
        continue;
      }
      // L[r]'s neighbours: the last one kept and the next one, or the slice's outer ones (one
      // of those taking L[r] makes step 3 remove it here; the update is then done again
      // over a wider slice, where the neighbour can grow).
      const Interval* const prev = w > 0 ? &L[w - 1] : s.outerPrev;
      const Interval* const next = r + 1 < s.m ? &L[r + 1] : s.outerNext;
      // ε of L[r] itself, or a touching neighbour's ray-end precision when larger: a sliver
      // within that of a coarser window's end may be its rounding (tol::kRayEndRel). Not the
      // neighbour's whole ε: a longer sliver can be the start of a near saddle's shadow,
      // which fans out downstream where the far rays never reach. The checker applies the
      // same rule (tinyLengthInList) to the whole list, so the outer neighbours count here.
      const double tiny = tinyLengthBetween(prev, L[r], next, edgeLength);
      // An edge shorter than ε has nothing but D1 slivers: the last one left is the edge's
      // distance to the precision its source allows, and step 4 sews it to both ends.
      // Removing it too left the edge uncovered (corpus/fuzz_two_faces/regress/
      // full-coverage-edge-shorter-than-epsilon-lost-its-last-interval).
      const bool belowTiny = length < tiny;
      const bool lastOnShortEdge =
          belowTiny && edgeLength < tiny &&
          (prev == nullptr || prev->b1 < L[r].b0 - tinyLength(*prev, edgeLength)) &&
          (next == nullptr || next->b0 > L[r].b1 + tinyLength(*next, edgeLength));
      // Only a sliver asks its neighbours (two square roots each, for most intervals of a
      // solve otherwise).
      const bool sliver = belowTiny && !lastOnShortEdge;
      const bool prevTakes = sliver && prev != nullptr && canTakeSliver(*prev, L[r], edgeLength);
      const bool nextTakes = sliver && next != nullptr && canTakeSliver(*next, L[r], edgeLength);
      if (!(prevTakes || nextTakes)) {
        if (w != r) L[w] = L[r];
        ++w;
        continue;
      }
      removed = true;
      ++report.degeneracies[DegeneracyKind::D1];
      const Interval t = L[r];
      report.removedTiny.emplace_back(t.b0, t.b1);
      // An Eq. 1 breakpoint at an end of the removed sliver now joins a neighbour that grew
      // over the sliver to the one beyond, which Eq. 1 never made equal: it is no breakpoint
      // any more
      // (corpus/fuzz_edge_update/regress/continuous-at-eq1-breakpoint-of-removed-sliver).
      std::erase_if(report.eq1Breakpoints, [&](double x) { return x == t.b0 || x == t.b1; });
      // Prefer the neighbour with the coarser scale: merging into the same-scale one would only
      // leave a sliver as thin as before beside the coarse one. Between equal scales, prefer
      // the one that needs no second propagation (a pending one for a pending sliver).
      const bool prevTouches = w > 0 && prevTakes;
      const bool nextTouches = r + 1 < s.m && nextTakes;
      bool intoNext = nextTouches && !prevTouches;
      if (nextTouches && prevTouches) {
        const double tinyPrev = tinyLength(L[w - 1], edgeLength);
        const double tinyNext = tinyLength(L[r + 1], edgeLength);
        intoNext = tinyNext > tinyPrev || (tinyNext == tinyPrev && t.pending() &&
                                           L[r + 1].pending() && !L[w - 1].pending());
      }
      if (intoNext || prevTouches) {
        Interval& into = intoNext ? L[r + 1] : L[w - 1];
        if (intoNext) {
          setRange(into, std::min(into.b0, t.b0), into.b1);
        } else {
          setRange(into, into.b0, std::max(into.b1, t.b1));
        }
        if (t.pending() && !into.pending()) grewUnpropagated(into);
        // The neighbour's rays cover the sliver's range, but beyond a vertex the sliver ends at,
        // a nearer source fans out wider than they do: the solver relays that fan through the
        // vertex (corpus/fuzz_solver/regress/vertex-agreement-d1-sliver-at-a-vertex-loses-its-
        // fan-beyond-it).
        if (!sameSource(into, t, edgeLength)) {
          const double tiny = tinyLength(t, edgeLength);
          if (t.b0 <= tiny) report.fanLostAtVertex |= 1;
          if (t.b1 >= edgeLength - tiny) report.fanLostAtVertex |= 2;
        }
      }
    }
    s.m = w;
  }
}

// ===  Step 4: sew gaps shorter than ε (D3) =======================================================
// The paper sews a gap at its midpoint; where only one side is still pending we move that side's
// end across the whole gap instead, so the propagated side need not be propagated again (either
// way each point of the gap takes a neighbour's value, which is all step 4 promises). The edge's
// ends count as neighbours. Returns whether it sewed anything.
//
// Its three tests, which updateOneReached asks too: a gap before `front` at the edge's start, after
// `back` at its end, between neighbours p and q. (A flat vertex's shadow, kFlatVertexAngle × the
// rays' length, is below sewLength; wider shadows are closed when the wavefront has passed:
// tol::kShadowSewRel.)
bool sewsAtStart(const Interval& front, double edgeLength) {
  return front.b0 > 0.0 && front.b0 < sewLength(front, edgeLength);
}
bool sewsAtEnd(const Interval& back, double edgeLength) {
  return back.b1 < edgeLength && edgeLength - back.b1 < sewLength(back, edgeLength);
}
bool sewsBetween(const Interval& p, const Interval& q, double edgeLength) {
  const double gap = q.b0 - p.b1;
  return gap > 0.0 && gap < std::max(sewLength(p, edgeLength), sewLength(q, edgeLength));
}

bool sewSmallGaps(Slice& s, EdgeUpdateReport& report) {
  if (s.m == 0) return false;
  Interval* const L = s.L;
  const double edgeLength = s.edgeLength;
  bool sewn = false;
  Interval& front = L[0];
  if (s.outerPrev == nullptr && sewsAtStart(front, edgeLength)) {
    ++report.degeneracies[DegeneracyKind::D3];
    report.sewnGaps.emplace_back(0.0, front.b0);
    if (!front.pending()) grewUnpropagated(front);
    setRange(front, 0.0, front.b1);
    sewn = true;
  }
  Interval& back = L[s.m - 1];
  if (s.outerNext == nullptr && sewsAtEnd(back, edgeLength)) {
    ++report.degeneracies[DegeneracyKind::D3];
    report.sewnGaps.emplace_back(back.b1, edgeLength);
    if (!back.pending()) grewUnpropagated(back);
    setRange(back, back.b0, edgeLength);
    sewn = true;
  }
  for (std::size_t k = 0; k + 1 < s.m; ++k) {
    Interval& p = L[k];
    Interval& q = L[k + 1];
    const double gap = q.b0 - p.b1;
    if (gap == 0.0) continue;
    // No overlap reaches step 4: the slice comes from a list without one, step 1 resolves
    // every D2 at the incoming ends and cuts everything else exactly, step 3 grows a
    // neighbour exactly to a removed sliver's end, and steps 4 and 5 only close gaps. (The
    // D2 branch once here was reached by no test, property or corpus file: mutant
    // f1918372, docs/mutation.md.)
    GEODEX_CHECK(gap > 0.0, "step 4 met neighbours overlapping by " << -gap << " on [" << q.b0
                                                                    << ", " << p.b1 << "]");
    if (!sewsBetween(p, q, edgeLength)) continue;
    ++report.degeneracies[DegeneracyKind::D3];
    report.sewnGaps.emplace_back(p.b1, q.b0);
    sewn = true;
    if (p.pending() && !q.pending()) {
      setRange(p, p.b0, q.b0);
    } else if (q.pending() && !p.pending()) {
      setRange(q, p.b1, q.b1);
    } else {
      const double mid = 0.5 * (p.b1 + q.b0);
      if (!p.pending()) grewUnpropagated(p);
      if (!q.pending()) grewUnpropagated(q);
      setRange(p, p.b0, mid);
      setRange(q, mid, q.b1);
    }
  }
  return sewn;
}

// ===  Step 5: merge neighbours with the same pseudo-source =======================================
// And the same propagation state: merging a propagated interval into a pending one would
// propagate it a second time. The merged interval keeps the first one's function. Returns whether
// a merged pair differed in source or σ (within kSameSourceRel): only then can steps 3 and 4 find
// something new.
//
// Whether step 5 joins q to p (also asked by updateOneReached).
bool joins(const Interval& p, const Interval& q, double edgeLength) {
  return p.b1 == q.b0 && p.pending() == q.pending() && sameSource(p, q, edgeLength);
}

bool mergeSameSources(Slice& s) {
  Interval* const L = s.L;
  bool functionGrew = false;
  std::size_t w = 0;
  for (std::size_t r = 0; r < s.m; ++r) {
    if (w > 0 && joins(L[w - 1], L[r], s.edgeLength)) {
      setRange(L[w - 1], L[w - 1].b0, L[r].b1);
      L[w - 1].flags |= static_cast<std::uint8_t>(L[r].flags & kFromAnyIncoming);
      if (L[w - 1].source != L[r].source || L[w - 1].sigma != L[r].sigma) functionGrew = true;
      continue;
    }
    if (w != r) L[w] = L[r];
    ++w;
  }
  s.m = w;
  return functionGrew;
}

// ===  Tie strips inside the incoming window
// ======================================================= keepTieStripsInsideOld (step 2) for the
// other order of arrival: an old interval t (or what step 2 left of it) lies between two pieces of
// the incoming interval, touching both, on the same side, and the two distances tie over t's range
// (to the tie tolerance, both ways). The incoming interval takes t's range: its rays cross it
// anyway (its range was cut there by step 2, not by its own extent), and its distance there is t's
// to the tie tolerance. Whichever of the two arrives first, the strip then goes to the window
// around it. Pieces of the incoming interval are pending (or were made propagated, as its whole
// range is), so none is propagated again.
bool tiesOver(const Interval& a, const Interval& b, double lo, double hi) {
  return winsOnlyByTie(a, b, lo, hi) && winsOnlyByTie(b, a, lo, hi);
}

bool isTieStripInsideIncoming(const Interval& p, const Interval& t, const Interval& q) {
  return (p.flags & kFromIncoming) && (q.flags & kFromIncoming) && !(t.flags & kFromIncoming) &&
         p.b1 == t.b0 && t.b1 == q.b0 && t.side == p.side && tiesOver(p, t, t.b0, t.b1);
}

void giveTieStripsToTheIncoming(Slice& s, EdgeUpdateReport& report) {
  Interval* const L = s.L;
  std::size_t w = 0;
  for (std::size_t r = 0; r < s.m; ++r) {
    if (!(w > 0 && r + 1 < s.m && isTieStripInsideIncoming(L[w - 1], L[r], L[r + 1]))) {
      if (w != r) L[w] = L[r];
      ++w;
      continue;
    }
    const Interval t = L[r];
    ++report.degeneracies.tieStripsKept;
    std::erase_if(report.eq1Breakpoints, [&](double x) { return x == t.b0 || x == t.b1; });
    setRange(L[w - 1], L[w - 1].b0, t.b1);  // step 5 joins it to the next piece
  }
  s.m = w;
}

// ===  Steps 3–5 ==================================================================================
// They repeat while step 4 or 5 changes anything: an interval that grows over a sewn gap can come
// to touch a coarser neighbour and be a D1 sliver next to it
// (corpus/fuzz_edge_update/regress/no-tiny-interval-short-edge-window-not-sewn-to-a-near-
// neighbour), and one that step 5 merges with a piece of a near-equal source carries its own
// function over the piece's range, where it may take a sliver beside it (canTakeSliver) that the
// piece could not (corpus/fuzz_edge_update/regress/no-tiny-interval-step-5-merge-makes-a-sliver-
// takeable-after-step-3). Each pass sews or resolves what it finds for good, and steps 3 and 5
// only remove, so this ends. Returns whether any piece of the incoming interval is left. (The tie
// strips, which step 2 leaves, are given to the incoming interval before: by updateSlice, or per
// child of a run as it arrives.)
bool repairSlice(Slice& s, EdgeUpdateReport& report) {
  // No interval of the slice can be a D1 sliver unless it is shorter than ε at the largest
  // length scale around (tinyLengthBetween takes ε or a ray-end precision, kRayEndRel <=
  // kTinyIntervalRel, of the interval or a neighbour; steps 3–5 move ranges, never sources):
  // most of a solve's intervals are told apart by one comparison.
  double largestScale = s.edgeLength, shortest = s.edgeLength;
  for (std::size_t k = 0; k < s.m; ++k) {
    largestScale = std::max(largestScale, intervalLengthScale(s.L[k], s.edgeLength));
    shortest = std::min(shortest, s.L[k].length());
  }
  if (s.outerPrev != nullptr)
    largestScale = std::max(largestScale, intervalLengthScale(*s.outerPrev, s.edgeLength));
  if (s.outerNext != nullptr)
    largestScale = std::max(largestScale, intervalLengthScale(*s.outerNext, s.edgeLength));
  const double sliverBound = tol::kTinyIntervalRel * largestScale;
  // Steps 3–5 only move ends outwards or join neighbours, so with no interval below the bound
  // now, step 3 finds nothing in any pass.
  const bool mayHaveSlivers = shortest < sliverBound;

  for (bool again = true; again;) {
    if (mayHaveSlivers) removeTinyIntervals(s, sliverBound, report);
    const bool sewn = sewSmallGaps(s, report);
    const bool functionGrew = mergeSameSources(s);
    again = sewn || functionGrew;
  }

  bool incomingSurvived = false;
  for (std::size_t k = 0; k < s.m; ++k) {
    if (s.L[k].flags & kFromAnyIncoming) incomingSurvived = true;
    s.L[k].flags &= static_cast<std::uint8_t>(~kFromAnyIncoming);
  }
  return incomingSurvived;
}

// Whether `now`, the rewritten slice's first (`front`) or last interval, leaves the outer neighbour
// as `was`, the slice's first (last) before the update, did. The outer neighbour's relation to it
// (a gap to sew, a sliver to take, a source to merge with) depends on its outer end, function and
// state only: where steps 3–5 moved only its inner end, a wider slice finds nothing more. (One in
// eight of bunny00's updates was done twice when any change to it widened the slice.) The outer
// end moves when step 3 removes the first interval; the function alone does not tell it, for the
// next one may have the same source behind a gap (corpus/fuzz_edge_update/regress/pointwise-min-
// sliver-taken-by-the-outer-neighbour-before-a-gap-to-the-same-source). A sliver the outer
// neighbour takes moves the end too; one an inner neighbour takes changes the function
// (Algorithm2.AGapBesideTheUpdateIsSewnWhenTheIntervalNextToItGoesToACoarserWindow).
bool keepsTheOuterEnd(const Interval& now, const Interval& was, bool front) {
  return (front ? now.b0 == was.b0 : now.b1 == was.b1) && now.source == was.source &&
         now.sigma == was.sigma && now.side == was.side && now.origin == was.origin &&
         now.pending() == was.pending();
}

// The new intervals L[0, m) of the list's slice [s0, s1), with the list's intervals just outside
// it.
Slice sliceOf(Interval* L, std::size_t m, std::span<const Interval> list, std::size_t s0,
              std::size_t s1, double edgeLength) {
  return Slice{L, m, s0 == 0 ? nullptr : &list[s0 - 1], s1 == list.size() ? nullptr : &list[s1],
               edgeLength};
}

// Whether steps 3–5 left the outer ends of the list's slice [s0, s1) as they were
// (keepsTheOuterEnd), so that the rewritten slice `s` can go back; if not, the slice is widened by
// two on each side that changed, for the update to be done again.
bool outerEndsKeptElseWiden(const Slice& s, std::span<const Interval> list, std::size_t& s0,
                            std::size_t& s1) {
  const std::size_t n = list.size();
  const bool frontKept = s0 == 0 || (s.m > 0 && keepsTheOuterEnd(s.L[0], list[s0], true));
  const bool backKept = s1 == n || (s.m > 0 && keepsTheOuterEnd(s.L[s.m - 1], list[s1 - 1], false));
  if (frontKept && backKept) return true;
  if (!frontKept) s0 = s0 >= 2 ? s0 - 2 : 0;
  if (!backKept) s1 = std::min(n, s1 + 2);
  return false;
}

// Steps 3–5 over `s`, the rewritten slice [s0, s1) of `list`. Whether they left its outer ends as
// they were, so that it can go back; if not, the slice is widened (outerEndsKeptElseWiden) and the
// report cleared for the update to be done again over it.
bool repairedWithinTheSlice(Slice& s, std::span<const Interval> list, std::size_t& s0,
                            std::size_t& s1, EdgeUpdateReport& report) {
  report.incomingSurvived = repairSlice(s, report);
  if (outerEndsKeptElseWiden(s, list, s0, s1)) return true;
  report.clear();
  return false;
}

// The repaired slice back into the list in place of [s0, s1), and the range of the list it now
// holds, for the solver to look at.
void spliceBack(IntervalList& edgeList, std::size_t s0, std::size_t s1, const Slice& s,
                EdgeUpdateReport& report) {
  edgeList.replace(s0, s1, std::span<const Interval>(s.L, s.m));
  report.first = s0;
  report.last = s0 + s.m;
}

// The general update: steps 1–5 over the slice of the old intervals [j0, j1) the incoming range
// reaches and one neighbour on each side, widened while steps 3–5 change an outer one, spliced
// back.
void updateSlice(IntervalList& edgeList, std::size_t j0, std::size_t j1, const Interval& incoming,
                 const ReachedScan& scan, double edgeLength, EdgeUpdateReport& report,
                 std::vector<Interval>& out) {
  // --- The slice this update reads and rewrites: the old intervals the incoming range reaches,
  //     and one more on each side. The list is clean outside the incoming range (the previous
  //     update left it so), so steps 3–5 can only find something at the changed intervals and
  //     their neighbours. Should they change an outer neighbour (sew a gap to it, merge a tiny
  //     interval into it, merge it with a piece of the same source), its own neighbour may be
  //     involved too: the slice is widened and the update done again (keepsTheOuterEnd).
  const std::size_t n = edgeList.size();
  const std::span<const Interval> list(edgeList);
  std::size_t s0 = j0 >= 1 ? j0 - 1 : 0;
  std::size_t s1 = std::min(n, j1 + 1);
  Slice s{};
  for (;;) {
    // (`out` only grows: resize constructs what it adds.)
    if (out.size() < piecesBound(s1 - s0)) out.resize(piecesBound(s1 - s0));
    Pieces pieces{out.data(), 0, out.size(), 0};
    splitAndKeepShorter(list.subspan(s0, s1 - s0), j0 - s0, incoming, scan, edgeLength, report,
                        pieces);
    s = sliceOf(pieces.data, pieces.size, list, s0, s1, edgeLength);
    if (pieces.incomingRuns >= 2) [[unlikely]]
      giveTieStripsToTheIncoming(s, report);
    if (repairedWithinTheSlice(s, list, s0, s1, report)) break;
  }
  spliceBack(edgeList, s0, s1, s, report);
}

// ===  A run of incoming intervals ================================================================
// The children one batch of windows sends to this edge (GeodesicSolver::runBatch): steps
// 1 and 2 for each in turn, on a copy of the list's slice over all of them, then steps 3–5 once
// over that copy and one splice. Each child meets the intervals as the ones before it left them,
// as it would one update after another; only the repairs of steps 3–5 are not made between them,
// and neither are the finding of a slice, the splice and the solver's bookkeeping. Steps 1 and 2
// read nothing of a repair but the intervals themselves: a D1 sliver a child leaves is merged
// after the next one cut it or not, a same-source piece is joined after it met the next child
// (which it does as the one function it is), and a D2 overlap is resolved at the child's ends as
// it arrives.

// A child's piece, copied into the run's copy of the slice, becomes the run's to the children after
// it: kFromIncoming becomes kFromRun. (Branch-free: which of the pieces are the child's own and
// which are pieces of old intervals varies piece by piece.)
void markAsTheRuns(Interval& w) {
  static_assert(kFromRun == kFromIncoming << 1);
  w.flags =
      static_cast<std::uint8_t>((w.flags & ~kFromIncoming) | ((w.flags & kFromIncoming) << 1));
}

// Steps 1 and 2 for the child `in` of a run, on `work`, the run's copy of the list's slice as the
// children before it left it (their pieces carry kFromRun). `guess` is where the child before it
// went: a batch's children come along the edge. Returns whether any piece of `in` went in.
// report.eq1Breakpoints holds the earlier children's breakpoints sorted, and does so after.
bool runChildStepsOneAndTwo(IntervalList& work, std::size_t& guess, const Interval& in,
                            double edgeLength, EdgeUpdateReport& report,
                            std::vector<Interval>& out) {
  const std::span<const Interval> w(work);
  const std::size_t k0 = partitionFrom(w, guess, [&](const Interval& v) { return v.b1 <= in.b0; });
  guess = k0;
  const std::size_t k1 = partitionFrom(w, k0, [&](const Interval& v) { return v.b0 < in.b1; });
  ReachedScan scan;
  const std::span<const Interval> reached = w.subspan(k0, k1 - k0);
  if (incomingLosesEverywhere(in, reached, edgeLength, scan)) {
    reportFanOfALostSliver(in, reached, edgeLength, report);
    return false;
  }
  if (out.size() < piecesBound(reached.size())) out.resize(piecesBound(reached.size()));
  Pieces pieces{out.data(), 0, out.size(), 0};
  std::vector<double>& breakpoints = report.eq1Breakpoints;
  const std::size_t earlier = breakpoints.size();
  splitAndKeepShorter(reached, 0, in, scan, edgeLength, report, pieces);
  const std::size_t ownBreakpoints = breakpoints.size() - earlier;

  // An earlier child's Eq. 1 breakpoint that a piece of this one reaches joins other functions
  // now, which Eq. 1 never made equal: it is no breakpoint any more (corpus/fuzz_edge_update/
  // regress/continuous-at-eq1-run-breakpoint-of-an-earlier-child-taken-by-a-later-one). Only
  // those within this child's range can be; kept sorted, they are found by two binary searches
  // (a run's children all cross their neighbours on a convex surface, and comparing each with every
  // earlier breakpoint was 1.6 % of the icosphere's solve).
  const auto reachedByThisChild = [&](double x) {
    for (std::size_t k = 0; k < pieces.size; ++k)
      if ((pieces.data[k].flags & kFromIncoming) && pieces.data[k].b0 <= x &&
          x <= pieces.data[k].b1)
        return true;
    return false;
  };
  if (earlier > 0) {  // (searching and erasing over none was 0.9 % of bunny00's solve instructions)
    const auto earlierEnd = breakpoints.begin() + static_cast<std::ptrdiff_t>(earlier);
    const auto from = std::lower_bound(breakpoints.begin(), earlierEnd, in.b0);
    const auto to = std::upper_bound(from, earlierEnd, in.b1);
    breakpoints.erase(std::remove_if(from, to, reachedByThisChild), to);
  }
  // This child's own breakpoints into their places, each found by a binary search and the ones
  // after it moved up at once (children come along the edge either way round: moved one by one,
  // those of a run coming backwards cost 1.2 % of the icosphere's solve). Before the tie strips,
  // whose pass erases breakpoints of its own, earlier ones too (corpus/fuzz_edge_update/regress/
  // negative-size-param-run-tie-strip-erased-an-earlier-childs-breakpoint); an erasure keeps the
  // order.
  for (std::size_t i = breakpoints.size() - ownBreakpoints; i < breakpoints.size(); ++i) {
    const auto end = breakpoints.begin() + static_cast<std::ptrdiff_t>(i);
    const double x = *end;
    if (i == 0 || end[-1] <= x) continue;  // (in place already)
    const auto at = std::upper_bound(breakpoints.begin(), end, x);
    std::copy_backward(at, end, end + 1);
    *at = x;
  }
  // The tie strips between two pieces of this child, before the next child can cut them. The
  // earlier children's pieces are old intervals to this one, as they would be one update after
  // another: they carry kFromRun instead of kFromIncoming meanwhile.
  if (pieces.incomingRuns >= 2) [[unlikely]] {
    Slice own{pieces.data, pieces.size, nullptr, nullptr, edgeLength};
    giveTieStripsToTheIncoming(own, report);
    pieces.size = own.m;
  }
  work.replace(k0, k1, {pieces.data, pieces.size}, markAsTheRuns);
  return true;
}

void updateRunSlice(IntervalList& edgeList, std::size_t j0, std::size_t j1,
                    std::span<const Interval> run, double edgeLength, EdgeUpdateReport& report,
                    std::vector<Interval>& out, IntervalList& work) {
  const std::span<const Interval> list(edgeList);
  // The slice as updateSlice takes it: the children's range and a neighbour on each side, widened
  // while steps 3–5 change an outer one.
  std::size_t s0 = j0 >= 1 ? j0 - 1 : 0, s1 = std::min(list.size(), j1 + 1);
  Slice s{};
  for (;;) {
    work.assign(list.subspan(s0, s1 - s0));
    bool changed = false;
    std::size_t guess = 0;
    for (const Interval& in : run) {
      const std::uint64_t repairedBefore =
          report.degeneracies[DegeneracyKind::D2] + report.degeneracies[DegeneracyKind::D4];
      changed |= runChildStepsOneAndTwo(work, guess, in, edgeLength, report, out);
      report.repairedInStepsOneAndTwo.push_back(report.degeneracies[DegeneracyKind::D2] +
                                                    report.degeneracies[DegeneracyKind::D4] !=
                                                repairedBefore);
    }
    if (!changed) {  // every child lost everywhere: the list stays as it was
      report.first = j0;
      report.last = j1;
      return;
    }
    // (Steps 3–5 take the run's pieces, kFromRun, for the incoming interval's.)
    s = sliceOf(work.data(), work.size(), list, s0, s1, edgeLength);
    if (repairedWithinTheSlice(s, list, s0, s1, report)) break;
  }
  spliceBack(edgeList, s0, s1, s, report);
}

// ===  One reached interval, nothing to repair ====================================================
// Half of bunny00's updates and 95 % of the icosphere's reach exactly one old interval w, and in
// most of them (six in ten of those that do not lose everywhere on bunny00, all but 40 of 3.8 M
// on the icosphere) steps 3 and 4 find nothing and step 5 only joins pieces of w, or of the
// incoming interval, that steps 1 and 2 cut apart. Then the general update's slice, prev + w's
// pieces + next, comes back with prev and next as they were. This makes w's pieces as steps 1
// and 2 do (the same cut, findWinners, and the same flags), joined as they are made the way step 5
// joins them, and splices them in place of w, after making sure that steps 3 and 4 would find
// nothing in the general slice: no interval in it, before the joins, shorter than the sliver bound
// (repairSlice's mayHaveSlivers); no gap at the slice's ends that step 4 would sew; nothing to join
// across them. The list and the report are the general update's to the bit; checked builds run
// both and compare (sameUpdate). Returns false, having changed nothing but the report, when the
// general update must decide.
class OneReachedPieces {
 public:
  OneReachedPieces() {}  // (leaves piece_ unconstructed)

  // The pieces of w: each cut from `cut` (the piece whose state it starts from) to [lo, hi].
  void addOld(const Interval& cut, double lo, double hi, double minX, Interval::MinAt minAt) {
    shortest_ = std::min(shortest_, hi - lo);
    anyOld_ = true;
    if (m_ > 0 && !lastIsNew_) {  // step 5 joins it to the piece of w before it
      setRange(piece_[m_ - 1], piece_[m_ - 1].b0, hi);
      return;
    }
    keepOrRequeue(append(cut, lo, hi), minX, minAt);
    lastIsNew_ = false;
  }
  // The incoming interval's pieces, `in` carrying the flags of a new interval.
  void addNew(const Interval& in, double lo, double hi) {
    shortest_ = std::min(shortest_, hi - lo);
    anyNew_ = true;
    if (m_ > 0 && lastIsNew_) {  // joined: a new interval is marked changed already
      piece_[m_ - 1].b1 = hi;
      return;
    }
    newMask_ |= 1u << m_;
    append(in, lo, hi);
    lastIsNew_ = true;
  }
  const Interval* data() const { return piece_; }
  std::size_t size() const { return m_; }
  bool isNew(std::size_t k) const { return (newMask_ >> k) & 1u; }
  double shortest() const { return shortest_; }  // of the pieces before they were joined
  bool anyNew() const { return anyNew_; }
  bool anyOld() const { return anyOld_; }

 private:
  Interval& append(const Interval& from, double lo, double hi) {
    GEODEX_CHECK(m_ < kMaxPieces, "more than " << kMaxPieces << " pieces of one interval");
    Interval& w = piece_[m_++];
    w = from;
    w.b0 = lo;
    w.b1 = hi;
    return w;
  }

  // A gap or a piece of w before the incoming range, findWinners' up to four, a gap or a piece
  // of w after it: at most six, fewer after the joins.
  static constexpr std::size_t kMaxPieces = 6;
  union {
    Interval piece_[kMaxPieces];  // (not constructed: filled before it is read)
  };
  std::size_t m_ = 0;
  unsigned newMask_ = 0;
  double shortest_ = std::numeric_limits<double>::infinity();
  bool lastIsNew_ = false;
  bool anyNew_ = false;
  bool anyOld_ = false;
};

bool updateOneReached(IntervalList& list, std::size_t j, const Interval& incoming,
                      const ReachedScan& scan, double edgeLength, EdgeUpdateReport& report) {
  const std::size_t n = list.size();
  const Interval& w = list[j];
  if (!scan.firstPlain) {
    const double overlapTiny =
        std::max(tinyLength(w, edgeLength), tinyLength(incoming, edgeLength));
    if (overlapsStartByD2(w, incoming, overlapTiny) || overlapsEndByD2(w, incoming, overlapTiny) ||
        sameSource(incoming, w, edgeLength))
      return false;
  }
  // A piece step 1 cuts off at an end of the incoming range that is shorter than the sliver
  // bound (below) is known before step 2 (a fifth of bunny00's updates of one interval): the
  // general update removes it.
  double scaleAtEnds = edgeLength;
  if (w.b0 < incoming.b0 || w.b1 > incoming.b1)
    scaleAtEnds = std::max(scaleAtEnds, intervalLengthScale(w, edgeLength));
  if (w.b0 > incoming.b0 || w.b1 < incoming.b1)
    scaleAtEnds = std::max(scaleAtEnds, intervalLengthScale(incoming, edgeLength));
  const double endsTiny = tol::kTinyIntervalRel * scaleAtEnds;
  const double startPiece = std::abs(incoming.b0 - w.b0), endPiece = std::abs(w.b1 - incoming.b1);
  if ((startPiece > 0.0 && startPiece < endsTiny) || (endPiece > 0.0 && endPiece < endsTiny))
    return false;
  const Interval* const prev = j >= 1 ? &list[j - 1] : nullptr;
  const Interval* const next = j + 1 < n ? &list[j + 1] : nullptr;

  // Steps 1 and 2, as splitAndKeepShorter makes them for w.
  Interval in = incoming;
  in.flags = static_cast<std::uint8_t>((incoming.flags & Interval::kPending) | Interval::kChanged);
  const double minX = w.argMinDistance();
  const Interval::MinAt minAt = w.minAt();
  OneReachedPieces pieces;
  if (w.b0 < in.b0) pieces.addOld(w, w.b0, in.b0, minX, minAt);
  if (w.b0 > in.b0) pieces.addNew(in, in.b0, w.b0);
  Interval inside = w;  // w as step 1 cuts it to the incoming range
  inside.b0 = std::max(w.b0, in.b0);
  inside.b1 = std::min(w.b1, in.b1);
  keepOrRequeue(inside, minX, minAt);
  if (scan.lostPrefix > 0) {
    pieces.addOld(inside, inside.b0, inside.b1, minX, minAt);
  } else {
    SampledWinners fresh;
    const SampledWinners& sampled = samplesOf(in, inside, scan, 0, fresh, edgeLength);
    Winners cuts = findWinners(in, inside, sampled, edgeLength, report);
    keepTieStripsInsideOld(cuts, in, inside, sampled, w.b0<in.b0, w.b1> in.b1, report);
    for (int k = 0; k < cuts.m; ++k) {
      if (cuts.wins[k]) {
        pieces.addNew(in, cuts.cut[k], cuts.cut[k + 1]);
      } else {
        pieces.addOld(inside, cuts.cut[k], cuts.cut[k + 1], minX, minAt);
      }
    }
  }
  if (w.b1 > in.b1) pieces.addOld(w, in.b1, w.b1, minX, minAt);
  if (w.b1 < in.b1) pieces.addNew(in, w.b1, in.b1);
  const Interval& first = pieces.data()[0];
  const Interval& last = pieces.data()[pieces.size() - 1];

  // Step 3: nothing in the general slice is shorter than the bound over it and its outer
  // neighbours (prev's and next's own neighbours).
  double largestScale = edgeLength;
  if (pieces.anyOld()) largestScale = std::max(largestScale, intervalLengthScale(w, edgeLength));
  if (pieces.anyNew()) largestScale = std::max(largestScale, intervalLengthScale(in, edgeLength));
  double shortest = std::min(edgeLength, pieces.shortest());
  // (The four neighbours written out: a loop over j - 2 .. j + 2 that skipped j cost 1.6 % more of
  // the icosphere's solve instructions. largestScale, at least the edge length already, stands in
  // for it: max(largestScale, intervalLengthScale(v, edgeLength)) cost 0.1 % more of them.)
  const auto widen = [&](const Interval& v) {
    largestScale = intervalLengthScale(v, largestScale);
  };
  if (prev != nullptr) {
    widen(*prev);
    shortest = std::min(shortest, prev->length());
    if (j >= 2) widen(list[j - 2]);
  }
  if (next != nullptr) {
    widen(*next);
    shortest = std::min(shortest, next->length());
    if (j + 2 < n) widen(list[j + 2]);
  }
  if (shortest < tol::kTinyIntervalRel * largestScale) return false;

  // Step 4: the gaps at the edge's ends (tested on the slice's first and last interval when
  // nothing lies beyond it) and beside the pieces. (Between them there is none.)
  const Interval& front = prev != nullptr ? *prev : first;
  const Interval& back = next != nullptr ? *next : last;
  if ((j <= 1 && sewsAtStart(front, edgeLength)) || (j + 2 >= n && sewsAtEnd(back, edgeLength)))
    return false;
  // (An overlap, which step 4 would report, declines too. Most neighbours touch.)
  const auto sews = [&](const Interval& p, const Interval& q) {
    return q.b0 != p.b1 && (q.b0 < p.b1 || sewsBetween(p, q, edgeLength));
  };
  if ((prev != nullptr && sews(*prev, first)) || (next != nullptr && sews(last, *next)))
    return false;

  // A piece of w between two of the incoming interval that ties it (giveTieStripsToTheIncoming).
  for (std::size_t k = 0; k + 2 < pieces.size(); ++k) {
    const Interval* p = &pieces.data()[k];
    if (pieces.isNew(k) && !pieces.isNew(k + 1) && pieces.isNew(k + 2) && p[1].side == p[0].side &&
        tiesOver(p[0], p[1], p[1].b0, p[1].b1))
      return false;
  }

  // Step 5 across the pieces' ends.
  if ((prev != nullptr && joins(*prev, first, edgeLength)) ||
      (next != nullptr && joins(last, *next, edgeLength)))
    return false;

  report.incomingSurvived = pieces.anyNew();
  report.first = prev != nullptr ? j - 1 : j;
  report.last = j + pieces.size() + (next != nullptr ? 1 : 0);
  list.replace(j, j + 1, std::span<const Interval>(pieces.data(), pieces.size()));
  return true;
}

#if defined(GEODEX_ENABLE_CHECKS)
bool sameInterval(const Interval& a, const Interval& b) {
  return a.b0 == b.b0 && a.b1 == b.b1 && a.source == b.source && a.sigma == b.sigma &&
         a.origin == b.origin && a.side == b.side && a.flags == b.flags && a.regrown == b.regrown;
}

// Whether updateOneReached gave the general update's list and report.
bool sameUpdate(std::span<const Interval> fast, const EdgeUpdateReport& fastReport,
                std::span<const Interval> general, const EdgeUpdateReport& generalReport) {
  return std::equal(fast.begin(), fast.end(), general.begin(), general.end(), sameInterval) &&
         fastReport.first == generalReport.first && fastReport.last == generalReport.last &&
         fastReport.eq1Breakpoints == generalReport.eq1Breakpoints &&
         fastReport.removedTiny == generalReport.removedTiny &&
         fastReport.sewnGaps == generalReport.sewnGaps &&
         fastReport.incomingSurvived == generalReport.incomingSurvived &&
         fastReport.fanLostAtVertex == generalReport.fanLostAtVertex &&
         fastReport.degeneracies.count == generalReport.degeneracies.count;
}
#endif

}  // namespace

void EdgeIntervals::insert(const Interval& incoming, double edgeLength, EdgeUpdateReport& report,
                           std::vector<Interval>& out) {
  GEODEX_CHECK(incoming.b0 >= 0.0 && incoming.b1 <= edgeLength && incoming.b0 < incoming.b1,
               "incoming interval [" << incoming.b0 << ", " << incoming.b1 << "] not inside [0, "
                                     << edgeLength << "]");
  report.clear();
  const std::size_t n = list_.size();
  const std::size_t j0 = partitionFrom(list_, guessIndex(n, incoming.b0, edgeLength),
                                       [&](const Interval& w) { return w.b1 <= incoming.b0; });
  const std::size_t j1 =
      partitionFrom(list_, j0, [&](const Interval& w) { return w.b0 < incoming.b1; });
  // The list is left as it is when the incoming interval loses everywhere: 8 % of the updates
  // on bunny00, reaching 13 intervals each, mostly a saddle's whole-edge windows (its windows
  // along its own edges lose, by the triangle inequality, to those that reached it). The
  // report names the intervals it lost to; the full verify tier samples the incoming range.
  ReachedScan scan;
  const std::span<const Interval> reached = std::span<const Interval>(list_).subspan(j0, j1 - j0);
  if (incomingLosesEverywhere(incoming, reached, edgeLength, scan)) {
    reportFanOfALostSliver(incoming, reached, edgeLength, report);
    report.first = j0;
    report.last = j1;
    return;
  }
  if (j1 - j0 == 1) {
#if defined(GEODEX_ENABLE_CHECKS)
    IntervalList before(list_);
#endif
    if (updateOneReached(list_, j0, incoming, scan, edgeLength, report)) {
#if defined(GEODEX_ENABLE_CHECKS)
      EdgeUpdateReport general;
      updateSlice(before, j0, j1, incoming, scan, edgeLength, general, out);
      GEODEX_CHECK(sameUpdate(list_, report, before, general),
                   "the one-reached-interval update of [" << incoming.b0 << ", " << incoming.b1
                                                          << "] differs from the general one");
#endif
      return;
    }
    report.clear();
  }
  updateSlice(list_, j0, j1, incoming, scan, edgeLength, report, out);
}

void EdgeIntervals::insertRun(std::span<const Interval> run, double edgeLength,
                              EdgeUpdateReport& report, std::vector<Interval>& out,
                              IntervalList& work) {
  if (run.size() == 1) {
    insert(run.front(), edgeLength, report, out);
    return;
  }
  report.clear();
  if (run.empty()) return;
  double lo = run.front().b0, hi = run.front().b1;
  for (const Interval& in : run) {
    GEODEX_CHECK(in.b0 >= 0.0 && in.b1 <= edgeLength && in.b0 < in.b1,
                 "incoming interval [" << in.b0 << ", " << in.b1 << "] not inside [0, "
                                       << edgeLength << "]");
    lo = std::min(lo, in.b0);
    hi = std::max(hi, in.b1);
  }
  const std::size_t n = list_.size();
  const std::size_t j0 = partitionFrom(list_, guessIndex(n, lo, edgeLength),
                                       [&](const Interval& w) { return w.b1 <= lo; });
  const std::size_t j1 = partitionFrom(list_, j0, [&](const Interval& w) { return w.b0 < hi; });
  updateRunSlice(list_, j0, j1, run, edgeLength, report, out, work);
}

}  // namespace geodex
