#pragma once
// Every RapidCheck generator of the property suite, in one header (STYLE.md: "Generators for
// property tests in one header"). Each `gen::` function returns an rc::Gen<T> whose values say
// which degenerate case of Liu, Zhou & Hu 2007 they aim at (`target`), so that every property
// can RC_TAG its cases and the coverage table can be read against the generators.
//
//   gen::localCase(...)       one propagation case (geodex::LocalWindow, the Fig. 3 frame) aimed
//                             at G1–G5, the composites s = b0 = v0 / s = b1 = v2, a zero-area
//                             face, or a generic wedge; exactly degenerate or "near" (moved by
//                             ±k ulp or ±k·ε of the tolerance that decides it); lattice or
//                             arbitrary-double coordinates at scales 1e-6 … 1e+6.
//   gen::intervalListCase(...) a sequence of intervals inserted into one edge by Algorithm 2,
//                             aimed at D1–D4 and the other list hazards (same source, tangent
//                             distance functions, a new interval covering many, far sources).
//   gen::meshCase(...)        a small triangle mesh from verify/'s generators: planar grids with
//                             either diagonal pattern, jittered grids, quantized height fields,
//                             bumpy height fields, fans of needles, an L shape, a square with a
//                             hole, a bumpy patch fed by a source 1e4–1e7 edge lengths away.
//   gen::sourcePoint(mesh)    a source on that mesh: any / boundary / saddle vertex, a point on
//                             an edge, a point in a face.
//
// Coordinates: "lattice" cases are integers times 2^e (every coordinate, sum and cross product
// of the configuration is exact), "arbitrary" cases use full 53-bit mantissas at a random decimal
// scale. Doubles are always built from integers (never rc::gen::arbitrary<double>), so no NaN or
// infinity is ever generated and shrinking moves towards small, simple numbers.

#include <rapidcheck.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "geodex/interval.h"
#include "geodex/mesh.h"
#include "geodex/propagate.h"
#include "geodex/surface_point.h"
#include "geodex/tolerance.h"
#include "geodex/verify/mesh_generators.h"

namespace geodex::proptest {

// ===  Shared value types =========================================================================

/// The local configuration a generator aimed at (Fig. 4 cases and the composites).
enum class LocalTarget : std::uint8_t {
  Generic,    ///< no degeneracy intended: left of, right of or inside the wedge
  ZeroArea,   ///< apex on the line of e0 (not in the paper; a zero-area face)
  G1Inside,   ///< s on e0's line at b0, at b1 or between
  G1Outside,  ///< s on e0's line outside [b0, b1]
  G2,         ///< s, b0, v1 collinear, b0 ≠ v0
  G3,         ///< s, b1, v1 collinear, b1 ≠ v2
  G4,         ///< s, v0 = b0, v1 collinear
  G5,         ///< s, v2 = b1, v1 collinear
  SAtB0AtV0,  ///< composite: s = b0 = v0 (G1, G2 and G4 at once)
  SAtB1AtV2,  ///< composite: s = b1 = v2 (G1, G3 and G5 at once)
};
inline constexpr std::array kAllLocalTargets{
    LocalTarget::Generic,   LocalTarget::ZeroArea, LocalTarget::G1Inside, LocalTarget::G1Outside,
    LocalTarget::G2,        LocalTarget::G3,       LocalTarget::G4,       LocalTarget::G5,
    LocalTarget::SAtB0AtV0, LocalTarget::SAtB1AtV2};

inline const char* name(LocalTarget t) {
  switch (t) {
    case LocalTarget::Generic: return "generic";
    case LocalTarget::ZeroArea: return "zero-area";
    case LocalTarget::G1Inside: return "G1-inside";
    case LocalTarget::G1Outside: return "G1-outside";
    case LocalTarget::G2: return "G2";
    case LocalTarget::G3: return "G3";
    case LocalTarget::G4: return "G4";
    case LocalTarget::G5: return "G5";
    case LocalTarget::SAtB0AtV0: return "s=b0=v0";
    case LocalTarget::SAtB1AtV2: return "s=b1=v2";
  }
  return "?";
}

enum class Coords : std::uint8_t { Lattice, Arbitrary };
inline const char* name(Coords c) { return c == Coords::Lattice ? "lattice" : "arbitrary"; }

/// How far a configuration was moved off the exact degeneracy.
enum class Nearness : std::uint8_t {
  Exact,  ///< not moved
  Ulps,   ///< moved by k units in the last place (well inside the tolerance: still degenerate)
  Eps,    ///< moved by k × the tolerance that decides the case (k < 1 inside, k > 1 outside)
};
inline const char* name(Nearness n) {
  switch (n) {
    case Nearness::Exact: return "exact";
    case Nearness::Ulps: return "k-ulp";
    case Nearness::Eps: return "k-eps";
  }
  return "?";
}

/// What was moved for a "near" configuration.
enum class Axis : std::uint8_t {
  None,
  SourcePerpendicular,  ///< s across the line through b0 (b1) and the apex: the collinearity test
  SourceDown,           ///< s away from e0's line (s.y decreases): the G1 coincidence test
  SourceAlong,          ///< s along e0 past b0 (b1): G1 inside/outside
  WindowEnd,            ///< b0 off v0 (b1 off v2), s re-aimed through the apex: b0 = v0 test
  ApexHeight,           ///< apex lifted off e0's line: the zero-area test
};
inline const char* name(Axis a) {
  switch (a) {
    case Axis::None: return "-";
    case Axis::SourcePerpendicular: return "s-perpendicular";
    case Axis::SourceDown: return "s-down";
    case Axis::SourceAlong: return "s-along";
    case Axis::WindowEnd: return "window-end";
    case Axis::ApexHeight: return "apex-height";
  }
  return "?";
}

struct LocalCase {
  LocalWindow window;
  LocalTarget target = LocalTarget::Generic;
  Coords coords = Coords::Lattice;
  Nearness nearness = Nearness::Exact;
  Axis axis = Axis::None;
  double k = 0.0;  ///< the multiple of ulp or ε, signed (the side)
  /// Reflected through the perpendicular bisector of e0 (x → L − x) after it was made, the target
  /// with it (G2 ↔ G3, G4 ↔ G5): every one-sided configuration is also run as its mirror image.
  bool mirrored = false;
};

inline void showValue(const LocalCase& c, std::ostream& os) {
  const LocalWindow& w = c.window;
  os.precision(17);
  os << name(c.target) << " " << name(c.coords) << " " << name(c.nearness) << " " << name(c.axis)
     << " k=" << c.k << (c.mirrored ? " mirrored" : "") << "\n  LocalWindow{" << w.edgeLength
     << ", Vec2(" << w.apex.x() << ", " << w.apex.y() << "), " << w.b0 << ", " << w.b1
     << ", Vec2(" << w.source.x() << ", " << w.source.y() << ")}";
}

/// One Algorithm 2 scenario on one edge: the intervals are inserted in order, each with a fresh id.
struct IntervalListCase {
  double edgeLength = 1.0;
  std::vector<Interval> inserts;
  const char* target = "";
  bool mirrored = false;  ///< reflected along the edge (x → L − x) after it was made
};

inline void showValue(const IntervalListCase& c, std::ostream& os) {
  os.precision(17);
  os << c.target << (c.mirrored ? " mirrored" : "") << " on an edge of length " << c.edgeLength
     << ", inserting:";
  for (const Interval& w : c.inserts) {
    os << "\n  [" << w.b0 << ", " << w.b1 << "] s=(" << w.source.x() << ", " << w.source.y()
       << ") sigma=" << w.sigma << (w.fullyPropagated() ? " propagated" : "");
  }
}

struct MeshCase {
  TriangleSoup soup;
  const char* family = "";
  bool planarConvex = false;  ///< planar with a convex domain: distances are Euclidean
  bool planarDomain = false;  ///< planar (maybe non-convex, with holes): the visibility graph
  std::string recipe;         ///< how to rebuild it with verify/'s generators
};

inline void showValue(const MeshCase& c, std::ostream& os) {
  os << c.family << ": " << c.recipe << " (" << c.soup.positions.size() << " vertices, "
     << c.soup.faces.size() << " faces)";
}

struct SourceCase {
  SurfacePoint point;
  const char* kind = "";  ///< vertex, boundary-vertex, saddle-vertex, edge, edge-midpoint, face, …
};

inline void showValue(const SourceCase& c, std::ostream& os) {
  os << c.kind << " " << formatSurfacePoint(c.point);
}

/// A rotation and a translation (the translation's size relative to the mesh is part of the test:
/// far from the origin, coordinates carry less precision relative to the mesh's features).
struct RigidMotion {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Vec3 translation = Vec3::Zero();
};

inline void showValue(const RigidMotion& m, std::ostream& os) {
  os.precision(17);
  os << "rotation (w, x, y, z) = (" << m.rotation.w() << ", " << m.rotation.x() << ", "
     << m.rotation.y() << ", " << m.rotation.z() << "), translation (" << m.translation.x() << ", "
     << m.translation.y() << ", " << m.translation.z() << ")";
}

/// A coplanar refinement: a face split 1→3 at an interior point, or an edge split at a point.
struct Refinement {
  bool splitEdge = false;
  std::size_t element = 0;              ///< the face or edge to split (the first one not carrying
                                        ///< the source, from here on, cyclically)
  std::array<double, 3> bary{1, 1, 1};  ///< face split: weights of the corners (normalised)
  double t = 0.5;                       ///< edge split: fraction from edge(e).vertex[0]
};

inline void showValue(const Refinement& r, std::ostream& os) {
  os.precision(17);
  if (r.splitEdge)
    os << "split edge " << r.element << "+ at t = " << r.t;
  else
    os << "split face " << r.element << "+ 1-to-3 at weights (" << r.bary[0] << ", " << r.bary[1]
       << ", " << r.bary[2] << ")";
}

namespace gen {

// ===  Numbers ====================================================================================

/// Uniform in [lo, hi), shrinking towards lo, whatever RapidCheck's size. (rc::gen::inRange grows
/// its range with the size, 0 → 100 over a run, so early cases would all sit near lo: right for
/// mesh dimensions — small meshes first — but not for coordinates, scales and choices.)
template <typename T = int>
inline rc::Gen<T> uniformInt(T lo, T hi) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::inRange<T>(lo, hi));
}

