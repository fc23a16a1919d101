// `geodex crosscheck --solver 'CMD' [--cases N] [--seed S] [--time-limit SEC] [--tolerance REL]
//                   [--out DIR] [--mesh FILE --source v:I …] [--max-findings N]
//                   [--minimize-time SEC] [--quiet]`
// Runs another exact-geodesic program on the cases of verify/crosscheck_cases.h (and on given
// meshes), judges each run against geodex's checked distances and the oracles
// (crosscheck_trial.h), minimizes every new kind of finding by removing faces
// (verify/face_minimizer.h) and writes it to DIR/NNN-<kind>/ (crosscheck_report.h).
// Summary on stdout, progress on stderr; exit 0 no finding, 1 findings, 2 bad usage.

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "crosscheck_report.h"
#include "crosscheck_trial.h"
#include "geodex/error.h"
#include "geodex/mesh_io.h"
#include "geodex/verify/face_minimizer.h"

namespace geodex::cli {

namespace {

struct CrossCheckOptions {
  std::string solver;
  std::size_t cases = 100;
  std::uint64_t seed = 1;
  double timeLimit = 10.0;
  double tolerance = 1e-9;
  std::string outDir = "crosscheck-findings";
  std::vector<std::string> meshes;
  std::vector<std::string> sources;
  std::size_t maxFindings = 20;
  double minimizeTime = 60.0;
  bool quiet = false;
};

/// Trials one minimization may make (the deterministic budget; --minimize-time is the other).
constexpr std::size_t kMinimizeMaxTrials = 1000;

// ===  Checking what the user asked for ===========================================================

void checkNumbers(const CrossCheckOptions& o) {
  const auto positive = [](const char* option, double value, const char* what) {
    if (!(std::isfinite(value) && value > 0.0)) {
      throw InputError("usage", std::string(option) + " must be a positive number of " + what + ", not " +
                                    formatDistance(value));
    }
  };
  positive("--time-limit", o.timeLimit, "seconds");
  positive("--minimize-time", o.minimizeTime, "seconds");
  if (!(std::isfinite(o.tolerance) && o.tolerance >= 0.0))
    throw InputError("usage", "--tolerance must be a finite number >= 0 (relative to the largest distance), not " +
                                  formatDistance(o.tolerance));
  if (o.maxFindings == 0) throw InputError("usage", "--max-findings must be at least 1");
}

/// The --mesh files with their --source vertices, as cases (each source on each mesh).
std::vector<std::pair<verify::CrossCheckCase, std::string>> givenCases(const CrossCheckOptions& o) {
  if (o.meshes.empty() && !o.sources.empty()) throw InputError("usage", "--source needs a --mesh to be on");
  if (!o.meshes.empty() && o.sources.empty()) throw InputError("usage", "--mesh needs at least one --source v:I");
  const std::vector<SurfacePoint> sources = parseSurfacePoints(o.sources, "--source");
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (sources[i].kind != SurfacePoint::Kind::Vertex)
      throw InputError("usage", "--source " + o.sources[i] + ": crosscheck runs vertex sources (v:I) only");
  }
  std::vector<std::pair<verify::CrossCheckCase, std::string>> cases;
  for (const std::string& path : o.meshes) {
    const Mesh mesh = loadMeshWithWarnings(path);
    try {
      checkPointsOnMesh(mesh, sources, "--source");
    } catch (const InputError& e) {
      throw InputError(e.kind(), "--mesh " + path + ": " + e.what());
    }
    for (const SurfacePoint& s : sources) {
      verify::CrossCheckCase c{"mesh " + path + " v:" + std::to_string(s.vertex), path, mesh.soup(), s.vertex,
                               verify::PlanarOracle::None};
      c.soup.vertexLines.clear();
      c.soup.faceLines.clear();
      cases.emplace_back(std::move(c), "--mesh " + path + " --source v:" + std::to_string(s.vertex));
    }
  }
  return cases;
}

/// The number the next finding in `dir` gets: one more than the largest NNN-… there, so that a
/// second run beside the first never overwrites it.
std::size_t nextFindingNumber(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw InputError("output", "--out " + dir + ": cannot create the directory" + (error ? ": " + error.message() : ""));
  std::size_t next = 1;
  static const std::regex numbered("([0-9]{3,})-.*");
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, m, numbered)) next = std::max<std::size_t>(next, std::stoull(m[1].str()) + 1);
  }
  return next;
}

