// Exact geodesic distances with an installed geodex (find_package(geodex), geodex::geodex).
#include <cmath>
#include <cstdio>
#include <vector>

#include <geodex/geodesic_solver.h>

int main() {
  geodex::TriangleSoup soup;  // a 3 × 3 grid of points in the plane z = 0, 2 triangles a square
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) soup.positions.emplace_back(x, y, 0.0);
  for (geodex::Index v : {0u, 1u, 3u, 4u}) {
    soup.faces.push_back({v, v + 1, v + 4});
    soup.faces.push_back({v, v + 4, v + 3});
  }
  const geodex::Mesh mesh(std::move(soup));  // throws geodex::InputError for a bad mesh

  const std::vector<geodex::SurfacePoint> sources{geodex::SurfacePoint::atVertex(0)};
  geodex::GeodesicSolver solver(mesh);  // or the one call geodex::exactGeodesicDistance
  solver.solve(sources);
  const double d = solver.vertexDistances()[8];  // the far corner, (2, 2, 0)
  const geodex::GeodesicPath path = solver.path(geodex::SurfacePoint::onEdge(4, 5, 0.5));
  std::printf("distance to (2, 2): %.17g\n", d);
  std::printf("path to (1.5, 1): %zu points, length %.17g\n", path.points.size(), path.length);
  // The mesh is flat, so geodesic distance = straight-line distance.
  const bool ok = std::abs(d - std::sqrt(8.0)) < 1e-12 &&
                  std::abs(path.length - std::hypot(1.5, 1.0)) < 1e-12;
  return ok ? 0 : 1;
}