/// Uniform in [0, 1) on the 2^-53 grid: a full mantissa.
inline rc::Gen<double> unit() {
  return rc::gen::map(uniformInt<std::int64_t>(0, std::int64_t{1} << 53),
                      [](std::int64_t i) { return std::ldexp(static_cast<double>(i), -53); });
}

/// Uniform in [lo, hi).
inline rc::Gen<double> uniform(double lo, double hi) {
  return rc::gen::map(unit(), [lo, hi](double u) { return lo + (hi - lo) * u; });
}

/// Log-uniform in [lo, hi), lo > 0: every order of magnitude equally likely.
inline rc::Gen<double> logUniform(double lo, double hi) {
  return rc::gen::map(unit(), [lo, hi](double u) { return lo * std::pow(hi / lo, u); });
}

/// A decimal scale 10^e, e uniform in [-6, 6]: the range the tolerances must be invariant over.
inline rc::Gen<double> decimalScale() { return logUniform(1e-6, 1e6); }

/// A lattice step 2^e, e in [-20, 20] (2^±20 ≈ 1e±6): multiplying by it is exact.
inline rc::Gen<double> latticeStep() {
  return rc::gen::map(uniformInt(-20, 21), [](int e) { return std::ldexp(1.0, e); });
}

/// The distance from |x| to the next larger double; for x = 0 that of `fallback`.
inline double ulpOf(double x, double fallback) {
  const double a = x != 0.0 ? std::abs(x) : std::abs(fallback);
  return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

// ===  Local configurations (Fig. 3 frame) ========================================================

namespace detail {

inline int gcd(int a, int b) { return std::gcd(std::abs(a), std::abs(b)); }

/// v0 = origin, v2 = (L, 0); a lattice configuration in integer units before scaling.
struct LatticeConfig {
  int L, ax, ay, b0, b1;
  std::int64_t sx, sy;
};

/// The configuration aimed at `t`, all coordinates integers (times `step` afterwards).
inline LatticeConfig latticeConfig(LocalTarget t) {
  LatticeConfig c{};
  c.L = *uniformInt(2, 65);
  c.ax = *uniformInt(-c.L, 2 * c.L + 1);
  c.ay = t == LocalTarget::ZeroArea ? 0 : *uniformInt(1, 2 * c.L + 1);
  if (t == LocalTarget::ZeroArea && (c.ax == 0 || c.ax == c.L)) c.ax = c.L + 1;  // no zero edge
  switch (t) {
    case LocalTarget::G2:
      c.b0 = *uniformInt(1, c.L);
      c.b1 = *uniformInt(c.b0 + 1, c.L + 1);
      break;
    case LocalTarget::G3:
      c.b1 = *uniformInt(1, c.L);
      c.b0 = *uniformInt(0, c.b1);
      break;
    case LocalTarget::G4:
    case LocalTarget::SAtB0AtV0:
      c.b0 = 0;
      c.b1 = *uniformInt(1, c.L + 1);
      break;
    case LocalTarget::G5:
    case LocalTarget::SAtB1AtV2:
      c.b1 = c.L;
      c.b0 = *uniformInt(0, c.L);
      break;
    default: c.b0 = *uniformInt(0, c.L); c.b1 = *uniformInt(c.b0 + 1, c.L + 1);
  }
  // A ray from the point (px, 0) away from the apex, m lattice steps long: s, (px, 0), v1
  // collinear exactly.
  auto awayFromApex = [&](int px) {
    const int dx = px - c.ax, dy = -c.ay;
    const int g = gcd(dx, dy);
    const int m = *uniformInt(1, 9);
    c.sx = px + std::int64_t{m} * (dx / g);
    c.sy = std::int64_t{m} * (dy / g);
  };
  switch (t) {
    case LocalTarget::G1Inside: {
      const int where = *uniformInt(0, 3);  // at b0, at b1, between
      c.sx = where == 0 ? c.b0 : where == 1 ? c.b1 : *uniformInt(c.b0, c.b1 + 1);
      c.sy = 0;
      break;
    }
    case LocalTarget::G1Outside: {
      const bool left = *rc::gen::arbitrary<bool>();
      c.sx = left ? c.b0 - *uniformInt(1, c.L + 1) : c.b1 + *uniformInt(1, c.L + 1);
      c.sy = 0;
      break;
    }
    case LocalTarget::G2: awayFromApex(c.b0); break;
    case LocalTarget::G3: awayFromApex(c.b1); break;
    case LocalTarget::G4: awayFromApex(0); break;
    case LocalTarget::G5: awayFromApex(c.L); break;
    case LocalTarget::SAtB0AtV0:
      c.sx = 0;
      c.sy = 0;
      break;
    case LocalTarget::SAtB1AtV2:
      c.sx = c.L;
      c.sy = 0;
      break;
    case LocalTarget::Generic:
    case LocalTarget::ZeroArea:
      c.sx = *uniformInt(-2 * c.L, 3 * c.L + 1);
      c.sy = -*uniformInt(1, 3 * c.L + 1);
      break;
  }
  return c;
}

/// The same configuration with full-mantissa coordinates at a decimal scale. Collinear points
/// are computed in floating point, so "exact" here means "within rounding".
inline LocalWindow arbitraryWindow(LocalTarget t) {
  const double scale = *decimalScale();
  const double L = scale * *uniform(0.5, 2.0);
  const double ax = L * *uniform(-0.5, 1.5);
  double ay = t == LocalTarget::ZeroArea ? 0.0 : L * *logUniform(0.01, 2.0);
  double b0 = 0.0, b1 = L;
  switch (t) {
    case LocalTarget::G2:
      b0 = L * *uniform(0.05, 0.9);
      b1 = b0 + (L - b0) * *uniform(0.1, 1.0);
      break;
    case LocalTarget::G3:
      b1 = L * *uniform(0.1, 0.95);
      b0 = b1 * *uniform(0.0, 0.9);
      break;
    case LocalTarget::G4:
    case LocalTarget::SAtB0AtV0:
      b0 = 0.0;
      b1 = L * *uniform(0.1, 1.0);
      break;
    case LocalTarget::G5:
    case LocalTarget::SAtB1AtV2:
      b1 = L;
      b0 = L * *uniform(0.0, 0.9);
      break;
    default: b0 = L * *uniform(0.0, 0.9); b1 = b0 + (L - b0) * *uniform(0.1, 1.0);
  }
  if (!(b1 <= L)) b1 = L;
  if (!(b0 < b1)) b0 = 0.0;
  const Vec2 v1(ax, ay);
  auto awayFromApex = [&](double px) {
    const Vec2 p(px, 0.0);
    return Vec2(p + *logUniform(0.01, 100.0) * (p - v1));
  };
  Vec2 s;
  switch (t) {
    case LocalTarget::G1Inside: {
      const int where = *uniformInt(0, 3);
      s = Vec2(where == 0 ? b0 : where == 1 ? b1 : b0 + (b1 - b0) * *unit(), 0.0);
      break;
    }
    case LocalTarget::G1Outside: {
      const double off = L * *logUniform(1e-3, 2.0);
      s = Vec2(*rc::gen::arbitrary<bool>() ? b0 - off : b1 + off, 0.0);
      break;
    }
    case LocalTarget::G2: s = awayFromApex(b0); break;
    case LocalTarget::G3: s = awayFromApex(b1); break;
    case LocalTarget::G4: s = awayFromApex(0.0); break;
    case LocalTarget::G5: s = awayFromApex(L); break;
    case LocalTarget::SAtB0AtV0: s = Vec2(0.0, 0.0); break;
    case LocalTarget::SAtB1AtV2: s = Vec2(L, 0.0); break;
    case LocalTarget::Generic:
    case LocalTarget::ZeroArea:
      s = Vec2(L * *uniform(-2.0, 3.0), -L * *logUniform(1e-3, 1e3));
      break;
  }
  s.y() = std::min(s.y(), 0.0);  // rounding never puts s on the apex's side
  return {L, v1, b0, b1, s};
}

/// The axes along which a configuration aimed at t can be moved off its degeneracy.
inline std::vector<Axis> axesFor(LocalTarget t) {
  switch (t) {
    case LocalTarget::Generic: return {};
    case LocalTarget::ZeroArea: return {Axis::ApexHeight};
    case LocalTarget::G1Inside:
    case LocalTarget::G1Outside: return {Axis::SourceDown, Axis::SourceAlong};
    case LocalTarget::G2:
    case LocalTarget::G3: return {Axis::SourcePerpendicular};
    case LocalTarget::G4:
    case LocalTarget::G5: return {Axis::SourcePerpendicular, Axis::WindowEnd};
    case LocalTarget::SAtB0AtV0:
    case LocalTarget::SAtB1AtV2: return {Axis::SourceDown, Axis::SourceAlong, Axis::WindowEnd};
  }
  return {};
}

/// Which end of the window the target's degeneracy is about: 0 for b0 (G2, G4, s = b0 = v0 and
/// G1 cases whose source is nearer b0), 1 for b1.
inline int endOf(const LocalCase& c) {
  switch (c.target) {
    case LocalTarget::G3:
    case LocalTarget::G5:
    case LocalTarget::SAtB1AtV2: return 1;
    case LocalTarget::G1Inside:
    case LocalTarget::G1Outside:
      return std::abs(c.window.source.x() - c.window.b1) <
             std::abs(c.window.source.x() - c.window.b0);
    default: return 0;
  }
}

/// Moves the configuration along c.axis by c.k ulps or c.k × ε (the tolerance of tolerance.h the
/// moved quantity is compared with). Returns false if the move leaves the LocalWindow's domain.
inline bool perturb(LocalCase& c) {
  LocalWindow& w = c.window;
  const double scale = localScale(w);
  const int end = endOf(c);
  const double bEnd = end == 0 ? w.b0 : w.b1;
  const double eps = c.nearness == Nearness::Ulps ? 0.0 : 1.0;
  switch (c.axis) {
    case Axis::None: return true;
    case Axis::SourcePerpendicular: {
      // Across the line through (bEnd, 0) and the apex: the sine at bEnd becomes δ / |s − b|.
      const Vec2 b(bEnd, 0.0);
      const Vec2 along = (w.apex - b).normalized();
      const Vec2 normal(-along.y(), along.x());
      const double d = (w.source - b).norm();
      const double delta =
          eps != 0.0 ? c.k * tol::kCollinearSin * d
                     : c.k * ulpOf(std::max(std::abs(w.source.x()), std::abs(w.source.y())), scale);
      w.source += delta * normal;
      break;
    }
    case Axis::SourceDown: {
      const double delta = eps != 0.0 ? std::abs(c.k) * tol::kCoincideRel * scale
                                      : std::abs(c.k) * ulpOf(w.source.y(), scale);
      w.source.y() -= delta;
      break;
    }
    case Axis::SourceAlong: {
      const double delta =
          eps != 0.0 ? c.k * tol::kCoincideRel * scale : c.k * ulpOf(w.source.x(), scale);
      w.source.x() += delta;
      break;
    }
    case Axis::WindowEnd: {
      // b0 moves off v0 into the edge (b1 off v2), s is re-aimed through the new end and the apex.
      const double delta = eps != 0.0 ? std::abs(c.k) * tol::kCoincideRel * scale
                                      : std::abs(c.k) * ulpOf(bEnd, scale);
      double& b = end == 0 ? w.b0 : w.b1;
      const double dist = (w.source - Vec2(bEnd, 0.0)).norm();
      b = end == 0 ? b + delta : b - delta;
      if (dist > 0.0) {
        const Vec2 p(b, 0.0);
        const Vec2 away = (p - w.apex).normalized();
        w.source = p + dist * away;
        w.source.y() = std::min(w.source.y(), 0.0);
      }
      break;
    }
    case Axis::ApexHeight: {
      const double delta = eps != 0.0 ? std::abs(c.k) * tol::kFlatFaceRel * scale
                                      : std::abs(c.k) * ulpOf(w.apex.y(), scale);
      w.apex.y() += delta;
      break;
    }
  }
  return w.b0 >= 0.0 && w.b0 < w.b1 && w.b1 <= w.edgeLength && w.source.y() <= 0.0 &&
         w.apex.y() >= 0.0 && isFinite(w.source) && isFinite(w.apex);
}

inline LocalTarget mirrorOf(LocalTarget t) {
  switch (t) {
    case LocalTarget::G2: return LocalTarget::G3;
    case LocalTarget::G3: return LocalTarget::G2;
    case LocalTarget::G4: return LocalTarget::G5;
    case LocalTarget::G5: return LocalTarget::G4;
    case LocalTarget::SAtB0AtV0: return LocalTarget::SAtB1AtV2;
    case LocalTarget::SAtB1AtV2: return LocalTarget::SAtB0AtV0;
    default: return t;
  }
}

/// The mirror image of w through the perpendicular bisector of e0 (v0 and v2 trade places), when
/// it is still a valid window after rounding L − x (exact on the lattice).
inline std::optional<LocalWindow> mirrored(const LocalWindow& w) {
  const double L = w.edgeLength;
  LocalWindow m{L, Vec2(L - w.apex.x(), w.apex.y()), L - w.b1, L - w.b0,
                Vec2(L - w.source.x(), w.source.y())};
  if (!(m.b0 >= 0.0 && m.b0 < m.b1 && m.b1 <= L && isFinite(m.source) && isFinite(m.apex)))
    return std::nullopt;
  return m;
}

/// A local configuration aimed at `target`, as made (not mirrored).
inline rc::Gen<LocalCase> unmirroredLocalCase(LocalTarget target) {
  return rc::gen::exec([target] {
    LocalCase c;
    c.target = target;
    c.coords = *rc::gen::element(Coords::Lattice, Coords::Arbitrary);
    if (c.coords == Coords::Lattice) {
      const detail::LatticeConfig l = detail::latticeConfig(target);
      const double h = *latticeStep();
      c.window = {l.L * h, Vec2(l.ax * h, l.ay * h), l.b0 * h, l.b1 * h,
                  Vec2(static_cast<double>(l.sx) * h, static_cast<double>(l.sy) * h)};
    } else {
      c.window = detail::arbitraryWindow(target);
    }
    const std::vector<Axis> axes = detail::axesFor(target);
    if (axes.empty()) return c;
    c.nearness = *rc::gen::weightedElement<Nearness>(
        {{2, Nearness::Exact}, {1, Nearness::Ulps}, {2, Nearness::Eps}});
    if (c.nearness == Nearness::Exact) return c;
    c.axis = *rc::gen::elementOf(axes);
    const double sign = *rc::gen::element(1.0, -1.0);
    // k ulps stays deep inside every tolerance; k·ε straddles it (0.9 and 1.1 sit 10% from the
    // threshold, well outside the 1% band where rounding may decide either way).
    c.k = sign * (c.nearness == Nearness::Ulps ? *rc::gen::element(1.0, 2.0, 4.0, 16.0, 256.0)
                                               : *rc::gen::element(0.25, 0.5, 0.9, 1.1, 2.0, 4.0));
    LocalCase moved = c;
    if (detail::perturb(moved)) return moved;
    c.nearness = Nearness::Exact;  // the move left the domain (e.g. b0 < 0): keep it exact
    c.axis = Axis::None;
    c.k = 0.0;
    return c;
  });
}

}  // namespace detail

/// A local configuration aimed at `target`, or its mirror image aimed at the mirrored target (half
/// the time): the generators move b0 and its side of the wedge, the mirror covers b1's.
inline rc::Gen<LocalCase> localCase(LocalTarget target) {
  return rc::gen::exec([target] {
    LocalCase c = *detail::unmirroredLocalCase(target);
    if (!*rc::gen::arbitrary<bool>()) return c;
    if (const auto m = detail::mirrored(c.window)) {
      c.window = *m;
      c.target = detail::mirrorOf(c.target);
      c.mirrored = true;
    }
    return c;
  });
}

/// Any local configuration: each target equally often.
inline rc::Gen<LocalCase> localCase() {
  return rc::gen::mapcat(rc::gen::elementOf(kAllLocalTargets),
                         [](LocalTarget t) { return localCase(t); });
}

// ===  Edge interval lists (Algorithm 2) ==========================================================

namespace detail {

inline Interval interval(double b0, double b1, Vec2 source, double sigma) {
  Interval w;
  w.b0 = b0;
  w.b1 = b1;
  w.source = source;
  w.sigma = sigma;
  return w;
}

/// A pseudo-source on the source side of an edge of length L: above [−L, 2L], sometimes on the
/// edge's own line (the windows vertices cast along their edges have y = 0).
inline Vec2 someSource(double L) {
  const double x = L * *uniform(-1.0, 2.0);
  const double y =
      *rc::gen::weightedElement<int>({{1, 0}, {6, 1}}) == 0 ? 0.0 : L * *logUniform(1e-4, 3.0);
  return {x, y};
}

/// σ such that the interval from `source` has distance `d` at x (or more, so that σ >= 0).
inline double sigmaFor(double d, double x, const Vec2& source) {
  return std::max(0.0, d - std::hypot(x - source.x(), source.y()));
}

/// A small length relative to ε = kTinyIntervalRel × L: k × ε (k < 1) or k ulps of L.
inline double tinyLengthFor(double L) {
  if (*rc::gen::arbitrary<bool>())
    return *rc::gen::element(0.01, 0.1, 0.5, 0.9) * tol::kTinyIntervalRel * L;
  return *rc::gen::element(1.0, 4.0, 64.0, 1024.0) * ulpOf(L, L);
}

/// Two neighbouring intervals meeting at m, from two sources, continuous there when `continuous`.
inline std::vector<Interval> twoNeighbours(double L, double m, bool continuous) {
  const Vec2 a = someSource(L), b = someSource(L);
  const double sa = L * *uniform(0.0, 2.0);
  const double sb =
      continuous ? sigmaFor(sa + std::hypot(m - a.x(), a.y()), m, b) : L * *uniform(0.0, 2.0);
  return {interval(0.0, m, a, sa), interval(m, L, b, sb)};
}

}  // namespace detail

/// D1: a new interval shorter than ε, or one that wins only on a sliver shorter than ε.
inline rc::Gen<IntervalListCase> tinyIntervalList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "D1-tiny-interval";
    const double L = *decimalScale();
    c.edgeLength = L;
    const double m = L * *uniform(0.1, 0.9);
    c.inserts = detail::twoNeighbours(L, m, *rc::gen::arbitrary<bool>());
    const double tiny = detail::tinyLengthFor(L);
    if (*rc::gen::arbitrary<bool>()) {
      // A tiny interval from a source right above it: it is the shorter there.
      const double where = *rc::gen::element(0.0, m - 0.5 * tiny, m, L - tiny, L * *unit());
      const double x0 = std::clamp(where, 0.0, L - tiny);
      const Vec2 s(x0 + 0.5 * tiny, L * *logUniform(1e-6, 1e-2));
      c.inserts.push_back(detail::interval(x0, std::min(L, x0 + tiny), s, 0.0));
    } else {
      // A whole-edge interval that beats the list only on [0, tiny] (or [L − tiny, L]): its
      // distance function crosses the old one's `tiny` from the edge's end.
      const bool atStart = *rc::gen::arbitrary<bool>();
      const double xc = atStart ? tiny : L - tiny;
      const Interval& old = atStart ? c.inserts.front() : c.inserts.back();
      const Vec2 s(atStart ? -L * *uniform(0.1, 2.0) : L * *uniform(1.1, 3.0),
                   L * *logUniform(1e-3, 2.0));
      c.inserts.push_back(detail::interval(0.0, L, s, detail::sigmaFor(old.distanceAt(xc), xc, s)));
    }
    return c;
  });
}

