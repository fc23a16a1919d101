#pragma once
// A monotone priority queue on non-negative double keys (a radix heap, Ahuja, Mehlhorn, Orlin &
// Tarjan 1990), for the solver's wavefront. Window propagation is Dijkstra-like: what is pushed
// is (up to rounding) never below what was last popped, which is all a radix heap needs; in
// exchange a push is O(1) and a pop O(1) amortised plus a bucket scan, against the O(log n)
// cache-missing sift of a binary heap (that sift was a third of an 82K-face icosphere's solve).
//
// Keys are ordered by their IEEE-754 bit patterns (monotone for non-negative doubles). A key
// below the last popped one (rounding, or an interval Algorithm 2 re-opened) counts as equal to
// it: it is popped next. Entries of equal key come out in no particular order.

#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "geodex/check.h"

namespace geodex {

/// Entry must have a member `double key`.
template <typename Entry>
class RadixHeap {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  void push(const Entry& e) {
    GEODEX_CHECK(e.key >= 0.0, "radix heap key " << e.key << " is negative");
    buckets_[bucketOf(radixKey(e))].push_back(e);
    ++size_;
  }

  /// The entry with the smallest key (the last popped key for any below it).
  const Entry& top() {
    if (buckets_[0].empty()) refill();
    return buckets_[0].back();
  }

  void pop() {
    if (buckets_[0].empty()) refill();
    buckets_[0].pop_back();
    --size_;
  }

  void clear() {
    for (auto& b : buckets_) b.clear();
    size_ = 0;
    last_ = 0;
  }

 private:
  static std::uint64_t bits(double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
  }
  std::uint64_t radixKey(const Entry& e) const {
    const std::uint64_t k = bits(e.key);
    return k < last_ ? last_ : k;
  }
  // Bucket 0 holds keys equal to last_; bucket i >= 1 those whose highest bit differing from
  // last_ is bit i − 1.
  std::size_t bucketOf(std::uint64_t k) const {
    return k == last_ ? 0 : static_cast<std::size_t>(64 - std::countl_zero(k ^ last_));
  }
  // Bucket 0 is empty: the smallest key is in the first non-empty bucket; it becomes last_, and
  // that bucket's entries move to lower buckets (each entry moves down at most 64 times).
  void refill() {
    GEODEX_CHECK(size_ > 0, "pop from an empty radix heap");
    std::size_t i = 1;
    while (buckets_[i].empty()) ++i;
    std::vector<Entry>& b = buckets_[i];
    std::uint64_t smallest = radixKey(b.front());
    for (const Entry& e : b) {
      const std::uint64_t k = radixKey(e);
      if (k < smallest) smallest = k;
    }
    last_ = smallest;
    for (const Entry& e : b) buckets_[bucketOf(radixKey(e))].push_back(e);
    b.clear();
  }

  std::vector<Entry> buckets_[65];
  std::size_t size_ = 0;
  std::uint64_t last_ = 0;
};

}  // namespace geodex
