#pragma once
// What every mesh reader fills: the soup's vertices and triangles with their file lines, the fan
// triangulation of polygons (and its one warning), and the InputError thrown for anything
// malformed. Private to solver/src/mesh_io/.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/mesh_io.h"

namespace geodex::detail {

/// Highest element count a soup can hold: indices are 32-bit and kNoIndex is reserved.
inline constexpr std::uint64_t kMaxElements = kNoIndex;

class SoupBuilder {
 public:
  explicit SoupBuilder(std::string fileName) { soup_.fileName = std::move(fileName); }

  /// Throws InputError(kind) with a message starting with where(file, line).
  [[noreturn]] void fail(const char* kind, int line, const std::string& what) const;
  void warn(const char* kind, int line, const std::string& what);

  /// Call only with counts already checked against the bytes that remain.
  void reserve(std::uint64_t vertices, std::uint64_t faces) {
    soup_.positions.reserve(vertices);
    soup_.vertexLines.reserve(vertices);
    soup_.faces.reserve(faces);
    soup_.faceLines.reserve(faces);
  }

  void addVertex(double x, double y, double z, int line) {
    if (soup_.positions.size() + 1 >= kMaxElements) {
      fail("absurd-count", line, "more vertices than 32-bit indices can address");
    }
    soup_.positions.emplace_back(x, y, z);
    soup_.vertexLines.push_back(line);
  }

  /// A face with corners `corners` (vertex indices, not yet checked against the vertex count),
  /// fan-triangulated when it has more than three: each triangle keeps the polygon's line.
  void addPolygon(std::span<const Index> corners, int line);

  std::size_t numVertices() const { return soup_.positions.size(); }
  /// Faces read so far, counting a polygon once (the index used in reader messages).
  std::size_t numSourceFaces() const { return sourceFaces_; }

  /// The soup and the reader's warnings; refuses a soup without faces.
  MeshReadResult finish();

 private:
  TriangleSoup soup_;
  std::vector<MeshIssue> issues_;
  std::size_t sourceFaces_ = 0;
  // The fan triangulation, reported once: how many polygons, into how many triangles, and the
  // first polygon as the example.
  std::size_t polygons_ = 0;
  std::size_t polygonTriangles_ = 0;
  int firstPolygonLine_ = 0;
  std::size_t firstPolygonSource_ = 0;
  std::size_t firstPolygonTriangle_ = 0;
  std::size_t firstPolygonCorners_ = 0;
};

}  // namespace geodex::detail
