// One window across one face in Fig. 3's frame: exits, coverage, text and picture (local_window.h).
#include "local_window.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "check_support.h"
#include "fig6_exact.h"
#include "geodex/tolerance.h"
#include "svg.h"

namespace geodex::verify::detail {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

double sinAngle(const Vec2& a, const Vec2& b) {
  const double na = a.norm(), nb = b.norm();
  if (na == 0.0 || nb == 0.0 || a.dot(b) <= 0.0) return 2.0;
  return std::abs(cross2(a, b)) / (na * nb);
}

bool decidedAlikeAtUnitScale(const LocalWindow& w, const LocalWindow& u) {
  const double k = u.edgeLength / w.edgeLength;  // a power of two
  for (double x : {w.edgeLength, w.apex.x(), w.apex.y(), w.b0, w.b1, w.source.x(), w.source.y()}) {
    if (!scalesExactly(x, k)) return false;
    if (x != 0.0 && !(std::abs(x * k) >= 0x1p-100 && std::abs(x * k) <= 0x1p100)) return false;
  }
  return true;
}

bool sameDecision(const LocalPropagation& a, const LocalPropagation& b) {
  if (a.branch != b.branch || a.numChildren != b.numChildren) return false;
  for (int i = 0; i < a.numChildren; ++i)
    if (a.children[i].edge != b.children[i].edge || a.children[i].t0 != b.children[i].t0 ||
        a.children[i].t1 != b.children[i].t1)
      return false;
  return true;
}

// Measured from p (not s) and from the segment's end nearer the crossing: from s, or from the far
// end of a long edge, the cross products cancel down to the rounding of those long vectors, and
// the coverage check would ask a window to cover a stretch its rays never reach
// (corpus/fuzz_propagation/regress/coverage-crossing-near-v2-of-a-long-edge-measured-from-its-far-end).
Exit exitOf(const Vec2& s, const Vec2& p, const Vec2& v0, const Vec2& v1, const Vec2& v2) {
  const Vec2 d = p - s;
  Exit best;
  double bestBeyond = -INFINITY;
  const Vec2 A[2] = {v0, v1}, B[2] = {v1, v2};
  for (int k = 0; k < 2; ++k) {
    const Vec2 e = B[k] - A[k];
    const double denom = cross2(e, d);
    if (denom == 0.0) continue;
    double t = cross2(p - A[k], d) / denom;
    const double beyond = cross2(p - A[k], e) / denom;  // p + beyond·d is on the line
    Vec2 point;
    if (t <= 0.5) {
      if (!(t >= -1e-9)) continue;
      point = A[k] + std::max(t, 0.0) * e;
    } else {  // from B: t = 1 − tB
      const double tB = cross2(p - B[k], d) / cross2(A[k] - B[k], d);
      if (!(tB >= -1e-9)) continue;
      t = 1.0 - tB;
      point = B[k] + std::max(tB, 0.0) * (A[k] - B[k]);
    }
    if (beyond > bestBeyond) {
      bestBeyond = beyond;
      best.edge = k + 1;
      best.t = std::clamp(t, 0.0, 1.0);
      best.point = point;
    }
  }
  return best;
}

Vec2 childPoint(const LocalWindow& w, int edge, double t) {
  const Vec2 v0(0.0, 0.0), v2(w.edgeLength, 0.0);
  return edge == 1 ? Vec2(v0 + t * (w.apex - v0)) : Vec2(w.apex + t * (v2 - w.apex));
}

std::string describeLocal(const LocalWindow& w) {
  std::ostringstream os;
  os << std::setprecision(17) << "L=" << w.edgeLength << " apex=(" << w.apex.x() << ", "
     << w.apex.y() << ") window=[" << w.b0 << ", " << w.b1 << "] s=(" << w.source.x() << ", "
     << w.source.y() << ")";
  return os.str();
}

std::string describeResult(const LocalPropagation& r) {
  std::ostringstream os;
  os << std::setprecision(17) << name(r.branch);
  for (int c = 0; c < r.numChildren; ++c)
    os << " e" << int(r.children[c].edge) << "[" << r.children[c].t0 << ", " << r.children[c].t1 << "]";
  return os.str();
}


// ===  Coverage of the wedge =====================================================================

double wedgeSlack(const LocalWindow& w) {
  const Vec2 s = w.source, b0(w.b0, 0.0), b1(w.b1, 0.0);
  return 100.0 * (tol::kCollinearSin + tol::kCoincideRel * localScale(w) / std::min((b0 - s).norm(), (b1 - s).norm()));
}

const char* localChildrenProblem(const LocalPropagation& r) {
  if (r.numChildren > 2) return "more than two children";
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& ch = r.children[i];
    if ((ch.edge != 1 && ch.edge != 2) || !(ch.t0 >= 0.0 && ch.t0 <= ch.t1 && ch.t1 <= 1.0))
      return i == 0 ? "child 0 outside 0 <= t0 <= t1 <= 1" : "child 1 outside 0 <= t0 <= t1 <= 1";
    if (i == 1 && ch.edge == r.children[0].edge) return "two children on the same edge";
  }
  return nullptr;
}

