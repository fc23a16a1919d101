#include "geodex/interval_pool.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <type_traits>
#include <utility>

#if __has_include(<sys/mman.h>)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace geodex {
namespace {

constexpr std::size_t kChunk = std::size_t{1} << 16;  // intervals per chunk, at most (3 MB)
// The first chunk is small and each next one twice the last: a solve on a 50-face mesh (the
// fuzzers run thousands a second) should not fault in 3 MB.
constexpr std::size_t kFirstChunk = std::size_t{1} << 10;

// Size classes 1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 18, 22, 27, ... each a quarter above the last,
// up to one chunk; and, for every capacity up to a chunk, the class that holds it (a table: this
// is asked at every growth of every list, six in ten of the edge updates on fandisk).
struct SizeClasses {
  std::array<std::size_t, IntervalPool::kMaxClasses> capacity{};
  int count = 0;
  std::array<std::uint8_t, kChunk + 1> classFor{};  // the smallest class with capacity >= n
  SizeClasses() {
    std::size_t c = 1;
    while (c <= kChunk && count < static_cast<int>(IntervalPool::kMaxClasses)) {
      capacity[static_cast<std::size_t>(count++)] = c;
      c = std::max(c + 1, c + c / 4);
    }
    std::size_t k = 0;
    for (std::size_t n = 0; n <= kChunk; ++n) {
      while (k + 1 < static_cast<std::size_t>(count) && capacity[k] < n) ++k;
      classFor[n] = static_cast<std::uint8_t>(k);
    }
  }
};
// At namespace scope, not a function's static: read without a guard on every growth. Nothing
// allocates from a pool before main.
const SizeClasses kSizeClasses;

// How far ahead of the carving the pages of a chunk are faulted in (faultInUpTo), in intervals:
// 192 KB, so a solve's resident memory stays within that of what it uses.
constexpr std::size_t kFaultInAhead = std::size_t{1} << 12;

// Asks the kernel to fault in the whole pages of [begin, end) now, in one call, rather than one
// trap at the first write to each (MADV_POPULATE_WRITE, Linux 5.14; elsewhere, or refused, the
// pages fault in as they are written, as before).
void faultIn(const Interval* begin, const Interval* end) {
#if defined(MADV_POPULATE_WRITE)
  // (The system's page size: with 4 KB assumed, a 16 or 64 KB system refused most calls.)
  static const auto kPage = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  if (kPage == 0 || (kPage & (kPage - 1)) != 0) return;  // (sysconf failed: -1)
  const std::uintptr_t from = reinterpret_cast<std::uintptr_t>(begin) & ~(kPage - 1);
  const std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) & ~(kPage - 1);
  // (From the page begin is on, which is mapped, to the last whole page before end: never
  // beyond the chunk.)
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
#else
  (void)begin;
  (void)end;
#endif
}

}  // namespace

IntervalPool::~IntervalPool() {
  for (const Chunk& c : chunks_) ::operator delete(c.data, std::align_val_t(alignof(Interval)));
}

int IntervalPool::classOf(std::size_t capacity) {
  const SizeClasses& c = kSizeClasses;
  if (capacity > kChunk) return -1;
  const int k = c.classFor[capacity];
  return c.capacity[static_cast<std::size_t>(k)] == capacity ? k : -1;
}

std::size_t IntervalPool::capacityFor(std::size_t n) {
  const SizeClasses& c = kSizeClasses;
  return n <= c.capacity[static_cast<std::size_t>(c.count - 1)] ? c.capacity[c.classFor[n]] : n;
}

Interval* IntervalPool::allocate(std::size_t capacity) {
  const int k = classOf(capacity);
  if (k < 0) {  // not a size class (a list assigned whole, or longer than a chunk)
    return static_cast<Interval*>(
        ::operator new(capacity * sizeof(Interval), std::align_val_t(alignof(Interval))));
  }
  FreeBlock*& head = free_[static_cast<std::size_t>(k)];
  if (head != nullptr) {
    FreeBlock* p = head;
    head = p->next;
    p->~FreeBlock();
    return reinterpret_cast<Interval*>(p);
  }
  // Carve from the current chunk; the rest of a chunk too full for this block stays unused.
  while (chunk_ < chunks_.size() && used_ + capacity > chunks_[chunk_].capacity) {
    ++chunk_;
    used_ = 0;
    faultedIn_ = 0;
  }
  if (chunk_ == chunks_.size()) {
    const std::size_t last = chunks_.empty() ? kFirstChunk / 2 : chunks_.back().capacity;
    const std::size_t size = std::max(capacity, std::min(kChunk, 2 * last));
    chunks_.push_back({static_cast<Interval*>(::operator new(
                           size * sizeof(Interval), std::align_val_t(alignof(Interval)))),
                       size});
  }
  Interval* p = chunks_[chunk_].data + used_;
  used_ += capacity;
  faultInUpTo(used_);
  return p;
}

