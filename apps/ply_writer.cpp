#include "ply_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "render/colormap.h"

namespace geodex::cli {

namespace {

constexpr double kUnreachableSentinel = -1.0;  // distances are never negative
constexpr render::Rgb8 kUnreachableColour{128, 128, 128};

/// The value a `float` property holds, printed with %.9g so that it round-trips.
double asFloat(double x) { return static_cast<double>(static_cast<float>(x)); }

}  // namespace

bool hasPlyExtension(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  std::transform(tail.begin(), tail.end(), tail.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return tail == ".ply";
}

void writeDistancePly(std::FILE* file, const Mesh& mesh, std::span<const double> vertexDistance,
                      const std::vector<std::string>& sourceSpecs) {
  double maxDistance = 0.0;
  for (double d : vertexDistance) {
    if (std::isfinite(d)) maxDistance = std::max(maxDistance, d);
  }
  std::string sources;
  for (const std::string& spec : sourceSpecs) sources += " " + spec;

  std::fprintf(file,
               "ply\n"
               "format ascii 1.0\n"
               "comment geodex distance: exact geodesic distance per vertex from sources%s\n"
               "comment distance -1 means unreachable (+inf: another component, a vertex no "
               "face uses, or beyond a stop)\n"
               "comment red green blue: viridis from 0 to %.9g (the largest finite distance), "
               "grey where unreachable\n"
               "element vertex %zu\n"
               "property float x\n"
               "property float y\n"
               "property float z\n"
               "property float distance\n"
               "property uchar red\n"
               "property uchar green\n"
               "property uchar blue\n"
               "element face %zu\n"
               "property list uchar int vertex_indices\n"
               "end_header\n",
               sources.c_str(), maxDistance, mesh.numVertices(), mesh.numFaces());

  for (Index v = 0; v < mesh.numVertices(); ++v) {
    const Vec3& p = mesh.position(v);
    const double d = vertexDistance[v];
    const bool reachable = std::isfinite(d);
    const render::Rgb8 c =
        !reachable ? kUnreachableColour
                   : render::viridis8(maxDistance > 0.0 ? d / maxDistance : 0.0);
    std::fprintf(file, "%.9g %.9g %.9g %.9g %u %u %u\n", asFloat(p.x()), asFloat(p.y()),
                 asFloat(p.z()), reachable ? asFloat(d) : kUnreachableSentinel, unsigned{c.r},
                 unsigned{c.g}, unsigned{c.b});
  }
  for (Index f = 0; f < mesh.numFaces(); ++f) {
    const auto& v = mesh.face(f);
    std::fprintf(file, "3 %u %u %u\n", v[0], v[1], v[2]);
  }
}

}  // namespace geodex::cli
