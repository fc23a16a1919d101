// `geodex path MESH --source SPEC… --target SPEC`
// The geodesic from the nearest source to the target: one point per line, from the source to the
// target, as `SPEC x y z` (SPEC as `--source` takes it: v:I, e:I,J,T or f:F,A,B,C), then
// `length L`. An unreachable target prints only `length inf`.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "geodex/geodesic_solver.h"

namespace geodex::cli {

namespace {

struct PathOptions {
  std::string meshPath;
  std::vector<std::string> sources;
  std::string target;
  unsigned threads = defaultThreads();
};

int runPath(const PathOptions& o) {
  const std::vector<SurfacePoint> sources = parseSurfacePoints(o.sources, "--source");
  const SurfacePoint target = parseSurfacePoints({o.target}, "--target").front();
  checkThreads(o.threads);

  const Mesh mesh = loadMeshWithWarnings(o.meshPath);
  checkPointsOnMesh(mesh, sources, "--source");
  checkPointsOnMesh(mesh, {target}, "--target");

  GeodesicSolver solver(mesh);
  SolveOptions options;
  options.targets = {target};
  options.threads = o.threads;
  solver.solve(sources, options);
  const GeodesicPath path = solver.path(target);

  OutputFile out("");
  // The solver lists the points from the target back to the source; print source → target.
  for (auto it = path.points.rbegin(); it != path.points.rend(); ++it) {
    std::fprintf(out.get(), "%s %.17g %.17g %.17g\n", formatSurfacePoint(it->where).c_str(),
                 it->position.x(), it->position.y(), it->position.z());
  }
  std::fprintf(out.get(), "length %s\n", formatDistance(path.length).c_str());
  out.commit();
  return kExitOk;
}

}  // namespace

Command addPathCommand(CLI::App& app) {
  auto o = std::make_shared<PathOptions>();
  CLI::App* sub = app.add_subcommand(
      "path", "The geodesic path from the nearest source to the target: `SPEC x y z` per point "
              "(source first), then `length L`");
  sub->add_option("MESH", o->meshPath, "Triangle mesh (OFF, OBJ or PLY)")->required();
  sub->add_option("--source,-s", o->sources,
                  "Source point, repeatable: v:I, e:I,J,T or f:F,A,B,C")
      ->required()
      ->allow_extra_args(false)
      ->type_name("SPEC");
  sub->add_option("--target,-t", o->target, "The path's end point: v:I, e:I,J,T or f:F,A,B,C")
      ->required()
      ->type_name("SPEC");
  addThreadsOption(sub, o->threads);
  return {sub, [o] { return runPath(*o); }};
}

}  // namespace geodex::cli
