// Judging another program's distances for `geodex crosscheck` (crosscheck_judge.h).
#include "geodex/verify/crosscheck_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>

#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "geodex/mesh_io.h"
#include "geodex/tolerance.h"
#include "geodex/verify/cases/fuzz_solver.h"
#include "geodex/verify/oracles.h"

namespace geodex::verify {

std::string_view name(FindingKind k) {
  switch (k) {
    case FindingKind::WrongDistance: return "wrong-distance";
    case FindingKind::Reachability: return "reachability";
    case FindingKind::LineCount: return "line-count";
    case FindingKind::BadValue: return "bad-value";
    case FindingKind::Crash: return "crash";
    case FindingKind::Timeout: return "timeout";
  }
  return "?";
}

namespace {

// ===  What a case exercises =====================================================================

/// A corner this sharp (radians) makes its face a needle in the report; only a label.
constexpr double kNeedleAngle = 1e-3;
/// Longest message of geodex's own failed check kept in a Reference.
constexpr std::size_t kMaxProblemChars = 2000;

void addCount(std::vector<std::string>& out, const std::string& what, std::uint64_t count) {
  if (count > 0) out.push_back(what + " ×" + std::to_string(count));
}

/// The mesh-level cases of DESIGN.md the mesh holds: what the paper leaves out but real data has.
void addMeshLevelCases(const Mesh& mesh, std::vector<std::string>& out) {
  std::uint64_t flat = 0, saddles = 0, boundary = 0, needles = 0;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    if (!mesh.isReferenced(v)) continue;
    if (mesh.isBoundaryVertex(v)) {
      ++boundary;
    } else if (std::abs(mesh.angleSum(v) - 2.0 * std::numbers::pi) <= tol::kFlatVertexAngle) {
      ++flat;
    } else if (mesh.isPseudoSourceVertex(v)) {
      ++saddles;
    }
  }
  for (Index f = 0; f < mesh.numFaces(); ++f)
    needles += std::min({mesh.cornerAngle(f, 0), mesh.cornerAngle(f, 1), mesh.cornerAngle(f, 2)}) < kNeedleAngle;
  addCount(out, "flat vertices (angle sum 2π)", flat);
  addCount(out, "saddle vertices", saddles);
  addCount(out, "boundary vertices", boundary);
  addCount(out, "needle faces (a corner below 1e-3 rad)", needles);
  if (mesh.numComponents() > 1) addCount(out, "components", mesh.numComponents());
  std::vector<MeshIssue> issues;
  validateMesh(mesh.soup(), issues);
  for (const MeshIssue& issue : issues)
    if (issue.severity == Severity::Warning && issue.kind != "components") out.push_back(issue.kind);
}

void addDegeneracies(const DegeneracyCounters& counters, std::vector<std::string>& out) {
  for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k)
    addCount(out, std::string(name(static_cast<DegeneracyKind>(k))), counters.count[k]);
  addCount(out, "windows through zero-area faces", counters.zeroAreaFaces);
}

// ===  Reading the output ========================================================================

/// One line as a distance, or nullopt when it is not exactly one number.
std::optional<double> parseValue(std::string_view line) {
  const auto blank = [](char ch) { return ch == ' ' || ch == '\t' || ch == '\r'; };
  while (!line.empty() && blank(line.front())) line.remove_prefix(1);
  while (!line.empty() && blank(line.back())) line.remove_suffix(1);
  if (line.empty()) return std::nullopt;
  const std::string text(line);
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  if (std::isnan(x) || x < 0.0 || x >= kUnreachableAtLeast) return INFINITY;
  return x;
}

// ===  Judging ===================================================================================

/// The oracles on the program's distances, one line each; false when one failed.
bool runOracles(const CrossCheckCase& c, std::span<const double> got, double tolerance,
                std::vector<std::string>& lines) {
  const double rel = std::max(tolerance, kOracleRel);
  const TriangleSoup& soup = c.soup;
  const std::vector<double> euclid = euclideanDistances(soup.positions, soup.positions[c.source]);
  std::vector<std::pair<std::string, CheckReport>> reports;
  reports.emplace_back("euclidean-lower-bound", checkEuclideanLowerBound(got, euclid, rel));
  reports.emplace_back("edge-graph-upper-bound", checkUpperBound(got, edgeGraphDijkstra(soup, {{c.source, 0.0}}), rel));
  reports.emplace_back("lipschitz", checkLipschitz(soup, got, rel));
  if (c.planar == PlanarOracle::Convex) reports.emplace_back("planar-euclidean", checkAgreement(got, euclid, rel));
  if (c.planar == PlanarOracle::Domain) {
    try {
      const PlanarDomain domain(planarBoundaryPolygons(soup));
      const Vec3& s = soup.positions[c.source];
      std::vector<double> exact = domain.distances(Vec2(s.x(), s.y()), planarPositions(soup));
      reports.emplace_back("planar-domain", checkAgreement(got, exact, rel));
    } catch (const std::invalid_argument& e) {
      lines.push_back(std::string("planar-domain: not run (") + e.what() + ")");
    }
  }
  bool ok = true;
  for (const auto& [oracle, report] : reports) {
    lines.push_back(oracle + ": " + (report.ok() ? "ok, " : "FAILED, ") + report.summary());
    ok = ok && report.ok();
  }
  return ok;
}

