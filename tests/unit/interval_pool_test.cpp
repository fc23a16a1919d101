// The pool the solver's interval lists live in: what it promises about memory, which no distance
// shows (a list given a block far too large, or a freed block never used again, leaves every
// distance as it was and only the memory grows).

#include "geodex/interval_pool.h"

#include <gtest/gtest.h>

#include <cstddef>

namespace geodex {
namespace {

// A list holding n intervals reserves a size class: one that holds it, the smallest, and so at
// most a quarter (or one interval) above n; a list's next growth asks for the same class again.
TEST(IntervalPool, AListReservesTheSmallestSizeClassThatHoldsIt) {
  EXPECT_EQ(IntervalPool::capacityFor(1), 1u);
  EXPECT_EQ(IntervalPool::capacityFor(8), 8u);
  EXPECT_EQ(IntervalPool::capacityFor(9), 10u);
  EXPECT_EQ(IntervalPool::capacityFor(13), 15u);
  for (std::size_t n = 1; n <= 5000; ++n) {
    const std::size_t c = IntervalPool::capacityFor(n);
    ASSERT_GE(c, n) << "n = " << n;
    ASSERT_LE(c, n + n / 4 + 1) << "n = " << n;
    ASSERT_EQ(IntervalPool::capacityFor(c), c) << "n = " << n;
  }
}

// The size classes end at a chunk (2^16 intervals): a list longer than that reserves exactly its
// length, a block of its own, as no class would come back to it.
TEST(IntervalPool, AListLongerThanAChunkReservesExactlyItsLength) {
  for (std::size_t n = (std::size_t{1} << 16) + 1; n <= (std::size_t{1} << 18); n += 997)
    ASSERT_EQ(IntervalPool::capacityFor(n), n) << "n = " << n;
}

// A block a list gave back is the next one handed out for its size class, so that the wavefront,
// freeing a small block on one edge as it needs one on the next, keeps reusing the same memory.
TEST(IntervalPool, AFreedBlockIsTheNextOneHandedOutForItsSize) {
  IntervalPool pool;
  for (const std::size_t capacity : {std::size_t{1}, std::size_t{4}, std::size_t{10}}) {
    SCOPED_TRACE(capacity);
    Interval* const first = pool.allocate(capacity);
    Interval* const other = pool.allocate(capacity);
    pool.deallocate(first, capacity);
    EXPECT_EQ(pool.allocate(capacity), first);
    pool.deallocate(other, capacity);
    EXPECT_EQ(pool.allocate(capacity), other);
  }
}

// A recycled pool forgets its blocks and carves the next solve's lists from the start of its
// first chunk again: a solver re-run on the same mesh holds the memory of one solve, not two.
TEST(IntervalPool, ARecycledPoolCarvesFromTheStartOfItsFirstChunkAgain) {
  IntervalPool pool;
  Interval* const first = pool.allocate(4);
  for (int i = 0; i < 100; ++i) pool.allocate(8);
  pool.recycle();
  EXPECT_EQ(pool.allocate(4), first);
}

}  // namespace
}  // namespace geodex
