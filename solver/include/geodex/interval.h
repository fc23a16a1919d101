#pragma once
// An interval ("window", Surazhsky et al. 2005; the 6-tuple of Liu et al. Fig. 2) on one edge.
//
// We store the unfolded pseudo-source s as 2-D coordinates in the edge's frame (x along the edge
// from edge.vertex[0], y >= 0 its height on the source side) rather than the paper's (d0, d1):
// the same information, but a distance is σ + |x − s| without first re-deriving s from d0, d1.
// d0 and d1 are available as functions. τ (the side the source lies on) is `side`.

#include <cmath>
#include <cstdint>
#include <limits>

#include "geodex/mesh.h"

namespace geodex {

struct Interval {
  double b0 = 0.0;  ///< range start on the edge, 0 <= b0 < b1 <= edge length
  double b1 = 0.0;  ///< range end
  Vec2 source{0.0, 0.0};  ///< unfolded pseudo-source (x along the edge, y >= 0 height)
  double sigma = 0.0;     ///< σ: geodesic length from the real source to the pseudo-source
  /// τ: the source lies on the side of edge.face[side]; the interval propagates into
  /// edge.face[1 - side]. (A source on the edge line, y == 0, propagates nowhere by itself:
  /// such intervals are created already propagated, see GeodesicSolver.)
  std::uint8_t side = 0;
  /// True once the interval has been propagated across its face (or needs no propagation).
  bool propagated = false;
  /// What the pseudo-source is, for path tracing: >= 0 a mesh vertex (a saddle or boundary
  /// vertex, or a source vertex), < 0 the real source number -(origin + 1).
  std::int32_t origin = -1;
  /// Unique within one solve; identifies the interval in the priority queue.
  std::uint32_t id = 0;

  double distanceAt(double x) const {
    const double dx = x - source.x();
    return sigma + std::sqrt(dx * dx + source.y() * source.y());
  }
  double d0() const { return distanceAt(b0) - sigma; }
  double d1() const { return distanceAt(b1) - sigma; }
  /// Smallest distance over [b0, b1]: the priority-queue key.
  double minDistance() const {
    const double x = source.x() < b0 ? b0 : (source.x() > b1 ? b1 : source.x());
    return distanceAt(x);
  }
  double length() const { return b1 - b0; }
};

inline constexpr std::int32_t sourceOrigin(std::size_t sourceNumber) {
  return -static_cast<std::int32_t>(sourceNumber) - 1;
}

}  // namespace geodex
