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
  /// edge.face[1 - side].
  std::uint8_t side = 0;
  /// What the pseudo-source is, for path tracing: >= 0 a mesh vertex (a saddle or boundary
  /// vertex, or a source vertex), < 0 the real source number -(origin + 1).
  std::int32_t origin = -1;
  /// Unique within one solve; identifies the interval in the priority queue.
  std::uint32_t id = 0;
  /// The part of [b0, b1] already propagated across the face (empty when pb0 > pb1). Algorithm 2
  /// may grow an interval (step 3 merges a tiny neighbour in, step 4 sews a gap, step 5 merges a
  /// neighbour with the same source); only the grown part then needs propagating, so growth
  /// never re-propagates what was done.
  double pb0 = std::numeric_limits<double>::infinity();
  double pb1 = -std::numeric_limits<double>::infinity();
  /// Key of this interval's latest priority-queue entry, rounded to float (the solver's
  /// bookkeeping, compared only for equality with the key it would push now; -1: none). A float
  /// keeps the interval at 72 bytes: intervals are most of the solver's memory.
  float queuedKey = -1.0f;

  bool fullyPropagated() const { return pb0 <= b0 && pb1 >= b1; }
  bool nothingPropagated() const { return pb0 > pb1 || pb1 <= b0 || pb0 >= b1; }
  void markPropagated() {
    pb0 = b0;
    pb1 = b1;
  }
  void markUnpropagated() {
    pb0 = std::numeric_limits<double>::infinity();
    pb1 = -std::numeric_limits<double>::infinity();
  }

  double distanceAt(double x) const {
    const double dx = x - source.x();
    return sigma + std::sqrt(dx * dx + source.y() * source.y());
  }
  /// Distance from the pseudo-source to b0 (b1); computed directly, not as distanceAt − σ, which
  /// would cancel when σ is large.
  double d0() const { return std::hypot(b0 - source.x(), source.y()); }
  double d1() const { return std::hypot(b1 - source.x(), source.y()); }
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
