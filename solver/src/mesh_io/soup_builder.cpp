// What every mesh reader fills (see soup_builder.h).

#include "soup_builder.h"

#include <utility>

#include "geodex/error.h"
#include "text_input.h"

namespace geodex::detail {

void SoupBuilder::fail(const char* kind, int line, const std::string& what) const {
  throw InputError(kind, where(soup_.fileName, line) + what);
}

void SoupBuilder::warn(const char* kind, int line, const std::string& what) {
  issues_.push_back({Severity::Warning, kind, where(soup_.fileName, line) + what});
}

void SoupBuilder::addPolygon(std::span<const Index> corners, int line) {
  if (corners.size() < 3) {
    fail("face-too-small", line,
         "face " + std::to_string(sourceFaces_) + " has " + std::to_string(corners.size()) +
             " corner(s); a face needs at least 3");
  }
  if (soup_.faces.size() + corners.size() - 2 >= kMaxElements) {
    fail("absurd-count", line, "more faces than 32-bit indices can address");
  }
  if (corners.size() > 3) {
    if (polygons_ == 0) {
      firstPolygonLine_ = line;
      firstPolygonSource_ = sourceFaces_;
      firstPolygonTriangle_ = soup_.faces.size();
      firstPolygonCorners_ = corners.size();
    }
    ++polygons_;
    polygonTriangles_ += corners.size() - 2;
  }
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    soup_.faces.push_back({corners[0], corners[k], corners[k + 1]});
    soup_.faceLines.push_back(line);
  }
  ++sourceFaces_;
}

MeshReadResult SoupBuilder::finish() {
  if (soup_.faces.empty()) {
    fail("empty-mesh", 0,
         "no faces found (" + std::to_string(soup_.positions.size()) + " vertices)");
  }
  if (polygons_ > 0) {
    warn("polygon-triangulated", firstPolygonLine_,
         "face " + std::to_string(firstPolygonSource_) + " has " +
             std::to_string(firstPolygonCorners_) + " corners and became triangles " +
             std::to_string(firstPolygonTriangle_) + ".." +
             std::to_string(firstPolygonTriangle_ + firstPolygonCorners_ - 3) + "; " +
             std::to_string(polygons_) +
             " polygon(s) with more than 3 corners were fan-triangulated into " +
             std::to_string(polygonTriangles_) + " triangles");
  }
  return {std::move(soup_), std::move(issues_)};
}

}  // namespace geodex::detail
