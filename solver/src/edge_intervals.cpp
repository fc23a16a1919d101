#include "geodex/edge_intervals.h"

#include <algorithm>
#include <cmath>

#include "geodex/check.h"
#include "geodex/tolerance.h"

namespace geodex {
namespace {

bool sameSource(const Interval& p, const Interval& q, double edgeLength) {
  const double tol = tol::kSameSourceRel * edgeLength;
  return p.side == q.side && std::abs(p.sigma - q.sigma) <= tol &&
         (p.source - q.source).squaredNorm() <= tol * tol;
}

// The incoming interval is shorter at x by more than the tie tolerance.
bool incomingWins(const Interval& incoming, const Interval& old, double x) {
  const double g = old.distanceAt(x);
  return incoming.distanceAt(x) < g - tol::kTieRel * g;
}

// Intersection of two propagated sub-ranges, used when an interval is cut to [lo, hi].
void clipPropagated(Interval& piece) {
  if (piece.pb0 < piece.b0) piece.pb0 = piece.b0;
  if (piece.pb1 > piece.b1) piece.pb1 = piece.b1;
}

}  // namespace

Interval* EdgeIntervals::find(std::uint32_t id) {
  for (Interval& w : list_)
    if (w.id == id) return &w;
  return nullptr;
}

double EdgeIntervals::distanceAt(double x) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Interval& w : list_) {
    if (x < w.b0) break;
    if (x <= w.b1) best = std::min(best, w.distanceAt(x));
  }
  return best;
}

