// The Fig. 6 tree evaluated exactly, where every predicate on its path is clearly decided
// (fig6_exact.h).
#include "fig6_exact.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>

#include "geodex/tolerance.h"

namespace geodex::verify::detail {
namespace {

// Every predicate of propagateLocal has the form "q ≤ k · √S2" (q and S2 rational in the inputs,
// k a tolerance). Evaluated on GMP rationals from the exact double inputs, it is *clearly* true
// when q ≤ k√S2 / 10 and clearly false when q ≥ 11 k√S2 (10× the tolerance beyond the boundary);
// in between the ε-decision may go either way and the case says nothing about the predicates.

using Rat = mpq_class;
enum class Tri { True, False, Near };

Tri decideLeq(const Rat& q, double k, const Rat& S2) {
  const Rat kk(k);
  auto leq = [&](const Rat& m) {  // q ≤ m·k·√S2, with m·k ≥ 0
    if (sgn(q) <= 0) return true;
    return q * q <= m * m * kk * kk * S2;
  };
  if (leq(Rat(1, 10))) return Tri::True;
  if (!leq(Rat(11))) return Tri::False;
  return Tri::Near;
}

Rat absRat(const Rat& x) { return sgn(x) < 0 ? Rat(-x) : x; }

// The same tree first in doubles, as a filter (CGAL's filtered predicates): each value with a
// bound on its rounding error, generous (several times Higham's γ_n for the few operations per
// value). Where every predicate on the path is certain — the value clearly on one side of both
// band edges, or clearly inside the band — that is the exact decision; otherwise nullopt and the
// rational evaluation decides. Inputs outside [1e-50, 1e50] (or 0) go to the rationals, so no
// product here under- or overflows. GMP's allocations would otherwise dominate the targets' time
// under ASan; the filter leaves them to the few cases near a band edge.
Tri filteredLeq(double q, double qError, double k, double S2, double S2RelError, bool& certain) {
  constexpr double kSlack = 1e-14;  // the rounding of the thresholds themselves, generously
  const double rootLo = std::sqrt(S2 * (1.0 - S2RelError)) * (1.0 - kSlack);
  const double rootHi = std::sqrt(S2 * (1.0 + S2RelError)) * (1.0 + kSlack);
  // Exactly: True when q ≤ k√S2 / 10, False when q ≥ 11 k√S2, Near in between.
  if (q + qError <= 0.1 * k * rootLo * (1.0 - kSlack)) return Tri::True;
  if (q - qError >= 11.0 * k * rootHi * (1.0 + kSlack)) return Tri::False;
  if (q - qError > 0.1 * k * rootHi * (1.0 + kSlack) && q + qError < 11.0 * k * rootLo * (1.0 - kSlack))
    return Tri::Near;
  certain = false;
  return Tri::Near;
}

std::optional<ExactFig6> filteredFig6(const LocalWindow& w) {
  const double L = w.edgeLength, ax = w.apex.x(), ay = w.apex.y(), b0 = w.b0, b1 = w.b1;
  const double sx = w.source.x(), sy = w.source.y();
  for (double x : {L, ax, ay, b0, b1, sx, sy}) {
    const double m = std::abs(x);
    if (m != 0.0 && !(m >= 1e-50 && m <= 1e50)) return std::nullopt;
  }
  constexpr double u = 0x1p-53;  // unit roundoff
  bool certain = true;
  const double S2 = std::max({L * L, ax * ax + ay * ay, (ax - L) * (ax - L) + ay * ay});
  const double S2Error = 16 * u;
  ExactFig6 r;
  auto done = [&](std::optional<Fig6Branch> b, const char* near = nullptr) -> std::optional<ExactFig6> {
    if (!certain) return std::nullopt;
    r.branch = b;
    if (near) r.nearWhat = near;
    return r;
  };
  const Tri flat = filteredLeq(ay, 0.0, tol::kFlatFaceRel, S2, S2Error, certain);
  if (!certain || flat == Tri::Near) return done(std::nullopt, "apex height vs kFlatFaceRel");
  if (flat == Tri::True) return done(Fig6Branch::ZeroAreaFace);
  const Tri g1 = filteredLeq(std::abs(sy), 0.0, tol::kCoincideRel, S2, S2Error, certain);
  if (!certain || g1 == Tri::Near) return done(std::nullopt, "|s.y| vs kCoincideRel (G1)");
  if (g1 == Tri::True) {
    const double d0 = b0 - sx, d1 = sx - b1;
    const Tri in0 = filteredLeq(d0, 2 * u * std::abs(d0), tol::kCoincideRel, S2, S2Error, certain);
    const Tri in1 = filteredLeq(d1, 2 * u * std::abs(d1), tol::kCoincideRel, S2, S2Error, certain);
    if (!certain || in0 == Tri::Near || in1 == Tri::Near) return done(std::nullopt, "s.x vs [b0, b1] (G1 inside)");
    return done(in0 == Tri::True && in1 == Tri::True ? Fig6Branch::G1Inside : Fig6Branch::G1Outside);
  }
  auto side = [&](double bx, Tri& collinear) {
    const double ux = bx - sx, uy = -sy, vx = ax - bx, vy = ay;
    const double z = ux * vy - uy * vx;
    const double zError = 8 * u * (std::abs(ux * vy) + std::abs(uy * vx));
    collinear = filteredLeq(std::abs(z), zError, tol::kCollinearSin, (ux * ux + uy * uy) * (vx * vx + vy * vy),
                            32 * u, certain);
    return z;  // its sign is certain where `collinear` is certainly False: |z| ≥ 11 k √S2 ≫ zError
  };
  Tri col0, col1;
  const double z0 = side(b0, col0);
  if (!certain || col0 == Tri::Near) return done(std::nullopt, "s, b0, v1 collinearity (G2/G4)");
  if (col0 == Tri::True) {
    const Tri atV0 = filteredLeq(b0, 0.0, tol::kCoincideRel, S2, S2Error, certain);
    if (!certain || atV0 == Tri::Near) return done(std::nullopt, "b0 = v0 (G4 vs G2)");
    return done(atV0 == Tri::True ? Fig6Branch::G4 : Fig6Branch::G2);
  }
  const double z1 = side(b1, col1);
  if (!certain || col1 == Tri::Near) return done(std::nullopt, "s, b1, v1 collinearity (G3/G5)");
  if (col1 == Tri::True) {
    const double d = L - b1;
    const Tri atV2 = filteredLeq(d, 2 * u * std::abs(d), tol::kCoincideRel, S2, S2Error, certain);
    if (!certain || atV2 == Tri::Near) return done(std::nullopt, "b1 = v2 (G5 vs G3)");
    return done(atV2 == Tri::True ? Fig6Branch::G5 : Fig6Branch::G3);
  }
  if (z0 > 0) return done(Fig6Branch::LeftOfWedge);
  if (z1 < 0) return done(Fig6Branch::RightOfWedge);
  return done(Fig6Branch::InsideWedge);
}

ExactFig6 exactFig6Rational(const LocalWindow& w) {
  const Rat L(w.edgeLength), ax(w.apex.x()), ay(w.apex.y()), b0(w.b0), b1(w.b1);
  const Rat sx(w.source.x()), sy(w.source.y());
  Rat S2 = L * L;
  S2 = std::max(S2, Rat(ax * ax + ay * ay));
  S2 = std::max(S2, Rat((ax - L) * (ax - L) + ay * ay));
  ExactFig6 r;
  auto near = [&](const char* what) {
    r.nearWhat = what;
    return r;
  };
  const Tri flat = decideLeq(ay, tol::kFlatFaceRel, S2);
  if (flat == Tri::Near) return near("apex height vs kFlatFaceRel");
  if (flat == Tri::True) return r.branch = Fig6Branch::ZeroAreaFace, r;
  const Tri g1 = decideLeq(absRat(sy), tol::kCoincideRel, S2);
  if (g1 == Tri::Near) return near("|s.y| vs kCoincideRel (G1)");
  if (g1 == Tri::True) {
    const Tri in0 = decideLeq(b0 - sx, tol::kCoincideRel, S2);
    const Tri in1 = decideLeq(sx - b1, tol::kCoincideRel, S2);
    if (in0 == Tri::Near || in1 == Tri::Near) return near("s.x vs [b0, b1] (G1 inside)");
    return r.branch = (in0 == Tri::True && in1 == Tri::True) ? Fig6Branch::G1Inside
                                                                : Fig6Branch::G1Outside,
           r;
  }
  // sideOfRay(s, b, v1): z = (b − s) × (v1 − b), collinear when |z| ≤ kCollinearSin |b − s| |v1 − b|.
  auto side = [&](const Rat& bx, Tri& collinear) {
    const Rat ux = bx - sx, uy = -sy, vx = ax - bx, vy = ay;
    const Rat z = ux * vy - uy * vx;
    collinear = decideLeq(absRat(z), tol::kCollinearSin, Rat((ux * ux + uy * uy) * (vx * vx + vy * vy)));
    return sgn(z);
  };
  Tri col0, col1;
  const int z0 = side(b0, col0);
  if (col0 == Tri::Near) return near("s, b0, v1 collinearity (G2/G4)");
  if (col0 == Tri::True) {
    const Tri atV0 = decideLeq(b0, tol::kCoincideRel, S2);
    if (atV0 == Tri::Near) return near("b0 = v0 (G4 vs G2)");
    return r.branch = atV0 == Tri::True ? Fig6Branch::G4 : Fig6Branch::G2, r;
  }
  const int z1 = side(b1, col1);
  if (col1 == Tri::Near) return near("s, b1, v1 collinearity (G3/G5)");
  if (col1 == Tri::True) {
    const Tri atV2 = decideLeq(L - b1, tol::kCoincideRel, S2);
    if (atV2 == Tri::Near) return near("b1 = v2 (G5 vs G3)");
    return r.branch = atV2 == Tri::True ? Fig6Branch::G5 : Fig6Branch::G3, r;
  }
  if (z0 > 0) return r.branch = Fig6Branch::LeftOfWedge, r;
  if (z1 < 0) return r.branch = Fig6Branch::RightOfWedge, r;
  return r.branch = Fig6Branch::InsideWedge, r;
}

}  // namespace


ExactFig6 exactFig6(const LocalWindow& w) {
  for (double x : {w.edgeLength, w.apex.x(), w.apex.y(), w.b0, w.b1, w.source.x(), w.source.y()})
    if (!std::isfinite(x)) return {std::nullopt, "a non-finite value in the configuration"};
  if (auto r = filteredFig6(w)) return *std::move(r);
  return exactFig6Rational(w);
}

}  // namespace geodex::verify::detail