/// A fresh directory under $TMPDIR (or /tmp) for one run's case files, removed at the end.
class WorkDir {
 public:
  WorkDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/geodex-crosscheck.XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr)
      throw InputError("output", "cannot create a working directory '" + pattern + "': " + std::strerror(errno));
    path_ = pattern;
  }
  ~WorkDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// ===  The run ====================================================================================

/// Findings with the same key share one reproducer: a crash by how it ended and the first line
/// it printed (the same abort on every mesh is one bug), any other kind by kind and case family
/// (the geometry is what tells a solver's wrong answers apart).
std::string dedupeKey(const Trial& t) {
  const std::string kind(verify::name(*t.kind));
  if (*t.kind != verify::FindingKind::Crash) return kind + " " + t.c.family;
  const std::string firstLine = t.run.output.substr(0, t.run.output.find('\n'));
  return kind + " " + std::to_string(t.run.exitStatus) + " " + std::to_string(t.run.signal) + " " + firstLine;
}

/// What a run has found so far.
struct Tally {
  std::size_t cases = 0, agreed = 0, skipped = 0, findings = 0, notWritten = 0;
  std::map<std::string, std::size_t> byKind;
  std::set<std::string> written;  ///< dedupeKey of each finding written
  std::vector<std::string> lines;  ///< the summary line of each written finding
};

/// The faces a wrong or unreachable vertex's distance can depend on: those within its distance
/// D of the source. A face is kept when a corner is within D + its longest edge (a geodesic may
/// cross a face whose corners are all farther than the points it passes). Empty when the finding
/// names no such vertex.
std::vector<bool> geodesicBall(const Trial& t) {
  if (t.judgement.worst.empty() || !std::isfinite(t.judgement.worst.front().expected)) return {};
  const double radius = t.judgement.worst.front().expected;
  const auto& P = t.c.soup.positions;
  const std::vector<double>& d = t.reference.distances;
  std::vector<bool> keep;
  for (const auto& f : t.c.soup.faces) {
    const double nearest = std::min({d[f[0]], d[f[1]], d[f[2]]});
    const double longest = std::max({(P[f[0]] - P[f[1]]).norm(), (P[f[1]] - P[f[2]]).norm(), (P[f[2]] - P[f[0]]).norm()});
    keep.push_back(nearest <= radius + longest);
  }
  return keep;
}

/// The kinds of validateMesh's warnings a soup gets (non-manifold-vertex, components, …).
std::set<std::string> warningKinds(const TriangleSoup& soup) {
  std::vector<MeshIssue> issues;
  validateMesh(soup, issues);
  std::set<std::string> kinds;
  for (const MeshIssue& issue : issues) kinds.insert(issue.kind);
  return kinds;
}

/// Removes faces from a finding's case while the same kind of finding persists, and without a
/// kind of mesh defect the case did not have: removing faces easily pinches a vertex or splits
/// a part off, and a reproducer of that would be another bug than the one found. Returns the
/// trial of the smallest case (the first one when nothing could go or the program is not
/// repeatable).
Trial minimize(const Trial& first, const CaseRunner& runner, double minimizeSeconds, FindingOrigin& origin) {
  const verify::FindingKind kind = *first.kind;
  verify::CrossCheckCase candidate = first.c;
  // Without some faces a convex domain may be convex no more: the visibility-graph oracle holds
  // for every planar domain.
  if (candidate.planar == verify::PlanarOracle::Convex) candidate.planar = verify::PlanarOracle::Domain;
  const std::set<std::string> defects = warningKinds(first.c.soup);
  const auto stillFails = [&](const TriangleSoup& soup, Index source) {
    if (!std::ranges::includes(defects, warningKinds(soup))) return false;
    candidate.soup = soup;
    candidate.source = source;
    return runner.run(candidate).kind == kind;
  };
  verify::MinimizeBudget budget;
  budget.maxTrials = kMinimizeMaxTrials;
  budget.maxTime = std::chrono::duration<double>(minimizeSeconds);
  const verify::MinimizedCase m =
      verify::minimizeFaces(first.c.soup, first.c.source, stillFails, budget, geodesicBall(first));
  origin.trials = m.trials;
  origin.stoppedBy = m.stoppedBy;
  if (m.soup.faces.size() == first.c.soup.faces.size()) return first;
  candidate.soup = m.soup;
  candidate.source = m.source;
  Trial smallest = runner.run(candidate);
  return smallest.kind == kind ? smallest : first;
}

