// `geodex distance MESH --source SPEC… [--stop-distance D] [--target SPEC…] [--out FILE] [--stats]
//                  [--quiet]`
// One line per vertex, in vertex order: the geodesic distance (%.17g) or `inf`; with
// `--out FILE.ply`, the mesh with the distances on its vertices instead (ply_writer.h).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "degeneracy_table.h"
#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "ply_writer.h"
#include "progress.h"

namespace geodex::cli {

namespace {

struct DistanceOptions {
  std::string meshPath;
  std::vector<std::string> sources;
  std::vector<std::string> targets;
  double stopDistance = kInfinity;
  std::string outPath;
  bool stats = false;
  bool quiet = false;
  unsigned threads = defaultThreads();
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void writeStats(std::ostream& err, const GeodesicSolver& solver, double loadSeconds,
                double solveSeconds, unsigned threads, const std::vector<std::string>& targetSpecs,
                const std::vector<SurfacePoint>& targets) {
  const std::span<const double> d = solver.vertexDistances();
  std::size_t reached = 0;
  double minD = kInfinity, maxD = -kInfinity, sum = 0.0;
  for (double x : d) {
    if (!std::isfinite(x)) continue;
    ++reached;
    minD = std::min(minD, x);
    maxD = std::max(maxD, x);
    sum += x;
  }
  const SolveStats& s = solver.stats();
  char line[200];
  auto put = [&](const char* label, const std::string& value) {
    std::snprintf(line, sizeof line, "%-22s %s\n", label, value.c_str());
    err << line;
  };
  put("vertices:", std::to_string(d.size()));
  put("reached:", std::to_string(reached) + " (" + std::to_string(d.size() - reached) +
                      " at inf)");
  if (reached > 0) {
    put("min distance:", formatDistance(minD));
    put("max distance:", formatDistance(maxD));
    put("mean distance:", formatDistance(sum / static_cast<double>(reached)));
  }
  if (std::isfinite(s.radius)) put("final up to:", formatDistance(s.radius));
  std::snprintf(line, sizeof line, "%.3f s load, %.3f s solve", loadSeconds, solveSeconds);
  put("time:", line);
  put("threads:", std::to_string(std::min(threads, 2u)));
  put("intervals created:", std::to_string(s.intervalsCreated));
  put("windows propagated:", std::to_string(s.intervalsPropagated));
  put("batches beside front:", std::to_string(s.batchesBesideTheFront));
  put("pseudo-source events:", std::to_string(s.pseudoSourceEvents));
  // (After a solve that released lists, of the lists it kept: the wavefront's last stretch.)
  const std::string ofKept = s.edgesReleased > 0 ? " (in the lists not released)" : "";
  put("max intervals/edge:", std::to_string(s.maxIntervalsPerEdge) + ofKept);
  put("intervals at end:", std::to_string(s.intervalsAtEnd) + ofKept);
  put("shadows closed:", std::to_string(s.shadowsClosed));
  put("dropped at edge end:", std::to_string(s.windowsDroppedAtEdgeEnd));
  put("dropped along edge:", std::to_string(s.windowsDroppedAlongEdge));
  put("lists released:",
      std::to_string(s.edgesReleased) +
          (s.releaseUndone ? " (solved again keeping them: a window reached one)" : ""));
  for (std::size_t i = 0; i < targets.size(); ++i) {
    err << "target " << targetSpecs[i] << ": " << formatDistance(solver.distance(targets[i]))
        << '\n';
  }
  err << '\n';
  writeDegeneracyTable(err, solver.counters());
}

int runDistance(const DistanceOptions& o) {
  // Everything the user typed is checked before the (possibly long) load and solve.
  const std::vector<SurfacePoint> sources = parseSurfacePoints(o.sources, "--source");
  const std::vector<SurfacePoint> targets = parseSurfacePoints(o.targets, "--target");
  checkThreads(o.threads);
  if (std::isnan(o.stopDistance) || o.stopDistance < 0.0) {
    throw InputError("usage", "--stop-distance must be a non-negative number, not " +
                                  formatDistance(o.stopDistance));
  }

  const auto loadStart = std::chrono::steady_clock::now();
  const Mesh mesh = loadMeshWithWarnings(o.meshPath);
  const double loadSeconds = secondsSince(loadStart);
  checkPointsOnMesh(mesh, sources, "--source");
  checkPointsOnMesh(mesh, targets, "--target");

  // Create the output before solving: an unwritable --out fails fast, and a failed solve
  // leaves no file (OutputFile removes its temporary unless committed).
  OutputFile out(o.outPath);

  GeodesicSolver solver(mesh);
  ProgressReporter progress(solver);
  if (showProgress(o.quiet)) solver.setObserver(&progress);
  SolveOptions options;
  options.stopDistance = o.stopDistance;
  options.targets = targets;
  options.vertexDistancesOnly = true;  // (the solver keeps the lists when targets need them)
  options.threads = o.threads;
  const auto solveStart = std::chrono::steady_clock::now();
  solver.solve(sources, options);
  const double solveSeconds = secondsSince(solveStart);
  solver.setObserver(nullptr);

  if (hasPlyExtension(o.outPath)) {
    writeDistancePly(out.get(), mesh, solver.vertexDistances(), o.sources);
  } else {
    char buffer[32];
    for (double d : solver.vertexDistances()) {
      if (std::isinf(d) && d > 0) {
        std::fputs("inf\n", out.get());
      } else {
        std::snprintf(buffer, sizeof buffer, "%.17g\n", d);
        std::fputs(buffer, out.get());
      }
    }
  }
  out.commit();

  if (o.stats)
    writeStats(std::cerr, solver, loadSeconds, solveSeconds, o.threads, o.targets, targets);
  return kExitOk;
}

}  // namespace

Command addDistanceCommand(CLI::App& app) {
  auto o = std::make_shared<DistanceOptions>();
  CLI::App* sub = app.add_subcommand(
      "distance", "Geodesic distance from the sources to every vertex, one line per vertex "
                  "in vertex order (%.17g, or inf where unreachable)");
  sub->add_option("MESH", o->meshPath, "Triangle mesh (OFF, OBJ or PLY)")->required();
  sub->add_option("--source,-s", o->sources,
                  "Source point, repeatable: v:I (vertex), e:I,J,T (fraction T from vertex I "
                  "to vertex J), f:F,A,B,C (barycentrics of face F)")
      ->required()
      ->allow_extra_args(false)
      ->type_name("SPEC");
  sub->add_option("--stop-distance", o->stopDistance,
                  "Stop the wavefront at this distance; vertices beyond it get inf")
      ->type_name("D");
  sub->add_option("--target,-t", o->targets,
                  "Stop once the distance of every target is final (repeatable); vertices "
                  "not final by then get inf")
      ->allow_extra_args(false)
      ->type_name("SPEC");
  sub->add_option("--out,-o", o->outPath,
                  "Write the distances to FILE (atomically: whole or not at all) instead of "
                  "stdout; FILE.ply: the mesh as ASCII PLY with per-vertex distance (-1 where "
                  "unreachable) and viridis colours")
      ->type_name("FILE");
  addThreadsOption(sub, o->threads);
  sub->add_flag("--stats", o->stats,
                "Print counts, distance range, time and the degeneracy table to stderr");
  sub->add_flag("--quiet,-q", o->quiet, "No progress on stderr (shown only on a terminal, for "
                                        "solves longer than a second)");
  return {sub, [o] { return runDistance(*o); }};
}

}  // namespace geodex::cli
