#pragma once
// Where a solver's interval lists live. The lists are most of its memory (30 million intervals,
// 1.45 GB, on the 871K-face dragon) and grow one interval at a time as the wavefront crosses
// their edge; through malloc every growth would be an allocation, a copy and a free, about 8% of
// a solve. Here blocks come in size classes a quarter apart, carved from large chunks and reused
// through a free list per class: the wavefront frees a small block on one edge as it needs one on
// the next, so the free lists stay short.
//
// IntervalList is a list in such a block; without a pool (EdgeIntervals on its own, in tests and
// tools) it falls back to operator new.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <span>
#include <vector>

#include "geodex/interval.h"

namespace geodex {

class IntervalPool {
 public:
  /// At most this many size classes (a quarter apart from 1 to a chunk: about 40).
  static constexpr std::size_t kMaxClasses = 64;

  IntervalPool() = default;
  IntervalPool(const IntervalPool&) = delete;
  IntervalPool& operator=(const IntervalPool&) = delete;
  ~IntervalPool();

  /// The capacity a list holding n intervals should reserve: the smallest size class >= n (or n
  /// itself beyond the largest class).
  static std::size_t capacityFor(std::size_t n);

  Interval* allocate(std::size_t capacity);
  void deallocate(Interval* p, std::size_t capacity);

  /// Forgets every block (all lists allocated from the pool must be gone), keeping the chunks
  /// for the next solve.
  void recycle();

 private:
  static int classOf(std::size_t capacity);   // -1 beyond the largest class
  void faultInUpTo(std::size_t used);
  struct Chunk {
    Interval* data;
    std::size_t capacity;  // intervals
  };
  // A freed block holds the next free block of its class in its first bytes: freeing allocates
  // nothing (a vector per class would allocate at every growth of every list and again when a
  // solver's lists go).
  struct FreeBlock {
    FreeBlock* next;
  };
  static_assert(sizeof(FreeBlock) <= sizeof(Interval) && alignof(FreeBlock) <= alignof(Interval));
  std::vector<Chunk> chunks_;                     // each twice the last, up to 3 MB
  std::size_t chunk_ = 0;                         // the chunk being carved
  std::size_t used_ = 0;                          // intervals carved from it
  std::size_t faultedIn_ = 0;                     // of it, intervals whose pages are faulted in
  std::array<FreeBlock*, kMaxClasses> free_{};    // per size class, the first free block
};

/// One edge's intervals in a block of `pool` (or of operator new without one): a vector cut to
/// what Algorithm 2 asks of it. std::vector with a pool allocator built, moved and copied its
/// elements one at a time through the allocator (libstdc++ copies as bytes only with
/// std::allocator), in the splice that ends every update; Interval is trivially copyable, so runs
/// of intervals are copied at once here.
class IntervalList {
 public:
  explicit IntervalList(IntervalPool* pool = nullptr) : pool_(pool) {}
  IntervalList(const IntervalList& o) : pool_(o.pool_) { assign(o); }
  IntervalList(IntervalList&& o) noexcept { take(o); }
  IntervalList& operator=(const IntervalList& o);
  IntervalList& operator=(IntervalList&& o) noexcept;
  ~IntervalList() { release(); }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  Interval* data() { return data_; }
  const Interval* data() const { return data_; }
  Interval* begin() { return data_; }
  Interval* end() { return data_ + size_; }
  const Interval* begin() const { return data_; }
  const Interval* end() const { return data_ + size_; }
  Interval& operator[](std::size_t i) { return data_[i]; }
  const Interval& operator[](std::size_t i) const { return data_[i]; }
  const Interval& front() const { return data_[0]; }
  const Interval& back() const { return data_[size_ - 1]; }
  operator std::span<Interval>() { return {data_, size_}; }              // NOLINT: a view
  operator std::span<const Interval>() const { return {data_, size_}; }  // NOLINT: a view

  void clear() { size_ = 0; }
  /// Empties the list and hands its block back to the pool.
  void clearAndRelease() { release(); }
  /// Its block goes back to `pool`, and its next ones come from there: a solve's two threads each
  /// allocate from their own pool for the lists they update (GeodesicSolver's batches). Both the
  /// old pool and `pool` must be pools: a block of one is a block of any (the size classes are
  /// the same, and every chunk lives as long as the solver's pools).
  void usePool(IntervalPool* pool) { pool_ = pool; }
  IntervalPool* pool() const { return pool_; }
  /// The list becomes a copy of `list` (which must not be part of it).
  void assign(std::span<const Interval> list);
  /// Replaces the intervals [s0, s1) by `with` (which must not be part of the list), moving the
  /// tail once, and calls touch(w) on each interval w copied in (a run's update marks its pieces on
  /// the way). A list that must grow is built in a block of the next size class directly.
  template <class Touch = void (*)(Interval&)>
  void replace(
      std::size_t s0, std::size_t s1, std::span<const Interval> with,
      Touch touch = [](Interval&) {}) {
    const std::size_t newSize = size_ - (s1 - s0) + with.size();
    Interval* to = data_ + s0;
    if (newSize > capacity_) {
      replaceIntoALargerBlock(s0, s1, with, newSize);
      for (Interval& w : std::span<Interval>(data_ + s0, with.size())) touch(w);
      return;
    }
    if (with.size() != s1 - s0) {  // the tail moves (memmove: the two runs may overlap)
      std::memmove(static_cast<void*>(to + with.size()), data_ + s1,
                   (size_ - s1) * sizeof(Interval));
    }
    // One to a few intervals as a rule, the pieces of an update: copied inline, where a call to
    // memcpy cost more than the copy.
    for (const Interval& w : with) {
      *to = w;
      touch(*to++);
    }
    size_ = newSize;
  }

 private:
  void replaceIntoALargerBlock(std::size_t s0, std::size_t s1, std::span<const Interval> with,
                               std::size_t newSize);
  Interval* allocate(std::size_t capacity);
  void release();
  void take(IntervalList& o) noexcept;

  IntervalPool* pool_ = nullptr;
  Interval* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace geodex
