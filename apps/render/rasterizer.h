#pragma once
// The small software rasteriser behind `geodex render`: an orthographic camera, a z-buffered
// visibility buffer (nearest face and barycentrics per pixel, shaded afterwards, once per pixel),
// antialiased overlays (polylines, discs, rings) depth-tested against it, and image helpers.
// Headless and dependency-free on purpose: `render` must work on a build server.
//
// Screen space: x to the right, y down, in pixels; pixel (i, j) covers [i, i+1) × [j, j+1) and is
// sampled at its centre. Depth grows toward the viewer (world units along the view direction).

#include <array>
#include <span>
#include <vector>

#include "geodex/mesh.h"
#include "render/colormap.h"

namespace geodex::render {

// ===  Camera =====================================================================================

/// An orthographic camera: world point p maps to pixel center + pixelsPerUnit · (p − target)
/// projected on (right, −up), with depth (p − target) · toViewer.
struct OrthoCamera {
  Vec3 right{1, 0, 0};
  Vec3 up{0, 1, 0};
  Vec3 toViewer{0, 0, 1};  ///< unit vector from the scene toward the camera
  Vec3 target{0, 0, 0};    ///< the world point at the image centre
  double pixelsPerUnit = 1.0;
  int width = 1;
  int height = 1;

  /// (x, y) in pixels and depth (larger is nearer the viewer).
  Vec3 toScreen(const Vec3& p) const;
};

/// A camera looking at `points` from the direction (azimuth, elevation) in degrees, y up:
/// azimuth turns about +y from +z toward +x, elevation rises above the xz-plane (±90° look
/// straight down or up, with −z as the image's up). The view is centred on the points'
/// projected extent and scaled so that it fills the image less `marginFraction` on each side.
/// @param[in] points  world positions to frame (at least one; all finite)
OrthoCamera fitOrthoCamera(std::span<const Vec3> points, double azimuthDeg, double elevationDeg,
                           int width, int height, double marginFraction);

// ===  Visibility buffer ==========================================================================

/// Per pixel, the nearest triangle and where on it: shading then runs once per visible pixel.
struct VisibilityBuffer {
  int width = 0;
  int height = 0;
  std::vector<float> depth;                  ///< −inf where no triangle covers the pixel
  std::vector<Index> face;                   ///< kNoIndex where no triangle covers the pixel
  std::vector<std::array<float, 3>> bary;    ///< barycentric weights of the face's 3 corners

  bool covered(int x, int y) const { return face[index(x, y)] != kNoIndex; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
};

/// Rasterises triangles into a visibility buffer with a z-buffer (nearest wins; ties keep the
/// first). A pixel belongs to a triangle when its centre is inside, or on a top or left edge
/// (the usual fill rule: pixels on a shared edge are drawn once). Triangles of zero area on
/// screen (seen edge-on) cover no pixel.
/// @param[in] screen  #V screen positions (x, y, depth), from OrthoCamera::toScreen
/// @param[in] faces   #F triangles, indices into `screen`
VisibilityBuffer rasterizeTriangles(std::span<const Vec3> screen,
                                    std::span<const std::array<Index, 3>> faces, int width,
                                    int height);

// ===  Images and overlays ========================================================================

/// A floating-point RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;

  Image(int w, int h, Rgb fill)
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}
  Rgb& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// An 8-bit RGB image, rows top to bottom (what the PNG writer takes).
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<Rgb8> pixels;
};

/// Antialiased coverage in [0, 1] per pixel; shapes drawn into it combine by maximum, so a
/// polyline's joints are not drawn twice.
struct CoverageMask {
  int width = 0;
  int height = 0;
  std::vector<float> alpha;

  CoverageMask(int w, int h) : width(w), height(h), alpha(static_cast<std::size_t>(w) * h, 0.f) {}
};

/// A polyline `halfWidth` pixels either side of its centre line, depth-tested: a pixel is
/// skipped where the visible surface is nearer than the line (at the nearest point of the
/// segment) by more than `depthTolerance` — the line is drawn slightly in front of the surface
/// it lies on and hidden behind what occludes it.
/// @param[in] points  screen positions (x, y, depth) of the polyline's vertices, in order
void drawPolyline(CoverageMask& mask, std::span<const Vec3> points, double halfWidth,
                  const VisibilityBuffer& visibility, double depthTolerance);

/// A filled disc (no depth test).
void drawDisc(CoverageMask& mask, double cx, double cy, double radius);
/// A circle `halfWidth` pixels either side of radius `radius` (no depth test).
void drawRing(CoverageMask& mask, double cx, double cy, double radius, double halfWidth);

/// Blends `colour` over the image with the mask's coverage (times `opacity`).
void composite(Image& image, const CoverageMask& mask, Rgb colour, float opacity = 1.0f);

/// Averages factor × factor blocks (supersampling antialiasing) and rounds to 8 bits.
/// image.width and image.height must be multiples of factor.
RgbImage downsample(const Image& image, int factor);

}  // namespace geodex::render
