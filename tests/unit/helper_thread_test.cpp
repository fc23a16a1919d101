// The solve's helper thread (solver/src/helper_thread.h): a posted job runs once, on the helper or
// taken back by the poster, and what it throws reaches finish().
#include "../../solver/src/helper_thread.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace geodex::detail {
namespace {

struct Record {
  std::atomic<int> runs{0};
  std::atomic<bool> done{false};
  std::thread::id ranOn;
};

void recordRun(void* context) {
  auto* r = static_cast<Record*>(context);
  r->ranOn = std::this_thread::get_id();
  r->runs.fetch_add(1);
  r->done.store(true);
}

// Waits (up to a generous limit, not a timing assumption) for the helper to have run the job.
bool waitUntilDone(const Record& r) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!r.done.load()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::yield();
  }
  return true;
}

TEST(HelperThread, RunsAPostedJobOnItsOwnThreadWhenThePosterWaits) {
  HelperThread helper;
  for (int i = 0; i < 3; ++i) {  // also after sleeping between posts
    Record r;
    helper.post(&recordRun, &r);
    ASSERT_TRUE(waitUntilDone(r));
    helper.finish();
    EXPECT_EQ(r.runs.load(), 1);
    EXPECT_NE(r.ranOn, std::this_thread::get_id());
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // past the spin: it sleeps
  }
}

TEST(HelperThread, RunsEveryJobExactlyOnceWhenThePosterTakesSomeBack) {
  HelperThread helper;
  int onHelper = 0, here = 0;
  for (int i = 0; i < 20000; ++i) {
    Record r;
    helper.post(&recordRun, &r);
    helper.finish();  // at once: the helper has taken it or not yet
    ASSERT_EQ(r.runs.load(), 1) << "job " << i;
    (r.ranOn == std::this_thread::get_id() ? here : onHelper) += 1;
  }
  EXPECT_EQ(onHelper + here, 20000);
}

void throwOnce(void* context) {
  auto* r = static_cast<Record*>(context);
  r->done.store(true);
  throw std::runtime_error("from the job");
}

TEST(HelperThread, FinishRethrowsWhatTheJobThrewAndTheHelperGoesOn) {
  HelperThread helper;
  Record failing;
  helper.post(&throwOnce, &failing);
  ASSERT_TRUE(waitUntilDone(failing));
  EXPECT_THROW(helper.finish(), std::runtime_error);
  Record next;
  helper.post(&recordRun, &next);
  ASSERT_TRUE(waitUntilDone(next));
  EXPECT_NO_THROW(helper.finish());
  EXPECT_EQ(next.runs.load(), 1);
}

}  // namespace
}  // namespace geodex::detail
