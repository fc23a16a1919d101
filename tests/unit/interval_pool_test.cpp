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

}  // namespace
}  // namespace geodex