/// D2: two intervals overlapping by less than ε (the second inserted over the first's end).
inline rc::Gen<IntervalListCase> tinyOverlapList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "D2-tiny-overlap";
    const double L = *decimalScale();
    c.edgeLength = L;
    const double m = L * *uniform(0.1, 0.9);
    const double overlap = detail::tinyLengthFor(L);
    auto two = detail::twoNeighbours(L, m, *rc::gen::arbitrary<bool>());
    if (*rc::gen::arbitrary<bool>()) {
      two[1].b0 = m - overlap;  // the right one reaches back over the left one's end
    } else {
      std::swap(two[0], two[1]);  // right one first, then the left one reaching over its start
      two[1].b1 = m + overlap;
    }
    c.inserts = two;
    return c;
  });
}

/// D3: two intervals separated by a gap below ε, or an interval ending ε short of an edge end.
inline rc::Gen<IntervalListCase> tinyGapList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "D3-tiny-gap";
    const double L = *decimalScale();
    c.edgeLength = L;
    const double gap = detail::tinyLengthFor(L);
    const int where = *uniformInt(0, 3);
    if (where == 0) {
      const double m = L * *uniform(0.1, 0.9);
      auto two = detail::twoNeighbours(L, m, *rc::gen::arbitrary<bool>());
      two[1].b0 = m + gap;
      if (*rc::gen::arbitrary<bool>()) std::swap(two[0], two[1]);
      c.inserts = two;
    } else {
      const Vec2 s = detail::someSource(L);
      const double sigma = L * *uniform(0.0, 2.0);
      c.inserts.push_back(where == 1 ? detail::interval(gap, L, s, sigma)
                                     : detail::interval(0.0, L - gap, s, sigma));
    }
    return c;
  });
}