class CrossCheckRun {
 public:
  CrossCheckRun(const CrossCheckOptions& o, const CaseRunner& runner, std::size_t firstNumber)
      : o_(o), runner_(runner), number_(firstNumber) {}

  /// Runs one case; a new kind of finding is minimized and written.
  void check(const verify::CrossCheckCase& c, const std::string& label) {
    ++tally_.cases;
    const Trial t = runner_.run(c);
    if (t.skipped()) {
      ++tally_.skipped;
      std::cerr << "warning: " << label << " (" << c.family << ") not judged: geodex's own check failed: "
                << t.reference.problem.substr(0, 400) << "\n";
      return;
    }
    if (!t.kind) {
      ++tally_.agreed;
      progress(label, c, "ok");
      return;
    }
    const std::string kind(verify::name(*t.kind));
    ++tally_.findings;
    ++tally_.byKind[kind];
    if (!tally_.written.insert(dedupeKey(t)).second) {
      ++tally_.notWritten;
      progress(label, c, kind + " (as before: " + t.judgement.what + ")");
      return;
    }
    progress(label, c, kind + ": " + t.judgement.what + "; minimizing");
    write(t, label);
  }

  bool full() const { return tally_.written.size() >= o_.maxFindings; }
  const Tally& tally() const { return tally_; }

 private:
  void progress(const std::string& label, const verify::CrossCheckCase& c, const std::string& what) const {
    if (!o_.quiet)
      std::cerr << label << " " << c.family << " (" << c.soup.faces.size() << " faces, v:" << c.source << "): " << what
                << "\n";
  }

  void write(const Trial& first, const std::string& label) {
    FindingOrigin origin{label, first.c.soup, first.c.source, first.c.soup.faces.size(),
                         first.c.soup.positions.size(), 0, ""};
    const Trial smallest = minimize(first, runner_, o_.minimizeTime, origin);
    char number[16];
    std::snprintf(number, sizeof number, "%03zu", number_++);
    const std::string name = std::string(number) + "-" + std::string(verify::name(*smallest.kind));
    writeFinding(o_.outDir + "/" + name, smallest, origin, runner_);
    const std::string line = name + "  " + smallest.c.family + " (" + label + "): " +
                             std::to_string(origin.originalFaces) + " -> " +
                             std::to_string(smallest.c.soup.faces.size()) + " faces; " + smallest.judgement.what;
    tally_.lines.push_back(line);
    if (!o_.quiet) std::cerr << "  wrote " << o_.outDir << "/" << name << " (" << origin.trials << " trials)\n";
  }

  const CrossCheckOptions& o_;
  const CaseRunner& runner_;
  std::size_t number_;
  Tally tally_;
};

void printSummary(const CrossCheckOptions& o, const Tally& t, bool stoppedEarly) {
  std::cout << "crosscheck: " << t.cases << " cases (seed " << o.seed << "): " << t.agreed << " agree, "
            << t.findings << " with findings, " << t.skipped << " not judged (geodex's own check failed)\n";
  if (stoppedEarly) std::cout << "stopped after " << o.maxFindings << " findings written (--max-findings)\n";
  if (t.findings == 0) return;
  std::cout << "findings by kind:";
  for (const auto& [kind, count] : t.byKind) std::cout << " " << kind << " " << count;
  std::cout << "\nwritten to " << o.outDir << "/ (minimized; one per kind and case family, one per crash):\n";
  for (const std::string& line : t.lines) std::cout << "  " << line << "\n";
  if (t.notWritten > 0)
    std::cout << t.notWritten << " more cases had a finding like one written above\n";
}

