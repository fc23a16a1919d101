#pragma once
// Progress of a long solve on stderr, as a solver observer: the share of vertices whose distance
// is already final (the wavefront has passed them), the wavefront radius and the windows
// propagated per second, rewritten in place ('\r') about five times a second once the solve has
// run for a second, and ended with a newline. Attach it only when showProgress() says so: every
// observer call costs a little.

#include <chrono>
#include <cstdint>
#include <cstdio>

#include "geodex/geodesic_solver.h"
#include "geodex/observer.h"

namespace geodex::cli {

/// True when progress should be printed: stderr is a terminal and --quiet was not given.
bool showProgress(bool quiet);

class ProgressReporter : public SolverObserver {
 public:
  /// @param solver  the solver this reporter will be attached to (read during the solve)
  explicit ProgressReporter(const GeodesicSolver& solver, std::FILE* out = stderr);
  ~ProgressReporter() override;
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  void onPropagation(const PropagationEvent& event) override;
  void onFinish(const GeodesicSolver& solver) override;
  bool readsIntervalLists() const override { return false; }

 private:
  using Clock = std::chrono::steady_clock;
  void start();
  void print(bool finished);
  void endLine();

  const GeodesicSolver& solver_;
  std::FILE* out_;
  bool started_ = false;
  bool printed_ = false;   ///< a line is on screen, not yet ended by a newline
  Clock::time_point startTime_, nextPrint_;
  std::uint64_t propagations_ = 0;  ///< events seen, to read the clock only now and then
  double radius_ = 0.0;              ///< the wavefront: largest window minimum popped so far
  std::size_t reachableVertices_ = 0;  ///< vertices in a component with a source
};

}  // namespace geodex::cli