/// D4: a far source (σ = 0, 1e3–1e7 edge lengths away) against a near one whose σ makes the two
/// distance functions cross inside the edge: Eq. 1's coefficients cancel (tests/unit D4 test).
/// Also neighbours whose distances disagree at their shared end, overlapped by a new interval.
inline rc::Gen<IntervalListCase> mismatchedEndpointList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    const double L = *decimalScale();
    c.edgeLength = L;
    if (*rc::gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1) {
      c.target = "D4-discontinuous-neighbours";
      const double m = L * *uniform(0.1, 0.9);
      c.inserts = detail::twoNeighbours(L, m, false);
      const Vec2 s = detail::someSource(L);
      c.inserts.push_back(detail::interval(L * *uniform(0.0, 0.5), L * *uniform(0.5, 1.0), s,
                                           L * *uniform(0.0, 2.0)));
      return c;
    }
    c.target = "D4-far-source";
    const double far = L * *logUniform(1e3, 1e7);
    const double angle = *uniform(0.05, std::numbers::pi - 0.05);
    const Vec2 F(0.5 * L + far * std::cos(angle), far * std::sin(angle));
    const Vec2 N(L * *uniform(-1.0, 2.0), L * *logUniform(1e-3, 1.0));
    const double xc = L * *uniform(0.05, 0.95);
    const double sigmaN = std::hypot(xc - F.x(), F.y()) - std::hypot(xc - N.x(), N.y());
    const Interval farW = detail::interval(0.0, L, F, 0.0);
    const Interval nearW = detail::interval(0.0, L, N, std::max(0.0, sigmaN));
    c.inserts = *rc::gen::arbitrary<bool>() ? std::vector<Interval>{farW, nearW}
                                            : std::vector<Interval>{nearW, farW};
    return c;
  });
}

