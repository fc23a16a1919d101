#include "render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace geodex::render {

// ===  Camera =====================================================================================

Vec3 OrthoCamera::toScreen(const Vec3& p) const {
  const Vec3 d = p - target;
  return {0.5 * width + pixelsPerUnit * d.dot(right), 0.5 * height - pixelsPerUnit * d.dot(up),
          d.dot(toViewer)};
}

OrthoCamera fitOrthoCamera(std::span<const Vec3> points, double azimuthDeg, double elevationDeg,
                           int width, int height, double marginFraction) {
  const double az = azimuthDeg * std::numbers::pi / 180.0;
  const double el = elevationDeg * std::numbers::pi / 180.0;
  OrthoCamera camera;
  camera.width = width;
  camera.height = height;
  camera.toViewer = Vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
  // `right` stays horizontal whatever the elevation, so looking straight down is no special
  // case (up = toViewer × right then runs along −z).
  camera.right = Vec3(std::cos(az), 0.0, -std::sin(az));
  camera.up = camera.toViewer.cross(camera.right);

  constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3 lo(kInf, kInf, kInf), hi(-kInf, -kInf, -kInf);
  for (const Vec3& p : points) {
    const Vec3 q(p.dot(camera.right), p.dot(camera.up), p.dot(camera.toViewer));
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  if (points.empty()) lo = hi = Vec3::Zero();
  const Vec3 mid = 0.5 * (lo + hi);
  camera.target = mid.x() * camera.right + mid.y() * camera.up + mid.z() * camera.toViewer;

  const double usable = std::max(1.0 - 2.0 * marginFraction, 0.1);
  const double extentX = hi.x() - lo.x(), extentY = hi.y() - lo.y();
  double scale = kInf;
  if (extentX > 0.0) scale = std::min(scale, usable * width / extentX);
  if (extentY > 0.0) scale = std::min(scale, usable * height / extentY);
  camera.pixelsPerUnit = std::isfinite(scale) ? scale : 1.0;  // a single point: any scale
  return camera;
}

// ===  Visibility buffer ==========================================================================

namespace {

/// Twice the signed area of (a, b, s): positive when s lies on the inner side of a → b for a
/// triangle of positive orientation. The barycentric weight of the corner opposite a → b.
inline double edgeFunction(const Vec3& a, const Vec3& b, double sx, double sy) {
  return (b.x() - a.x()) * (sy - a.y()) - (b.y() - a.y()) * (sx - a.x());
}

/// The fill rule for a pixel centre exactly on edge a → b (positive orientation, y down): it
/// belongs to the triangle when the edge is a top edge (horizontal, interior below) or a left
/// edge (running up the screen).
inline bool isTopLeft(const Vec3& a, const Vec3& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  return (dy == 0.0 && dx > 0.0) || dy < 0.0;
}

}  // namespace

VisibilityBuffer rasterizeTriangles(std::span<const Vec3> screen,
                                    std::span<const std::array<Index, 3>> faces, int width,
                                    int height) {
  VisibilityBuffer buffer;
  buffer.width = width;
  buffer.height = height;
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  buffer.depth.assign(n, -std::numeric_limits<float>::infinity());
  buffer.face.assign(n, kNoIndex);
  buffer.bary.assign(n, {0.f, 0.f, 0.f});

  for (std::size_t f = 0; f < faces.size(); ++f) {
    // corner[k] is the face's corner k; the loop below walks them in positive orientation.
    std::array<int, 3> order{0, 1, 2};
    const Vec3* p[3] = {&screen[faces[f][0]], &screen[faces[f][1]], &screen[faces[f][2]]};
    double area2 = edgeFunction(*p[0], *p[1], p[2]->x(), p[2]->y());
    if (!(std::abs(area2) > 0.0) || !std::isfinite(area2)) continue;  // edge-on, or NaN
    if (area2 < 0.0) {
      std::swap(p[1], p[2]);
      std::swap(order[1], order[2]);
      area2 = -area2;
    }
    const Vec3 &a = *p[0], &b = *p[1], &c = *p[2];
    const double minX = std::min({a.x(), b.x(), c.x()}), maxX = std::max({a.x(), b.x(), c.x()});
    const double minY = std::min({a.y(), b.y(), c.y()}), maxY = std::max({a.y(), b.y(), c.y()});
    const int x0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5)));
    const int y1 = std::min(height - 1, static_cast<int>(std::floor(maxY - 0.5)));
    if (x0 > x1 || y0 > y1) continue;
    const bool topLeftA = isTopLeft(b, c), topLeftB = isTopLeft(c, a), topLeftC = isTopLeft(a, b);
    const double inv = 1.0 / area2;

    for (int y = y0; y <= y1; ++y) {
      const double sy = y + 0.5;
      for (int x = x0; x <= x1; ++x) {
        const double sx = x + 0.5;
        const double wa = edgeFunction(b, c, sx, sy);
        const double wb = edgeFunction(c, a, sx, sy);
        const double wc = edgeFunction(a, b, sx, sy);
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        if ((wa == 0.0 && !topLeftA) || (wb == 0.0 && !topLeftB) || (wc == 0.0 && !topLeftC)) {
          continue;
        }
        const double la = wa * inv, lb = wb * inv, lc = wc * inv;
        const float depth = static_cast<float>(la * a.z() + lb * b.z() + lc * c.z());
        const std::size_t i = buffer.index(x, y);
        if (!(depth > buffer.depth[i])) continue;
        buffer.depth[i] = depth;
        buffer.face[i] = static_cast<Index>(f);
        std::array<float, 3>& w = buffer.bary[i];
        w[order[0]] = static_cast<float>(la);
        w[order[1]] = static_cast<float>(lb);
        w[order[2]] = static_cast<float>(lc);
      }
    }
  }
  return buffer;
}

