#pragma once
// An interval ("window", Surazhsky et al. 2005; the 6-tuple of Liu et al. Fig. 2) on one edge.
//
// We store the unfolded pseudo-source s as 2-D coordinates in the edge's frame (x along the edge
// from edge.vertex[0], y >= 0 its height on the source side) rather than the paper's (d0, d1):
// the same information, but a distance is σ + |x − s| without first re-deriving s from d0, d1.
// d0 and d1 are available as functions. τ (the side the source lies on) is `side`.
//
// 48 bytes: intervals are most of the solver's memory (4 million of them on an 82K-face
// icosphere), so there is no id and no queue bookkeeping beyond two bits.

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "geodex/mesh.h"

namespace geodex {

/// An unfolded pseudo-source: two doubles, converting to and from Vec2. Unlike Eigen's Vector2d it
/// is trivially copyable, and so is Interval: its copy is three 16-byte moves instead of eight
/// member moves, and Algorithm 2 shifts a list's tail with memmove (copies of intervals were
/// 7 % of bunny00's instructions).
struct SourcePoint {
  double px = 0.0;
  double py = 0.0;

  SourcePoint() = default;
  SourcePoint(double x, double y) : px(x), py(y) {}
  explicit SourcePoint(const Vec2& v) : px(v.x()), py(v.y()) {}
  SourcePoint& operator=(const Vec2& v) {
    px = v.x();
    py = v.y();
    return *this;
  }
  operator Vec2() const { return Vec2(px, py); }  // NOLINT(google-explicit-constructor)

  double& x() { return px; }
  double& y() { return py; }
  double x() const { return px; }
  double y() const { return py; }
  double norm() const { return std::hypot(px, py); }
  SourcePoint& operator*=(double k) {
    px *= k;
    py *= k;
    return *this;
  }
  friend bool operator==(const SourcePoint&, const SourcePoint&) = default;
};
inline Vec2 operator-(const SourcePoint& a, const SourcePoint& b) {
  return Vec2(a.px - b.px, a.py - b.py);
}
inline Vec2 operator-(const SourcePoint& a, const Vec2& b) {
  return Vec2(a.px - b.x(), a.py - b.y());
}
inline Vec2 operator-(const Vec2& a, const SourcePoint& b) {
  return Vec2(a.x() - b.px, a.y() - b.py);
}
inline Vec2 operator*(const SourcePoint& a, double k) { return Vec2(a.px * k, a.py * k); }
inline bool operator==(const SourcePoint& a, const Vec2& b) {
  return a.px == b.x() && a.py == b.y();
}
inline bool isFinite(const SourcePoint& p) { return std::isfinite(p.px) && std::isfinite(p.py); }

struct Interval {
  double b0 = 0.0;        ///< range start on the edge, 0 <= b0 < b1 <= edge length
  double b1 = 0.0;        ///< range end
  SourcePoint source;     ///< unfolded pseudo-source (x along the edge, y >= 0 height)
  double sigma = 0.0;     ///< σ: geodesic length from the real source to the pseudo-source
  /// What the pseudo-source is, for path tracing: >= 0 a mesh vertex (a saddle or boundary
  /// vertex, or a source vertex), < 0 the real source number -(origin + 1).
  std::int32_t origin = -1;
  /// τ: the source lies on the side of edge.face[side]; the interval propagates into
  /// edge.face[1 - side].
  std::uint8_t side = 0;
  /// kPending: [b0, b1] still has to be propagated across the face (a new interval, or one that
  /// Algorithm 2 grew after it was propagated). kChanged: the last edge update created this
  /// interval, or moved its point of smallest distance (argMinDistance, minAt), so the solver
  /// must give it a fresh queue entry (and then clears the bit). Trimming an interval elsewhere
  /// keeps its queue entry: its key, the smallest distance, is where it was.
  std::uint8_t flags = kPending;
  /// How often Algorithm 2 made this interval pending again after its propagation because it
  /// grew over a part nothing propagated (a D1 sliver still pending, half a sewn D3 gap); capped
  /// at tol::kMaxRegrowths (see grewUnpropagated in edge_intervals.cpp).
  std::uint8_t regrown = 0;
  static constexpr std::uint8_t kPending = 1;
  static constexpr std::uint8_t kChanged = 2;

  bool pending() const { return (flags & kPending) != 0; }
  bool fullyPropagated() const { return !pending(); }
  void markPropagated() { flags &= static_cast<std::uint8_t>(~kPending); }
  void markPending() { flags |= kPending; }

  double distanceAt(double x) const {
    const double dx = x - source.x();
    return sigma + std::sqrt(dx * dx + source.y() * source.y());
  }
  /// Distance from the pseudo-source to b0 (b1); computed directly, not as distanceAt − σ, which
  /// would cancel when σ is large.
  double d0() const { return std::hypot(b0 - source.x(), source.y()); }
  double d1() const { return std::hypot(b1 - source.x(), source.y()); }
  /// Where on [b0, b1] the distance is smallest (the foot of the source, clamped).
  double argMinDistance() const {
    return source.x() < b0 ? b0 : (source.x() > b1 ? b1 : source.x());
  }
  /// Whether argMinDistance() is the start, the end or inside: with it, that point names the
  /// interval uniquely among its edge's (two intervals can meet at a point, but only one starts
  /// and one ends there). The solver's queue entries find their interval this way.
  enum class MinAt : std::uint8_t { Start, Inside, End };
  MinAt minAt() const {
    const double x = argMinDistance();
    return x == b0 ? MinAt::Start : (x == b1 ? MinAt::End : MinAt::Inside);
  }
  /// Smallest distance over [b0, b1]: the priority-queue key.
  double minDistance() const { return distanceAt(argMinDistance()); }
  double length() const { return b1 - b0; }
};
static_assert(std::is_trivially_copyable_v<Interval> && sizeof(Interval) == 48);

inline constexpr std::int32_t sourceOrigin(std::size_t sourceNumber) {
  return -static_cast<std::int32_t>(sourceNumber) - 1;
}

}  // namespace geodex
