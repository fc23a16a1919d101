// fuzz_predicates: one Fig. 6 decision against the exact tree (fuzz_predicates.h).
#include "geodex/verify/cases/fuzz_predicates.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <variant>

#include "check_support.h"
#include "fig6_exact.h"
#include "geodex/verify/repro.h"  // FuzzCase, which the seeds' expectations take
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

// ===  Seeds =====================================================================================
// Frame of Fig. 3: v0 = (0, 0), v2 = (L, 0), the apex v1 above, the source s below e0.

namespace {

using Q = Quantity;
Q n(int v) { return Q::lattice(v); }

/// A seed whose window propagateLocal must decide as `expected`.
Seed predicate(const std::string& name, Fig6Branch expected, const PredicateSpec& s) {
  return {name, encode(s), [expected](const FuzzCase& c, const Verdict&) {
            const auto r = propagateLocal(std::get<PredicateCase>(c).window);
            return r.branch == expected ? std::string()
                                        : "ends in " + std::string(geodex::name(r.branch)) + ", not " +
                                              std::string(geodex::name(expected));
          }};
}

PredicateSpec local(int L, Q ax, Q ay, Q b0, Q b1, Q sx, Q sy, int unitExp = 0) {
  PredicateSpec s;
  s.unitExp = static_cast<std::int8_t>(unitExp);
  s.edgeLength = n(L);
  s.apexX = ax, s.apexY = ay, s.b0 = b0, s.b1 = b1, s.sourceX = sx, s.sourceY = sy;
  return s;
}

/// A minimized reproducer of a fixed bug, in regress/.
Seed regress(const std::string& name, const PredicateSpec& s) {
  return {.name = name, .bytes = encode(s), .expect = {}, .dir = "regress"};
}

}  // namespace