// ===  Overlays ===================================================================================

namespace {

/// Pixel range [lo, hi] whose centres may lie within `reach` of the interval [a, b].
inline std::pair<int, int> pixelSpan(double a, double b, double reach, int size) {
  const int lo = std::max(0, static_cast<int>(std::floor(std::min(a, b) - reach)));
  const int hi = std::min(size - 1, static_cast<int>(std::ceil(std::max(a, b) + reach)));
  return {lo, hi};
}

/// Coverage of a pixel whose centre is `distance` pixels outside a shape's edge (negative:
/// inside): a one-pixel-wide linear ramp centred on the edge.
inline float edgeCoverage(double distance) {
  return static_cast<float>(std::clamp(0.5 - distance, 0.0, 1.0));
}

}  // namespace

void drawPolyline(CoverageMask& mask, std::span<const Vec3> points, double halfWidth,
                  const VisibilityBuffer& visibility, double depthTolerance) {
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Vec3& p = points[k];
    const Vec3& q = points[k + 1];
    const double dx = q.x() - p.x(), dy = q.y() - p.y();
    const double length2 = dx * dx + dy * dy;
    const auto [x0, x1] = pixelSpan(p.x(), q.x(), halfWidth + 1.0, mask.width);
    const auto [y0, y1] = pixelSpan(p.y(), q.y(), halfWidth + 1.0, mask.height);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double sx = x + 0.5 - p.x(), sy = y + 0.5 - p.y();
        const double t = length2 > 0.0 ? std::clamp((sx * dx + sy * dy) / length2, 0.0, 1.0) : 0.0;
        const double ex = sx - t * dx, ey = sy - t * dy;
        const float coverage = edgeCoverage(std::sqrt(ex * ex + ey * ey) - halfWidth);
        if (coverage <= 0.0f) continue;
        const std::size_t i = visibility.index(x, y);
        const double depth = p.z() + t * (q.z() - p.z());
        if (visibility.face[i] != kNoIndex && visibility.depth[i] > depth + depthTolerance) {
          continue;  // hidden behind the surface
        }
        mask.alpha[i] = std::max(mask.alpha[i], coverage);
      }
    }
  }
}

void drawDisc(CoverageMask& mask, double cx, double cy, double radius) {
  const auto [x0, x1] = pixelSpan(cx, cx, radius + 1.0, mask.width);
  const auto [y0, y1] = pixelSpan(cy, cy, radius + 1.0, mask.height);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const float coverage = edgeCoverage(std::hypot(x + 0.5 - cx, y + 0.5 - cy) - radius);
      float& a = mask.alpha[static_cast<std::size_t>(y) * mask.width + x];
      a = std::max(a, coverage);
    }
  }
}

void drawRing(CoverageMask& mask, double cx, double cy, double radius, double halfWidth) {
  const auto [x0, x1] = pixelSpan(cx, cx, radius + halfWidth + 1.0, mask.width);
  const auto [y0, y1] = pixelSpan(cy, cy, radius + halfWidth + 1.0, mask.height);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double r = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      const float coverage = edgeCoverage(std::abs(r - radius) - halfWidth);
      float& a = mask.alpha[static_cast<std::size_t>(y) * mask.width + x];
      a = std::max(a, coverage);
    }
  }
}

void composite(Image& image, const CoverageMask& mask, Rgb colour, float opacity) {
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const float a = mask.alpha[i] * opacity;
    if (a <= 0.0f) continue;
    Rgb& p = image.pixels[i];
    p.r += a * (colour.r - p.r);
    p.g += a * (colour.g - p.g);
    p.b += a * (colour.b - p.b);
  }
}

RgbImage downsample(const Image& image, int factor) {
  RgbImage out;
  out.width = image.width / factor;
  out.height = image.height / factor;
  out.pixels.resize(static_cast<std::size_t>(out.width) * out.height);
  const float norm = 1.0f / static_cast<float>(factor * factor);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      Rgb sum;
      for (int j = 0; j < factor; ++j) {
        const Rgb* row = &image.pixels[static_cast<std::size_t>(y * factor + j) * image.width +
                                       static_cast<std::size_t>(x) * factor];
        for (int i = 0; i < factor; ++i) {
          sum.r += row[i].r;
          sum.g += row[i].g;
          sum.b += row[i].b;
        }
      }
      out.pixels[static_cast<std::size_t>(y) * out.width + x] =
          toRgb8({sum.r * norm, sum.g * norm, sum.b * norm});
    }
  }
  return out;
}

}  // namespace geodex::render
