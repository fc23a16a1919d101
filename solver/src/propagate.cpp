#include "geodex/propagate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geodex/predicates.h"
#include "geodex/tolerance.h"

namespace geodex {

std::string_view name(Fig6Branch b) {
  switch (b) {
    case Fig6Branch::ZeroAreaFace: return "zero-area-face";
    case Fig6Branch::G1Inside: return "G1-inside";
    case Fig6Branch::G1Outside: return "G1-outside";
    case Fig6Branch::G2: return "G2";
    case Fig6Branch::G4: return "G4";
    case Fig6Branch::G3: return "G3";
    case Fig6Branch::G5: return "G5";
    case Fig6Branch::LeftOfWedge: return "left-of-wedge";
    case Fig6Branch::RightOfWedge: return "right-of-wedge";
    case Fig6Branch::InsideWedge: return "inside-wedge";
  }
  return "?";
}

std::optional<DegeneracyKind> degeneracyOf(Fig6Branch b) {
  switch (b) {
    case Fig6Branch::G1Inside:
    case Fig6Branch::G1Outside: return DegeneracyKind::G1;
    case Fig6Branch::G2: return DegeneracyKind::G2;
    case Fig6Branch::G3: return DegeneracyKind::G3;
    case Fig6Branch::G4: return DegeneracyKind::G4;
    case Fig6Branch::G5: return DegeneracyKind::G5;
    default: return std::nullopt;
  }
}

double localScale(const LocalWindow& w) {
  const Vec2 v2(w.edgeLength, 0.0);
  return std::sqrt(std::max({w.edgeLength * w.edgeLength, w.apex.squaredNorm(),
                             (w.apex - v2).squaredNorm()}));
}

namespace {

void addChild(LocalPropagation& r, std::uint8_t edge, double t0, double t1) {
  if (t0 > t1) std::swap(t0, t1);
  if (t1 <= t0) return;
  r.children[r.numChildren++] = {edge, t0, t1};
}

// A zero-area face: v1 lies on the line of e0, so e1 and e2 lie on it too. A ray from s crosses
// that common line once, inside [b0, b1], and enters whichever of e1, e2 covers the crossing:
// the window passes straight through, clipped to each edge's extent on the line.
LocalPropagation passThroughZeroAreaFace(const LocalWindow& w) {
  LocalPropagation r{Fig6Branch::ZeroAreaFace};
  const double px = w.apex.x(), L = w.edgeLength;
  // e1 runs from v0 (x = 0) to v1 (x = px): t = x / px.
  if (px != 0.0) {
    const double lo = std::max(w.b0, std::min(0.0, px)), hi = std::min(w.b1, std::max(0.0, px));
    if (hi > lo) addChild(r, 1, std::clamp(lo / px, 0.0, 1.0), std::clamp(hi / px, 0.0, 1.0));
  }
  // e2 runs from v1 (x = px) to v2 (x = L): t = (x − px) / (L − px).
  if (L != px) {
    const double d = L - px;
    const double lo = std::max(w.b0, std::min(px, L)), hi = std::min(w.b1, std::max(px, L));
    if (hi > lo) {
      addChild(r, 2, std::clamp((lo - px) / d, 0.0, 1.0), std::clamp((hi - px) / d, 0.0, 1.0));
    }
  }
  return r;
}

// Where the ray from s through q, beyond q, crosses the line of segment a→b: the parameter t on
// the segment if that crossing is on it, else no value. (rayHitsSegment clamps; this is for the
// extra child of an ambiguous branch, where a crossing off the segment means no child.)
// Measured from q, not from s: the same line, but q − a is a face-sized vector where s − a is as
// long as the source is far, and its cross product with the ray then cancels down to rounding.
// From s, a window end nearer v0 than the ulp of a far source's ray direction crosses e1 exactly
// at q, not beyond it, and a G2 needle's e1 — which every ray of the window crosses — gets
// nothing (corpus/fuzz_propagation/regress/coverage-G2-needle-e1-lost-window-end-below-far-
// source-resolution).
std::optional<double> forwardHit(const Vec2& s, const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 d = q - s;
  const Vec2 e = b - a;
  const double denom = pred::cross(e, d);
  if (denom == 0.0) return std::nullopt;
  const double t = pred::cross(q - a, d) / denom;
  const double beyond = pred::cross(q - a, e) / denom;  // q + beyond·d is on the line
  if (!(beyond > 0.0) || !(t >= 0.0 && t <= 1.0)) return std::nullopt;
  return t;
}

}  // namespace

LocalWindow atUnitScale(const LocalWindow& w) {
  const double size = std::max({w.edgeLength, std::abs(w.apex.x()), std::abs(w.apex.y())});
  if (!(size > 0.0 && size < std::numeric_limits<double>::infinity())) return w;
  const double k = std::ldexp(1.0, -std::ilogb(size));
  return {w.edgeLength * k, w.apex * k, w.b0 * k, w.b1 * k, w.source * k};
}

namespace {

// Whether the Fig. 6 tree must see w at unit scale first: its size, as atUnitScale measures it
// (max(|e0|, |apex.x|, |apex.y|)), is finite and outside [2^-100, 2^100]; atUnitScale puts it in
// [1, 2). (Edge length first: it is the size, nearly always in range.)
bool farFromUnitSize(const LocalWindow& w) {
  constexpr double kLow = 0x1p-100, kHigh = 0x1p100;
  const double ax = std::abs(w.apex.x()), ay = std::abs(w.apex.y());
  const bool inBand =
      (w.edgeLength >= kLow || ax >= kLow || ay >= kLow) && w.edgeLength <= kHigh && ax <= kHigh && ay <= kHigh;
  if (inBand) return false;
  const double size = std::max({w.edgeLength, ax, ay});
  return size > 0.0 && size < std::numeric_limits<double>::infinity();
}

}  // namespace

namespace {

// Cases (1b)–(6) of the tree: s clear of e0's line, or a hair below it outside the window.
LocalPropagation throughWedge(const LocalWindow& w, double scale) {
  using pred::Side;
  const Vec2 v0(0.0, 0.0), v2(w.edgeLength, 0.0), v1 = w.apex, s = w.source;
  const Vec2 b0(w.b0, 0.0), b1(w.b1, 0.0);
  const double coincide = tol::kCoincideRel * scale;
  const double tiny = tol::kTinyIntervalRel * scale;
  const bool b0IsV0 = w.b0 <= coincide;
  const bool b1IsV2 = w.edgeLength - w.b1 <= coincide;
  // Where the boundary rays leave through e1 and e2. A ray through a corner of the face leaves
  // exactly there: the ray through b0 = v0 meets e1 at its start, the one through b1 = v2 meets
  // e2 at its end, whatever its angle. Computed, that crossing is ill-conditioned when the ray
  // grazes the edge (error ≈ rounding / angle): along a line of grid edges through a flat vertex
  // it falls short of the vertex, and a far window claims the stretch
  // (corpus/fuzz_solver/regress/upper-bound-face-source-2e-11-from-flat-vertex).
  const auto b0OnE1 = [&] { return b0IsV0 ? 0.0 : pred::rayHitsSegment(s, b0, v0, v1); };
  const auto b1OnE2 = [&] { return b1IsV2 ? 1.0 : pred::rayHitsSegment(s, b1, v1, v2); };

  // (1b) v1 collinear with a boundary ray but *behind* it: between s and the window, not beyond
  //     it. "Collinear" is an angle, and a needle seen end-on from far away is collinear with
  //     everything; but rays that have passed the window head away from v1, so none of G2–G5
  //     applies: the whole wedge leaves through the edge on its side of travel (e1 heading
  //     towards v0, e2 towards v2), as in (4)/(5). Taken as G4, the needle's e1 would go whole
  //     to a source beyond its apex, and the apex would come out short of its distance
  //     (corpus/fuzz_two_faces/regress/two-face-distance-needle-apex-between-far-source-and-window).
  const Side sideB0 = pred::sideOfRay(s, b0, v1);
  const Side sideB1 = pred::sideOfRay(s, b1, v1);
  if ((sideB0 == Side::Collinear && (v1 - b0).dot(b0 - s) < 0.0) ||
      (sideB1 == Side::Collinear && (v1 - b1).dot(b1 - s) < 0.0)) {
    if (b1.x() - s.x() < 0.0) {  // travelling towards v0
      LocalPropagation r{Fig6Branch::RightOfWedge};
      addChild(r, 1, b0OnE1(), pred::rayHitsSegment(s, b1, v0, v1));
      return r;
    }
    LocalPropagation r{Fig6Branch::LeftOfWedge};
    addChild(r, 2, pred::rayHitsSegment(s, b0, v1, v2), b1OnE2());
    return r;
  }

  // (2) s, b0, v1 collinear: the left ray hits v1, so the wedge passes right of v1 onto e2 (G2)
  //     — and when b0 = v0 too, the ray runs along e1 and e1 gets the whole edge (G4).
  //     "Collinear" is up to kCollinearSin: the ray may really pass a hair left of v1 and cross e1
  //     first. Near v1 that is a sliver step 3 removes; but where the face is a needle the rays
  //     graze, e1 lies inside that angle along most of its length and the ray leaves through e1
  //     far from v1 (corpus/fuzz_predicates/regress/coverage-G2-needle-face-grazing-window-lost).
  //     So e1 also gets what the ray would cross if it passed left of v1: from there to v1. It is
  //     all within kCollinearSin of the ray, where any path's length differs from the straight
  //     one's by far less than the tolerances (a bend by an angle α changes a length by ~α²/2).
  if (sideB0 == Side::Collinear) {
    LocalPropagation r{b0IsV0 ? Fig6Branch::G4 : Fig6Branch::G2};
    addChild(r, 2, 0.0, b1OnE2());
    if (b0IsV0) {
      addChild(r, 1, 0.0, 1.0);
    } else if (const auto t = forwardHit(s, b0, v0, v1); t && (1.0 - *t) * v1.norm() > tiny) {
      addChild(r, 1, *t, 1.0);  // (only when longer than D1's ε: a sliver would just be removed)
    }
    return r;
  }
  // (3) s, b1, v1 collinear: the mirror image (G3, and G5 when b1 = v2; e2 gets, from v1, what
  //     the ray through b1 would cross if it passed a hair right of v1).
  if (sideB1 == Side::Collinear) {
    LocalPropagation r{b1IsV2 ? Fig6Branch::G5 : Fig6Branch::G3};
    addChild(r, 1, b0OnE1(), 1.0);
    if (b1IsV2) {
      addChild(r, 2, 0.0, 1.0);
    } else if (const auto t = forwardHit(s, b1, v1, v2); t && *t * (v2 - v1).norm() > tiny) {
      addChild(r, 2, 0.0, *t);
    }
    return r;
  }
  // (4) v1 left of the ray s→b0: the whole wedge passes right of v1, onto e2 (Fig. 3a).
  if (sideB0 == Side::Left) {
    LocalPropagation r{Fig6Branch::LeftOfWedge};
    addChild(r, 2, pred::rayHitsSegment(s, b0, v1, v2), b1OnE2());
    return r;
  }
  // (5) v1 right of the ray s→b1: the whole wedge passes left of v1, onto e1.
  if (sideB1 == Side::Right) {
    LocalPropagation r{Fig6Branch::RightOfWedge};
    addChild(r, 1, b0OnE1(), pred::rayHitsSegment(s, b1, v0, v1));
    return r;
  }
  // (6) v1 strictly inside the wedge: e1 up to v1, e2 from v1 (Fig. 3b).
  LocalPropagation r{Fig6Branch::InsideWedge};
  addChild(r, 1, b0OnE1(), 1.0);
  addChild(r, 2, 0.0, b1OnE2());
  return r;
}

}  // namespace

LocalPropagation propagateLocal(const LocalWindow& w) {
  // A face far from unit size is decided at unit scale (atUnitScale), so that the collinearity
  // tests' products of four lengths (sideOfRay) neither under- nor overflow: at 1e-106 they
  // underflow, and the tree decides G2 where the exact one says G3 (corpus/fuzz_propagation/
  // regress/exact-predicates-face-at-1e-106-fourth-powers-underflow). Inside the band the
  // configuration is used as it is: scaling by a power of two commutes with every operation here
  // (the square roots are of squares) while no product leaves the normal range, so either way
  // gives the same bits unless a value is 2^100 times smaller than the face — far below anything
  // the solver keeps (D1). atUnitScale lands in the band, so this recurses once at most.
#ifndef GEODEX_NO_MESH_UNITS  // (defined in a bench-only build: solver/CMakeLists.txt)
  if (farFromUnitSize(w)) [[unlikely]] return propagateLocal(atUnitScale(w));
#endif
  const Vec2 s = w.source;
  const double scale = localScale(w);
  const double coincide = tol::kCoincideRel * scale;

  if (w.apex.y() <= tol::kFlatFaceRel * scale) return passThroughZeroAreaFace(w);

  // (1) G1: s on the line of e0. Within the window (s = b0, s = b1, or between after a merge)
  //     every point of the face is seen straight from s: e1 and e2 whole.
  if (std::abs(s.y()) <= coincide) {
    if (s.x() >= w.b0 - coincide && s.x() <= w.b1 + coincide) {
      LocalPropagation r{Fig6Branch::G1Inside};
      addChild(r, 1, 0.0, 1.0);
      addChild(r, 2, 0.0, 1.0);
      return r;
    }
    // Outside it, exactly on the line, the rays run along e0 and none enters the face. A hair
    // below it they enter at a grazing angle, and where a flat vertex on the line lets nothing
    // else reach the sliver they cross, it is theirs alone (corpus/fuzz_solver/regress/vertex-
    // agreement-g1-outside-grazing-rays-dropped-beyond-a-flat-vertex). The wedge's own branches
    // give those children when they find the wedge clearly beside the apex, leaving through the
    // edge ahead (e2 travelling towards v2, e1 towards v0). Any other verdict is the tree's
    // collinearity tests failing on rays along e0, which in a needle face hand whole edges to a
    // source whose rays reach neither (corpus/fuzz_predicates/regress/soundness-g1-outside-rays-
    // along-a-needle-given-both-edges-whole).
    if (s.y() == 0.0) return {Fig6Branch::G1Outside};
    LocalPropagation r = throughWedge(w, scale);
    const bool towardsV2 = s.x() < w.b0;
    if (r.branch != (towardsV2 ? Fig6Branch::LeftOfWedge : Fig6Branch::RightOfWedge)) r.numChildren = 0;
    r.branch = Fig6Branch::G1Outside;
    return r;
  }
  return throughWedge(w, scale);
}

// ===  From a LocalChild to an Interval on the child edge =======================================

bool childEdgesOnOneLine(const LocalWindow& w) {
  return w.apex.y() <= tol::kFlatFaceRel * std::max(w.edgeLength, w.apex.norm());
}

ChildInterval childInterval(const LocalWindow& w, const LocalChild& c, const ChildEdge& e, bool oneLine) {
  // e1 = v0→v1, e2 = v1→v2 in the face frame; the child edge's own frame starts at its vertex[0].
  const Vec2 v0(0.0, 0.0), v1 = w.apex, v2(w.edgeLength, 0.0);
  const bool onE1 = c.edge == 1;
  const Vec2 A = onE1 ? v0 : v1;
  const Vec2 B = onE1 ? v1 : v2;
  const Vec2 origin = e.forward ? A : B;
  const Vec2 dir = (e.forward ? B - A : A - B).normalized();
  const Vec2 rel = w.source - origin;
  const double h = pred::cross(dir, rel);  // > 0: the source is left of the directed child edge

  ChildInterval r;
  Interval& n = r.interval;
  n.b0 = (e.forward ? c.t0 : 1.0 - c.t1) * e.length;
  n.b1 = (e.forward ? c.t1 : 1.0 - c.t0) * e.length;
  n.b0 = std::clamp(n.b0, 0.0, e.length);
  n.b1 = std::clamp(n.b1, 0.0, e.length);
  if (!(n.b1 > n.b0)) return r;
  // The source lies on the crossed face's side of the new edge (the rays leave the face through
  // it); rounding can put it a hair across, which is a source on the line. Clearly across, the
  // rays cannot leave through that edge at all, and the child is dropped (and counted by the
  // solver): clamped onto the line, such a source would stand beside a corner it is really far
  // from (corpus/fuzz_two_faces/regress/two-face-distance-needle-seen-end-on-from-far-source).
  // Fig. 6's case (1b) decides that needle itself; this is the safety net for any other
  // ε-decision that names an edge the wedge cannot reach. Through a zero-area face "across" has
  // no meaning: the source's distance from the common line is its height.
  // The face lies right of e1 (v0→v1) and of e2 (v1→v2): v1 is above e0, so v0, v1, v2 turn
  // clockwise. Taken from the edge's direction, not from a cross product with the third vertex:
  // for a needle seen from its far end that cross product is below its own rounding, can put v2
  // on the wrong side of a backward e1, and then drops the only child of a source well inside
  // the face (corpus/fuzz_propagation/regress/coverage-child-dropped-interior-side-of-backward-
  // e1-taken-from-far-apex).
  const double inward = e.forward ? -h : h;
  if (!oneLine && inward < 0.0 &&
      -inward > std::max(tol::kCoincideRel * localScale(w), tol::kCollinearSin * rel.norm())) {
    r.outcome = ChildOutcome::SeenFromOutside;
    return r;
  }
  n.source = Vec2(rel.dot(dir), oneLine ? std::abs(h) : std::max(0.0, inward));
  r.outcome = ChildOutcome::Made;
  return r;
}

}  // namespace geodex
