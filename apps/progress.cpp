#include "progress.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <unistd.h>

namespace geodex::cli {

namespace {

constexpr auto kQuietStart = std::chrono::seconds(1);         // short runs print nothing
constexpr auto kPrintInterval = std::chrono::milliseconds(200);  // ~5 Hz
/// Read the clock only every this many propagations (a window takes well under a microsecond).
constexpr std::uint64_t kClockStride = 1024;

/// The component (Mesh::componentOf) a resolved source lies in.
Index componentOfSource(const Mesh& mesh, const ResolvedPoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return mesh.componentOf(p.element);
    case SurfacePoint::Kind::Edge: return mesh.componentOf(mesh.edge(p.element).vertex[0]);
    case SurfacePoint::Kind::Face: return mesh.componentOf(mesh.face(p.element)[0]);
  }
  return kNoIndex;
}

}  // namespace

bool showProgress(bool quiet) { return !quiet && ::isatty(STDERR_FILENO) == 1; }

ProgressReporter::ProgressReporter(const GeodesicSolver& solver, std::FILE* out)
    : solver_(solver), out_(out) {}

ProgressReporter::~ProgressReporter() { endLine(); }  // a solve that threw: keep the shell tidy

void ProgressReporter::start() {
  started_ = true;
  startTime_ = Clock::now();
  nextPrint_ = startTime_ + kQuietStart;
  // The denominator: vertices the wavefront can reach at all (their component has a source).
  const Mesh& mesh = solver_.mesh();
  std::vector<char> sourceComponent(mesh.numVertices() + 1, 0);
  for (const ResolvedPoint& p : solver_.sources()) {
    const Index c = componentOfSource(mesh, p);
    if (c < sourceComponent.size()) sourceComponent[c] = 1;
  }
  reachableVertices_ = 0;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    const Index c = mesh.componentOf(v);
    if (mesh.isReferenced(v) && c < sourceComponent.size() && sourceComponent[c]) {
      ++reachableVertices_;
    }
  }
}

void ProgressReporter::onPropagation(const PropagationEvent& event) {
  if (!started_) start();  // the solver's sources are known from the first event on
  ++propagations_;
  radius_ = std::max(radius_, event.window.minDistance());
  if (propagations_ % kClockStride != 0) return;
  const Clock::time_point now = Clock::now();
  if (now < nextPrint_) return;
  nextPrint_ = now + kPrintInterval;
  print(false);
}

void ProgressReporter::onFinish(const GeodesicSolver&) {
  if (printed_) print(true);  // only runs that showed progress get a final line
  endLine();
}

void ProgressReporter::print(bool finished) {
  // Vertices at or below the wavefront radius are final: windows still queued are all farther.
  // Counting them is O(#V), affordable at 5 Hz. At the end every finite distance is final.
  std::size_t finalCount = 0;
  for (double d : solver_.vertexDistancesInMeshUnits()) {  // as radius_, the windows' distances
    if (finished ? std::isfinite(d) : d <= radius_) ++finalCount;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - startTime_).count();
  const double share = reachableVertices_ > 0
                           ? std::min(100.0, 100.0 * static_cast<double>(finalCount) /
                                                 static_cast<double>(reachableVertices_))
                           : 0.0;
  // The solver's own count (what --stats calls "windows propagated"); one window may make more
  // than one propagation event.
  const double windows = static_cast<double>(solver_.stats().intervalsPropagated);
  const double rate = seconds > 0.0 ? windows / seconds : 0.0;
  std::fprintf(out_,
               "\rsolving: %5.1f%% of vertices final, wavefront at %.6g, %.2f M windows/s  ",
               share, radius_ * solver_.mesh().unit(), rate * 1e-6);
  std::fflush(out_);
  printed_ = true;
}

void ProgressReporter::endLine() {
  if (!printed_) return;
  std::fputc('\n', out_);
  std::fflush(out_);
  printed_ = false;
}

}  // namespace geodex::cli
