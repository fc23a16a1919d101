// What the observer hooks cost a release solve with no observer attached (the budget: 2%).
// Built twice from this file: geodex_hooks_timing against the library as shipped and
// geodex_nohooks_timing against the same sources compiled with GEODEX_NO_OBSERVER_HOOKS (the
// hooks gone). scripts/hooks-overhead.sh runs the two alternately and compares their medians.
//
//   geodex_{hooks,nohooks}_timing MESH [RUNS]   prints the median thread CPU time of one solve
//                                               from vertex 0, in ms, after one warm-up solve
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "geodex/geodesic_solver.h"
#include "geodex/mesh_io.h"

namespace {

double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s MESH [RUNS]\n", argv[0]);
    return 2;
  }
  const int runs = argc == 3 ? std::atoi(argv[2]) : 5;
  if (runs < 1) {
    std::fprintf(stderr, "error: RUNS must be a positive number, got '%s'\n", argv[2]);
    return 2;
  }
  try {
    const geodex::Mesh mesh = geodex::loadMesh(argv[1]);
    const std::vector<geodex::SurfacePoint> source{geodex::SurfacePoint::atVertex(0)};
    std::vector<double> ms;
    for (int i = 0; i <= runs; ++i) {
      const double start = threadSeconds();
      geodex::GeodesicSolver solver(mesh);
      solver.solve(source);
      if (i > 0) ms.push_back(1e3 * (threadSeconds() - start));  // run 0 warms up
    }
    std::sort(ms.begin(), ms.end());
    std::printf("%.3f\n", ms[ms.size() / 2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