std::vector<Seed> predicateSeeds() {
  using B = Fig6Branch;
  return {
    // G1: the pseudo-source on the line of e0.
    predicate("G1-source-at-b0", B::G1Inside, local(8, n(4), n(4), n(2), n(6), n(2), n(0))),
    predicate("G1-source-at-b1", B::G1Inside, local(8, n(4), n(4), n(2), n(6), n(6), n(0))),
    predicate("G1-source-inside-window-after-merge", B::G1Inside, local(8, n(4), n(4), n(2), n(6), n(3), n(0))),
    predicate("G1-source-on-e0-line-outside-window", B::G1Outside, local(8, n(4), n(4), n(2), n(6), n(-3), n(0))),
    predicate("G1-source-half-tolerance-below-e0", B::G1Inside,
              local(8, n(4), n(4), n(2), n(6), n(2), n(0).nudged(-8, Nudge::Coincide, true))),
    predicate("G1-source-half-tolerance-before-b0", B::G1Inside,
              local(8, n(4), n(4), n(2), n(6), n(2).nudged(-8, Nudge::Coincide, true), n(0))),
    predicate("G1-G2-G4-source-at-b0-at-v0", B::G1Inside, local(8, n(4), n(4), n(0), n(6), n(0), n(0))),
    predicate("G1-G3-G5-source-at-b1-at-v2", B::G1Inside, local(8, n(4), n(4), n(2), n(8), n(8), n(0))),
    predicate("G1-G2-source-at-b0-apex-above", B::G1Inside, local(8, n(2), n(4), n(2), n(6), n(2), n(0))),
    // G2: s, b0, v1 collinear with b0 inside e0. s = b0 − (v1 − b0).
    predicate("G2-source-b0-apex-collinear", B::G2, local(8, n(4), n(4), n(2), n(6), n(0), n(-4))),
    predicate("G2-near-collinear-within-tolerance", B::G2,
              local(8, n(4), n(4), n(2), n(6), n(0).nudged(8, Nudge::Collinear, true), n(-4))),
    predicate("G2-just-outside-tolerance-inside-wedge", B::InsideWedge,
              local(8, n(4), n(4), n(2), n(6), n(0).nudged(4, Nudge::Collinear), n(-4))),
    predicate("G2-just-outside-tolerance-left-of-wedge", B::LeftOfWedge,
              local(8, n(4), n(4), n(2), n(6), n(0).nudged(-4, Nudge::Collinear), n(-4))),
    predicate("G2-b0-12eps-from-v0-collinear-not-G4", B::G2,
              local(8, n(4), n(4), n(0).nudged(12, Nudge::Coincide), n(6), n(-4).nudged(24, Nudge::Coincide), n(-4))),
    predicate("G2-far-source-collinear", B::G2, local(8, n(4), n(4), n(2), n(6), n(-14), n(-32))),
    predicate("G2-scaled-1e-6", B::G2, local(8, n(4), n(4), n(2), n(6), n(0), n(-4), -20)),
    // G3: s, b1, v1 collinear with b1 inside e0. s = b1 + (b1 − v1).
    predicate("G3-source-b1-apex-collinear", B::G3, local(8, n(4), n(4), n(2), n(6), n(8), n(-4))),
    predicate("G3-near-collinear-within-tolerance", B::G3,
              local(8, n(4), n(4), n(2), n(6), n(8).nudged(-8, Nudge::Collinear, true), n(-4))),
    predicate("G3-just-outside-tolerance-right-of-wedge", B::RightOfWedge,
              local(8, n(4), n(4), n(2), n(6), n(8).nudged(4, Nudge::Collinear), n(-4))),
    predicate("G3-scaled-1e+6", B::G3, local(8, n(4), n(4), n(2), n(6), n(8), n(-4), 20)),
    // G4: s, v0 = b0, v1 collinear: the left ray runs along e1.
    predicate("G4-source-v0-b0-collinear", B::G4, local(8, n(4), n(4), n(0), n(6), n(-4), n(-4))),
    predicate("G4-b0-half-tolerance-from-v0", B::G4,
              local(8, n(4), n(4), n(0).nudged(8, Nudge::Coincide, true), n(6), n(-4).nudged(16, Nudge::Coincide, true), n(-4))),
    predicate("G4-obtuse-at-v0", B::G4, local(8, n(-2), n(4), n(0), n(6), n(1), n(-2))),
    predicate("G4-window-whole-edge", B::G4, local(8, n(4), n(4), n(0), n(8), n(-4), n(-4))),
    // G5: s, v2 = b1, v1 collinear: the right ray runs along e2.
    predicate("G5-source-v2-b1-collinear", B::G5, local(8, n(4), n(4), n(2), n(8), n(12), n(-4))),
    predicate("G5-b1-half-tolerance-from-v2", B::G5,
              local(8, n(4), n(4), n(2), n(8).nudged(-8, Nudge::Coincide, true), n(12).nudged(-16, Nudge::Coincide, true), n(-4))),
    predicate("G5-obtuse-at-v2", B::G5, local(8, n(10), n(4), n(2), n(8), n(7), n(-2))),
    // Composites decided by the order of the tree: G2 is tested before G3.
    predicate("G2-G3-both-rays-collinear-with-v1-G2-first", B::G2,
              local(8, n(4), n(4), n(4), n(4).nudged(4, Nudge::Coincide), n(4), n(-4))),
    // The general cases of Fig. 3.
    predicate("left-of-wedge", B::LeftOfWedge, local(8, n(1), n(4), n(4), n(6), n(5), n(-4))),
    predicate("right-of-wedge", B::RightOfWedge, local(8, n(7), n(4), n(2), n(4), n(3), n(-4))),
    predicate("inside-wedge", B::InsideWedge, local(8, n(4), n(4), n(2), n(6), n(4), n(-4))),
    predicate("left-of-wedge-b0-at-v0-fig3c", B::LeftOfWedge, local(8, n(-2), n(4), n(0), n(4), n(-1), n(-4))),
    predicate("right-of-wedge-b1-at-v2-fig3c-mirror", B::RightOfWedge, local(8, n(10), n(4), n(4), n(8), n(9), n(-4))),
    predicate("inside-wedge-far-source", B::InsideWedge, local(8, n(4), n(4), n(2), n(6), n(4), n(-32).times8(7))),
    predicate("inside-wedge-grazing-source-11eps-below-e0", B::InsideWedge,
              local(8, n(4), n(4), n(0), n(8), n(4), n(0).nudged(-11, Nudge::Coincide))),
    predicate("left-of-wedge-tiny-window", B::LeftOfWedge,
              local(8, n(3), n(4), n(4), n(4).nudged(20, Nudge::Coincide), n(4), n(-4))),
    // Mesh-level: a zero-area face (apex on e0's line) and a needle below kFlatFaceRel.
    predicate("zero-area-face-apex-on-e0", B::ZeroAreaFace, local(8, n(4), n(0), n(2), n(6), n(4), n(-4))),
    predicate("zero-area-face-apex-beyond-v2", B::ZeroAreaFace, local(8, n(12), n(0), n(2), n(6), n(4), n(-4))),
    predicate("zero-area-needle-below-flat-tolerance", B::ZeroAreaFace,
              local(8, n(4), n(0).nudged(8, Nudge::FlatFace, true), n(2), n(6), n(4), n(-4))),
    // G2 in a needle face seen by a grazing window: the face lies within the collinearity
    // tolerance of the almost horizontal rays from s, so Fig. 6 decides G2 although the window's
    // rays cross e1. An ambiguous branch therefore also gives the edge the ray would cross on the
    // other side of v1 (propagate.cpp); else the whole window is lost.
    regress("coverage-G2-needle-face-grazing-window-lost",
            local(8, n(-6), n(0).nudged(10, Nudge::FlatFace), n(2), n(3), n(24), n(0).nudged(-2, Nudge::Coincide))),
  };
}

}  // namespace geodex::verify
