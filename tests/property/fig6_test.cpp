// Properties of one propagation case (propagateLocal, the Fig. 6 decision tree of Liu, Zhou & Hu
// 2007 and the children of Surazhsky et al.'s Fig. 3), on configurations aimed at G1–G5, their
// composites, zero-area faces and generic wedges, exactly degenerate or moved off by ±k ulp or
// ±k·ε (generators.h).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "coverage.h"
#include "exact_fig6.h"
#include "generators.h"
#include "geodex/predicates.h"
#include "geodex/propagate.h"
#include "geodex/tolerance.h"
#include "weighted_prop.h"

namespace geodex::proptest {
namespace {

std::string describe(const LocalPropagation& r) {
  std::ostringstream os;
  os.precision(17);
  os << name(r.branch) << " with " << int(r.numChildren) << " children";
  for (int i = 0; i < r.numChildren; ++i)
    os << " (e" << int(r.children[i].edge) << ": " << r.children[i].t0 << ".." << r.children[i].t1
       << ")";
  return os.str();
}

std::string describe(const std::vector<Fig6Branch>& leaves) {
  std::string s = "{";
  for (Fig6Branch b : leaves) s += (s.size() > 1 ? ", " : "") + std::string(name(b));
  return s + "}";
}

bool contains(const std::vector<Fig6Branch>& leaves, Fig6Branch b) {
  return std::find(leaves.begin(), leaves.end(), b) != leaves.end();
}

// ===  The Fig. 6 leaf agrees with the exactly evaluated predicates ===============================
//
// Tolerance mode: the leaf is one the tree reaches with tolerance.h's predicates evaluated
// without rounding (several only when a predicate sits within 1% of its threshold).
// Exact-sign mode: the leaf is the one of exact geometry whenever no predicate is non-zero but
// within (1 + 1%)·ε of zero — exact degeneracies (lattice cases) must be recognised as such, and
// configurations farther than ε from every degeneracy must be decided as exact geometry does.
GEODEX_RC_GTEST_PROP(Fig6, BranchMatchesExactlyEvaluatedPredicates, kLocalPropertyWeight, ()) {
  const LocalCase c = *gen::localCase();
  RC_TAG(name(c.target), name(c.nearness), c.mirrored ? "mirrored" : "as made");
  const LocalPropagation r = propagateLocal(c.window);
  recordLocal(r.branch);

  const auto tolerant = exactFig6Branches(c.window, ExactMode::Tolerance);
  if (!contains(tolerant, r.branch)) {
    RC_FAIL("propagateLocal decided " + describe(r) +
            " but the exactly evaluated tolerance "
            "predicates allow only " +
            describe(tolerant));
  }
  const auto ideal = exactFig6Branches(c.window, ExactMode::ExactSign);
  if (!contains(ideal, r.branch)) {
    RC_FAIL("propagateLocal decided " + describe(r) +
            " but exact geometry (exact predicates, "
            "ambiguous only within epsilon of a degeneracy) allows only " +
            describe(ideal));
  }
  // An exactly degenerate lattice case is a degeneracy, whatever the tolerance: the generator's
  // target must be what exact geometry says (guards the generators themselves).
  if (c.coords == Coords::Lattice && c.nearness == Nearness::Exact && ideal.size() == 1) {
    const Fig6Branch want = ideal.front();
    switch (c.target) {
      case LocalTarget::G2: RC_ASSERT(want == Fig6Branch::G2); break;
      case LocalTarget::G3: RC_ASSERT(want == Fig6Branch::G3); break;
      case LocalTarget::G4: RC_ASSERT(want == Fig6Branch::G4); break;
      case LocalTarget::G5: RC_ASSERT(want == Fig6Branch::G5); break;
      case LocalTarget::G1Inside:
      case LocalTarget::SAtB0AtV0:
      case LocalTarget::SAtB1AtV2: RC_ASSERT(want == Fig6Branch::G1Inside); break;
      case LocalTarget::G1Outside: RC_ASSERT(want == Fig6Branch::G1Outside); break;
      case LocalTarget::ZeroArea: RC_ASSERT(want == Fig6Branch::ZeroAreaFace); break;
      case LocalTarget::Generic: break;
    }
  }
}

// ===  The children cover exactly the wedge's shadow ==============================================
//
// Seen from s, the window is the angular range of the rays s→x, x in [b0, b1]; each such ray enters
// the face through e0 and leaves it through e1 (if it passes left of the apex) or e2. The children
// must (a) lie inside that range, on the correct side of the apex, and (b) contain the exit point
// of every sampled ray. All comparisons are of angles seen from s, which stay well conditioned
// where a ray grazes an edge (a child's end parameter t does not).
//
// Angular slack η: a leaf taken by a tolerance may move a wedge boundary by what the tolerance
// allows — the apex is called "on" the ray s→b0 up to a sine of kCollinearSin (seen from s, an
// angle at most that, since b0 lies between s and the apex), and b0 is called v0 up to kCoincideRel
// × scale, which seen from s subtends at most that length over |s − b0|. Each wedge boundary moves
// at most once of each kind, both ends may: factor 2. Rounding of the sample points and atan2 adds
// a few ulps relative to scale / distance.
double angularSlack(const LocalWindow& w) {
  const Vec2 s = w.source;
  const double dmin = std::min((s - Vec2(w.b0, 0.0)).norm(), (s - Vec2(w.b1, 0.0)).norm());
  const double scale = localScale(w);
  return 2.0 * tol::kCollinearSin + 2.0 * tol::kCoincideRel * scale / dmin +
         16.0 * DBL_EPSILON * (1.0 + scale / dmin);
}

// What is wrong with r as the shadow of w's wedge ("" if nothing).
std::string shadowViolation(const LocalWindow& w, const LocalPropagation& r) {
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& ch = r.children[i];
    if (!(ch.edge == 1 || ch.edge == 2) || !(0.0 <= ch.t0 && ch.t0 < ch.t1 && ch.t1 <= 1.0))
      return "child " + std::to_string(i) +
             " is not a proper sub-range of e1 or e2: " + describe(r);
  }
  switch (r.branch) {
    case Fig6Branch::ZeroAreaFace:
      return "";  // a pass-through along e0's line: no wedge to speak of (unit-tested by hand)
    case Fig6Branch::G1Outside:
      // s on e0's line outside the window: exactly on it, its rays run along e0 and none enters
      // the face; a hair below it, the ones that enter are checked as any wedge's below (rays
      // within the angular slack of the wedge's or the apex's angle may go either way).
      if (w.source.y() == 0.0)
        return r.numChildren == 0 ? "" : "G1-outside with s on the line made children: " + describe(r);
      break;
    case Fig6Branch::G1Inside: {
      // s on e0 within the window: the whole (convex) face is seen from s.
      const bool ok = r.numChildren == 2 && r.children[0].edge != r.children[1].edge &&
                      r.children[0].t0 == 0.0 && r.children[0].t1 == 1.0 &&
                      r.children[1].t0 == 0.0 && r.children[1].t1 == 1.0;
      return ok ? "" : "G1-inside must give e1 and e2 whole: " + describe(r);
    }
    default: break;
  }