/// Two intervals with the same pseudo-source, or one moved by k ulps or k × the step-5 tolerance.
inline rc::Gen<IntervalListCase> sameSourceList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "same-source";
    const double L = *decimalScale();
    c.edgeLength = L;
    const Vec2 s = detail::someSource(L);
    const double sigma = L * *uniform(0.0, 2.0);
    Vec2 s2 = s;
    double sigma2 = sigma;
    const int how = *uniformInt(0, 3);
    if (how == 1) {
      const double k = *rc::gen::element(1.0, -1.0, 4.0, -4.0);
      s2.x() += k * ulpOf(s.x(), L);
      sigma2 += std::abs(k) * ulpOf(sigma, L);
    } else if (how == 2) {
      const double k = *rc::gen::element(0.5, -0.5, 2.0, -2.0);
      s2.x() += k * tol::kSameSourceRel * L;
      if (*rc::gen::arbitrary<bool>()) s2.y() = std::max(0.0, s2.y() + k * tol::kSameSourceRel * L);
    }
    const double m = L * *uniform(0.1, 0.9);
    const int layout = *uniformInt(0, 3);  // adjacent, overlapping, identical ranges
    if (layout == 0) {
      c.inserts = {detail::interval(0.0, m, s, sigma), detail::interval(m, L, s2, sigma2)};
    } else if (layout == 1) {
      c.inserts = {detail::interval(0.0, m, s, sigma), detail::interval(0.5 * m, L, s2, sigma2)};
    } else {
      c.inserts = {detail::interval(0.0, L, s, sigma), detail::interval(0.0, L, s2, sigma2)};
    }
    if (*rc::gen::arbitrary<bool>()) c.inserts[0].markPropagated();
    return c;
  });
}

