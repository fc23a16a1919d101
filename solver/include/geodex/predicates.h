#pragma once
// The incidence predicates of Sect. 4.1, as small pure functions on 2-D points so that an exact
// evaluation (verify/, tests) can stand beside each one. Every tolerance comes from tolerance.h
// and is relative: coincidence to a length scale, collinearity as the sine of an angle.

#include <cmath>

#include "geodex/mesh.h"
#include "geodex/tolerance.h"

namespace geodex::pred {

enum class Side { Left, Collinear, Right };

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// |p − q| < ε · scale.
inline bool coincide(const Vec2& p, const Vec2& q, double scale) {
  return (p - q).norm() < tol::kCoincideRel * scale;
}

/// Where c lies relative to the ray from a through b: the sign of ((b − a) × (c − b)).z, with
/// |sin| of the angle at b below tol::kCollinearSin counting as collinear (Sect. 4.1 rules 3–6).
/// Left means counter-clockwise.
inline Side sideOfRay(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a;
  const Vec2 v = c - b;
  const double z = cross(u, v);
  // |z| <= sin · |u| |v|, squared: no square roots on the solver's hottest path.
  if (z * z <= tol::kCollinearSin * tol::kCollinearSin * u.squaredNorm() * v.squaredNorm())
    return Side::Collinear;
  return z > 0.0 ? Side::Left : Side::Right;
}

/// Parameter t in [0, 1] along segment a→b where the line through s and q crosses it (the ray
/// s→q meets the segment's line). Clamped to [0, 1]; callers only ask when the crossing is known
/// to be on the segment up to rounding. Returns 0.5 for a line parallel to the segment (callers
/// rule that out before asking).
/// Measured from q (a point of the window, near the face) and from the end of the segment nearer
/// the crossing: from s or from the far end, the cross product is of long vectors and cancels
/// down to their rounding, which a grazing ray divides by its small angle: measured from a, a
/// crossing near b on a long edge can land past b, and the window's whole image on that edge is
/// lost (corpus/fuzz_propagation/regress/coverage-crossing-near-v2-of-a-long-edge-measured-from-
/// its-far-end).
inline double rayHitsSegment(const Vec2& s, const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 d = q - s;
  const double denom = cross(b - a, d);
  if (denom == 0.0) return 0.5;
  double t = cross(q - a, d) / denom;
  if (t > 0.5) t = 1.0 + cross(q - b, d) / denom;  // 1 − (the parameter from b towards a)
  return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

}  // namespace geodex::pred
