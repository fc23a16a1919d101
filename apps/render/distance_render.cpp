#include "render/distance_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "render/colormap.h"

namespace geodex::render {

namespace {

// ===  Look =======================================================================================
// Sizes are in output pixels; the picture is rendered kSupersample times larger and averaged.

constexpr int kSupersample = 2;        // 2×2 samples per output pixel: smooth silhouettes
constexpr double kMarginFraction = 0.05;
constexpr float kAmbient = 0.22f;      // light on faces turned away from the lamp
constexpr Rgb kBackground{0.97f, 0.97f, 0.97f};
constexpr Rgb kUnreachable{0.62f, 0.62f, 0.62f};  // faces with a vertex at +inf
constexpr Rgb kIsolineColour{0.0f, 0.0f, 0.0f};
constexpr float kIsolineOpacity = 0.55f;
constexpr double kIsolineHalfWidth = 0.6;
/// Isolines closer together than this on screen (grazing views, silhouettes) fade out instead of
/// turning the surface black.
constexpr double kIsolineMinGap = 3.0;
constexpr Rgb kPathColour{0.92f, 0.11f, 0.14f};
constexpr Rgb kOutlineColour{0.05f, 0.05f, 0.05f};
constexpr double kPathHalfWidth = 1.7;
constexpr double kOutlineWidth = 1.1;   // dark rim around the path and the marks
constexpr Rgb kSourceColour{1.0f, 1.0f, 1.0f};
constexpr double kSourceRadius = 5.0;
constexpr double kTargetRadius = 4.0;
/// How far in front of the surface (as a fraction of the bounding-box diagonal) the path and the
/// marks still count as visible: they lie on the surface, and a thick line also covers pixels of
/// neighbouring, slanted faces.
constexpr double kDepthToleranceRel = 0.01;

Rgb scale(Rgb c, float s) { return {c.r * s, c.g * s, c.b * s}; }
Rgb mix(Rgb a, Rgb b, float t) {
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
}

/// Angle-weighted vertex normals (faces as wound in the file) and unit face normals (zero for
/// zero-area faces).
void computeNormals(const Mesh& mesh, std::vector<Vec3>& vertexNormals,
                    std::vector<Vec3>& faceNormals) {
  vertexNormals.assign(mesh.numVertices(), Vec3::Zero());
  faceNormals.assign(mesh.numFaces(), Vec3::Zero());
  for (Index f = 0; f < mesh.numFaces(); ++f) {
    const auto& v = mesh.face(f);
    const Vec3 n = (mesh.position(v[1]) - mesh.position(v[0]))
                       .cross(mesh.position(v[2]) - mesh.position(v[0]));
    const double length = n.norm();
    if (!(length > 0.0)) continue;
    faceNormals[f] = n / length;
    for (int k = 0; k < 3; ++k) vertexNormals[v[k]] += mesh.cornerAngle(f, k) * faceNormals[f];
  }
  for (Vec3& n : vertexNormals) {
    const double length = n.norm();
    if (length > 0.0) n /= length;
  }
}

/// |∇d| on screen (distance per pixel) of the distance interpolated linearly over face f.
double screenGradient(const std::array<Index, 3>& v, std::span<const Vec3> screen,
                      std::span<const double> d) {
  const Vec3 e1 = screen[v[1]] - screen[v[0]], e2 = screen[v[2]] - screen[v[0]];
  const double det = e1.x() * e2.y() - e1.y() * e2.x();
  if (!(std::abs(det) > 0.0)) return std::numeric_limits<double>::infinity();
  const double d1 = d[v[1]] - d[v[0]], d2 = d[v[2]] - d[v[0]];
  const double gx = (d1 * e2.y() - d2 * e1.y()) / det;
  const double gy = (d2 * e1.x() - d1 * e2.x()) / det;
  return std::hypot(gx, gy);
}

/// A mark (source or target): filled when visible, a ring when hidden behind the surface.
void drawMark(CoverageMask& outline, CoverageMask& fill, const Vec3& at, double radius,
              bool visible) {
  const double rim = kOutlineWidth * kSupersample;
  if (visible) {
    drawDisc(outline, at.x(), at.y(), radius + rim);
    drawDisc(fill, at.x(), at.y(), radius);
  } else {
    drawRing(outline, at.x(), at.y(), radius, 0.5 * rim + kSupersample);
    drawRing(fill, at.x(), at.y(), radius, 0.5 * rim);
  }
}

}  // namespace

RgbImage renderDistanceField(const Mesh& mesh, std::span<const double> vertexDistance,
                             const RenderMarks& marks, const RenderSettings& settings) {
  const int width = settings.width * kSupersample, height = settings.height * kSupersample;

  // ---  Camera, framing the vertices that faces use --------------------------------------------
  std::vector<Vec3> framed;
  framed.reserve(mesh.numVertices());
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.isReferenced(v)) framed.push_back(mesh.position(v));
  }
  const OrthoCamera camera = fitOrthoCamera(framed, settings.azimuthDeg, settings.elevationDeg,
                                            width, height, kMarginFraction);
  std::vector<Vec3> screen(mesh.numVertices());
  for (Index v = 0; v < mesh.numVertices(); ++v) screen[v] = camera.toScreen(mesh.position(v));
  const VisibilityBuffer visibility =
      rasterizeTriangles(screen, mesh.soup().faces, width, height);

  // ---  Shading, once per covered pixel ---------------------------------------------------------
  double maxDistance = 0.0;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.isReferenced(v) && std::isfinite(vertexDistance[v])) {
      maxDistance = std::max(maxDistance, vertexDistance[v]);
    }
  }
  const double spacing =
      settings.isolineCount > 0 ? maxDistance / settings.isolineCount : 0.0;
  std::vector<Vec3> vertexNormals, faceNormals;
  computeNormals(mesh, vertexNormals, faceNormals);
  // The lamp: above, left of and behind the viewer.
  const Vec3 light =
      (camera.toViewer + 0.55 * camera.up - 0.35 * camera.right).normalized();
  std::vector<double> faceGradient(mesh.numFaces(), -1.0);  // computed on first use

  Image image(width, height, kBackground);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = visibility.index(x, y);
      const Index f = visibility.face[i];
      if (f == kNoIndex) continue;
      const auto& v = mesh.face(f);
      const std::array<float, 3>& b = visibility.bary[i];

      // Two-sided smooth shading: seen from behind, the face (and its normals) turn around; a
      // vertex normal disagreeing with its face (inconsistent winding nearby) gives way to it.
      Vec3 faceNormal = faceNormals[f];
      const double facing = faceNormal.dot(camera.toViewer) < 0.0 ? -1.0 : 1.0;
      faceNormal *= facing;
      Vec3 normal =
          facing * (b[0] * vertexNormals[v[0]] + b[1] * vertexNormals[v[1]] +
                    b[2] * vertexNormals[v[2]]);
      if (!(normal.dot(faceNormal) > 0.0)) normal = faceNormal;
      const double length = normal.norm();
      const float lambert =
          length > 0.0 ? static_cast<float>(std::max(0.0, normal.dot(light) / length)) : 1.0f;
      const float shade = kAmbient + (1.0f - kAmbient) * lambert;

      const double d0 = vertexDistance[v[0]], d1 = vertexDistance[v[1]], d2 = vertexDistance[v[2]];
      if (!std::isfinite(d0) || !std::isfinite(d1) || !std::isfinite(d2)) {
        image.at(x, y) = scale(kUnreachable, shade);
        continue;
      }
      const double d = b[0] * d0 + b[1] * d1 + b[2] * d2;
      Rgb colour = scale(viridis(maxDistance > 0.0 ? d / maxDistance : 0.0), shade);

      // Isolines where d crosses k · spacing, antialiased by the distance's screen-space
      // derivative (constant on a face): the pixel's distance to the level, in pixels.
      if (spacing > 0.0) {
        if (faceGradient[f] < 0.0) faceGradient[f] = screenGradient(v, screen, vertexDistance);
        const double gradient = faceGradient[f];
        const double u = d / spacing;
        const double level = std::round(u);
        if (level >= 1.0 && gradient > 0.0 && std::isfinite(gradient)) {
          const double pixelsToLevel = std::abs(u - level) * spacing / gradient;
          const double gap = spacing / gradient / kSupersample;  // output pixels between lines
          const double fade = std::clamp(gap / kIsolineMinGap - 1.0, 0.0, 1.0);
          const double coverage =
              std::clamp(kIsolineHalfWidth * kSupersample + 0.5 - pixelsToLevel, 0.0, 1.0);
          colour = mix(colour, kIsolineColour,
                       static_cast<float>(coverage * fade) * kIsolineOpacity);
        }
      }
      image.at(x, y) = colour;
    }
  }

  // ---  Path and marks on top ------------------------------------------------------------------
  const double depthTolerance = kDepthToleranceRel * mesh.boundingBoxDiagonal();
  auto visible = [&](const Vec3& p) {
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    if (x < 0 || y < 0 || x >= width || y >= height) return false;
    const std::size_t i = visibility.index(x, y);
    return visibility.face[i] == kNoIndex || visibility.depth[i] <= p.z() + depthTolerance;
  };

  if (marks.path.size() >= 2) {
    std::vector<Vec3> path;
    path.reserve(marks.path.size());
    for (const Vec3& p : marks.path) path.push_back(camera.toScreen(p));
    CoverageMask outline(width, height), line(width, height);
    drawPolyline(outline, path, (kPathHalfWidth + kOutlineWidth) * kSupersample, visibility,
                 depthTolerance);
    drawPolyline(line, path, kPathHalfWidth * kSupersample, visibility, depthTolerance);
    composite(image, outline, kOutlineColour, 0.8f);
    composite(image, line, kPathColour);
  }

  CoverageMask outline(width, height), sourceFill(width, height), targetFill(width, height);
  for (const Vec3& s : marks.sources) {
    const Vec3 p = camera.toScreen(s);
    drawMark(outline, sourceFill, p, kSourceRadius * kSupersample, visible(p));
  }
  if (marks.target) {
    const Vec3 p = camera.toScreen(*marks.target);
    drawMark(outline, targetFill, p, kTargetRadius * kSupersample, visible(p));
  }
  composite(image, outline, kOutlineColour);
  composite(image, sourceFill, kSourceColour);
  composite(image, targetFill, kPathColour);

  return downsample(image, kSupersample);
}

}  // namespace geodex::render
