#include "helper_thread.h"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace geodex::detail {
namespace {

void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// How long a thread spins on the state before it sleeps on it: a batch takes 1–3 µs on the
// benchmark meshes, and a futex wake-up 10–50 µs, so a helper that slept between two posts a few
// batches apart would never start one before the poster took it back.
constexpr auto kSpin = std::chrono::microseconds(50);

// Waits until `state` leaves the values `stay` holds for, spinning first, then sleeping on it.
template <typename Stay>
std::uint32_t awaitChange(std::atomic<std::uint32_t>& state, Stay stay) {
  std::uint32_t s = state.load(std::memory_order_acquire);
  if (!stay(s)) return s;
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (unsigned n = 1;; ++n) {
    cpuRelax();
    s = state.load(std::memory_order_acquire);
    if (!stay(s)) return s;
    if (n % 64 == 0 && std::chrono::steady_clock::now() > until) break;
  }
  for (;;) {
    state.wait(s, std::memory_order_acquire);
    s = state.load(std::memory_order_acquire);
    if (!stay(s)) return s;
  }
}

}  // namespace

void awaitSet(const std::atomic<bool>& flag) {
  for (unsigned n = 1; !flag.load(std::memory_order_acquire); ++n) {
    cpuRelax();
    if (n % 1024 == 0) std::this_thread::yield();  // (the other thread may have lost its core)
  }
}

HelperThread::HelperThread() : thread_([this] { loop(); }) {}

HelperThread::~HelperThread() {
  state_.store(kStop, std::memory_order_release);
  state_.notify_all();
  thread_.join();
}

void HelperThread::post(Job job, void* context) {
  job_ = job;
  context_ = context;
  state_.store(kPosted, std::memory_order_release);
  state_.notify_all();
}

void HelperThread::finish() {
  std::uint32_t expected = kPosted;
  if (state_.compare_exchange_strong(expected, kIdle, std::memory_order_acq_rel)) {
    job_(context_);  // not started: run here (an exception goes straight to the caller)
    return;
  }
  awaitChange(state_, [](std::uint32_t s) { return s == kRunning; });
  state_.store(kIdle, std::memory_order_relaxed);
  if (error_) {
    std::exception_ptr e = std::exchange(error_, nullptr);
    std::rethrow_exception(e);
  }
}

void HelperThread::loop() {
  for (;;) {
    const std::uint32_t s =
        awaitChange(state_, [](std::uint32_t v) { return v != kPosted && v != kStop; });
    if (s == kStop) return;
    std::uint32_t expected = kPosted;
    if (!state_.compare_exchange_strong(expected, kRunning, std::memory_order_acq_rel)) continue;
    try {
      job_(context_);
    } catch (...) {
      error_ = std::current_exception();
    }
    state_.store(kDone, std::memory_order_release);
    state_.notify_all();
  }
}

}  // namespace geodex::detail