  const Vec2 s = w.source, v0(0.0, 0.0), v2(w.edgeLength, 0.0), v1 = w.apex;
  if (!(s.y() < 0.0)) return "not G1, yet s is on e0's line: " + describe(r);
  auto theta = [&](const Vec2& p) { return std::atan2(p.y() - s.y(), p.x() - s.x()); };
  auto pointOn = [&](int edge, double t) {
    return edge == 1 ? Vec2(v0 + t * (v1 - v0)) : Vec2(v1 + t * (v2 - v1));
  };
  const double eta = angularSlack(w);
  const double hiAngle = theta(Vec2(w.b0, 0.0)), loAngle = theta(Vec2(w.b1, 0.0));
  const double apexAngle = theta(v1);
  std::ostringstream ctx;
  ctx.precision(17);
  ctx << describe(r) << "; window angles [" << loAngle << ", " << hiAngle << "], apex angle "
      << apexAngle << ", slack " << eta;

  // (a) children inside the wedge, e1 ones at or beyond the apex's angle, e2 ones at or before it.
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& ch = r.children[i];
    for (double t : {ch.t0, 0.5 * (ch.t0 + ch.t1), ch.t1}) {
      const double a = theta(pointOn(ch.edge, t));
      std::ostringstream os;
      os.precision(17);
      os << "child e" << int(ch.edge) << " at t = " << t << " (angle " << a << ")";
      if (a < loAngle - eta || a > hiAngle + eta)
        return os.str() + " is outside the window's shadow: " + ctx.str();
      if ((ch.edge == 1 && a < apexAngle - eta) || (ch.edge == 2 && a > apexAngle + eta))
        return os.str() + " is on the wrong side of the apex: " + ctx.str();
    }
  }
  // (b) every sampled ray's exit point is in a child on the edge it leaves through.
  constexpr int kRays = 16;
  for (int k = 0; k < kRays; ++k) {
    const double x = w.b0 + (w.b1 - w.b0) * (k + 0.5) / kRays;
    const Vec2 d = Vec2(x, 0.0) - s;
    const double a = std::atan2(d.y(), d.x());
    if (std::abs(a - hiAngle) <= eta || std::abs(a - loAngle) <= eta ||
        std::abs(a - apexAngle) <= eta)
      continue;  // within the slack of a boundary: either side is right
    const int exitEdge =
        pred::cross(d, v1 - s) > 0.0 ? 2 : 1;  // apex left of the ray: leaves via e2
    bool covered = false;
    for (int i = 0; i < r.numChildren && !covered; ++i) {
      const LocalChild& ch = r.children[i];
      if (ch.edge != exitEdge) continue;
      const double a0 = theta(pointOn(ch.edge, ch.t0)), a1 = theta(pointOn(ch.edge, ch.t1));
      covered = std::min(a0, a1) - eta <= a && a <= std::max(a0, a1) + eta;
    }
    if (!covered) {
      std::ostringstream os;
      os.precision(17);
      os << "the ray through x = " << x << " (angle " << a << ") leaves through e" << exitEdge
         << " where no child covers it: " << ctx.str();
      return os.str();
    }
  }
  return "";
}

