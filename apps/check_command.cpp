// `geodex check MESH --source SPEC… [--oracles LIST] [--level cheap|full] [--json] [--repro FILE]`
// Solves with the step-6 invariants checked live and the oracles of verify/check.h; prints per
// invariant and per oracle what was checked, what failed and the worst error, then the
// degeneracy table (or one JSON object with --json). Exit 0 if everything held, 1 otherwise, with
// the first violation described and a reproducer written.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "degeneracy_table.h"
#include "geodex/error.h"
#include "geodex/verify/check.h"
#if defined(GEODEX_HAVE_CGAL_ORACLE)
#include "geodex/verify/cgal_oracle.h"
#endif

namespace geodex::cli {

namespace {

struct CheckCommandOptions {
  std::string meshPath;
  std::vector<std::string> sources;
  std::string oracles;  // comma-separated
  std::string level = "cheap";
  bool json = false;
  bool sampleSources = false;
  std::string reproducer = "geodex-check-repro.txt";
};

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) parts.push_back(item);
  return parts;
}

// A vertex, a point on an edge and a point in a face, spread over the mesh and chosen the same
// way every time: the first referenced vertex, and a face half-way through the face list.
std::vector<SurfacePoint> sampleSources(const Mesh& mesh) {
  std::vector<SurfacePoint> s;
  if (mesh.numFaces() == 0) return s;
  Index v = 0;
  while (!mesh.isReferenced(v)) ++v;
  s.push_back(SurfacePoint::atVertex(v));
  const Index f = static_cast<Index>(mesh.numFaces() / 2);
  const auto& t = mesh.face(f);
  s.push_back(SurfacePoint::onEdge(t[0], t[1], 0.37));
  s.push_back(SurfacePoint::inFace(f, 0.2, 0.3, 0.5));
  return s;
}

int runCheck(const CheckCommandOptions& o) {
  std::vector<SurfacePoint> sources = parseSurfacePoints(o.sources, "--source");
  if (o.level != "cheap" && o.level != "full")
    throw InputError("usage", "--level must be cheap or full, not '" + o.level + "'");
  const Mesh mesh = loadMeshWithWarnings(o.meshPath);
  if (o.sampleSources) {
    const auto more = sampleSources(mesh);
    sources.insert(sources.end(), more.begin(), more.end());
  }
  if (sources.empty()) throw InputError("usage", "give --source (at least one) or --sample-sources");
  checkPointsOnMesh(mesh, sources, "--source");
  if (!o.json) {
    std::cout << "sources:";
    for (const SurfacePoint& p : sources) std::cout << " " << formatSurfacePoint(p);
    std::cout << "\n";
  }

  verify::CheckOptions options;
  options.level = o.level == "full" ? verify::CheckLevel::Full : verify::CheckLevel::Cheap;
  options.oracles = splitList(o.oracles);
  options.reproducerPath = o.reproducer;
  options.meshPath = o.meshPath;
#if defined(GEODEX_HAVE_CGAL_ORACLE)
  options.cgal = [](const TriangleSoup& soup, const std::vector<SurfacePoint>& s) {
    return verify::cgalGeodesicDistances(soup, s);
  };
#endif
  const verify::CheckResult result = verify::runChecks(mesh, sources, options);
  if (o.json) {
    verify::writeCheckJson(std::cout, result);
  } else {
    verify::writeCheckText(std::cout, result);
    std::cout << "\n";
    writeDegeneracyTable(std::cout, result.counters);
    std::cout << (result.ok() ? "check passed\n" : "check FAILED\n");
  }
  return result.ok() ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addCheckCommand(CLI::App& app) {
  auto o = std::make_shared<CheckCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "check", "Solve with every invariant checked and independent oracles; exit 1 on a violation");
  sub->add_option("MESH", o->meshPath, "Triangle mesh (OFF, OBJ or PLY)")->required();
  sub->add_option("--source,-s", o->sources, "Source point, repeatable: v:I, e:I,J,T or f:F,A,B,C");
  sub->add_flag("--sample-sources", o->sampleSources,
                "Add a vertex, an edge point and a face point chosen from the mesh");
  sub->add_option("--oracles", o->oracles,
                  "Comma-separated: bounds,lipschitz,planar,symmetry,metamorphic,paths,"
                  "exact-predicates,cgal (default: all but cgal)");
  sub->add_option("--level", o->level, "Invariant tier: cheap (every update) or full (adds the "
                                       "pointwise-min property and end-of-run coverage)");
  sub->add_flag("--json", o->json, "Print one JSON object instead of tables");
  sub->add_option("--repro", o->reproducer, "Where to write a reproducer of the first failure");
  return {sub, [o] { return runCheck(*o); }};
}

}  // namespace geodex::cli
