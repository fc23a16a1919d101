#pragma once
// A second thread for the solve: it takes one job at a time, which the thread that posted it may
// take back and run itself if the helper has not started it (a helper asleep or descheduled then
// costs nothing but the post). GeodesicSolver::runRound posts the taking of its round's batches;
// both threads then take them one at a time (claimBatches, finishRound).

#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <utility>

namespace geodex::detail {

/// Returns once `flag` is set by another thread that is running (spinning, then yielding).
void awaitSet(const std::atomic<bool>& flag);

class HelperThread {
 public:
  using Job = void (*)(void* context);

  HelperThread();
  ~HelperThread();
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

  /// Hands `job(context)` to the helper. The previous job must have been collected (finish()).
  void post(Job job, void* context);
  /// Returns once the posted job has run, here if the helper had not started it; rethrows what it
  /// threw.
  void finish();

 private:
  void loop();

  // kIdle → (post) kPosted → (the helper) kRunning → kDone → (finish) kIdle, or kPosted → kIdle
  // when finish() takes the job back; kStop ends the helper.
  enum State : std::uint32_t { kIdle, kPosted, kRunning, kDone, kStop };
  std::atomic<std::uint32_t> state_{kIdle};
  Job job_ = nullptr;
  void* context_ = nullptr;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace geodex::detail