GEODEX_RC_GTEST_PROP(Fig6, ChildrenCoverExactlyTheWedgeShadow, kLocalPropertyWeight, ()) {
  const LocalCase c = *gen::localCase();
  RC_TAG(name(c.target), name(c.nearness), c.mirrored ? "mirrored" : "as made");
  const LocalPropagation r = propagateLocal(c.window);
  recordLocal(r.branch);
  const std::string why = shadowViolation(c.window, r);
  if (!why.empty()) RC_FAIL(why);
}

// The shadow oracle itself must see a wrong answer: on tests/unit's hand-made inside-wedge case
// (children e1 [1/3, 1], e2 [0, 2/3]), cut short, pushed outside, or put on the wrong edge.
TEST(Fig6Oracles, ShadowCheckRejectsWrongChildren) {
  const LocalWindow w{2.0, Vec2(1.0, 1.0), 0.5, 1.5, Vec2(1.0, -1.0)};
  const LocalPropagation right = propagateLocal(w);
  ASSERT_EQ(right.branch, Fig6Branch::InsideWedge);
  EXPECT_EQ(shadowViolation(w, right), "");
  LocalPropagation cut = right;
  cut.children[0].t0 = 0.5;  // e1 should start at 1/3: rays through [0.5, 0.6] lost
  EXPECT_NE(shadowViolation(w, cut), "");
  LocalPropagation outside = right;
  outside.children[1].t1 = 0.9;  // e2 beyond 2/3 is not seen through [0.5, 1.5]
  EXPECT_NE(shadowViolation(w, outside), "");
  LocalPropagation swapped = right;
  std::swap(swapped.children[0].edge, swapped.children[1].edge);
  EXPECT_NE(shadowViolation(w, swapped), "");
  LocalPropagation one = right;
  one.numChildren = 1;  // e2 dropped
  EXPECT_NE(shadowViolation(w, one), "");
}

