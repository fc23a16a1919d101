// `geodex render MESH --source SPEC… [--target SPEC] --out FILE.png [--width W] [--height H]
//               [--view AZIMUTH,ELEVATION] [--quiet]`
// A PNG of the mesh coloured by geodesic distance from the sources, with isolines, the sources
// marked and, with --target, the geodesic path drawn (render/distance_render.h).

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "progress.h"
#include "render/distance_render.h"
#include "render/png_writer.h"

namespace geodex::cli {

namespace {

// Rendering takes about 160 bytes per output pixel (2×2 supersampled buffers): 2.7 GB at the
// largest size.
constexpr int kMaxImageSide = 4096;

struct RenderOptions {
  std::string meshPath;
  std::vector<std::string> sources;
  std::string target;
  std::string outPath;
  int width = 800;
  int height = 600;
  std::string view;
  bool quiet = false;
  unsigned threads = defaultThreads();
};

/// "AZIMUTH,ELEVATION" in degrees; elevation within [-90, 90].
void parseView(const std::string& text, render::RenderSettings& settings) {
  const auto bad = [&](const std::string& why) {
    return InputError("usage", "--view '" + text + "': " + why +
                                   " (expected AZIMUTH,ELEVATION in degrees, e.g. 30,20)");
  };
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) throw bad("no comma");
  double values[2];
  const std::string parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
  for (int k = 0; k < 2; ++k) {
    std::size_t used = 0;
    try {
      values[k] = std::stod(parts[k], &used);
    } catch (const std::exception&) {
      throw bad("'" + parts[k] + "' is not a number");
    }
    if (used != parts[k].size() || !std::isfinite(values[k])) {
      throw bad("'" + parts[k] + "' is not a finite number");
    }
  }
  if (values[1] < -90.0 || values[1] > 90.0) throw bad("elevation must be within [-90, 90]");
  settings.azimuthDeg = values[0];
  settings.elevationDeg = values[1];
}

int runRender(const RenderOptions& o) {
  // Everything the user typed is checked before the (possibly long) load and solve.
  const std::vector<SurfacePoint> sources = parseSurfacePoints(o.sources, "--source");
  std::optional<SurfacePoint> target;
  if (!o.target.empty()) target = parseSurfacePoints({o.target}, "--target").front();
  render::RenderSettings settings;
  const auto checkSide = [](const char* option, int value) {
    if (value < 1 || value > kMaxImageSide) {
      throw InputError("usage", std::string(option) + " must be within 1.." +
                                    std::to_string(kMaxImageSide) + ", not " +
                                    std::to_string(value));
    }
  };
  checkSide("--width", o.width);
  checkSide("--height", o.height);
  checkThreads(o.threads);
  settings.width = o.width;
  settings.height = o.height;
  if (!o.view.empty()) parseView(o.view, settings);

  const Mesh mesh = loadMeshWithWarnings(o.meshPath);
  checkPointsOnMesh(mesh, sources, "--source");
  if (target) checkPointsOnMesh(mesh, {*target}, "--target");

  // Create the output before solving: an unwritable --out fails fast, and a failed run leaves
  // no file (OutputFile removes its temporary unless committed).
  OutputFile out(o.outPath);

  GeodesicSolver solver(mesh);
  ProgressReporter progress(solver);
  if (showProgress(o.quiet)) solver.setObserver(&progress);
  SolveOptions options;  // (the whole field is drawn, so no early stop at the target)
  options.threads = o.threads;
  solver.solve(sources, options);
  solver.setObserver(nullptr);

  std::vector<Vec3> sourcePositions;
  for (const ResolvedPoint& p : solver.sources()) sourcePositions.push_back(p.position);
  std::vector<Vec3> pathPositions;
  render::RenderMarks marks;
  marks.sources = sourcePositions;
  if (target) {
    const GeodesicPath path = solver.path(*target);
    if (path.points.empty()) {
      std::cerr << "warning: --target " << o.target
                << " is not reachable from the sources; no path drawn\n";
    }
    for (const PathPoint& p : path.points) pathPositions.push_back(p.position);
    marks.path = pathPositions;
    marks.target = resolve(mesh, *target).position;
  }

  const render::RgbImage image = render::renderDistanceField(mesh, solver.vertexDistances(),
                                                             marks, settings);
  render::writePng(out.get(), image, o.outPath);
  out.commit();
  return kExitOk;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* sub = app.add_subcommand(
      "render", "PNG picture of the mesh coloured by geodesic distance (viridis), with "
                "isolines, the sources marked and, with --target, the geodesic path");
  sub->add_option("MESH", o->meshPath, "Triangle mesh (OFF, OBJ or PLY)")->required();
  sub->add_option("--source,-s", o->sources,
                  "Source point, repeatable: v:I, e:I,J,T or f:F,A,B,C")
      ->required()
      ->allow_extra_args(false)
      ->type_name("SPEC");
  sub->add_option("--target,-t", o->target, "Draw the geodesic path from the nearest source "
                                             "to this point")
      ->type_name("SPEC");
  sub->add_option("--out,-o", o->outPath,
                  "The PNG to write (atomically: whole or not at all)")
      ->required()
      ->type_name("FILE");
  sub->add_option("--width", o->width, "Image width in pixels (default 800)")->type_name("W");
  sub->add_option("--height", o->height, "Image height in pixels (default 600)")
      ->type_name("H");
  sub->add_option("--view", o->view,
                  "View direction in degrees, y up: azimuth about +y from +z toward +x, "
                  "elevation above the xz-plane (default 30,20); orthographic, fitted to the "
                  "mesh")
      ->type_name("AZIMUTH,ELEVATION");
  addThreadsOption(sub, o->threads);
  sub->add_flag("--quiet,-q", o->quiet, "No progress on stderr (shown only on a terminal, for "
                                        "solves longer than a second)");
  return {sub, [o] { return runRender(*o); }};
}

}  // namespace geodex::cli