int runCrossCheck(const CrossCheckOptions& o) {
  // Every mistake in the command line is reported before the first case runs.
  checkCommandTemplate(o.solver);
  checkNumbers(o);
  const auto given = givenCases(o);
  const std::size_t firstNumber = nextFindingNumber(o.outDir);
  const WorkDir work;
  const CaseRunner runner(o.solver, o.timeLimit, o.tolerance, work.path());
  CrossCheckRun run(o, runner, firstNumber);

  bool stoppedEarly = false;
  for (const auto& [c, label] : given) {
    if ((stoppedEarly = run.full())) break;
    run.check(c, label);
  }
  for (std::size_t i = 0; i < o.cases && !stoppedEarly; ++i) {
    if ((stoppedEarly = run.full())) break;
    run.check(verify::crossCheckCase(o.seed, i), "case " + std::to_string(i) + " of seed " + std::to_string(o.seed));
  }
  printSummary(o, run.tally(), stoppedEarly);
  return run.tally().findings > 0 ? kExitCheckFailed : kExitOk;
}

/// Digits only, at most 18 of them (what a 64-bit count holds without wrapping): what the
/// counts and the seed accept.
CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](std::string& text) {
        const bool digits = !text.empty() && text.size() <= 18 && text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? std::string() : "must be a whole number from 0 to 10^18 - 1, not '" + text + "'";
      },
      "");
}

}  // namespace

Command addCrossCheckCommand(CLI::App& app) {
  auto o = std::make_shared<CrossCheckOptions>();
  CLI::App* sub = app.add_subcommand(
      "crosscheck", "Fuzz another exact-geodesic program against geodex and the oracles; minimized "
                    "reproducers of what it gets wrong");
  sub->add_option("--solver", o->solver,
                  "Command template, run through the shell: {mesh} an OFF file, {source} a 0-based vertex, "
                  "{out} the file to write one distance per vertex to (inf, nan, negative or >= 1e99: "
                  "unreachable)")
      ->required()
      ->type_name("'CMD'");
  // wholeNumber(): CLI11 would otherwise read -3 into an unsigned option as a huge number.
  sub->add_option("--cases", o->cases, "Generated cases to run, small ones first (default 100)")
      ->type_name("N")
      ->check(wholeNumber());
  sub->add_option("--seed", o->seed, "The cases' seed: the same seed runs the same cases in the same order "
                                     "(default 1)")
      ->type_name("S")
      ->check(wholeNumber());
  sub->add_option("--time-limit", o->timeLimit, "Seconds one run may take before its process group is "
                                                "killed and it counts as a timeout (default 10)")
      ->type_name("SEC");
  sub->add_option("--tolerance", o->tolerance, "Allowed |got - expected|, relative to the largest distance "
                                               "(default 1e-9)")
      ->type_name("REL");
  sub->add_option("--out", o->outDir, "Where findings go, as NNN-<kind>/ (default crosscheck-findings)")
      ->type_name("DIR");
  sub->add_option("--mesh", o->meshes, "A mesh of your own (OFF, OBJ or PLY) to run first, repeatable")
      ->type_name("FILE");
  sub->add_option("--source,-s", o->sources, "Source vertex on every --mesh, repeatable: v:I")->type_name("v:I");
  sub->add_option("--max-findings", o->maxFindings, "Stop after writing this many findings (default 20)")
      ->type_name("N")
      ->check(wholeNumber());
  sub->add_option("--minimize-time", o->minimizeTime, "Seconds minimizing one finding may take at most "
                                                      "(default 60)")
      ->type_name("SEC");
  sub->add_flag("--quiet,-q", o->quiet, "No progress on stderr (one line per case)");
  sub->footer("Findings: DIR/NNN-<kind>/ (mesh.off, source.txt, expected.txt, got.txt, report.txt, picture.png, "
              "original.off); kinds: wrong-distance, reachability, line-count, bad-value, crash, timeout.\n"
              "Exit codes: 0 no finding, 1 findings, 2 bad usage. docs/crosscheck.md has more.");
  return {sub, [o] { return runCrossCheck(*o); }};
}

}  // namespace geodex::cli
