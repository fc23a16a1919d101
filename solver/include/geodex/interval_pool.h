#pragma once
// Where a solver's interval lists live. The lists are most of its memory (30 million intervals,
// 1.45 GB, on the 871K-face dragon) and grow one interval at a time as the wavefront crosses
// their edge; through malloc every growth would be an allocation, a copy and a free, about 8% of
// a solve. Here blocks come in size classes a quarter apart, carved from large chunks and reused
// through a free list per class: the wavefront frees a small block on one edge as it needs one on
// the next, so the free lists stay short.
//
// IntervalAllocator is the std::allocator-compatible handle a list's vector uses; without a pool
// (EdgeIntervals on its own, in tests and tools) it falls back to operator new.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
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
  std::array<FreeBlock*, kMaxClasses> free_{};    // per size class, the first free block
};

template <typename T>
struct IntervalAllocator {
  using value_type = T;
  IntervalPool* pool = nullptr;

  IntervalAllocator() = default;
  explicit IntervalAllocator(IntervalPool* p) : pool(p) {}
  template <typename U>
  IntervalAllocator(const IntervalAllocator<U>& o) : pool(o.pool) {}  // NOLINT: allocator rebind

  T* allocate(std::size_t n) {
    if constexpr (std::is_same_v<T, Interval>) {
      if (pool != nullptr) return pool->allocate(n);
    }
    return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(alignof(T))));
  }
  void deallocate(T* p, std::size_t n) {
    if constexpr (std::is_same_v<T, Interval>) {
      if (pool != nullptr) return pool->deallocate(p, n);
    }
    ::operator delete(p, std::align_val_t(alignof(T)));
  }
  template <typename U>
  bool operator==(const IntervalAllocator<U>& o) const {
    return pool == o.pool;
  }

  // Lists move with their pool; a copied list keeps allocating from it.
  using propagate_on_container_copy_assignment = std::true_type;
  using propagate_on_container_move_assignment = std::true_type;
  using propagate_on_container_swap = std::true_type;
};

}  // namespace geodex
