#pragma once
// The Fig. 6 decision tree evaluated *exactly*: every input double is converted to a GMP rational
// (exact), every predicate of Sect. 4.1 is evaluated without rounding (squared, so no square root
// is needed), and the tree's leaves are enumerated over every resolution of the predicates that
// sit too close to their threshold to be decided by a floating-point evaluation.
//
// Two modes:
//  - Tolerance: the predicates exactly as tolerance.h states them (|s − b0| < ε·scale, |sin| ≤ ε,
//    …). A predicate is *ambiguous* when its exact value is within kBand of its threshold —
//    there a correctly rounded floating-point evaluation may fall either way.
//  - ExactSign: the ideal predicates of exact geometry (coincide iff equal, collinear iff the
//    cross product is 0). A predicate is ambiguous when its value is non-zero but within
//    (1 + kBand) × ε of 0: the tolerance deliberately calls that degenerate. Outside that band
//    ("farther than ε from ambiguity") the floating-point tree must agree with exact geometry.
//
// The tree's order is the spec (DESIGN.md, "The decision order of Fig. 6"), not the code under
// test: zero-area face; (1) s on e0's line (inside or outside [b0, b1]); (2) s, b0, v1 collinear
// (G4 if b0 = v0, else G2); (3) s, b1, v1 collinear (G5 / G3); (4) v1 left of s→b0; (5) v1 right
// of s→b1; (6) inside.

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "geodex/propagate.h"
#include "geodex/tolerance.h"

namespace geodex::proptest {

enum class ExactMode { Tolerance, ExactSign };

/// Width of the ambiguity band around a threshold, relative to the threshold. The floating-point
/// predicates round by at most ~1.3e-15 × |u||v| (the cross product of two rounded differences)
/// against a threshold of 1e-11 × |u||v|, i.e. 1.3e-4 of the threshold; the coincidence and
/// zero-area tests by ~1e-15 of theirs. 1e-2 leaves a margin of 75 over the worst of them while
/// keeping the band a hundredth of the tolerance.
inline constexpr double kBand = 1e-2;

namespace exact_detail {

enum class Tri : std::uint8_t { False, True, Either };

inline mpq_class q(double x) { return mpq_class(x); }  // exact: mpq_set_d

/// v ≤ c·sqrt(s2) exactly (c ≥ 0, s2 ≥ 0).
inline bool leqScaledRoot(const mpq_class& v, const mpq_class& c, const mpq_class& s2) {
  if (sgn(v) <= 0) return true;
  return v * v <= c * c * s2;
}

/// The predicate "v ≤ eps·sqrt(s2)" (v may be signed) as tolerance.h states it (Tolerance) or as
/// exact geometry has it, "v ≤ 0" (ExactSign), with its ambiguity band.
inline Tri within(const mpq_class& v, double eps, const mpq_class& s2, ExactMode mode) {
  const mpq_class hi = q(eps) * q(1.0 + kBand);
  if (mode == ExactMode::Tolerance) {
    const mpq_class lo = q(eps) * q(1.0 - kBand);
    if (leqScaledRoot(v, lo, s2)) return Tri::True;
    if (!leqScaledRoot(v, hi, s2)) return Tri::False;
    return Tri::Either;
  }
  if (sgn(v) <= 0) return Tri::True;
  if (!leqScaledRoot(v, hi, s2)) return Tri::False;
  return Tri::Either;
}

inline mpq_class abs(const mpq_class& x) { return sgn(x) < 0 ? mpq_class(-x) : x; }

struct P2 {
  mpq_class x, y;
};
inline P2 sub(const P2& a, const P2& b) { return {a.x - b.x, a.y - b.y}; }
inline mpq_class cross(const P2& a, const P2& b) { return a.x * b.y - a.y * b.x; }
inline mpq_class norm2(const P2& a) { return a.x * a.x + a.y * a.y; }

}  // namespace exact_detail

/// The leaves the Fig. 6 tree may end in for w, over every resolution of its ambiguous
/// predicates (one leaf when nothing is ambiguous), in the order of the Fig6Branch enum.
inline std::vector<Fig6Branch> exactFig6Branches(const LocalWindow& w, ExactMode mode) {
  using namespace exact_detail;
  const P2 v0{0, 0}, v2{q(w.edgeLength), 0}, v1{q(w.apex.x()), q(w.apex.y())};
  const P2 s{q(w.source.x()), q(w.source.y())}, b0{q(w.b0), 0}, b1{q(w.b1), 0};
  // scale² = max(L², |v1|², |v1 − v2|²): the face's longest edge (localScale).
  const mpq_class scale2 = std::max({norm2(v2), norm2(v1), norm2(sub(v1, v2))});

  const Tri zeroArea = within(v1.y, tol::kFlatFaceRel, scale2, mode);
  const Tri onLine = within(abs(s.y), tol::kCoincideRel, scale2, mode);
  // s.x ≥ b0 − c  ⇔  b0 − s.x ≤ c;  s.x ≤ b1 + c  ⇔  s.x − b1 ≤ c.
  const Tri afterB0 = within(b0.x - s.x, tol::kCoincideRel, scale2, mode);
  const Tri beforeB1 = within(s.x - b1.x, tol::kCoincideRel, scale2, mode);
  const Tri b0IsV0 = within(b0.x, tol::kCoincideRel, scale2, mode);
  const Tri b1IsV2 = within(v2.x - b1.x, tol::kCoincideRel, scale2, mode);
  // sideOfRay(a, b, c): z = (b − a) × (c − b), collinear when |z| ≤ sin·|b − a||c − b|.
  auto side = [&](const P2& b) {
    const P2 u = sub(b, s), v = sub(v1, b);
    const mpq_class z = cross(u, v);
    return std::pair{within(abs(z), tol::kCollinearSin, norm2(u) * norm2(v), mode), sgn(z)};
  };
  const auto [colB0, signB0] = side(b0);
  const auto [colB1, signB1] = side(b1);

  std::array<Tri, 8> preds{zeroArea, onLine, afterB0, beforeB1, b0IsV0, b1IsV2, colB0, colB1};
  std::vector<int> open;
  for (int i = 0; i < 8; ++i)
    if (preds[i] == Tri::Either) open.push_back(i);
  std::vector<Fig6Branch> leaves;
  for (unsigned mask = 0; mask < (1u << open.size()); ++mask) {
    std::array<bool, 8> p{};
    for (int i = 0; i < 8; ++i) p[i] = preds[i] == Tri::True;
    for (std::size_t j = 0; j < open.size(); ++j) p[open[j]] = (mask >> j) & 1u;
    Fig6Branch b;
    if (p[0])
      b = Fig6Branch::ZeroAreaFace;
    else if (p[1])
      b = p[2] && p[3] ? Fig6Branch::G1Inside : Fig6Branch::G1Outside;
    else if (p[6])
      b = p[4] ? Fig6Branch::G4 : Fig6Branch::G2;
    else if (p[7])
      b = p[5] ? Fig6Branch::G5 : Fig6Branch::G3;
    else if (signB0 > 0)
      b = Fig6Branch::LeftOfWedge;
    else if (signB1 < 0)
      b = Fig6Branch::RightOfWedge;
    else
      b = Fig6Branch::InsideWedge;
    if (std::find(leaves.begin(), leaves.end(), b) == leaves.end()) leaves.push_back(b);
  }
  std::sort(leaves.begin(), leaves.end());
  return leaves;
}

}  // namespace geodex::proptest
