// fuzz_predicates: one Fig. 6 decision against the exact tree (fuzz_predicates.h).
#include "geodex/verify/cases/fuzz_predicates.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "check_support.h"
#include "fig6_exact.h"
#include "local_window.h"

namespace geodex::verify {

using namespace detail;

// ===  Format ====================================================================================

namespace {

PredicateSpec readPredicateSpec(ByteReader& r) {
  PredicateSpec s;
  s.unitExp = r.i8();
  s.edgeLength = r.quantity();
  s.apexX = r.quantity();
  s.apexY = r.quantity();
  s.b0 = r.quantity();
  s.b1 = r.quantity();
  s.sourceX = r.quantity();
  s.sourceY = r.quantity();
  return s;
}

}  // namespace

std::vector<std::uint8_t> encode(const PredicateSpec& s) {
  ByteWriter w;
  w.i8(s.unitExp);
  for (const Quantity* q : {&s.edgeLength, &s.apexX, &s.apexY, &s.b0, &s.b1, &s.sourceX, &s.sourceY})
    w.quantity(*q);
  return w.bytes();
}

// ===  Decoding ==================================================================================

namespace {

std::optional<PredicateCase> makePredicateCase(const PredicateSpec& s) {
  const double unit = unitOf(s.unitExp);
  const auto [L, nL] = edgeLengthOf(s.edgeLength, unit);
  PredicateCase c;
  LocalWindow& w = c.window;
  w.edgeLength = L;
  w.apex = Vec2(fieldValue(s.apexX, -2 * nL, 3 * nL, unit, L),
                std::abs(fieldValue(s.apexY, 0, 2 * nL, unit, L)));
  double b0 = fieldValue(s.b0, 0, nL, unit, L), b1 = fieldValue(s.b1, 0, nL, unit, L);
  if (b0 > b1) std::swap(b0, b1);
  w.b0 = std::max(b0, 0.0);
  w.b1 = std::min(b1, L);
  w.source = Vec2(fieldValue(s.sourceX, -4 * nL, 5 * nL, unit, L),
                  -std::abs(fieldValue(s.sourceY, -4 * nL, 0, unit, L)));
  if (!(L > 0.0) || !(w.b0 < w.b1) || !isFinite(w.apex) || !isFinite(w.source)) return std::nullopt;
  return c;
}

}  // namespace

std::optional<PredicateCase> decodePredicates(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxFuzzInputBytes) return std::nullopt;
  ByteReader r(bytes);
  return makePredicateCase(readPredicateSpec(r));
}

// ===  Check =====================================================================================

Verdict checkPredicates(const PredicateCase& c) {
  Verdict v;
  v.interesting = true;
  const LocalWindow& w = c.window;
  LocalPropagation r;
  try {
    r = propagateLocal(w);
  } catch (const std::exception& e) {
    return fail(v, "unexpected-exception", std::string("propagateLocal threw: ") + e.what());
  }
  if (const auto k = degeneracyOf(r.branch)) ++v.degeneracies[*k];
  v.summary = describeResult(r);
  auto where = [&] { return " in " + describeLocal(w) + " → " + describeResult(r); };

  // (b) the children's ranges.
  if (const char* why = localChildrenProblem(r)) return fail(v, "child-range", why + where());

  // (a) the branch agrees with the exact tree where every predicate on its path is clear.
  const ExactFig6 exact = exactFig6(w);
  if (exact.branch && *exact.branch != r.branch) {
    return fail(v, "exact-predicates",
                "exactly evaluated the tree ends in " + std::string(name(*exact.branch)) + where());
  }
  if (!exact.branch) v.summary += " (near: " + exact.nearWhat + ")";

  // (d) the same case at unit scale (exact) is decided the same way, bit for bit; the checks
  // below work on it, so that their own arithmetic holds at any scale the decoder reaches.
  const LocalWindow u = atUnitScale(w);
  if (decidedAlikeAtUnitScale(w, u)) {
    const LocalPropagation atUnit = propagateLocal(u);
    if (!sameDecision(atUnit, r)) return fail(v, "scale-invariance", "at unit scale " + describeResult(atUnit) + where());
  }

  // (c) coverage and soundness. Along e0 (G1) and through a zero-area face the rays graze the
  // edges: the whole-edge children are the paper's contract there, nothing to sample. Outside
  // the window (G1 outside) the rays run along e0, none or only a grazing sliver entering the
  // face; where the tree gives that sliver it is judged as any wedge's children.
  if (r.branch == Fig6Branch::ZeroAreaFace || r.branch == Fig6Branch::G1Inside ||
      (r.branch == Fig6Branch::G1Outside && r.numChildren == 0))
    return v;
  const Vec2 s = u.source, b0(u.b0, 0.0), b1(u.b1, 0.0);
  const double scale = localScale(u);
  const double kappa = wedgeSlack(u);
  const Coverage coverage = wedgeCoverage(u, {r.children.data(), r.numChildren});
  if (coverage.imageBelowEpsilon) return v.summary += " (image below epsilon)", v;
  if (!coverage.uncovered.empty()) return fail(v, "coverage", coverage.uncovered + where());
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& ch = r.children[i];
    for (double t : {ch.t0, 0.5 * (ch.t0 + ch.t1), ch.t1}) {
      const Vec2 y = childPoint(u, ch.edge, t);
      const Vec2 d = y - s;
      const double xStar = d.y() > 0.0 ? s.x() + d.x() * (-s.y()) / d.y() : y.x();
      const double slack = 1e-12 * scale;
      if (xStar >= u.b0 - slack && xStar <= u.b1 + slack) continue;
      if (sinAngle(d, b0 - s) <= kappa || sinAngle(d, b1 - s) <= kappa) continue;
      std::ostringstream os;
      os << std::setprecision(17) << "the point t = " << t << " of the e" << int(ch.edge)
         << " child is seen from s through x = " << xStar << ", outside the window" << where();
      return fail(v, "soundness", os.str());
    }
  }
  return v;
}

// ===  Description and picture ===================================================================

void describe(const PredicateCase& c, std::ostream& out) {
  out << std::setprecision(17);
  const LocalWindow& w = c.window;
  out << "# fuzz_predicates: a window on e0 = v0v2 propagated across the face v0 v1 v2 (Fig. 3 frame)\n"
      << "edge-length " << w.edgeLength << "\n"
      << "apex " << w.apex.x() << " " << w.apex.y() << "\n"
      << "window " << w.b0 << " " << w.b1 << "\n"
      << "source " << w.source.x() << " " << w.source.y() << "\n"
      << "# local scale " << localScale(w) << "; v0 = (0, 0), v2 = (" << w.edgeLength << ", 0)\n";
  const LocalPropagation r = propagateLocal(w);
  out << "# propagateLocal: " << describeResult(r) << "\n";
  const ExactFig6 e = exactFig6(w);
  out << "# exact tree: " << (e.branch ? std::string(name(*e.branch)) : "undecided, near " + e.nearWhat) << "\n";
}

void writeSvg(const PredicateCase& c, std::ostream& out) { svgLocalWindow(c.window, out); }

}  // namespace geodex::verify