/// Tangent distance functions (Eq. 1 has a double root): two sources on one ray from a point xt
/// of the edge, σ chosen so that the two distances agree at xt; the nearer-σ one is then the
/// shorter everywhere except at xt, where they touch. Optionally σ moved by a few ulps.
inline rc::Gen<IntervalListCase> tangentList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "tangent";
    const double L = *decimalScale();
    c.edgeLength = L;
    const double xt = L * *uniform(0.0, 1.0);
    const Vec2 p(xt, 0.0);
    const double angle = *uniform(0.02, std::numbers::pi - 0.02);
    const Vec2 dir(std::cos(angle), std::sin(angle));
    const double r1 = L * *logUniform(1e-2, 1e2), lambda = *uniform(0.05, 0.95);
    const Vec2 s1 = p + r1 * dir, s2 = p + lambda * r1 * dir;
    const double sigma1 = L * *uniform(0.0, 2.0);
    double sigma2 = sigma1 + (1.0 - lambda) * r1;
    const int nudge = *rc::gen::element(0, 0, 1, -1, 8, -8);
    sigma2 += nudge * ulpOf(sigma2, L);
    const Interval a = detail::interval(0.0, L, s1, sigma1),
                   b = detail::interval(0.0, L, s2, sigma2);
    c.inserts =
        *rc::gen::arbitrary<bool>() ? std::vector<Interval>{a, b} : std::vector<Interval>{b, a};
    return c;
  });
}

/// Many old intervals, then one new interval over (nearly) all of them.
inline rc::Gen<IntervalListCase> coveringList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "covering";
    const double L = *decimalScale();
    c.edgeLength = L;
    const int n = *uniformInt(3, 13);
    for (int i = 0; i < n; ++i) {
      double a = L * *unit(), b = L * *unit();
      if (a > b) std::swap(a, b);
      if (!(b > a)) b = std::min(L, a + 0.01 * L);
      if (!(b > a)) a = b - 0.01 * L;
      c.inserts.push_back(detail::interval(a, b, detail::someSource(L), L * *uniform(0.0, 2.0)));
    }
    const double lo = *rc::gen::element(0.0, 0.0, 0.1 * L), hi = *rc::gen::element(L, L, 0.9 * L);
    c.inserts.push_back(detail::interval(lo, hi, detail::someSource(L), L * *uniform(0.0, 2.5)));
    return c;
  });
}

/// Random intervals with random sources: whatever the others missed.
inline rc::Gen<IntervalListCase> randomList() {
  return rc::gen::exec([] {
    IntervalListCase c;
    c.target = "random";
    const double L = *decimalScale();
    c.edgeLength = L;
    const int n = *uniformInt(2, 9);
    for (int i = 0; i < n; ++i) {
      double a = L * *unit(), b = L * *unit();
      if (*rc::gen::arbitrary<bool>()) a = 0.0;
      if (*rc::gen::arbitrary<bool>()) b = L;
      if (a > b) std::swap(a, b);
      if (!(b > a)) continue;
      Interval w = detail::interval(a, b, detail::someSource(L), L * *uniform(0.0, 2.0));
      if (*rc::gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1) w.markPropagated();
      c.inserts.push_back(w);
    }
    if (c.inserts.empty()) c.inserts.push_back(detail::interval(0.0, L, Vec2(0.5 * L, L), 0.0));
    return c;
  });
}

