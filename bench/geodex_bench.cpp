// geodex_bench: single-source, all-vertex exact geodesic distances on a fixed set of synthetic
// and real meshes, against CGAL's Surface_mesh_shortest_path and the edge-graph Dijkstra floor,
// all measured in the same run (DESIGN.md, "bench/"; what is timed: docs/benchmarks.md).
//
//   geodex_bench [--json FILE] [--runs N] [--only NAME,...] [--big] [--no-cgal] ...
//
// Per mesh (one source, mesh already loaded and its connectivity built, nothing read from disk
// inside a timed region):
//   clock      thread CPU time (CLOCK_THREAD_CPUTIME_ID): the machine is shared and wall time
//              grows with other processes' load; wall times are kept in the JSON too
//   geodex     GeodesicSolver construction + solve(): median of --runs runs after one warm-up run
//   CGAL       CgalGeodesicOracle::solve (add_source_point + build_sequence_tree) and
//              vertexDistances (one shortest_distance_to_source_points query per vertex), median
//              of --cgal-runs, a fresh oracle per run; building the CGAL Surface_mesh and the
//              Surface_mesh_shortest_path object is not timed, just as geodex's Mesh
//              construction is not
//   Dijkstra   verify::edgeGraphDijkstra from the source vertex: the floor any exact method pays
//   memory     RSS high-water mark of a forked child doing one solve, minus its RSS just before
//              (after malloc_trim, with the high-water mark reset through /proc/self/clear_refs)
//   hooks      solve with a no-op SolverObserver attached vs none (interleaved runs), and with
//              verify::InvariantChecker at CheckLevel::Cheap and ::Full
// A Markdown table goes to stdout, progress to stderr, everything to --json FILE.

#include <malloc.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "geodex/geodesic_solver.h"
#include "geodex/mesh.h"
#include "geodex/mesh_io.h"
#include "geodex/observer.h"
#include "geodex/surface_point.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/mesh_generators.h"
#include "geodex/verify/oracles.h"
#ifdef GEODEX_HAVE_CGAL_ORACLE
#include "geodex/verify/cgal_oracle.h"
#endif