// The kernel was a tenth of a `geodex distance` profile, mostly traps at the first write to each
// new page of a chunk (bunny00 from v:0: 30,000 page faults in the process; with the pages
// faulted in a window ahead, 8,300); the anchor meshes' solves are 2–4 % faster with it
// (docs/benchmarks.md).
void IntervalPool::faultInUpTo(std::size_t used) {
  if (used <= faultedIn_) return;
  const Chunk& c = chunks_[chunk_];
  const std::size_t upTo = std::min(c.capacity, std::max(used, faultedIn_ + kFaultInAhead));
  faultIn(c.data + faultedIn_, c.data + upTo);
  faultedIn_ = upTo;
}

void IntervalPool::deallocate(Interval* p, std::size_t capacity) {
  const int k = classOf(capacity);
  if (k < 0) {
    ::operator delete(p, std::align_val_t(alignof(Interval)));
    return;
  }
  FreeBlock*& head = free_[static_cast<std::size_t>(k)];
  head = ::new (static_cast<void*>(p)) FreeBlock{head};
}

void IntervalPool::recycle() {
  free_.fill(nullptr);
  chunk_ = 0;
  used_ = 0;
  faultedIn_ = 0;
}

// ===  IntervalList ===============================================================================
static_assert(std::is_trivially_copyable_v<Interval>, "lists copy intervals as bytes");

namespace {
// std::copy of a trivially copyable type is a memmove (none for an empty run).
void copyRun(Interval* to, const Interval* from, std::size_t n) { std::copy(from, from + n, to); }
}  // namespace

IntervalList& IntervalList::operator=(const IntervalList& o) {
  if (this != &o) {
    if (pool_ != o.pool_) {  // the copy lives where the original does
      release();
      pool_ = o.pool_;
    }
    assign(o);
  }
  return *this;
}

IntervalList& IntervalList::operator=(IntervalList&& o) noexcept {
  if (this != &o) {
    release();
    take(o);
  }
  return *this;
}

void IntervalList::take(IntervalList& o) noexcept {
  pool_ = o.pool_;
  data_ = std::exchange(o.data_, nullptr);
  size_ = std::exchange(o.size_, 0);
  capacity_ = std::exchange(o.capacity_, 0);
}

Interval* IntervalList::allocate(std::size_t capacity) {
  if (pool_ != nullptr) return pool_->allocate(capacity);
  return static_cast<Interval*>(
      ::operator new(capacity * sizeof(Interval), std::align_val_t(alignof(Interval))));
}

void IntervalList::release() {
  if (data_ != nullptr) {
    if (pool_ != nullptr) {
      pool_->deallocate(data_, capacity_);
    } else {
      ::operator delete(data_, std::align_val_t(alignof(Interval)));
    }
  }
  data_ = nullptr;
  size_ = 0;
  capacity_ = 0;
}

void IntervalList::assign(std::span<const Interval> list) {
  if (list.size() > capacity_) {
    release();
    capacity_ = IntervalPool::capacityFor(list.size());
    data_ = allocate(capacity_);
  }
  copyRun(data_, list.data(), list.size());
  size_ = list.size();
}

void IntervalList::replaceIntoALargerBlock(std::size_t s0, std::size_t s1,
                                           std::span<const Interval> with, std::size_t newSize) {
  // To the next size class, a quarter up, not a doubling: the lists are most of the solver's
  // memory. (A list grows at six in ten of fandisk's updates.)
  const std::size_t capacity = IntervalPool::capacityFor(newSize);
  Interval* const block = allocate(capacity);
  copyRun(block, data_, s0);
  copyRun(block + s0, with.data(), with.size());
  copyRun(block + s0 + with.size(), data_ + s1, size_ - s1);
  release();
  data_ = block;
  capacity_ = capacity;
  size_ = newSize;
}

}  // namespace geodex