// The exact evaluator on tests/unit's hand-made configurations (v0 = (0,0), v2 = (2,0),
// v1 = (1,1)), and on one moved just inside and just outside the collinearity tolerance.
TEST(Fig6Oracles, ExactTreeAgreesWithHandWorkedCases) {
  auto only = [](const LocalWindow& w, ExactMode mode) {
    const auto leaves = exactFig6Branches(w, mode);
    return leaves.size() == 1 ? std::string(name(leaves[0])) : describe(leaves);
  };
  const Vec2 apex(1.0, 1.0);
  for (ExactMode mode : {ExactMode::Tolerance, ExactMode::ExactSign}) {
    EXPECT_EQ(only({2.0, apex, 0.5, 1.5, Vec2(1.0, -1.0)}, mode), "inside-wedge");
    EXPECT_EQ(only({2.0, apex, 1.2, 1.6, Vec2(1.0, -1.0)}, mode), "left-of-wedge");
    EXPECT_EQ(only({2.0, apex, 0.4, 0.8, Vec2(1.0, -1.0)}, mode), "right-of-wedge");
    EXPECT_EQ(only({2.0, apex, 0.5, 1.5, Vec2(0.5, 0.0)}, mode), "G1-inside");
    EXPECT_EQ(only({2.0, apex, 0.5, 1.5, Vec2(-1.0, 0.0)}, mode), "G1-outside");
    EXPECT_EQ(only({2.0, apex, 0.5, 1.5, Vec2(0.0, -1.0)}, mode), "G2");
    EXPECT_EQ(only({2.0, apex, 0.5, 1.5, Vec2(2.0, -1.0)}, mode), "G3");
    EXPECT_EQ(only({2.0, apex, 0.0, 1.0, Vec2(-1.0, -1.0)}, mode), "G4");
    EXPECT_EQ(only({2.0, apex, 1.0, 2.0, Vec2(3.0, -1.0)}, mode), "G5");
    EXPECT_EQ(only({2.0, apex, 0.0, 1.0, Vec2(0.0, 0.0)}, mode), "G1-inside");
    EXPECT_EQ(only({2.0, Vec2(1.0, 0.0), 0.5, 1.5, Vec2(1.0, -1.0)}, mode), "zero-area-face");
  }
  // s moved off the line through b0 and v1 by a sine of 0.5 ε: G2 with the tolerance, ambiguous
  // for exact geometry; by 2 ε: inside the wedge for both.
  const Vec2 s(0.0, -1.0), normal = Vec2(1.0, -0.5).normalized();
  const double len = std::sqrt(1.25);
  EXPECT_EQ(only({2.0, apex, 0.5, 1.5, s + 0.5 * tol::kCollinearSin * len * normal},
                 ExactMode::Tolerance),
            "G2");
  EXPECT_EQ(only({2.0, apex, 0.5, 1.5, s + 0.5 * tol::kCollinearSin * len * normal},
                 ExactMode::ExactSign),
            "{G2, inside-wedge}");
  EXPECT_EQ(only({2.0, apex, 0.5, 1.5, s + 2.0 * tol::kCollinearSin * len * normal},
                 ExactMode::ExactSign),
            "inside-wedge");
}

// ===  Decisions do not depend on the scale =======================================================
//
// Scaling by a power of two scales every floating-point operation exactly, so the leaf and the
// children's parameters must be bit-identical. Scaling by 1e-6 or 1e+6 rounds the inputs once;
// the leaf must stay the same wherever exact predicates decide the case before and after alike.
GEODEX_RC_GTEST_PROP(Fig6, DecisionsAreScaleInvariant, kLocalPropertyWeight, ()) {
  const LocalCase c = *gen::localCase();
  RC_TAG(name(c.target), name(c.nearness), c.mirrored ? "mirrored" : "as made");
  const bool powerOfTwo = *rc::gen::arbitrary<bool>();
  const double factor =
      powerOfTwo ? std::ldexp(1.0, *gen::uniformInt(-20, 21)) : *rc::gen::element(1e-6, 1e6);
  LocalWindow scaled = c.window;
  scaled.edgeLength *= factor;
  scaled.apex *= factor;
  scaled.b0 *= factor;
  scaled.b1 *= factor;
  scaled.source *= factor;
  scaled.b1 = std::min(scaled.b1, scaled.edgeLength);
  const LocalPropagation a = propagateLocal(c.window), b = propagateLocal(scaled);
  recordLocal(a.branch);
  if (powerOfTwo) {
    bool same = a.branch == b.branch && a.numChildren == b.numChildren;
    for (int i = 0; same && i < a.numChildren; ++i) {
      same = a.children[i].edge == b.children[i].edge && a.children[i].t0 == b.children[i].t0 &&
             a.children[i].t1 == b.children[i].t1;
    }
    if (!same)
      RC_FAIL("scaled by " + std::to_string(factor) + ": " + describe(a) + " became " +
              describe(b));
    return;
  }
  // Rounding the scaled inputs moves the configuration by an ulp; where that changes what exact
  // predicates decide (a tolerance band, or a needle whose apex lands exactly on v2), the leaf
  // must follow the scaled configuration (Fig6.BranchMatchesExactlyEvaluatedPredicates).
  const auto before = exactFig6Branches(c.window, ExactMode::Tolerance);
  const auto after = exactFig6Branches(scaled, ExactMode::Tolerance);
  const bool sameCase = before.size() == 1 && before == after;
  RC_CLASSIFY(!sameCase, "rounding moved the case");
  if (!contains(after, b.branch)) {
    RC_FAIL("scaled by " + std::to_string(factor) + ": " + describe(b) +
            " but the scaled case's exact leaves are " + describe(after));
  }
  if (sameCase && a.branch != b.branch) {
    RC_FAIL("scaled by " + std::to_string(factor) + ": " + describe(a) + " became " + describe(b));
  }
}

}  // namespace
}  // namespace geodex::proptest