namespace {

using namespace geodex;
using Clock = std::chrono::steady_clock;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// === Options =====================================================================================

struct Options {
  std::string cgalMeshDir = GEODEX_CGAL_MESH_DIR;
  std::string sharedMeshDir = GEODEX_SHARED_MESH_DIR;
  std::string jsonPath;
  int runs = 3;        ///< timed geodex / Dijkstra / tier runs per mesh (median)
  int cgalRuns = 3;    ///< timed CGAL runs per mesh (median)
  /// Interleaved (none, no-op observer) pairs per mesh: at least 3, then more until they have
  /// taken hookBudgetSeconds or there are hookMaxPairs. Small meshes get many pairs, so an
  /// overhead of a few percent stands out of the noise.
  int hookMaxPairs = 200;
  double hookBudgetSeconds = 10;
  /// The full tier samples every edge update against the list before it: on meshes with many
  /// intervals per edge it costs minutes. Above this many faces it is skipped.
  std::size_t fullTierMaxFaces = 25000;
  bool big = false;    ///< also the 871K-face dragon (geodex and Dijkstra only)
  bool cgal = true;
  bool tiers = true;
  bool memory = true;
  std::vector<std::string> only;  ///< case names to run (all when empty)
};

void usage() {
  std::cerr <<
      "usage: geodex_bench [options]\n"
      "  --json FILE            also write every figure as JSON\n"
      "  --runs N               timed geodex/Dijkstra/tier runs per mesh, median (default 3)\n"
      "  --cgal-runs N          timed CGAL runs per mesh, median (default 3)\n"
      "  --hook-budget S        interleaved none/no-op-observer pairs per mesh: at least 3,\n"
      "                         more until S seconds have passed (default 10)...\n"
      "  --hook-max-pairs N     ...or there are N pairs (default 200)\n"
      "  --full-tier-max-faces N  skip the full invariant tier above N faces (default 25000)\n"
      "  --only A,B,...         run only these cases (see --list)\n"
      "  --list                 list the cases and exit\n"
      "  --big                  add the 871K-face dragon from the shared meshes (no CGAL)\n"
      "  --no-cgal, --no-tiers, --no-memory   skip those measurements\n"
      "  --meshes DIR           libcgal-demo meshes (default: the build tree's data/meshes)\n"
      "  --shared-meshes DIR    ../shared/meshes\n";
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// === Measuring ===================================================================================

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// CPU time of the calling thread. Every timed region is single-threaded, so this is the work it
/// did; unlike wall time it does not grow while other processes hold the cores (this machine is
/// shared). Cache and memory-bandwidth interference from them still count.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Both clocks from one start.
class Stopwatch {
 public:
  double cpu() const { return threadCpuSeconds() - cpu0_; }
  double wall() const { return secondsSince(wall0_); }

 private:
  double cpu0_ = threadCpuSeconds();
  Clock::time_point wall0_ = Clock::now();
};

struct Timing {
  std::vector<double> cpu, wall;
  void add(const Stopwatch& w) {
    cpu.push_back(w.cpu());
    wall.push_back(w.wall());
  }
};

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The ratios checked[i] / unchecked[i] of solves run in pairs, sorted.
std::vector<double> pairwiseRatios(const Timing& checked, const Timing& unchecked) {
  std::vector<double> ratios;
  for (std::size_t i = 0; i < checked.cpu.size() && i < unchecked.cpu.size(); ++i)
    ratios.push_back(checked.cpu[i] / unchecked.cpu[i]);
  std::sort(ratios.begin(), ratios.end());
  return ratios;
}

/// A field of /proc/self/status in kB ("VmRSS", "VmHWM"); -1 if absent.
long statusKiloBytes(const char* field) {
  std::ifstream in("/proc/self/status");
  const std::string prefix = std::string(field) + ":";
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) return std::strtol(line.c_str() + prefix.size(), nullptr, 10);
  return -1;
}

/// Peak extra resident memory of `work`, in MB: run in a forked child whose free heap pages are
/// first returned to the kernel (malloc_trim) and whose RSS high-water mark is reset to its
/// current RSS (`echo 5 > /proc/self/clear_refs`, Linux ≥ 4.0); the figure is VmHWM after `work`
/// minus VmRSS before it. Everything `work` allocates and touches counts, including memory freed
/// before it returns, and the few code pages it faults in; pages the child shares with the
/// parent (the mesh, already resident) do not. NaN if the mark cannot be reset or the child fails.
double peakExtraMegabytes(const std::function<void()>& work) {
  int pipeFds[2];
  if (pipe(pipeFds) != 0) return kNaN;
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) return kNaN;
  if (pid == 0) {
    close(pipeFds[0]);
    double mb = kNaN;
    malloc_trim(0);
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5" << std::flush;
    const bool cleared = clear.good();
    clear.close();
    const long before = statusKiloBytes("VmRSS");
    // The reset worked if the mark is back near the current RSS (a few pages of code and
    // stack may fault in between).
    const bool reset = cleared && statusKiloBytes("VmHWM") <= before + 1024;
    if (reset) {
      try {
        work();
        mb = double(statusKiloBytes("VmHWM") - before) / 1024.0;
      } catch (...) {
      }
    }
    const ssize_t written = write(pipeFds[1], &mb, sizeof mb);
    _exit(written == sizeof mb ? 0 : 1);
  }
  close(pipeFds[1]);
  double mb = kNaN;
  if (read(pipeFds[0], &mb, sizeof mb) != sizeof mb) mb = kNaN;
  close(pipeFds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return mb;
}

/// An observer that does nothing: what attaching one costs is the solver building its events.
class NoopObserver final : public SolverObserver {};

// === The cases ===================================================================================

/// Kirsanov's MMP on this machine and the target ratio for geodex (the reference figures of
/// docs/benchmarks.md).
struct Reference {
  double kirsanovRatio;    ///< CGAL Epick time / Kirsanov MMP time
  double kirsanovSeconds;
  double kirsanovMegabytes;
  double targetRatio;      ///< required CGAL / geodex
};

struct Case {
  std::string name;
  std::string origin;  ///< "synthetic", "libcgal-demo" or "shared"
  std::string description;
  std::function<TriangleSoup()> generate;  ///< synthetic cases
  std::string file;                        ///< file cases: the name inside their directory
  std::function<Index(const TriangleSoup&)> source;
  std::string sourceDescription;
  std::optional<Reference> reference;
  bool bigOnly = false;  ///< only with --big; CGAL skipped (it runs out of memory there)
};

Index nearestVertex(const TriangleSoup& soup, const Vec3& p) {
  Index best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (Index v = 0; v < soup.positions.size(); ++v) {
    const double d = (soup.positions[v] - p).squaredNorm();
    if (d < bestDistance) bestDistance = d, best = v;
  }
  return best;
}

Index highestVertex(const TriangleSoup& soup) {
  Index best = 0;
  for (Index v = 1; v < soup.positions.size(); ++v)
    if (soup.positions[v].z() > soup.positions[best].z()) best = v;
  return best;
}

std::vector<Case> allCases() {
  using verify::DiagonalPattern;
  std::vector<Case> cases;
  auto at = [](double x, double y) {
    return [x, y](const TriangleSoup& s) { return nearestVertex(s, Vec3(x, y, 0.0)); };
  };
  cases.push_back({"flat-grid", "synthetic", "gridMesh(100, 100, 1, 1), all diagonals one way",
                   [] { return verify::gridMesh(100, 100, 1.0, 1.0, DiagonalPattern::AllOneWay); },
                   "", at(0.5, 0.5), "centre vertex (0.5, 0.5)",
                   Reference{9.1, 0.36, 43, 27}});
  cases.push_back({"jittered-grid", "synthetic",
                   "jitteredGridMesh(100, 100, 1, 1, 0.15, seed 1)",
                   [] { return verify::jitteredGridMesh(100, 100, 1.0, 1.0, 0.15, 1); }, "",
                   at(0.5, 0.5), "vertex nearest (0.5, 0.5)", Reference{5.4, 0.73, 63, 16}});
  cases.push_back({"l-domain", "synthetic", "lShapeMesh(116, 1): 20,184 faces",
                   [] { return verify::lShapeMesh(116, 1.0); }, "", at(0.9, 0.1),
                   "vertex nearest (0.9, 0.1): the reflex corner shadows the upper arm",
                   Reference{8.7, 0.22, 30, 26}});
  cases.push_back({"icosphere-82k", "synthetic", "icosphereMesh(6, 1): 81,920 faces",
                   [] { return verify::icosphereMesh(6, 1.0); }, "",
                   [](const TriangleSoup&) { return Index{0}; }, "vertex 0",
                   Reference{2.8, 3.7, 283, 8.5}});
  cases.push_back({"uv-sphere-pole", "synthetic", "uvSphereMesh(100, 100, 1): 19,800 faces",
                   [] { return verify::uvSphereMesh(100, 100, 1.0); }, "", highestVertex,
                   "the north pole (valence 100)", std::nullopt});
  auto vertex0 = [](const TriangleSoup&) { return Index{0}; };
  for (const auto& [file, what] : std::vector<std::pair<std::string, std::string>>{
           {"mushroom.off", "closed, smooth"},
           {"fandisk.off", "CAD: coplanar faces, flat vertices"},
           {"cylinder_locally_refined.off", "mixed resolution"},
           {"armadillo.off", "closed scan"},
           {"bunny00.off", "scan"},
           {"refined_elephant.off", "closed, refined"}}) {
    const std::string name = file.substr(0, file.rfind('.'));
    cases.push_back({name, "libcgal-demo", what, {}, file, vertex0, "vertex 0", std::nullopt});
  }
  Case dragon{"dragon-871k", "shared", "dragon_vrip_welded.obj: 871,306 faces, closed, genus 55",
              {}, "dragon_vrip_welded.obj", vertex0, "vertex 0", std::nullopt};
  dragon.bigOnly = true;
  cases.push_back(dragon);
  return cases;
}

// === One case ====================================================================================

struct Result {
  std::string name, origin, description, sourceDescription;
  std::size_t vertices = 0, faces = 0, edges = 0;
  Index source = 0;
  bool skipped = false;
  std::string skipReason;
  // geodex (all *Seconds: median thread CPU time; the per-run lists keep CPU and wall time)
  Timing geodexRuns;
  double geodexSeconds = kNaN;
  double geodexMegabytes = kNaN;
  SolveStats stats;
  // CGAL
  Timing cgalRuns;
  std::vector<double> cgalOwnWallRuns;  ///< CgalTiming::sequenceTreeSeconds + querySeconds
  double cgalSeconds = kNaN;
  double cgalMegabytes = kNaN;
  std::string cgalError;
  double maxAbsDiff = kNaN;      ///< max over vertices |geodex − CGAL|
  double maxRelDiff = kNaN;      ///< maxAbsDiff / bounding-box diagonal
  std::size_t verticesOver1e6 = 0;  ///< vertices with |Δ| > 1e-6 × diagonal
  // floor
  Timing dijkstraRuns;
  double dijkstraSeconds = kNaN;
  // hooks and tiers
  Timing noneRuns, noopRuns, cheapRuns, fullRuns;
  /// The unchecked solve run just before each tier run, and the median of the pairwise ratios.
  Timing cheapBaseRuns, fullBaseRuns;
  double cheapRatio = kNaN, fullRatio = kNaN;
  double noopRatioQ1 = kNaN, noopRatioQ3 = kNaN;  ///< quartiles of the pairwise ratios
  double noneSeconds = kNaN, noopSeconds = kNaN, cheapSeconds = kNaN, fullSeconds = kNaN;
  std::uint64_t cheapViolations = 0, fullViolations = 0;
  std::string firstViolation;
  std::string fullSkipReason;
  std::optional<Reference> reference;

