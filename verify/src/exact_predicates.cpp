#include "geodex/verify/exact_predicates.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geodex/tolerance.h"

namespace geodex::verify {
namespace {

struct Q2 {
  mpq_class x, y;
};
Q2 exact(const Vec2& p) { return {mpq_class(p.x()), mpq_class(p.y())}; }
int sign(const mpq_class& v) { return sgn(v); }

// ((b − a) × (c − b)).z exactly.
mpq_class crossAt(const Q2& a, const Q2& b, const Q2& c) {
  return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
}

}  // namespace

ExactFig6 exactFig6(const LocalWindow& unscaled) {
  // The margin's floating-point sines and ratios on the configuration at unit scale: at 1e-160
  // a cross product of two face-sized vectors is subnormal, at 1e160 it overflows.
  const LocalWindow w = atUnitScale(unscaled);
  const double scale = localScale(w);
  const double coincide = tol::kCoincideRel * scale;
  double margin = std::numeric_limits<double>::infinity();
  // Each test: value and the ε the floating-point tree compares it with.
  auto note = [&](double value, double eps) { margin = std::min(margin, std::abs(value) / eps); };

  // The decisions on the input itself (rationals are exact at any scale); the margins, in
  // doubles, on w.
  const Q2 v0{0, 0}, v2{mpq_class(unscaled.edgeLength), 0}, v1 = exact(unscaled.apex),
           s = exact(unscaled.source);
  const Q2 b0{mpq_class(unscaled.b0), 0}, b1{mpq_class(unscaled.b1), 0};

  note(w.apex.y(), tol::kFlatFaceRel * scale);
  if (sign(v1.y) == 0) return {Fig6Branch::ZeroAreaFace, margin};

  note(w.source.y(), coincide);
  if (sign(s.y) == 0) {
    note(w.source.x() - w.b0, coincide);
    note(w.source.x() - w.b1, coincide);
    const bool inside = s.x >= b0.x && s.x <= b1.x;
    return {inside ? Fig6Branch::G1Inside : Fig6Branch::G1Outside, margin};
  }

  // Sines as the floating-point tree normalizes them, for the margin only.
  auto sineOf = [](const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 u = b - a, v = c - b;
    const double z = u.x() * v.y() - u.y() * v.x();
    return z / (u.norm() * v.norm());
  };
  const Vec2 b0d(w.b0, 0.0), b1d(w.b1, 0.0);
  const int side0 = sign(crossAt(s, b0, v1));
  note(sineOf(w.source, b0d, w.apex), tol::kCollinearSin);
  if (side0 == 0) {
    note(w.b0, coincide);
    return {sign(b0.x) == 0 ? Fig6Branch::G4 : Fig6Branch::G2, margin};
  }
  const int side1 = sign(crossAt(s, b1, v1));
  note(sineOf(w.source, b1d, w.apex), tol::kCollinearSin);
  if (side1 == 0) {
    note(w.edgeLength - w.b1, coincide);
    return {b1.x == v2.x ? Fig6Branch::G5 : Fig6Branch::G3, margin};
  }
  if (side0 > 0) return {Fig6Branch::LeftOfWedge, margin};
  if (side1 < 0) return {Fig6Branch::RightOfWedge, margin};
  return {Fig6Branch::InsideWedge, margin};
}

}  // namespace geodex::verify
