// The pool the solver's interval lists live in: what it promises about memory, which no distance
// shows (a list given a block far too large, or a freed block never used again, leaves every
// distance as it was and only the memory grows).

#include "geodex/interval_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <random>
#include <span>
#include <utility>
#include <vector>

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

// ---  IntervalList --------------------------------------------------------------------------

// Intervals told apart by their range alone, enough to see which one went where.
Interval numbered(int k) {
  Interval w;
  w.b0 = k;
  w.b1 = k + 1;
  w.origin = k;
  return w;
}

bool sameList(std::span<const Interval> list, const std::vector<Interval>& expected) {
  if (list.size() != expected.size()) return false;
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i].b0 != expected[i].b0 || list[i].origin != expected[i].origin ||
        list[i].regrown != expected[i].regrown)
      return false;
  return true;
}

// The splice every edge update ends with: whatever the slice and whatever replaces it (fewer,
// as many, more; at the front, inside, at the back; growing past the block or not), the list is
// the old one with the slice cut out and the new intervals put in its place, in order, in a
// block of the smallest size class that held the list at its longest. Every other step touches
// the intervals it copies in (as a run's update marks its children's pieces), and only those.
TEST(IntervalList, AReplacedSliceLeavesTheRestOfTheListInOrderAroundTheNewIntervals) {
  IntervalPool pool;
  std::mt19937 random(7);
  int next = 0;
  for (IntervalPool* const p : {&pool, static_cast<IntervalPool*>(nullptr)}) {
    for (int trial = 0; trial < 3000; ++trial) {
      IntervalList list(p);
      std::vector<Interval> expected;
      std::size_t largest = 0;
      const int steps = 1 + static_cast<int>(random() % 20);
      for (int step = 0; step < steps; ++step) {
        const std::size_t n = expected.size();
        const std::size_t s0 = random() % (n + 1);
        const std::size_t s1 = s0 + random() % (n - s0 + 1);
        std::vector<Interval> with(random() % 5);
        for (Interval& w : with) w = numbered(next++);
        const bool touching = step % 2 == 1;
        if (touching) {
          list.replace(s0, s1, with, [](Interval& w) { ++w.regrown; });
          for (Interval& w : with) ++w.regrown;
        } else {
          list.replace(s0, s1, with);
        }
        expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(s0),
                       expected.begin() + static_cast<std::ptrdiff_t>(s1));
        expected.insert(expected.begin() + static_cast<std::ptrdiff_t>(s0), with.begin(),
                        with.end());
        ASSERT_TRUE(sameList(list, expected)) << "trial " << trial << " step " << step;
        // A size class a quarter up from the longest the list has been, never more.
        largest = std::max(largest, list.size());
        ASSERT_GE(list.capacity(), list.size());
        ASSERT_LE(list.capacity(), IntervalPool::capacityFor(largest));
      }
    }
  }
}

// Copies are lists of their own (the checked builds copy a list to run the general update
// beside the fast one); a moved-from list is empty and usable.
TEST(IntervalList, ACopyIsIndependentAndAMovedFromListIsEmpty) {
  IntervalPool pool;
  IntervalList a(&pool);
  const std::vector<Interval> three{numbered(0), numbered(1), numbered(2)};
  a.assign(three);
  IntervalList b(a);
  b.replace(1, 2, std::vector<Interval>{numbered(9), numbered(10)});
  EXPECT_TRUE(sameList(a, three));
  EXPECT_TRUE(sameList(b, {numbered(0), numbered(9), numbered(10), numbered(2)}));

  IntervalList c(std::move(b));
  EXPECT_TRUE(b.empty());  // NOLINT(bugprone-use-after-move): what a move leaves is the point
  EXPECT_EQ(c.size(), 4u);
  b.replace(0, 0, three);
  EXPECT_TRUE(sameList(b, three));

  c = a;
  EXPECT_TRUE(sameList(c, three));
  a = std::move(c);
  EXPECT_TRUE(sameList(a, three));
  a.clear();
  EXPECT_TRUE(a.empty());
}

// Copy-assigning a list of another pool (here a pool's list to one on operator new) moves the
// copy to the original's pool: the list gives its own block back, once, and keeps nothing of it;
// what it grows into next, and its destructor, free only blocks it holds. (A block freed twice is
// an ASan report in the asan build; in the others the heap's own double-free check aborts.)
TEST(IntervalList, ACopyFromAnotherPoolGivesItsOwnBlockBackOnce) {
  IntervalPool pool;
  const std::vector<Interval> three{numbered(0), numbered(1), numbered(2)};
  IntervalList inPool(&pool);
  inPool.assign(three);
  {
    IntervalList onHeap;
    onHeap.assign(std::vector<Interval>{numbered(7), numbered(8)});
    onHeap = inPool;
    EXPECT_TRUE(sameList(onHeap, three));
    onHeap.replace(3, 3, std::vector<Interval>{numbered(3)});
    EXPECT_TRUE(sameList(onHeap, {numbered(0), numbered(1), numbered(2), numbered(3)}));
  }
  // An empty original: the copy is empty, and the first interval put in it is all it holds.
  const IntervalList emptyInPool(&pool);
  {
    IntervalList onHeap;
    onHeap.assign(std::vector<Interval>{numbered(7), numbered(8)});
    onHeap = emptyInPool;
    EXPECT_TRUE(onHeap.empty());
    onHeap.replace(0, 0, std::vector<Interval>{numbered(4)});
    EXPECT_TRUE(sameList(onHeap, {numbered(4)}));
  }
  EXPECT_TRUE(sameList(inPool, three));
}

}  // namespace
}  // namespace geodex