// ===  Eq. 1 ======================================================================================
// σa + |x − sa| = σb + |x − sb| for x on the edge line. With c = σb − σa, squaring twice gives
// A x² + B x + C = 0. Coordinates are shifted to the middle of [lo, hi] first, so that the
// squares stay of the size of the configuration rather than of the edge's distance to the origin.
int equalDistanceCandidates(const Interval& a, const Interval& b, double lo, double hi,
                            double roots[2]) {
  const double m = 0.5 * (lo + hi);
  const double half = 0.5 * (hi - lo);
  const double x1 = a.source.x() - m, y1 = a.source.y();
  const double x2 = b.source.x() - m, y2 = b.source.y();
  const double c = b.sigma - a.sigma;
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
  for (int i = 0; i < n; ++i) {
    const double x = r[i] + m;
    if (std::isfinite(x) && x > lo && x < hi) roots[kept++] = x;
  }
  if (kept == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return kept;
}

// ===  Algorithm 2 ================================================================================
void EdgeIntervals::insert(const Interval& incoming, double edgeLength, IntervalIdSource& ids,
                           EdgeUpdateReport& report, std::vector<Interval>& out) {
  GEODEX_CHECK(incoming.b0 >= 0.0 && incoming.b1 <= edgeLength && incoming.b0 < incoming.b1,
               "incoming interval [" << incoming.b0 << ", " << incoming.b1 << "] not inside [0, "
                                     << edgeLength << "]");
  report.clear();
  // Bisection (D4) stops well below the smallest ε any interval on this edge can have.
  const double bisectionResolution = 1e-3 * tol::kTinyIntervalRel * edgeLength;
  Interval in = incoming;
  bool incomingIdUsed = false;
  auto newPiece = [&](double lo, double hi) {
    Interval w = in;
    w.b0 = lo;
    w.b1 = hi;
    clipPropagated(w);
    w.queuedKey = -1.0f;
    if (incomingIdUsed) w.id = ids();
    incomingIdUsed = true;
    return w;
  };

  // --- Step 1: split the old intervals at the new one's ends, so each is wholly inside or
  //     outside it. An overlap shorter than ε is not split off: it is a D2 degeneracy (two
  //     intervals intersecting by a rounding error), resolved by meeting at the overlap's midpoint.
  out.clear();
  {
    std::vector<Interval>& split = out;
    for (const Interval& oldInterval : list_) {
      Interval w = oldInterval;
      if (w.b1 <= in.b0 || w.b0 >= in.b1) {
        split.push_back(w);
        continue;
      }
      const double overlapTiny = std::max(tinyLength(w, edgeLength), tinyLength(in, edgeLength));
      if (w.b0 < in.b0 && w.b1 - in.b0 < overlapTiny && w.b1 < in.b1) {  // D2 at the new one's start
        ++report.degeneracies[DegeneracyKind::D2];
        const double mid = 0.5 * (in.b0 + w.b1);
        w.b1 = mid;
        in.b0 = mid;
        clipPropagated(w);
        split.push_back(w);
        continue;
      }
      if (w.b1 > in.b1 && in.b1 - w.b0 < overlapTiny && w.b0 > in.b0) {  // D2 at the new one's end
        ++report.degeneracies[DegeneracyKind::D2];
        const double mid = 0.5 * (in.b1 + w.b0);
        w.b0 = mid;
        in.b1 = mid;
        clipPropagated(w);
        split.push_back(w);
        continue;
      }
      if (w.b0 < in.b0) {  // 1.3: separate at interb0
        Interval left = w;
        left.b1 = in.b0;
        clipPropagated(left);
        split.push_back(left);
        w.b0 = in.b0;
        w.id = ids();
        w.queuedKey = -1.0f;
      }
      Interval right = w;
      const bool hasRight = w.b1 > in.b1;
      if (hasRight) {  // 1.4: separate at interb1
        w.b1 = in.b1;
        right.b0 = in.b1;
        right.id = ids();
        right.queuedKey = -1.0f;
        clipPropagated(right);
      }
      clipPropagated(w);
      split.push_back(w);
      if (hasRight) split.push_back(right);
    }
  }
  // --- Step 2: for each old interval inside the new one, keep on each piece the shorter of the
  //     two; the new interval fills what no old interval covered. (A D2 repair may have
  //     consumed the whole, tiny, incoming interval: then there is nothing to compare.)
  if (in.b1 <= in.b0) {
    list_.assign(out.begin(), out.end());
    out.clear();
  } else {
    // Read the split list from `out`, build the merged one in a second reused buffer.
    const std::vector<Interval>& split = out;
    static thread_local std::vector<Interval> merged;
    merged.clear();
    std::size_t i = 0;
    for (; i < split.size() && split[i].b1 <= in.b0; ++i) merged.push_back(split[i]);
    double cursor = in.b0;
    for (; i < split.size() && split[i].b0 < in.b1; ++i) {
      const Interval& old = split[i];
      if (old.b0 > cursor) merged.push_back(newPiece(cursor, old.b0));  // a gap: the new one's
      cursor = old.b1;
      if (sameSource(in, old, edgeLength)) {  // the same geodesic arriving again: keep the old
        merged.push_back(old);
        continue;
      }
      // Eq. 1's roots only *propose* where the winner may change: with σ or the source distance
      // many orders above the edge length its coefficients cancel, and a root can be off or
      // missing. The winner is decided by evaluating both distances, at the piece's ends and at
      // the middle of each sub-range the roots delimit; where it changes between two samples, a
      // root that lies there and makes the distances agree is the breakpoint, else (D4) the
      // change is located by bisection.
      double roots[2];
      int numRoots = equalDistanceCandidates(in, old, old.b0, old.b1, roots);
      const double pieceTiny = std::max(tinyLength(in, edgeLength), tinyLength(old, edgeLength));
      if (numRoots == 2 && roots[1] - roots[0] <= pieceTiny) {  // a double root: tangent functions
        roots[0] = 0.5 * (roots[0] + roots[1]);
        numRoots = 1;
      }
      // h = f − g has h' = cos θ_in − cos θ_old, zero only where x is collinear with the two
      // sources (both lie on one side of the line, heights >= 0): so h is monotone on either
      // side of that point x*, and with x* among the samples every sign change of h lies between
      // two samples. (Sources on the line itself add kinks at their feet: sampled too.)
      double sample[9];
      int numSamples = 0;
      sample[numSamples++] = old.b0;
      {
        double prev = old.b0;
        for (int k = 0; k <= numRoots; ++k) {
          const double next = k < numRoots ? roots[k] : old.b1;
          sample[numSamples++] = 0.5 * (prev + next);
          prev = next;
        }
      }
      const double y1 = in.source.y(), y2 = old.source.y();
      if (y1 != y2) {
        const double xStar = (in.source.x() * y2 - old.source.x() * y1) / (y2 - y1);
        if (xStar > old.b0 && xStar < old.b1) sample[numSamples++] = xStar;
      }
      for (const double foot : {in.source.x(), old.source.x()})
        if (foot > old.b0 && foot < old.b1) sample[numSamples++] = foot;
      sample[numSamples++] = old.b1;
      std::sort(sample, sample + numSamples);
      bool wins[9];
      for (int k = 0; k < numSamples; ++k) wins[k] = incomingWins(in, old, sample[k]);
      // Where the two distances agree at an end of the piece (both windows through the same
      // point, typically a vertex or a shared boundary ray), the tie there says nothing about
      // the inside: the end takes the verdict of the sample next to it.
      auto agreeAt = [&](double x) {
        const double g = old.distanceAt(x);
        return std::abs(in.distanceAt(x) - g) <= tol::kContinuityRel * (g + edgeLength);
      };
      if (agreeAt(old.b0)) wins[0] = wins[1];
      if (agreeAt(old.b1)) wins[numSamples - 1] = wins[numSamples - 2];
      double cut[10];
      bool cutWins[9];
      int m = 0;
      cut[0] = old.b0;
      cutWins[0] = wins[0];
      for (int k = 1; k < numSamples; ++k) {
        if (wins[k] == cutWins[m]) continue;
        const double lo0 = sample[k - 1], hi0 = sample[k];
        double x = -1.0;
        for (int r = 0; r < numRoots; ++r) {
          if (roots[r] <= lo0 || roots[r] >= hi0) continue;
          const double f = in.distanceAt(roots[r]), g = old.distanceAt(roots[r]);
          if (std::abs(f - g) <= tol::kContinuityRel * (g + edgeLength)) x = roots[r];
        }
        if (x < 0.0) {  // no accurate root between two samples with different winners
          double lo = lo0, hi = hi0;
          const bool loWins = wins[k - 1];
          for (int it = 0; it < 200 && hi - lo > bisectionResolution; ++it) {
            const double mid = 0.5 * (lo + hi);
            (incomingWins(in, old, mid) == loWins ? lo : hi) = mid;
          }
          x = 0.5 * (lo + hi);
          // D4 if the change is a real crossing inside the piece. One within ε of the piece's
          // end is the two functions meeting there (e.g. both through the same vertex), which
          // Eq. 1 need not resolve: the sliver it leaves is step 3's (D1).
          if (x - old.b0 > pieceTiny && old.b1 - x > pieceTiny) ++report.degeneracies[DegeneracyKind::D4];
        }
        report.eq1Breakpoints.push_back(x);
        cut[++m] = x;
        cutWins[m] = wins[k];
      }
      cut[++m] = old.b1;
      bool oldIdUsed = false;
      for (int k = 0; k < m; ++k) {
        if (cutWins[k]) {
          merged.push_back(newPiece(cut[k], cut[k + 1]));
        } else {
          Interval w = old;
          w.b0 = cut[k];
          w.b1 = cut[k + 1];
          clipPropagated(w);
          if (oldIdUsed) {
            w.id = ids();
            w.queuedKey = -1.0f;
          }
          oldIdUsed = true;
          merged.push_back(w);
        }
      }
    }
    if (cursor < in.b1) merged.push_back(newPiece(cursor, in.b1));
    for (; i < split.size(); ++i) merged.push_back(split[i]);
    report.incomingSurvived = incomingIdUsed;
    // assign, not swap: the edge's buffer then grows to exactly what it holds (intervals are
    // most of the solver's memory), and the scratch keeps its large capacity for reuse.
    list_.assign(merged.begin(), merged.end());
    out.clear();
  }

  std::vector<Interval>& L = list_;

  // --- Step 3: remove tiny intervals (D1), merging each into a neighbour that touches it. The
  //     grown neighbour keeps its propagated range, so the tiny part still gets propagated. A
  //     neighbour grown this way may itself still be tiny next to a coarser one: repeat until
  //     nothing is (each pass removes at least one interval, so this ends).
  for (bool removed = true; removed;) {
    removed = false;
    std::size_t w = 0;
    for (std::size_t r = 0; r < L.size(); ++r) {
      // ε against the neighbours L[r] will have: the last one kept (L[w − 1]) and the next.
      double tiny = tinyLength(L[r], edgeLength);
      if (w > 0) {
        const double t = tinyLength(L[w - 1], edgeLength);
        if (L[w - 1].b1 >= L[r].b0 - t) tiny = std::max(tiny, t);
      }
      if (r + 1 < L.size()) {
        const double t = tinyLength(L[r + 1], edgeLength);
        if (L[r + 1].b0 <= L[r].b1 + t) tiny = std::max(tiny, t);
      }
      if (L[r].length() >= tiny) {
        L[w++] = L[r];
        continue;
      }
      removed = true;
      ++report.degeneracies[DegeneracyKind::D1];
      const Interval t = L[r];
      report.removedTiny.emplace_back(t.b0, t.b1);
      // Prefer the neighbour with the coarser scale: merging into the same-scale one would only
      // leave a sliver as thin as before beside the coarse one.
      const bool prevTouches = w > 0 && L[w - 1].b1 >= t.b0 - tiny;
      const bool nextTouches = r + 1 < L.size() && L[r + 1].b0 <= t.b1 + tiny;
      const bool intoNext = nextTouches && (!prevTouches || tinyLength(L[r + 1], edgeLength) >
                                                                 tinyLength(L[w - 1], edgeLength));
      if (intoNext) {
        Interval& next = L[r + 1];
        if (t.fullyPropagated() && next.pb0 <= next.b0 && !next.nothingPropagated()) next.pb0 = t.b0;
        next.b0 = std::min(next.b0, t.b0);
      } else if (prevTouches) {
        Interval& prev = L[w - 1];
        if (t.fullyPropagated() && prev.pb1 >= prev.b1 && !prev.nothingPropagated()) prev.pb1 = t.b1;
        prev.b1 = std::max(prev.b1, t.b1);
      }
    }
    L.resize(w);
  }

  // --- Step 4: sew gaps shorter than ε at their midpoint (D3); an overlap left here (D2) is
  //     resolved the same way. The edge's ends count as neighbours.
  if (!L.empty()) {
    if (L.front().b0 > 0.0 && L.front().b0 < tinyLength(L.front(), edgeLength)) {
      ++report.degeneracies[DegeneracyKind::D3];
      L.front().b0 = 0.0;
    }
    if (L.back().b1 < edgeLength && edgeLength - L.back().b1 < tinyLength(L.back(), edgeLength)) {
      ++report.degeneracies[DegeneracyKind::D3];
      L.back().b1 = edgeLength;
    }
    for (std::size_t k = 0; k + 1 < L.size(); ++k) {
      const double gap = L[k + 1].b0 - L[k].b1;
      if (gap == 0.0) continue;
      const double tiny = std::max(tinyLength(L[k], edgeLength), tinyLength(L[k + 1], edgeLength));
      if (gap > 0.0) {
        // The shadow a flat vertex leaves grows with the distance (see tol::kFlatVertexAngle).
        const double shadow = tol::kFlatVertexAngle *
                              std::min(L[k].distanceAt(L[k].b1), L[k + 1].distanceAt(L[k + 1].b0));
        if (gap >= std::max(tiny, shadow)) continue;
      } else if (gap <= -tiny) {
        continue;
      }
      ++report.degeneracies[gap > 0.0 ? DegeneracyKind::D3 : DegeneracyKind::D2];
      const double mid = 0.5 * (L[k].b1 + L[k + 1].b0);
      L[k].b1 = mid;
      L[k + 1].b0 = mid;
      clipPropagated(L[k]);
      clipPropagated(L[k + 1]);
    }
  }

  // --- Step 5: merge neighbours with the same pseudo-source.
  {
    std::size_t w = 0;
    for (std::size_t r = 0; r < L.size(); ++r) {
      if (w > 0 && L[w - 1].b1 == L[r].b0 && sameSource(L[w - 1], L[r], edgeLength)) {
        Interval& p = L[w - 1];
        const Interval& q = L[r];
        const bool pReachesEnd = !p.nothingPropagated() && p.pb1 >= p.b1;
        const bool qReachesStart = !q.nothingPropagated() && q.pb0 <= q.b0;
        if (pReachesEnd && qReachesStart) {
          p.pb1 = q.pb1;
        } else if (!q.nothingPropagated() &&
                   (p.nothingPropagated() || q.pb1 - q.pb0 > p.pb1 - p.pb0)) {
          p.pb0 = q.pb0;
          p.pb1 = q.pb1;
        }
        p.b1 = q.b1;
        if (p.id == incoming.id || q.id == incoming.id) report.incomingSurvived = true;
        continue;
      }
      L[w++] = L[r];
    }
    L.resize(w);
  }

  for (Interval& w : L) {
    if (w.fullyPropagated()) continue;
    if (w.queuedKey != static_cast<float>(w.minDistance())) report.toQueue.push_back(w.id);
  }
  if (!report.incomingSurvived) {
    for (const Interval& w : L)
      if (w.id == incoming.id) report.incomingSurvived = true;
  }
}

}  // namespace geodex