Coverage wedgeCoverage(const LocalWindow& w, std::span<const LocalChild> covering) {
  Coverage result;
  const Vec2 v0(0.0, 0.0), v2(w.edgeLength, 0.0), v1 = w.apex, s = w.source;
  const double scale = localScale(w);
  const double kappa = wedgeSlack(w);
  std::array<Vec2, 4> childEnds;
  std::size_t ends = 0;
  for (const LocalChild& ch : covering) {
    if (ends + 2 > childEnds.size()) break;
    childEnds[ends++] = childPoint(w, ch.edge, ch.t0);
    childEnds[ends++] = childPoint(w, ch.edge, ch.t1);
  }
  constexpr int kSamples = 16;
  // Where the wedge's image on e1 ∪ e2 is shorter than ε (a far, grazing source seen through a
  // tiny window), its children are below D1's ε or empty after rounding: nothing to cover. The ε
  // is the children's own (intervalLengthScale: the distance of the source when that is larger
  // than the face), because from far away the rays of a tiny window differ by less than one ulp
  // of the source's coordinates and their image rounds to nothing
  // (corpus/fuzz_predicates/regress/coverage-image-below-the-far-source-epsilon).
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (int i = 0; i <= kSamples; ++i) {
    const Exit x = exitOf(s, Vec2(w.b0 + (w.b1 - w.b0) * i / kSamples, 0.0), v0, v1, v2);
    if (x.edge != 0) lo = lo.cwiseMin(x.point), hi = hi.cwiseMax(x.point);
  }
  const double imageTiny = tol::kTinyIntervalRel * std::max(scale, std::abs(s.x()) + std::abs(s.y()));
  if ((hi - lo).norm() <= imageTiny) {
    result.imageBelowEpsilon = true;
    return result;
  }
  for (int i = 0; i <= kSamples; ++i) {
    const Vec2 p(w.b0 + (w.b1 - w.b0) * i / kSamples, 0.0);
    const Exit x = exitOf(s, p, v0, v1, v2);
    if (x.edge == 0) continue;  // ray along e0's line: nothing enters
    bool covered = false;
    for (const LocalChild& ch : covering)
      covered = covered || (ch.edge == x.edge && x.t >= ch.t0 - 1e-12 && x.t <= ch.t1 + 1e-12);
    for (std::size_t k = 0; k < ends && !covered; ++k)
      if (sinAngle(x.point - s, childEnds[k] - s) <= kappa) covered = true;
    if (!covered) {
      std::ostringstream os;
      os << std::setprecision(17) << "the ray from s through x = " << p.x() << " leaves the face on e"
         << x.edge << " at t = " << x.t << ", outside every child";
      result.uncovered = os.str();
      return result;
    }
  }
  return result;
}

// ===  Picture ===================================================================================

void svgLocalWindow(const LocalWindow& w, std::ostream& out, const std::string& title, const std::string& extra) {
  SvgDoc doc(900, 700);
  const Vec2 v0(0, 0), v2(w.edgeLength, 0), v1 = w.apex, s = w.source;
  const double scale = localScale(w);
  const bool sourceShown = (s - 0.5 * (v0 + v2)).norm() <= 6.0 * scale;
  double x0 = std::min({0.0, v1.x()}), x1 = std::max(w.edgeLength, v1.x());
  double y0 = 0.0, y1 = v1.y();
  if (sourceShown) x0 = std::min(x0, s.x()), x1 = std::max(x1, s.x()), y0 = std::min(y0, s.y());
  else y0 = -0.3 * scale;
  Panel P(20, 60, 860, 620, x0, y0, x1, y1, true);
  doc.polygon(P, {v0, v1, v2}, "#eeeeee", "#999999");
  doc.line(P, v0, v2, "#000", 2);
  doc.line(P, Vec2(w.b0, 0), Vec2(w.b1, 0), "#1f77b4", 6);
  const LocalPropagation r = propagateLocal(w);
  // The wedge: rays from s through b0 and b1 to where they leave the face.
  for (double b : {w.b0, w.b1}) {
    const Vec2 p(b, 0);
    const Exit x = exitOf(s, p, v0, v1, v2);
    const Vec2 far = x.edge != 0 ? x.point : p;
    const Vec2 from = sourceShown ? s : p - (p - s).normalized() * 0.3 * scale;
    doc.line(P, from, far, "#ff7f0e", 1.5, true);
  }
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& c = r.children[i];
    doc.line(P, childPoint(w, c.edge, c.t0), childPoint(w, c.edge, c.t1), c.edge == 1 ? "#2ca02c" : "#9467bd", 5);
  }
  doc.dot(P, v0, 4, "#000");
  doc.dot(P, v1, 4, "#000");
  doc.dot(P, v2, 4, "#000");
  doc.label(P, v0, "v0");
  doc.label(P, v1, "v1");
  doc.label(P, v2, "v2");
  doc.label(P, Vec2(w.b0, 0), "b0", 11, "#1f77b4", -6, 16);
  doc.label(P, Vec2(w.b1, 0), "b1", 11, "#1f77b4", -6, 16);
  if (sourceShown) {
    doc.dot(P, s, 5, "#d62728");
    doc.label(P, s, "s");
  }
  doc.labelPx(20, 20, title + ": " + describeResult(r), 14);
  if (!extra.empty()) doc.labelPx(20, 695, extra, 11);
  const ExactFig6 e = exactFig6(w);
  doc.labelPx(20, 40, "L=" + shortNum(w.edgeLength) + " v1=(" + shortNum(v1.x()) + ", " + shortNum(v1.y()) +
                          ") [b0,b1]=[" + shortNum(w.b0) + ", " + shortNum(w.b1) + "] s=(" + shortNum(s.x()) +
                          ", " + shortNum(s.y()) + ")  exact: " +
                          (e.branch ? std::string(name(*e.branch)) : "near " + e.nearWhat) +
                          "  (e1 green, e2 purple)", 12);
  doc.write(out);
}

}  // namespace geodex::verify::detail
