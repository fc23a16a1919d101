// The Fig. 6 decision tree on hand-made local configurations. Expected ranges are worked out by
// hand (ray/segment intersections with small rational answers), not by the code under test.
#include "geodex/propagate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geodex/predicates.h"

namespace geodex {
namespace {

// v0 = (0,0), v2 = (2,0), v1 = (1,1) unless said otherwise.
LocalWindow window(double b0, double b1, Vec2 source, Vec2 apex = Vec2(1.0, 1.0), double L = 2.0) {
  return {L, apex, b0, b1, source};
}

void expectChild(const LocalPropagation& r, int k, int edge, double t0, double t1) {
  ASSERT_LT(k, r.numChildren);
  EXPECT_EQ(r.children[k].edge, edge);
  EXPECT_NEAR(r.children[k].t0, t0, 1e-14);
  EXPECT_NEAR(r.children[k].t1, t1, 1e-14);
}

// Where the ray s→q meets the segment a–b, as a parameter along it. The boundary rays of the
// Fig. 6 branches cross the edges they are asked about; a ray parallel to the segment has no
// crossing, and gets the segment's middle rather than an end or a NaN (the documented answer).
TEST(RayHitsSegment, ACrossingIsItsParameterAndAParallelRayGetsTheMiddle) {
  const Vec2 s(0.0, -1.0), q(0.0, 0.0);  // up the y axis
  EXPECT_DOUBLE_EQ(pred::rayHitsSegment(s, q, Vec2(-1.0, 1.0), Vec2(3.0, 1.0)), 0.25);
  EXPECT_DOUBLE_EQ(pred::rayHitsSegment(s, q, Vec2(1.0, 0.0), Vec2(1.0, 2.0)), 0.5);
  EXPECT_DOUBLE_EQ(pred::rayHitsSegment(s, q, Vec2(-1.0, 2.0), Vec2(-1.0, 0.0)), 0.5);
}

TEST(Fig6, InsideWedgeGivesBothEdges) {
  // Rays from (1,-1) through (0.5,0) and (1.5,0) meet e1 at t = 1/3 and e2 at t = 2/3.
  const auto r = propagateLocal(window(0.5, 1.5, Vec2(1.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::InsideWedge);
  ASSERT_EQ(r.numChildren, 2);
  expectChild(r, 0, 1, 1.0 / 3.0, 1.0);
  expectChild(r, 1, 2, 0.0, 2.0 / 3.0);
}

TEST(Fig6, ApexLeftOfWedgeGivesE2Only) {
  // Source (1,-1), window [1.2, 1.6]: both rays pass right of v1 = (1,1) and hit e2 (v1→v2,
  // points (1+t, 1-t)): through (1.2,0): (1+0.2u, -1+u) → u = 5/3, t = 1/3;
  // through (1.6,0): (1+0.6u, -1+u) → u = 1.25, t = 0.75.
  const auto r = propagateLocal(window(1.2, 1.6, Vec2(1.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::LeftOfWedge);
  ASSERT_EQ(r.numChildren, 1);
  expectChild(r, 0, 2, 1.0 / 3.0, 0.75);
}

TEST(Fig6, ApexRightOfWedgeGivesE1Only) {
  // The mirror image of the previous case.
  const auto r = propagateLocal(window(0.4, 0.8, Vec2(1.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::RightOfWedge);
  ASSERT_EQ(r.numChildren, 1);
  expectChild(r, 0, 1, 0.25, 2.0 / 3.0);
}

TEST(Fig6, G1SourceOnEdgeInsideWindowGivesWholeEdges) {
  const auto r = propagateLocal(window(0.5, 1.5, Vec2(0.5, 0.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G1Inside);
  EXPECT_EQ(degeneracyOf(r.branch), DegeneracyKind::G1);
  ASSERT_EQ(r.numChildren, 2);
  expectChild(r, 0, 1, 0.0, 1.0);
  expectChild(r, 1, 2, 0.0, 1.0);
}

TEST(Fig6, G1SourceOnEdgeLineOutsideWindowPropagatesNothing) {
  const auto r = propagateLocal(window(0.5, 1.5, Vec2(-1.0, 0.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G1Outside);
  EXPECT_EQ(r.numChildren, 0);
}

// A hair below e0's line, behind v0: the rays enter the face at a grazing angle and leave
// through e2 beside v2. The ray through b0 = v0, direction (1, 1e-12), meets e2 (points
// (1+t, 1-t)) where x + y = 2: x = 2 / (1 + 1e-12), t = x − 1 ≈ 1 − 2e-12; the one through b1 = v2
// leaves at v2 itself. (corpus/fuzz_solver/regress/vertex-agreement-g1-outside-grazing-rays-
// dropped-beyond-a-flat-vertex: nothing else reached that sliver.)
TEST(Fig6, G1SourceAHairOffTheLineBehindV0GivesTheSliverBesideV2) {
  const auto r = propagateLocal(window(0.0, 2.0, Vec2(-1.0, -1e-12)));
  EXPECT_EQ(r.branch, Fig6Branch::G1Outside);
  ASSERT_EQ(r.numChildren, 1);
  expectChild(r, 0, 2, 1.0 - 2e-12, 1.0);
}

// The mirror image: behind v2, the rays leave through e1 beside v0, up to t ≈ 2e-12.
TEST(Fig6, G1SourceAHairOffTheLineBeyondV2GivesTheSliverBesideV0) {
  const auto r = propagateLocal(window(0.0, 2.0, Vec2(3.0, -1e-12)));
  EXPECT_EQ(r.branch, Fig6Branch::G1Outside);
  ASSERT_EQ(r.numChildren, 1);
  expectChild(r, 0, 1, 0.0, 2e-12);
}

// A needle whose apex (−14, 8e-11) sits beside e0's line, the source 1.6e-11 below it and beyond
// the window [0, 2]: the rays run along e0 towards v0, within the collinearity tolerance of
// every corner, and the wedge's branches have no clear verdict. Nothing is propagated, as
// exactly on the line: whole edges would claim points no ray of the window reaches.
TEST(Fig6, G1SourceAHairOffTheLineOfANeedleGivesNoWholeEdges) {
  const auto r = propagateLocal(window(0.0, 2.0, Vec2(7.00000000024, -1.6e-11), Vec2(-14.0, 8e-11), 8.0));
  EXPECT_EQ(r.branch, Fig6Branch::G1Outside);
  EXPECT_EQ(r.numChildren, 0);
}

TEST(Fig6, G2LeftRayThroughApex) {
  // s = (0,-1), b0 = (0.5,0), v1 = (1,1) collinear. The right ray through (1.5,0) meets e2 at
  // (1.5u, -1+u) = (1+t, 1-t) → t = 0.8.
  const auto r = propagateLocal(window(0.5, 1.5, Vec2(0.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G2);
  ASSERT_EQ(r.numChildren, 1);
  expectChild(r, 0, 2, 0.0, 0.8);
}

TEST(Fig6, G3RightRayThroughApex) {
  // Mirror of G2: s = (2,-1), b1 = (1.5,0), v1 collinear; the left ray through (0.5,0) meets e1
  // at t = 0.2.
  const auto r = propagateLocal(window(0.5, 1.5, Vec2(2.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G3);
  ASSERT_EQ(r.numChildren, 1);
  expectChild(r, 0, 1, 0.2, 1.0);
}

TEST(Fig6, G4SourceV0ApexCollinear) {
  // s = (-1,-1), b0 = v0, v1 = (1,1): the left ray runs along e1, which gets the whole edge; the
  // right ray through (1,0): (-1+2u, -1+u) = (1+t, 1-t) → t = 2/3 on e2.
  const auto r = propagateLocal(window(0.0, 1.0, Vec2(-1.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G4);
  EXPECT_EQ(degeneracyOf(r.branch), DegeneracyKind::G4);
  ASSERT_EQ(r.numChildren, 2);
  expectChild(r, 0, 2, 0.0, 2.0 / 3.0);
  expectChild(r, 1, 1, 0.0, 1.0);
}

TEST(Fig6, G5SourceV2ApexCollinear) {
  const auto r = propagateLocal(window(1.0, 2.0, Vec2(3.0, -1.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G5);
  ASSERT_EQ(r.numChildren, 2);
  expectChild(r, 0, 1, 1.0 / 3.0, 1.0);
  expectChild(r, 1, 2, 0.0, 1.0);
}

TEST(Fig6, CompositeSourceAtB0AtV0IsDecidedAsG1) {
  // s = b0 = v0 is G1, G2 and G4 at once; the tree's order decides G1.
  const auto r = propagateLocal(window(0.0, 1.0, Vec2(0.0, 0.0)));
  EXPECT_EQ(r.branch, Fig6Branch::G1Inside);
}

TEST(Fig6, ZeroAreaFacePassesThrough) {
  // v1 = (1,0) on e0's line: [0.5, 1.5] splits into e1's t in [0.5, 1] and e2's t in [0, 0.5].
  const auto r = propagateLocal(window(0.5, 1.5, Vec2(1.0, -1.0), Vec2(1.0, 0.0)));
  EXPECT_EQ(r.branch, Fig6Branch::ZeroAreaFace);
  ASSERT_EQ(r.numChildren, 2);
  expectChild(r, 0, 1, 0.5, 1.0);
  expectChild(r, 1, 2, 0.0, 0.5);
}

TEST(Fig6, G2InANeedleFaceCoversWhereTheGrazingRaysLeave) {
  // Regression (corpus/fuzz_predicates/regress/coverage-G2-needle-face-grazing-window-lost): a
  // needle face (apex (-6, 8e-11) over e0 = [0, 8]) seen by rays that graze it, from a source
  // far right and 1.6e-10 below. The whole face lies within kCollinearSin of the ray through
  // b0 = 2, so Fig. 6 says G2, which used to give e1 nothing; but that ray leaves the face
  // through e1: (2, 0) + m (-22, 1.6e-10) = t (-6, 8e-11) gives m = t / 2, -6t = 2 - 11t, t = 0.4.
  const auto r = propagateLocal(window(2.0, 3.0, Vec2(24.0, -1.6e-10), Vec2(-6.0, 8e-11), 8.0));
  EXPECT_EQ(r.branch, Fig6Branch::G2);
  bool covered = false;
  for (int k = 0; k < r.numChildren; ++k)
    covered = covered || (r.children[k].edge == 1 && r.children[k].t0 <= 0.4 + 1e-9 &&
                          r.children[k].t1 >= 0.4);
  EXPECT_TRUE(covered) << "no child on e1 covers t = 0.4";
}

TEST(Fig6, NearCollinearWithinToleranceIsG2AndBeyondIsNot) {
  // Nudge s off the line through b0 and v1 perpendicular to it by δ: a sine of δ/|s-b0|.
  const Vec2 s(0.0, -1.0);
  const Vec2 normal = Vec2(1.0, -0.5).normalized();  // perpendicular to (0.5, 1)
  const double len = std::sqrt(1.25);
  EXPECT_EQ(propagateLocal(window(0.5, 1.5, s + 1e-13 * len * normal)).branch, Fig6Branch::G2);
  // Moving s towards +x tilts the ray s→b0 to the left of v1: v1 is then inside the wedge.
  EXPECT_EQ(propagateLocal(window(0.5, 1.5, s + 1e-6 * len * normal)).branch, Fig6Branch::InsideWedge);
  EXPECT_EQ(propagateLocal(window(0.5, 1.5, s - 1e-6 * len * normal)).branch, Fig6Branch::LeftOfWedge);
}

// Collinear means a sine below 1e-11 (tolerance.h, kCollinearSin), on both mirrored rays: a source
// a tenth of that off the line through a window end and the apex is G2 (G3), one ten times it is
// on a side. Written out, not read from the tolerance, so that moving it is seen; a wider
// "collinear" bends rays through the apex that pass beside it.
TEST(Fig6, TheRaysThroughEitherWindowEndAreCollinearWithTheApexToASineOf1eMinus11) {
  // G2's ray: s = (0,-1), b0 = (0.5,0), v1 = (1,1); G3's is its mirror image in x = 1. Moved
  // along +n (a unit normal to the line), s sees the apex inside the wedge; along -n, beside it.
  const Vec2 sG2(0.0, -1.0), sG3(2.0, -1.0);
  const Vec2 nG2 = Vec2(1.0, -0.5).normalized(), nG3 = Vec2(-1.0, -0.5).normalized();
  const double len = std::sqrt(1.25);  // |s - b| = |v1 - b|: an offset δ len is a sine of δ
  for (const double sine : {1e-12, 1e-10}) {
    SCOPED_TRACE(sine);
    const bool collinear = sine < 1e-11;
    EXPECT_EQ(propagateLocal(window(0.5, 1.5, sG2 + sine * len * nG2)).branch,
              collinear ? Fig6Branch::G2 : Fig6Branch::InsideWedge);
    EXPECT_EQ(propagateLocal(window(0.5, 1.5, sG2 - sine * len * nG2)).branch,
              collinear ? Fig6Branch::G2 : Fig6Branch::LeftOfWedge);
    EXPECT_EQ(propagateLocal(window(0.5, 1.5, sG3 + sine * len * nG3)).branch,
              collinear ? Fig6Branch::G3 : Fig6Branch::InsideWedge);
    EXPECT_EQ(propagateLocal(window(0.5, 1.5, sG3 - sine * len * nG3)).branch,
              collinear ? Fig6Branch::G3 : Fig6Branch::RightOfWedge);
  }
}

TEST(Fig6, DecisionsAreScaleInvariant) {
  const LocalWindow base = window(0.5, 1.5, Vec2(0.0, -1.0));
  for (double scale : {1e-6, 1e6}) {
    LocalWindow w = base;
    w.edgeLength *= scale;
    w.apex *= scale;
    w.b0 *= scale;
    w.b1 *= scale;
    w.source *= scale;
    const auto r = propagateLocal(w);
    EXPECT_EQ(r.branch, Fig6Branch::G2) << "scale " << scale;
    ASSERT_EQ(r.numChildren, 1);
    EXPECT_NEAR(r.children[0].t1, 0.8, 1e-12);
  }
}

// Every power-of-two scale a double holds gives the same leaf and the same children, bit for bit:
// the children are parameters along e1 and e2, and the tree's products of four lengths must
// neither under- nor overflow on the way.
TEST(Fig6, DecisionsAreTheSameBitForBitAtEveryPowerOfTwoScale) {
  const LocalWindow cases[] = {
      window(0.5, 1.5, Vec2(0.0, -1.0)),                                 // G2
      window(0.5, 1.5, Vec2(1.0, -1.0)),                                 // inside the wedge
      window(0.0, 2.0, Vec2(-1.0, -1.0)),                                // G4
      window(1.2, 1.6, Vec2(1.0, -1.0)),                                 // left of the wedge
      window(0.3, 1.9, Vec2(1.0, -1e-8), Vec2(1.0, 1e-7)),               // a flat cap
      window(0.1, 0.2, Vec2(-3e6, -2e6), Vec2(1e-3, 2e-3), 3e-3),        // a far source
  };
  for (const LocalWindow& base : cases) {
    const LocalPropagation want = propagateLocal(base);
    for (int k = -1000; k <= 1000; k += 37) {
      const double f = std::ldexp(1.0, k);
      const LocalWindow w{base.edgeLength * f, base.apex * f, base.b0 * f, base.b1 * f, base.source * f};
      // Outside the normal range the scaled configuration is not the same one. (Each number is
      // tested on its own: a norm here could overflow, which debug test runs trap.)
      const auto same = [](double x) { return x == 0.0 || std::isnormal(x); };
      if (!same(w.edgeLength) || !same(w.b0) || !same(w.b1) || !same(w.source.x()) ||
          !same(w.source.y()) || !same(w.apex.x()) || !same(w.apex.y()))
        continue;
      const LocalPropagation got = propagateLocal(w);
      EXPECT_EQ(got.branch, want.branch) << "2^" << k;
      ASSERT_EQ(got.numChildren, want.numChildren) << "2^" << k;
      for (int c = 0; c < got.numChildren; ++c) {
        EXPECT_EQ(got.children[c].edge, want.children[c].edge) << "2^" << k;
        EXPECT_EQ(got.children[c].t0, want.children[c].t0) << "2^" << k;
        EXPECT_EQ(got.children[c].t1, want.children[c].t1) << "2^" << k;
      }
    }
  }
}

// A face 4.4e-106 across, found by fuzz_propagation: the collinearity test's product of four
// lengths (~1e-424) underflowed to zero, so s, b0 and the apex read as collinear and the tree
// ended in G2 where it ends in G3 (the right ray passes through the apex). The same face at unit
// scale decides G3 (corpus/fuzz_propagation/regress/exact-predicates-face-at-1e-106-fourth-
// powers-underflow).
TEST(Fig6Regression, AFaceAt1eMinus106DecidesAsAtUnitScale) {
  const double L = 6.1722061676239887e-106;
  const LocalWindow tiny{L, Vec2(3.0861030838119938e-106, 3.0861030838119938e-106),
                         3.9502119472793527e-115, 3.8576288547649929e-107,
                         Vec2(-2.6521198376509326e-106, -3.4718659692884929e-106)};
  const double up = std::ldexp(1.0, 350);  // to about 1e-0, exactly
  const LocalWindow unit{tiny.edgeLength * up, tiny.apex * up, tiny.b0 * up, tiny.b1 * up,
                         tiny.source * up};
  const LocalPropagation want = propagateLocal(unit);
  EXPECT_EQ(want.branch, Fig6Branch::G3);
  const LocalPropagation got = propagateLocal(tiny);
  EXPECT_EQ(got.branch, Fig6Branch::G3);
  ASSERT_EQ(got.numChildren, want.numChildren);
  for (int c = 0; c < got.numChildren; ++c) {
    EXPECT_EQ(got.children[c].t0, want.children[c].t0);
    EXPECT_EQ(got.children[c].t1, want.children[c].t1);
  }
}

// ===  Far sources and long edges: crossings measured near the face ==============================

TEST(Fig6Regression, G2NeedleSeenFromFarKeepsE1WhenTheWindowEndIsBelowTheRaysResolution) {
  // corpus/fuzz_propagation/regress/coverage-G2-needle-e1-lost-window-end-below-far-source-
  // resolution: a needle (apex 1e-10 above e0, 15 along) and a window [6.4e-10, 1] seen from
  // 2.9e7 away, 2.06e-4 below e0. The rays rise at 2.06e-4 / 2.89e7 = 7.143e-12, e1 at
  // 1e-10 / 15 = 6.667e-12, so the ray through b0 crosses e1 where 7.143e-12 (x − 6.4e-10) =
  // 6.667e-12 x: x = 9.6e-9, t = x / 15 = 6.4e-10; every ray of the window crosses e1. Fig. 6
  // calls s, b0, v1 collinear (G2), and e1 gets the crossing on from there. Measured from s, the
  // crossing came out exactly at b0 (6.4e-10 is below the ulp of the ray's direction), not
  // beyond it, and e1 got nothing.
  const LocalWindow w{2.0, Vec2(15.000000000449999, 1e-10), 6.3999999999999996e-10, 1.0,
                      Vec2(-28901375.000928972, -0.00020644479999999999)};
  const LocalPropagation r = propagateLocal(w);
  EXPECT_EQ(r.branch, Fig6Branch::G2);
  ASSERT_EQ(r.numChildren, 1);
  EXPECT_EQ(r.children[0].edge, 1);
  EXPECT_NEAR(r.children[0].t0, 6.4e-10, 0.1e-10);
  EXPECT_EQ(r.children[0].t1, 1.0);
}

TEST(Fig6Regression, CrossingNearTheNearEndOfALongEdgeIsMeasuredFromThatEnd) {
  // corpus/fuzz_propagation/regress/coverage-crossing-near-v2-of-a-long-edge-measured-from-its-
  // far-end: e0 is 2.83e-10 long, the apex 6.7e7 away at almost 45°, and the whole-edge window is
  // seen from s = (−18.38478, −18.38477), also at almost 45°. The rays pass right of v1 onto e2
  // (Fig. 3a), meeting it at an angle of 45° − 3.235e-7 − (45° − 5.96e-8) = 2.64e-7 rad: the ray
  // through v0, 2.83e-10 × sin 45° = 2e-10 off e2's line at v2, meets it 2e-10 / 2.64e-7 =
  // 7.6e-4 from v2, t = 1 − 7.6e-4 / 6.71e7 = 1 − 1.13e-11. Measured from v1, 6.7e7 away, the
  // crossing was 0.03 off, past v2, and the child was empty.
  const double L = 2.8284271247461901e-10;
  const LocalWindow w{L, Vec2(47453135.640552901, 47453129.983698659), 0.0, L,
                      Vec2(-18.384782262420785, -18.384770366690944)};
  const LocalPropagation r = propagateLocal(w);
  EXPECT_EQ(r.branch, Fig6Branch::LeftOfWedge);
  ASSERT_EQ(r.numChildren, 1);
  EXPECT_EQ(r.children[0].edge, 2);
  EXPECT_NEAR(1.0 - r.children[0].t0, 1.13e-11, 0.02e-11);
  EXPECT_EQ(r.children[0].t1, 1.0);
}

// ===  childInterval: a LocalChild on its mesh edge ================================================
// The face v0 = (0,0), v2 = (2,0), v1 = (1,1) and the source s = (1,-1) below e0 unless said
// otherwise; e1 and e2 are √2 long. Expected ranges and sources are worked out by hand in the
// child edge's own frame (x from its vertex[0], y the source's distance from its line).

const double kRoot2 = std::sqrt(2.0);

TEST(ChildInterval, ChildOnE1ForwardKeepsTheSourceInTheEdgesFrame) {
  // Inside the wedge of [0.5, 1.5]: e1 from t = 1/3 (Fig6.InsideWedgeGivesBothEdges).
  const LocalWindow w = window(0.5, 1.5, Vec2(1.0, -1.0));
  const ChildInterval c = childInterval(w, {1, 1.0 / 3.0, 1.0}, {kRoot2, true}, false);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_NEAR(c.interval.b0, kRoot2 / 3.0, 1e-15);
  EXPECT_NEAR(c.interval.b1, kRoot2, 1e-15);
  // e1 runs along (1,1)/√2 from v0: s = (1,-1) projects onto x = 0 and lies √2 from the line.
  EXPECT_NEAR(c.interval.source.x(), 0.0, 1e-15);
  EXPECT_NEAR(c.interval.source.y(), kRoot2, 1e-15);
  // At v1 (x = √2) the distance is |v1 − s| = |(0, 2)| = 2.
  EXPECT_NEAR(c.interval.distanceAt(kRoot2), 2.0, 1e-15);
}

TEST(ChildInterval, ChildOnE2Forward) {
  // e2 up to t = 2/3, from v1 along (1,-1)/√2: s − v1 = (0, −2) projects onto x = √2 and lies √2
  // from the line.
  const LocalWindow w = window(0.5, 1.5, Vec2(1.0, -1.0));
  const ChildInterval c = childInterval(w, {2, 0.0, 2.0 / 3.0}, {kRoot2, true}, false);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_NEAR(c.interval.b0, 0.0, 1e-15);
  EXPECT_NEAR(c.interval.b1, 2.0 * kRoot2 / 3.0, 1e-15);
  EXPECT_NEAR(c.interval.source.x(), kRoot2, 1e-15);
  EXPECT_NEAR(c.interval.source.y(), kRoot2, 1e-15);
  EXPECT_NEAR(c.interval.distanceAt(0.0), 2.0, 1e-15);  // at v1
}

TEST(ChildInterval, BackwardChildEdgeMirrorsRangeAndSource) {
  // The same e2 child on a mesh edge running v2 → v1: the range [0, 2/3] of v1→v2 is
  // [1/3, 1] × √2 from v2, and s − v2 = (−1, −1) projects onto (−1,1)/√2 at x = 0, √2 away.
  const LocalWindow w = window(0.5, 1.5, Vec2(1.0, -1.0));
  const ChildInterval c = childInterval(w, {2, 0.0, 2.0 / 3.0}, {kRoot2, false}, false);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_NEAR(c.interval.b0, kRoot2 / 3.0, 1e-15);
  EXPECT_NEAR(c.interval.b1, kRoot2, 1e-15);
  EXPECT_NEAR(c.interval.source.x(), 0.0, 1e-15);
  EXPECT_NEAR(c.interval.source.y(), kRoot2, 1e-15);
  EXPECT_NEAR(c.interval.distanceAt(kRoot2), 2.0, 1e-15);  // at v1, now the far end
  EXPECT_NEAR(c.interval.distanceAt(0.0), kRoot2, 1e-15);  // at v2: |(2,0) − (1,−1)|
}

TEST(ChildInterval, ScalesTheRangeByTheMeshEdgesLength) {
  // The child's ends are t × the length the mesh gives, not |v0 v1| recomputed from the frame.
  const LocalWindow w = window(0.5, 1.5, Vec2(1.0, -1.0));
  const ChildInterval c = childInterval(w, {1, 0.25, 0.5}, {4.0, true}, false);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_EQ(c.interval.b0, 1.0);
  EXPECT_EQ(c.interval.b1, 2.0);
}

TEST(ChildInterval, ZeroAreaFaceTakesTheSourcesDistanceFromTheCommonLine) {
  // v1 = (1, 0) on e0's line: the window [0.5, 1.5] passes through, e1 gets x ∈ [0.5, 1], t ∈
  // [0.5, 1] of its length 1; s = (1, −1) is at x = 1 along it, 1 from the line.
  const LocalWindow w = window(0.5, 1.5, Vec2(1.0, -1.0), Vec2(1.0, 0.0));
  ASSERT_TRUE(childEdgesOnOneLine(w));
  const LocalPropagation r = propagateLocal(w);
  ASSERT_EQ(r.branch, Fig6Branch::ZeroAreaFace);
  ASSERT_EQ(r.numChildren, 2);
  const ChildInterval c = childInterval(w, r.children[0], {1.0, true}, true);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_EQ(c.interval.b0, 0.5);
  EXPECT_EQ(c.interval.b1, 1.0);
  EXPECT_EQ(c.interval.source, Vec2(1.0, 1.0));
  // e2 runs from v1 = (1, 0) to v2: s is at x = 0 along it, 1 from the line.
  const ChildInterval d = childInterval(w, r.children[1], {1.0, true}, true);
  ASSERT_EQ(d.outcome, ChildOutcome::Made);
  EXPECT_EQ(d.interval.b0, 0.0);
  EXPECT_EQ(d.interval.b1, 0.5);
  EXPECT_EQ(d.interval.source, Vec2(0.0, 1.0));
}

TEST(ChildInterval, OneLineIsTheApexWithinFlatFaceOfTheEdgesAtV0) {
  EXPECT_TRUE(childEdgesOnOneLine(window(0.5, 1.5, Vec2(1.0, -1.0), Vec2(1.0, 1e-13))));  // ≤ 1e-12 × 2
  EXPECT_FALSE(childEdgesOnOneLine(window(0.5, 1.5, Vec2(1.0, -1.0), Vec2(1.0, 1e-11))));
}

TEST(ChildInterval, SourceClearlyAcrossTheChildEdgeIsDropped) {
  // s = (−1, −0.5) lies above e1's line y = x, across it from v2: (0.5/√2 ≈ 0.35) far beyond the
  // rounding band, so the rays cannot leave the face through e1.
  const LocalWindow w = window(0.5, 1.5, Vec2(-1.0, -0.5));
  EXPECT_EQ(childInterval(w, {1, 0.0, 1.0}, {kRoot2, true}, false).outcome, ChildOutcome::SeenFromOutside);
  // In a zero-area face "across" means nothing: the same source is 1 from the common line.
  const LocalWindow flat = window(0.5, 1.5, Vec2(-1.0, -0.5), Vec2(1.0, 0.0));
  const ChildInterval c = childInterval(flat, {1, 0.0, 1.0}, {1.0, true}, true);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_EQ(c.interval.source, Vec2(-1.0, 0.5));
}

TEST(ChildInterval, SourceARoundingErrorAcrossIsPutOnTheLine) {
  // s on e1's line (y = x) moved 1e-13 across it: within max(kCoincideRel × 2, kCollinearSin ×
  // |s|), so kept, with the source on the line (height 0) at its projection −√2.
  const Vec2 s = Vec2(-1.0, -1.0) + 1e-13 * Vec2(-1.0, 1.0).normalized();
  const ChildInterval c = childInterval(window(0.5, 1.5, s), {1, 0.0, 1.0}, {kRoot2, true}, false);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_EQ(c.interval.source.y(), 0.0);
  EXPECT_NEAR(c.interval.source.x(), -kRoot2, 1e-15);
}

TEST(ChildInterval, InteriorSideComesFromTheEdgesDirectionNotFromTheFarApex) {
  // corpus/fuzz_propagation/regress/coverage-child-dropped-interior-side-of-backward-e1-taken-
  // from-far-apex: e0 is 1.9e-10 long, the apex 2.9e6 away, and the source 9.2e7 away almost on
  // e1's line behind v0. Measured at v0 (the near end), s lies (a × s)/|a| = −8.0 from e1's line,
  // a = v1: on the right, v2's side (v2 is −1.6e-10 from it), inside the face. On the mesh edge
  // running v1 → v0 the child keeps the source 8 from its line; the side of v2 taken as a cross
  // product from v1, 2.9e6 away, was below its rounding, came out on the left, and the child
  // was dropped as seen from outside.
  const double L = 1.8867962264113207e-10;
  const Vec2 apex(-1528296.4634101295, 2445274.341480948);
  const LocalWindow w{L, apex, 0.0, L, Vec2(48905493.613110587, -78248774.687398821)};
  const ChildInterval c = childInterval(w, {1, 0.0, 6.3999996489392092e-10}, {apex.norm(), false}, false);
  ASSERT_EQ(c.outcome, ChildOutcome::Made);
  EXPECT_NEAR(c.interval.source.y(), 8.0, 1e-6);
}

TEST(ChildInterval, EmptyRangeMakesNothing) {
  const LocalWindow w = window(0.5, 1.5, Vec2(1.0, -1.0));
  EXPECT_EQ(childInterval(w, {2, 0.5, 0.5}, {kRoot2, true}, false).outcome, ChildOutcome::Empty);
}

}  // namespace
}  // namespace geodex
