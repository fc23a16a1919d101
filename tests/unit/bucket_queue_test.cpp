// The wavefront queue (solver/include/geodex/bucket_queue.h): entries come out bucket by bucket
// in key order, first in first out inside a bucket, whether the key fell in the ring or in the
// overflow, and a reset queue is empty however the previous run left it. Expected orders are
// computed here from the keys (a stable sort by bucket), not by the queue.
#include "geodex/bucket_queue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace geodex {
namespace {

struct Entry {
  double key;
  int id;
};

// Pushes the keys in order and pops everything; returns the ids in pop order.
std::vector<int> drain(BucketQueue<Entry>& q, const std::vector<double>& keys) {
  for (std::size_t i = 0; i < keys.size(); ++i) q.push({keys[i], static_cast<int>(i)});
  EXPECT_EQ(q.size(), keys.size());
  std::vector<int> order;
  while (!q.empty()) {
    order.push_back(q.front().id);
    q.pop();
  }
  return order;
}

std::vector<int> expectedOrder(const std::vector<double>& keys, double width) {
  std::vector<int> ids(keys.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
  std::stable_sort(ids.begin(), ids.end(), [&](int a, int b) {
    return std::floor(keys[a] / width) < std::floor(keys[b] / width);
  });
  return ids;
}

TEST(BucketQueue, PopsBucketByBucketAndFirstInFirstOutInsideOne) {
  for (std::size_t ring : {64u, 4096u}) {
    BucketQueue<Entry> q;
    q.reset(1.0, ring);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> near(0.0, 50.0), far(0.0, 20000.0);
    std::vector<double> keys;
    // Far keys go to the overflow with a 64-bucket ring, and a bucket spans several pages.
    for (int i = 0; i < 3000; ++i) keys.push_back(i % 3 == 0 ? far(rng) : near(rng));
    EXPECT_EQ(drain(q, keys), expectedOrder(keys, 1.0)) << "ring " << ring;
  }
}

TEST(BucketQueue, ARingSizeIsRoundedUpToAPowerOfTwo) {
  BucketQueue<Entry> q;
  q.reset(0.5, 100);  // 128 buckets: keys 64 and 64.25 are still in the ring, 70 is not
  const std::vector<double> keys{70.0, 64.25, 0.1, 64.0, 0.2};
  EXPECT_EQ(drain(q, keys), expectedOrder(keys, 0.5));
}

TEST(BucketQueue, AResetQueueIsEmptyAfterAPartialOrAFullRun) {
  BucketQueue<Entry> q;
  q.reset(1.0, 64);
  for (int i = 0; i < 500; ++i) q.push({i * 0.7, i});
  for (int i = 0; i < 100; ++i) q.pop();  // stopped early: entries left in ring and overflow
  q.reset(2.0, 64);
  EXPECT_TRUE(q.empty());
  const std::vector<double> keys{5.0, 1.0, 3.0, 1.5, 400.0};
  EXPECT_EQ(drain(q, keys), expectedOrder(keys, 2.0));
  q.reset(2.0, 64);  // drained: the ring is reused as it is
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(drain(q, keys), expectedOrder(keys, 2.0));
  q.reset(2.0, 4096);  // another size
  EXPECT_EQ(drain(q, keys), expectedOrder(keys, 2.0));
}

TEST(BucketQueue, AKeyBelowTheCurrentBucketIsTakenNext) {
  BucketQueue<Entry> q;
  q.reset(1.0, 64);
  q.push({10.5, 0});
  q.push({12.0, 1});
  EXPECT_EQ(q.front().id, 0);
  q.pop();
  EXPECT_GE(q.lowerBound(), 10.0);
  q.push({3.0, 2});  // re-opened below the current bucket: filed in the current one
  EXPECT_EQ(q.front().id, 2);
  q.pop();
  EXPECT_EQ(q.front().id, 1);
}

}  // namespace
}  // namespace geodex