  double cgalRatio() const { return cgalSeconds / geodexSeconds; }
};

/// Solves once on a fresh solver with `observer`, adding the time it took (construction and
/// solve; not the solver's destruction) to `runs`.
void timeSolve(const Mesh& mesh, const std::vector<SurfacePoint>& sources,
               SolverObserver* observer, Timing& runs) {
  const Stopwatch watch;
  GeodesicSolver solver(mesh);
  solver.setObserver(observer);
  solver.solve(sources);
  runs.add(watch);
}

void runCase(const Case& c, const Options& options, Result& r) {
  r.name = c.name;
  r.origin = c.origin;
  r.description = c.description;
  r.sourceDescription = c.sourceDescription;
  r.reference = c.reference;

  std::optional<Mesh> loaded;
  if (c.generate) {
    loaded.emplace(c.generate());
  } else {
    const std::string dir = c.origin == "shared" ? options.sharedMeshDir : options.cgalMeshDir;
    const std::string path = (std::filesystem::path(dir) / c.file).string();
    if (!std::filesystem::exists(path)) {
      r.skipped = true;
      r.skipReason = path + " not found";
      return;
    }
    std::cerr << "  loading " << path << "\n";
    loaded.emplace(loadMesh(path));
  }
  const Mesh& mesh = *loaded;
  const TriangleSoup& soup = mesh.soup();
  r.vertices = mesh.numVertices();
  r.faces = mesh.numFaces();
  r.edges = mesh.numEdges();
  r.source = c.source(soup);
  const std::vector<SurfacePoint> sources{SurfacePoint::atVertex(r.source)};
  const double diagonal = mesh.boundingBoxDiagonal();

  // --- geodex: memory first (a clean heap in the child), then a warm-up run that keeps the
  //     distances and statistics, then the timed runs.
  if (options.memory) {
    r.geodexMegabytes = peakExtraMegabytes([&] {
      GeodesicSolver solver(mesh);
      solver.solve(sources);
    });
  }
  std::vector<double> distances;
  {
    GeodesicSolver solver(mesh);
    solver.solve(sources);
    r.stats = solver.stats();
    distances.assign(solver.vertexDistances().begin(), solver.vertexDistances().end());
  }
  for (int i = 0; i < options.runs; ++i) timeSolve(mesh, sources, nullptr, r.geodexRuns);
  r.geodexSeconds = median(r.geodexRuns.cpu);
  std::cerr << "  geodex " << r.geodexSeconds << " s, " << r.stats.intervalsCreated
            << " intervals created, " << r.stats.intervalsAtEnd << " at end\n";

  // --- the Dijkstra floor
  {
    const std::vector<std::pair<Index, double>> start{{r.source, 0.0}};
    for (int i = 0; i < options.runs; ++i) {
      const Stopwatch watch;
      const auto d = verify::edgeGraphDijkstra(mesh, start);
      r.dijkstraRuns.add(watch);
      if (d.size() != mesh.numVertices()) std::abort();
    }
    r.dijkstraSeconds = median(r.dijkstraRuns.cpu);
  }

  // --- CGAL
#ifdef GEODEX_HAVE_CGAL_ORACLE
  if (options.cgal && !c.bigOnly) {
    try {
      // A fresh oracle per run (its Surface_mesh and shortest-path object are built untimed), so
      // no run pays for tearing down the previous sequence tree; geodex's runs do not either.
      if (options.memory) {
        verify::CgalGeodesicOracle oracle(soup);
        r.cgalMegabytes = peakExtraMegabytes([&] {
          oracle.solve(sources);
          (void)oracle.vertexDistances();
        });
      }
      std::vector<double> cgalDistances;
      for (int i = 0; i < options.cgalRuns; ++i) {
        verify::CgalGeodesicOracle oracle(soup);
        const Stopwatch watch;
        oracle.solve(sources);
        cgalDistances = oracle.vertexDistances();
        r.cgalRuns.add(watch);
        r.cgalOwnWallRuns.push_back(oracle.timing().sequenceTreeSeconds +
                                    oracle.timing().querySeconds);
      }
      r.cgalSeconds = median(r.cgalRuns.cpu);
      r.maxAbsDiff = 0.0;
      for (std::size_t v = 0; v < distances.size(); ++v) {
        const double a = distances[v], b = cgalDistances[v];
        if (std::isinf(a) && std::isinf(b)) continue;
        const double diff = std::abs(a - b);  // +inf when only one is infinite
        r.maxAbsDiff = std::max(r.maxAbsDiff, diff);
        if (!(diff <= 1e-6 * diagonal)) ++r.verticesOver1e6;
      }
      r.maxRelDiff = r.maxAbsDiff / diagonal;
      std::cerr << "  CGAL " << r.cgalSeconds << " s, ratio " << r.cgalRatio()
                << ", max |diff|/diag " << r.maxRelDiff << "\n";
    } catch (const std::exception& e) {
      r.cgalError = e.what();
      std::cerr << "  CGAL failed: " << e.what() << "\n";
    }
  }
#endif

  // --- hooks and verify tiers
  if (options.tiers) {
    NoopObserver noop;
    const auto t0 = Clock::now();
    for (int i = 0; i < options.hookMaxPairs; ++i) {  // interleaved: drift hits both alike
      if (i >= 3 && secondsSince(t0) > options.hookBudgetSeconds) break;
      timeSolve(mesh, sources, nullptr, r.noneRuns);
      timeSolve(mesh, sources, &noop, r.noopRuns);
    }
    r.noneSeconds = median(r.noneRuns.cpu);
    r.noopSeconds = median(r.noopRuns.cpu);
    const std::vector<double> ratios = pairwiseRatios(r.noopRuns, r.noneRuns);
    r.noopRatioQ1 = ratios[ratios.size() / 4];
    r.noopRatioQ3 = ratios[(3 * ratios.size()) / 4];
    // Each tier run follows an unchecked solve, and the tier's figure is the median of the
    // pairwise ratios: a machine's speed can drift by tens of percent over minutes, and a ratio
    // of medians taken minutes apart moves with it.
    auto tier = [&](verify::CheckLevel level, std::uint64_t& violations, Timing& runs,
                    Timing& base) {
      for (int i = 0; i < options.runs; ++i) {
        timeSolve(mesh, sources, nullptr, base);
        verify::InvariantChecker checker(level, /*throwOnViolation=*/false);
        timeSolve(mesh, sources, &checker, runs);
        violations = checker.violations();
        if (violations > 0 && r.firstViolation.empty() && checker.firstViolation() != nullptr)
          r.firstViolation = checker.firstViolation()->invariant() + ": " +
                             checker.firstViolation()->what();
      }
      return median(pairwiseRatios(runs, base));
    };
    r.cheapRatio = tier(verify::CheckLevel::Cheap, r.cheapViolations, r.cheapRuns, r.cheapBaseRuns);
    r.cheapSeconds = median(r.cheapRuns.cpu);
    if (mesh.numFaces() <= options.fullTierMaxFaces) {
      r.fullRatio = tier(verify::CheckLevel::Full, r.fullViolations, r.fullRuns, r.fullBaseRuns);
      r.fullSeconds = median(r.fullRuns.cpu);
    } else {
      r.fullSkipReason = "more than " + std::to_string(options.fullTierMaxFaces) + " faces";
    }
    std::cerr << "  hooks: no-op " << r.noopSeconds / r.noneSeconds << "x, cheap " << r.cheapRatio
              << "x, full " << r.fullRatio << "x\n";
  }
}

// === Output ======================================================================================

std::string fixed(double x, int digits) {
  if (std::isnan(x)) return "n/a";
  if (std::isinf(x)) return "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string sci(double x) {
  if (std::isnan(x)) return "n/a";
  if (std::isinf(x)) return "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}

std::string milliseconds(double seconds) {
  if (std::isnan(seconds)) return "n/a";
  return fixed(seconds * 1e3, seconds < 0.1 ? 1 : 0);
}

std::string thousands(std::uint64_t n) {
  const std::string digits = std::to_string(n);
  std::string s;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) s += ',';
    s += digits[i];
  }
  return s;
}