std::string fmt(double x, const char* format = "%.17g") {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

std::string vertices(std::size_t n) { return std::to_string(n) + (n == 1 ? " vertex" : " vertices"); }

/// Fills the per-vertex errors and the worst vertices; returns how many differ in reachability
/// and how many are off by more than `allowed`.
std::pair<std::size_t, std::size_t> compare(const std::vector<double>& expected, const std::vector<double>& got,
                                            double allowed, Judgement& j) {
  std::size_t swapped = 0, off = 0;
  std::vector<VertexError> all;
  j.error.assign(expected.size(), 0.0);
  for (Index v = 0; v < expected.size(); ++v) {
    const bool e = std::isfinite(expected[v]), g = std::isfinite(got[v]);
    double error = 0.0;
    if (e != g) {
      error = INFINITY;
      ++swapped;
    } else if (e) {
      error = std::abs(got[v] - expected[v]);
      off += error > allowed;
    }
    j.error[v] = error;
    if (error > 0.0) all.push_back({v, expected[v], got[v], error});
  }
  // Beyond the tolerance when some are: the rest (rounding) would only hide them.
  if (swapped + off > 0)
    std::erase_if(all, [allowed](const VertexError& w) { return !(w.error > allowed); });
  const std::size_t keep = std::min(all.size(), kWorstVertices);
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep), all.end(),
                    [](const VertexError& a, const VertexError& b) {
                      return a.error != b.error ? a.error > b.error : a.vertex < b.vertex;
                    });
  j.worst.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep));
  return {swapped, off};
}

}  // namespace

Reference referenceDistances(const CrossCheckCase& c) {
  Reference r;
  SolverCase solverCase;
  solverCase.soup = c.soup;
  solverCase.sources = {SurfacePoint::atVertex(c.source)};
  solverCase.rectangle = c.planar == PlanarOracle::Convex;
  solverCase.planar = c.planar != PlanarOracle::None;
  try {
    const Verdict verdict = checkSolver(solverCase);
    if (!verdict.ok()) {
      r.problem = verdict.failed + ": " + verdict.message.substr(0, kMaxProblemChars);
      return r;
    }
    const Mesh mesh(c.soup);
    const SurfacePoint source = SurfacePoint::atVertex(c.source);
    r.distances = exactGeodesicDistance(mesh, {&source, 1});
    addDegeneracies(verdict.degeneracies, r.exercised);
    addMeshLevelCases(mesh, r.exercised);
  } catch (const std::exception& e) {
    r.problem = std::string("geodex refused or failed on the case: ") + e.what();
  }
  return r;
}

ProgramDistances parseDistances(std::string_view text) {
  ProgramDistances out;
  std::size_t lineNumber = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    ++lineNumber;
    const std::optional<double> value = parseValue(line);
    if (!value && out.badLine == 0) {
      out.badLine = lineNumber;
      out.badText = std::string(line.substr(0, 80)) + (line.size() > 80 ? "…" : "");
    }
    out.values.push_back(value.value_or(NAN));
  }
  return out;
}

Judgement judgeDistances(const CrossCheckCase& c, const Reference& reference, const ProgramDistances& got,
                         double tolerance) {
  Judgement j;
  const std::vector<double>& expected = reference.distances;
  for (double d : expected)
    if (std::isfinite(d)) j.largestDistance = std::max(j.largestDistance, d);
  if (got.badLine != 0) {
    j.kind = FindingKind::BadValue;
    j.what = "line " + std::to_string(got.badLine) + " is not a number: '" + got.badText + "'";
    return j;
  }
  if (got.values.size() != expected.size()) {
    j.kind = FindingKind::LineCount;
    j.what = std::to_string(got.values.size()) + " lines for " + std::to_string(expected.size()) + " vertices";
    return j;
  }
  // Relative to the largest distance; a mesh where every distance is 0 (the source alone) is
  // held to its size instead.
  const double scale = j.largestDistance > 0.0 ? j.largestDistance : Mesh(c.soup).boundingBoxDiagonal();
  const double allowed = j.allowed = tolerance * scale;
  const auto [swapped, off] = compare(expected, got.values, allowed, j);
  const bool oraclesOk = runOracles(c, got.values, tolerance, j.oracles);
  if (swapped > 0) {
    const VertexError& w = j.worst.front();
    j.kind = FindingKind::Reachability;
    j.what = vertices(swapped) + (swapped == 1 ? " differs" : " differ") + " in reachability, e.g. vertex " + std::to_string(w.vertex) +
             ": expected " + fmt(w.expected) + ", got " + fmt(w.got);
  } else if (off > 0 || !oraclesOk) {
    j.kind = FindingKind::WrongDistance;
    const double worst = j.worst.empty() ? 0.0 : j.worst.front().error;
    j.what = off > 0 ? vertices(off) + " off by more than " + fmt(tolerance, "%.3g") + " × the largest distance " +
                           fmt(j.largestDistance) + "; worst: vertex " + std::to_string(j.worst.front().vertex) +
                           " off by " + fmt(worst) + " (" + fmt(worst / scale, "%.3g") + " of the largest distance)"
                     : "within the tolerance of geodex, but an oracle fails (below)";
  }
  return j;
}

}  // namespace geodex::verify