namespace detail {

/// The scenario reflected along its edge (x → L − x, each list in reverse order of position), when
/// every interval stays valid after rounding L − x.
inline std::optional<IntervalListCase> mirrored(const IntervalListCase& c) {
  IntervalListCase m = c;
  const double L = c.edgeLength;
  for (Interval& w : m.inserts) {
    const double b0 = L - w.b1, b1 = L - w.b0;
    if (!(b0 >= 0.0 && b0 < b1 && b1 <= L)) return std::nullopt;
    w.b0 = b0;
    w.b1 = b1;
    w.source.x() = L - w.source.x();
  }
  m.mirrored = true;
  return m;
}

}  // namespace detail

/// `scenarios` or, half the time, its mirror image: the scenarios put their slivers, overlaps and
/// gaps at chosen ends, the mirror puts them at the others.
inline rc::Gen<IntervalListCase> orMirrored(rc::Gen<IntervalListCase> scenarios) {
  return rc::gen::exec([scenarios] {
    IntervalListCase c = *scenarios;
    if (!*rc::gen::arbitrary<bool>()) return c;
    const auto m = detail::mirrored(c);
    return m ? *m : c;
  });
}

/// Any of the interval-list scenarios, the D cases weighted up.
inline rc::Gen<IntervalListCase> intervalListCase() {
  return orMirrored(rc::gen::weightedOneOf<IntervalListCase>({{3, tinyIntervalList()},
                                                   {3, tinyOverlapList()},
                                                   {3, tinyGapList()},
                                                   {4, mismatchedEndpointList()},
                                                   {2, sameSourceList()},
                                                   {2, tangentList()},
                                                   {2, coveringList()},
                                                   {2, randomList()}}));
}

// ===  Meshes =====================================================================================

enum class MeshFamily : std::uint8_t {
  Grid,
  GridAlternating,
  JitteredGrid,
  NeedleFan,  // planar, convex
  LShape,
  SquareWithHole,  // planar, non-convex, with boundary
  QuantizedHeightField,
  BumpyHeightField,  // curved: saddles, flat vertices, terraces
  FarSourcePatch,    // a bumpy patch and a vertex 1e4–1e7 away
};

using verify::farSourceBumpyPatch;

/// A small mesh of the given family (a few dozen to ~150 vertices: whole solves with the full
/// invariant checker stay fast).
inline rc::Gen<MeshCase> meshCase(MeshFamily family) {
  return rc::gen::exec([family] {
    using verify::DiagonalPattern;
    MeshCase m;
    auto pattern = [](bool alternating) {
      return alternating ? DiagonalPattern::Alternating : DiagonalPattern::AllOneWay;
    };
    auto str = [](auto... parts) {
      std::string s;
      ((s += parts), ...);
      return s;
    };
    auto num = [](double x) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", x);
      return std::string(buf);
    };
    switch (family) {
      case MeshFamily::Grid:
      case MeshFamily::GridAlternating: {
        const int nx = *rc::gen::inRange(1, 11), ny = *rc::gen::inRange(1, 11);
        const double w = *rc::gen::element(1.0, 3.0, 0.7), h = *rc::gen::element(1.0, 0.5, 2.0);
        const bool alt = family == MeshFamily::GridAlternating;
        m.soup = verify::gridMesh(nx, ny, w, h, pattern(alt));
        m.family = alt ? "grid-alternating" : "grid";
        m.recipe = str("gridMesh(", std::to_string(nx), ", ", std::to_string(ny), ", ", num(w),
                       ", ", num(h), alt ? ", Alternating)" : ")");
        m.planarConvex = m.planarDomain = true;
        break;
      }
      case MeshFamily::JitteredGrid: {
        const int nx = *rc::gen::inRange(2, 11), ny = *rc::gen::inRange(2, 11);
        const double jitter = *uniform(0.0, 0.16);
        const auto seed = *uniformInt<std::uint64_t>(0, 1000);
        const bool alt = *rc::gen::arbitrary<bool>();
        m.soup = verify::jitteredGridMesh(nx, ny, 1.0, 1.0, jitter, seed, pattern(alt));
        m.family = "jittered-grid";
        m.recipe =
            str("jitteredGridMesh(", std::to_string(nx), ", ", std::to_string(ny), ", 1, 1, ",
                num(jitter), ", ", std::to_string(seed), alt ? ", Alternating)" : ")");
        m.planarConvex = m.planarDomain = true;
        break;
      }
      case MeshFamily::NeedleFan: {
        const int n = *rc::gen::inRange(1, 61);
        const double angle = std::numbers::pi / n * *logUniform(1e-7, 1.0);
        m.soup = verify::needleFanMesh(n, angle, 1.0);
        m.family = "needle-fan";
        m.recipe = str("needleFanMesh(", std::to_string(n), ", ", num(angle), ", 1)");
        m.planarConvex = m.planarDomain = true;
        break;
      }
      case MeshFamily::LShape: {
        const int n = 2 * *rc::gen::inRange(1, 6);
        const bool alt = *rc::gen::arbitrary<bool>();
        m.soup = verify::lShapeMesh(n, 1.0, pattern(alt));
        m.family = "L-shape";
        m.recipe = str("lShapeMesh(", std::to_string(n), ", 1", alt ? ", Alternating)" : ")");
        m.planarDomain = true;
        break;
      }
      case MeshFamily::SquareWithHole: {
        const int n = *rc::gen::inRange(3, 11);
        const double frac = *rc::gen::element(0.2, 0.35, 0.5, 0.65);
        const bool alt = *rc::gen::arbitrary<bool>();
        m.soup = verify::squareWithHoleMesh(n, 1.0, frac, pattern(alt));
        m.family = "square-with-hole";
        m.recipe = str("squareWithHoleMesh(", std::to_string(n), ", 1, ", num(frac),
                       alt ? ", Alternating)" : ")");
        m.planarDomain = true;
        break;
      }
      case MeshFamily::QuantizedHeightField: {
        const int nx = *rc::gen::inRange(3, 11), ny = *rc::gen::inRange(3, 11);
        const auto seed = *uniformInt<std::uint64_t>(0, 1000);
        const int levels = *rc::gen::inRange(2, 5);
        m.soup = verify::quantizedHeightField(nx, ny, seed, levels);
        m.family = "quantized-height-field";
        m.recipe = str("quantizedHeightField(", std::to_string(nx), ", ", std::to_string(ny), ", ",
                       std::to_string(seed), ", ", std::to_string(levels), ")");
        break;
      }
      case MeshFamily::BumpyHeightField: {
        const int nx = *rc::gen::inRange(2, 9), ny = *rc::gen::inRange(2, 9);
        const auto seed = *uniformInt<std::uint64_t>(0, 1000);
        const double amplitude = *rc::gen::element(0.05, 0.3, 1.0);
        m.soup = verify::bumpyHeightField(nx, ny, amplitude, seed);
        m.family = "bumpy-height-field";
        m.recipe = str("bumpyHeightField(", std::to_string(nx), ", ", std::to_string(ny), ", ",
                       num(amplitude), ", ", std::to_string(seed), ")");
        break;
      }
      case MeshFamily::FarSourcePatch: {
        const int n = *rc::gen::inRange(3, 9);
        const double far = n * *logUniform(1e4, 1e7);
        const auto seed = *uniformInt<std::uint64_t>(0, 1000);
        m.soup = farSourceBumpyPatch(n, far, seed);
        m.family = "far-source-patch";
        m.recipe = str("farSourceBumpyPatch(", std::to_string(n), ", ", num(far), ", ",
                       std::to_string(seed), ")");
        break;
      }
    }
    return m;
  });
}