/// The 1-minute load average: above ~1 on this machine other work competed for the cores.
std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty() ? "unknown" : one;
}

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

struct RunInfo {
  std::string loadBefore, loadAfter;
  double seconds = 0.0;
};

void printMarkdown(const std::vector<Result>& results, const Options& options,
                   const RunInfo& info, std::ostream& out) {
  out << "Machine: " << cpuModel() << ", " << std::thread::hardware_concurrency()
      << " hardware threads (all runs single-threaded); 1-minute load average " << info.loadBefore
      << " before, " << info.loadAfter << " after; the whole run took "
      << fixed(info.seconds / 60.0, 1) << " min.\n"
      << "Times in ms of thread CPU time: geodex and Dijkstra median of " << options.runs
      << ", CGAL median of "
      << options.cgalRuns << "; one source vertex per mesh. Memory: peak extra RSS of one solve. "
      << "Max abs diff: max over vertices |geodex − CGAL| / bounding-box diagonal.\n\n";
  out << "| mesh | V | F | geodex ms | CGAL ms | CGAL/geodex | target | met | Kirsanov ratio "
         "| Dijkstra ms | geodex/Dijkstra | geodex MB | CGAL MB | intervals created | at end "
         "| per edge | max per edge | max abs diff / diag |\n";
  out << "|---|--:|--:|--:|--:|--:|--:|:-:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const Result& r : results) {
    if (r.skipped) {
      out << "| " << r.name << " | skipped: " << r.skipReason << " |||||||||||||||||\n";
      continue;
    }
    const double ratio = r.cgalRatio();
    std::string target = "–", met = "–", kirsanov = "–";
    if (r.reference) {
      target = "≥ " + fixed(r.reference->targetRatio, 1);
      kirsanov = fixed(r.reference->kirsanovRatio, 1);
      met = std::isnan(ratio) ? "n/a" : ratio >= r.reference->targetRatio ? "yes" : "**no**";
    }
    out << "| " << r.name << " | " << thousands(r.vertices) << " | " << thousands(r.faces)
        << " | " << milliseconds(r.geodexSeconds) << " | "
        << (r.cgalError.empty() ? milliseconds(r.cgalSeconds) : "error") << " | "
        << fixed(ratio, 1) << " | " << target << " | " << met << " | " << kirsanov << " | "
        << milliseconds(r.dijkstraSeconds) << " | " << fixed(r.geodexSeconds / r.dijkstraSeconds, 1)
        << " | " << fixed(r.geodexMegabytes, 1) << " | " << fixed(r.cgalMegabytes, 1) << " | "
        << thousands(r.stats.intervalsCreated) << " | " << thousands(r.stats.intervalsAtEnd)
        << " | " << fixed(double(r.stats.intervalsAtEnd) / double(r.edges), 2) << " | "
        << r.stats.maxIntervalsPerEdge << " | " << sci(r.maxRelDiff) << " |\n";
  }
  if (!options.tiers) return;
  out << "\nHooks and verify tiers: solve time with an observer attached, relative to none. "
         "None and no-op are run as interleaved pairs (at least 3, more for up to "
      << fixed(options.hookBudgetSeconds, 0) << " s, at most " << options.hookMaxPairs
      << "), medians compared; [q1, q3]: quartiles of the pairwise no-op/none ratios, a "
         "measure of the noise. Tiers: each of "
      << options.runs
      << " checked solves follows an unchecked one; the median of those pairwise ratios. The full "
         "tier runs only up to "
      << thousands(options.fullTierMaxFaces) << " faces.\n\n";
  out << "| mesh | pairs | none ms | no-op observer | [q1, q3] | cheap tier | full tier | violations (cheap / full) |\n";
  out << "|---|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const Result& r : results) {
    if (r.skipped) continue;
    auto ratio = [&](double t) { return std::isnan(t) ? std::string("–") : fixed(t / r.noneSeconds, 3) + "×"; };
    out << "| " << r.name << " | " << r.noneRuns.cpu.size() << " | " << milliseconds(r.noneSeconds)
        << " | " << ratio(r.noopSeconds) << " | [" << fixed(r.noopRatioQ1, 3) << ", "
        << fixed(r.noopRatioQ3, 3) << "]"
        << " | " << fixed(r.cheapRatio, 3) << "×"
        << " | " << (std::isnan(r.fullRatio) ? std::string("skipped") : fixed(r.fullRatio, 3) + "×")
        << " | " << r.cheapViolations << " / "
        << (std::isnan(r.fullSeconds) ? std::string("–") : std::to_string(r.fullViolations))
        << " |\n";
  }
  for (const Result& r : results)
    if (!r.firstViolation.empty())
      out << "\nFirst violation on " << r.name << ": " << r.firstViolation << "\n";
  for (const Result& r : results)
    if (!r.cgalError.empty()) out << "\nCGAL failed on " << r.name << ": " << r.cgalError << "\n";
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\', out += ch;
    else if (static_cast<unsigned char>(ch) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", ch);
      out += buf;
    } else out += ch;
  }
  return out + "\"";
}

