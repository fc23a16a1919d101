#pragma once
// The picture `geodex render` draws: the mesh shaded (Lambert and a little ambient light),
// coloured by geodesic distance (viridis), with evenly spaced isolines, the sources marked by
// discs and, when given, the geodesic path on top. Faces with a vertex at +inf (unreachable) are
// grey.

#include <optional>
#include <span>

#include "geodex/mesh.h"
#include "render/rasterizer.h"

namespace geodex::render {

struct RenderSettings {
  int width = 800;   ///< output pixels
  int height = 600;
  double azimuthDeg = 30.0;    ///< view direction, see fitOrthoCamera
  double elevationDeg = 20.0;
  int isolineCount = 20;       ///< isolines at k · max / count, k = 1 … count
};

/// What to draw besides the mesh.
struct RenderMarks {
  std::span<const Vec3> sources;  ///< world positions, each drawn as a disc
  /// The geodesic, world positions in order along it (either direction); empty: none.
  std::span<const Vec3> path;
  std::optional<Vec3> target;     ///< drawn as a smaller disc in the path's colour
};

/// Renders the distance field. Visible marks are filled discs; a mark hidden behind the surface
/// is drawn as a ring, so that it is never lost.
/// @param[in] vertexDistance  #V distances (+inf unreachable), e.g. GeodesicSolver::vertexDistances
RgbImage renderDistanceField(const Mesh& mesh, std::span<const double> vertexDistance,
                             const RenderMarks& marks, const RenderSettings& settings);

}  // namespace geodex::render