/// Any family, each equally often.
inline rc::Gen<MeshCase> meshCase() {
  return rc::gen::mapcat(
      rc::gen::element(MeshFamily::Grid, MeshFamily::GridAlternating, MeshFamily::JitteredGrid,
                       MeshFamily::NeedleFan, MeshFamily::LShape, MeshFamily::SquareWithHole,
                       MeshFamily::QuantizedHeightField, MeshFamily::BumpyHeightField,
                       MeshFamily::FarSourcePatch),
      [](MeshFamily f) { return meshCase(f); });
}

/// A planar mesh with a convex domain (distances are Euclidean).
inline rc::Gen<MeshCase> planarConvexMeshCase() {
  return rc::gen::mapcat(rc::gen::element(MeshFamily::Grid, MeshFamily::GridAlternating,
                                          MeshFamily::JitteredGrid, MeshFamily::NeedleFan),
                         [](MeshFamily f) { return meshCase(f); });
}

/// A planar non-convex domain with boundary (distances from the visibility graph).
inline rc::Gen<MeshCase> planarDomainMeshCase() {
  return rc::gen::mapcat(rc::gen::element(MeshFamily::LShape, MeshFamily::SquareWithHole),
                         [](MeshFamily f) { return meshCase(f); });
}

/// A source on `mesh`: a vertex (any, a boundary one, a saddle), a point on an edge (anywhere or
/// its midpoint), a point in a face (anywhere or its centroid). The generator copies what it
/// needs from the mesh.
inline rc::Gen<SourceCase> sourcePoint(const Mesh& mesh) {
  std::vector<Index> vertices, boundary, saddles;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    if (!mesh.isReferenced(v)) continue;
    vertices.push_back(v);
    if (mesh.isBoundaryVertex(v))
      boundary.push_back(v);
    else if (mesh.isPseudoSourceVertex(v))
      saddles.push_back(v);
  }
  std::vector<std::array<Index, 2>> edges;
  for (Index e = 0; e < mesh.numEdges(); ++e) edges.push_back(mesh.edge(e).vertex);
  const Index numFaces = static_cast<Index>(mesh.numFaces());
  return rc::gen::exec([=] {
    std::vector<int> kinds{0, 3, 4, 5, 6};
    if (!boundary.empty()) kinds.push_back(1);
    if (!saddles.empty()) kinds.push_back(2);
    switch (*rc::gen::elementOf(kinds)) {
      case 0: return SourceCase{SurfacePoint::atVertex(*rc::gen::elementOf(vertices)), "vertex"};
      case 1:
        return SourceCase{SurfacePoint::atVertex(*rc::gen::elementOf(boundary)), "boundary-vertex"};
      case 2:
        return SourceCase{SurfacePoint::atVertex(*rc::gen::elementOf(saddles)), "saddle-vertex"};
      case 3: {
        const auto e = *rc::gen::elementOf(edges);
        return SourceCase{SurfacePoint::onEdge(e[0], e[1], *uniform(0.01, 0.99)), "edge"};
      }
      case 4: {
        const auto e = *rc::gen::elementOf(edges);
        return SourceCase{SurfacePoint::onEdge(e[0], e[1], 0.5), "edge-midpoint"};
      }
      case 5: {
        const Index f = *uniformInt<Index>(0, numFaces);
        const double a = *uniform(0.01, 1.0), b = *uniform(0.01, 1.0), c = *uniform(0.01, 1.0);
        const double sum = a + b + c;
        return SourceCase{SurfacePoint::inFace(f, a / sum, b / sum, 1.0 - a / sum - b / sum),
                          "face"};
      }
      default: {
        const Index f = *uniformInt<Index>(0, numFaces);
        return SourceCase{SurfacePoint::inFace(f, 1.0 / 3, 1.0 / 3, 1.0 - 2.0 / 3),
                          "face-centroid"};
      }
    }
  });
}

/// A rigid motion: a uniformly random rotation (normalised random quaternion) and a translation of
/// up to 10 × `size` along each axis.
inline rc::Gen<RigidMotion> rigidMotion(double size) {
  return rc::gen::exec([size] {
    RigidMotion m;
    Eigen::Quaterniond q(*uniform(-1, 1), *uniform(-1, 1), *uniform(-1, 1), *uniform(-1, 1));
    m.rotation = q.norm() < 1e-3 ? Eigen::Quaterniond::Identity() : q.normalized();
    m.translation =
        Vec3(size * *uniform(-10, 10), size * *uniform(-10, 10), size * *uniform(-10, 10));
    return m;
  });
}

/// A coplanar refinement of a mesh with `numFaces` faces and `numEdges` edges.
inline rc::Gen<Refinement> refinement(std::size_t numFaces, std::size_t numEdges) {
  return rc::gen::exec([=] {
    Refinement r;
    r.splitEdge = *rc::gen::arbitrary<bool>();
    r.element = *uniformInt<std::size_t>(0, r.splitEdge ? numEdges : numFaces);
    r.bary = {*uniform(0.05, 1.0), *uniform(0.05, 1.0), *uniform(0.05, 1.0)};
    r.t = *uniform(0.05, 0.95);
    return r;
  });
}

/// A vertex of `mesh` that some face references.
inline rc::Gen<Index> referencedVertex(const Mesh& mesh) {
  std::vector<Index> vertices;
  for (Index v = 0; v < mesh.numVertices(); ++v)
    if (mesh.isReferenced(v)) vertices.push_back(v);
  return rc::gen::elementOf(vertices);
}

}  // namespace gen
}  // namespace geodex::proptest