std::string jsonNumber(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

std::string jsonArray(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + jsonNumber(v[i]);
  return out + "]";
}

std::string jsonTiming(const Timing& t) {
  return "{\"cpu\": " + jsonArray(t.cpu) + ", \"wall\": " + jsonArray(t.wall) + "}";
}

void writeJson(const std::vector<Result>& results, const Options& options, const RunInfo& info,
               const std::string& path) {
  std::ofstream out(path);
  out << "{\n  \"machine\": {\"cpu\": " << jsonString(cpuModel())
      << ", \"hardware_threads\": " << std::thread::hardware_concurrency()
      << ", \"load_before\": " << jsonString(info.loadBefore)
      << ", \"load_after\": " << jsonString(info.loadAfter) << "},\n"
      << "  \"total_seconds\": " << jsonNumber(info.seconds) << ",\n"
      << "  \"runs\": " << options.runs << ", \"cgal_runs\": " << options.cgalRuns
      << ", \"hook_budget_seconds\": " << options.hookBudgetSeconds
      << ", \"hook_max_pairs\": " << options.hookMaxPairs
      << ", \"full_tier_max_faces\": " << options.fullTierMaxFaces << ",\n"
      << "  \"timed\": {\"clock\": \"*_seconds: median thread CPU time "
         "(CLOCK_THREAD_CPUTIME_ID); *_runs: cpu and wall (steady_clock) per run\", "
         "\"geodex\": \"GeodesicSolver construction + solve(), mesh built\", "
         "\"cgal\": \"CgalGeodesicOracle::solve (add_source_point + build_sequence_tree) + "
         "vertexDistances (shortest_distance_to_source_points per vertex), fresh oracle per run, "
         "Surface_mesh built\", \"dijkstra\": \"verify::edgeGraphDijkstra\", "
         "\"memory\": \"VmHWM - VmRSS around one solve in a forked child after malloc_trim and "
         "clear_refs=5\"},\n  \"cases\": [\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const Result& r = results[i];
    out << "    {\"name\": " << jsonString(r.name) << ", \"origin\": " << jsonString(r.origin)
        << ", \"description\": " << jsonString(r.description);
    if (r.skipped) {
      out << ", \"skipped\": " << jsonString(r.skipReason) << "}";
    } else {
      out << ", \"vertices\": " << r.vertices << ", \"faces\": " << r.faces
          << ", \"edges\": " << r.edges << ", \"source_vertex\": " << r.source
          << ", \"source\": " << jsonString(r.sourceDescription)
          << ",\n     \"geodex_seconds\": " << jsonNumber(r.geodexSeconds)
          << ", \"geodex_runs\": " << jsonTiming(r.geodexRuns)
          << ", \"geodex_megabytes\": " << jsonNumber(r.geodexMegabytes)
          << ",\n     \"intervals_created\": " << r.stats.intervalsCreated
          << ", \"intervals_at_end\": " << r.stats.intervalsAtEnd
          << ", \"intervals_propagated\": " << r.stats.intervalsPropagated
          << ", \"pseudo_source_events\": " << r.stats.pseudoSourceEvents
          << ", \"max_intervals_per_edge\": " << r.stats.maxIntervalsPerEdge
          << ",\n     \"cgal_seconds\": " << jsonNumber(r.cgalSeconds)
          << ", \"cgal_runs\": " << jsonTiming(r.cgalRuns)
          << ", \"cgal_oracle_wall_runs\": " << jsonArray(r.cgalOwnWallRuns)
          << ", \"cgal_megabytes\": " << jsonNumber(r.cgalMegabytes)
          << ", \"cgal_error\": " << (r.cgalError.empty() ? "null" : jsonString(r.cgalError))
          << ", \"cgal_over_geodex\": " << jsonNumber(r.cgalRatio())
          << ", \"max_abs_diff\": " << jsonNumber(r.maxAbsDiff)
          << ", \"max_abs_diff_over_diagonal\": " << jsonNumber(r.maxRelDiff)
          << ", \"vertices_diff_over_1e-6_diagonal\": " << r.verticesOver1e6
          << ",\n     \"dijkstra_seconds\": " << jsonNumber(r.dijkstraSeconds)
          << ", \"dijkstra_runs\": " << jsonTiming(r.dijkstraRuns)
          << ",\n     \"none_runs\": " << jsonTiming(r.noneRuns)
          << ", \"noop_observer_runs\": " << jsonTiming(r.noopRuns)
          << ", \"cheap_tier_runs\": " << jsonTiming(r.cheapRuns)
          << ", \"full_tier_runs\": " << jsonTiming(r.fullRuns)
          << ", \"cheap_tier_base_runs\": " << jsonTiming(r.cheapBaseRuns)
          << ", \"full_tier_base_runs\": " << jsonTiming(r.fullBaseRuns)
          << ", \"noop_observer_ratio\": " << jsonNumber(r.noopSeconds / r.noneSeconds)
          << ", \"noop_pair_ratio_quartiles\": [" << jsonNumber(r.noopRatioQ1) << ", "
          << jsonNumber(r.noopRatioQ3) << "]"
          << ", \"cheap_tier_ratio\": " << jsonNumber(r.cheapRatio)
          << ", \"full_tier_ratio\": " << jsonNumber(r.fullRatio)
          << ", \"cheap_violations\": " << r.cheapViolations
          << ", \"full_violations\": " << r.fullViolations << ", \"first_violation\": "
          << (r.firstViolation.empty() ? "null" : jsonString(r.firstViolation));
      if (r.reference)
        out << ",\n     \"reference\": {\"kirsanov_ratio\": " << r.reference->kirsanovRatio
            << ", \"kirsanov_seconds\": " << r.reference->kirsanovSeconds
            << ", \"kirsanov_megabytes\": " << r.reference->kirsanovMegabytes
            << ", \"target_ratio\": " << r.reference->targetRatio << ", \"met\": "
            << (r.cgalRatio() >= r.reference->targetRatio ? "true" : "false") << "}";
      out << "}";
    }
    out << (i + 1 < results.size() ? ",\n" : "\n");
  }
  out << "  ]\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "geodex_bench: " << arg << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--json") options.jsonPath = value();
    else if (arg == "--runs") options.runs = std::max(1, std::stoi(value()));
    else if (arg == "--cgal-runs") options.cgalRuns = std::max(1, std::stoi(value()));
    else if (arg == "--hook-max-pairs") options.hookMaxPairs = std::max(3, std::stoi(value()));
    else if (arg == "--hook-budget") options.hookBudgetSeconds = std::stod(value());
    else if (arg == "--full-tier-max-faces") options.fullTierMaxFaces = std::stoul(value());
    else if (arg == "--only") options.only = splitList(value());
    else if (arg == "--list") list = true;
    else if (arg == "--big") options.big = true;
    else if (arg == "--no-cgal") options.cgal = false;
    else if (arg == "--no-tiers") options.tiers = false;
    else if (arg == "--no-memory") options.memory = false;
    else if (arg == "--meshes") options.cgalMeshDir = value();
    else if (arg == "--shared-meshes") options.sharedMeshDir = value();
    else if (arg == "--help" || arg == "-h") {
      usage();
      return 0;
    } else {
      std::cerr << "geodex_bench: unknown option " << arg << "\n";
      usage();
      return 2;
    }
  }

  std::vector<Case> cases;
  for (Case& c : allCases()) {
    const bool named = std::find(options.only.begin(), options.only.end(), c.name) != options.only.end();
    if (!options.only.empty() ? named : (!c.bigOnly || options.big)) cases.push_back(std::move(c));
  }
  if (list) {
    for (const Case& c : allCases())
      std::cout << c.name << "\t" << c.origin << "\t" << c.description
                << (c.bigOnly ? "\t(--big)" : "") << "\n";
    return 0;
  }
#ifndef GEODEX_HAVE_CGAL_ORACLE
  std::cerr << "geodex_bench: built without CGAL: no CGAL columns\n";
#endif

  RunInfo info;
  info.loadBefore = loadAverage();
  const auto start = Clock::now();
  std::vector<Result> results;
  for (const Case& c : cases) {
    std::cerr << c.name << "\n";
    Result r;
    try {
      runCase(c, options, r);
    } catch (const std::exception& e) {
      r.skipped = true;
      r.skipReason = std::string("error: ") + e.what();
      std::cerr << "  " << r.skipReason << "\n";
    }
    results.push_back(std::move(r));
  }
  info.loadAfter = loadAverage();
  info.seconds = secondsSince(start);
  printMarkdown(results, options, info, std::cout);
  if (!options.jsonPath.empty()) writeJson(results, options, info, options.jsonPath);
  return 0;
}
