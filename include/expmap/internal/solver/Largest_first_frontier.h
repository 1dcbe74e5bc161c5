// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LARGEST_FIRST_FRONTIER_H
#define EXPMAP_INTERNAL_SOLVER_LARGEST_FIRST_FRONTIER_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// Where a back substitution that visits the elimination tree largest
/// first (`Largest_first_search`) goes next, and when it
/// may stop: the supernodes not visited yet whose parents were, each with
/// a bound on the values of its subtree, and the values solved so far.
///
/// The search may stop once `count` values exceed every bound left, or once
/// every bound left is below a threshold. The values are counted in buckets
/// of an eighth of a binade, and a value counts as exceeding a bound only
/// if its bucket is higher, so the search may go on up to a bucket longer
/// than it must, never shorter; with that, no selection over the values is
/// needed. Bounds only fall from pop to pop (a child's rows below are its
/// parent's rows or rows below), so the count above the bounds only grows.
class Largest_first_frontier {
 public:
  /// Stop once `count` values exceed every bound left, or once every bound
  /// left is below `threshold` (0: never).
  struct Stop {
    std::size_t count;
    double threshold;
  };
  /// A `Stop::count` never reached: the threshold alone decides.
  static constexpr std::size_t no_count = std::numeric_limits<std::size_t>::max();

  /// Starts a search: nothing on the frontier, no value counted.
  void clear() {
    m_heap.clear();
    if (m_bucket_count.size() != buckets) {
      m_bucket_count.assign(buckets, 0);
      m_touched_to = 0;
    }
    std::fill(m_bucket_count.begin() + static_cast<std::ptrdiff_t>(m_touched_from),
              m_bucket_count.begin() +
                  static_cast<std::ptrdiff_t>(std::max(m_touched_from, m_touched_to)),
              0u);
    m_touched_from = buckets;
    m_touched_to = 0;
    m_floor = buckets;
    m_values_above = 0;
  }

  /// Adds `supernode`, whose subtree holds no value above `bound` (infinity
  /// where that is not known).
  void push(double bound, int supernode) {
    m_heap.push_back({bound, supernode});
    std::push_heap(m_heap.begin(), m_heap.end());
  }

  /// Removes and returns the supernode of largest bound, or -1 if the
  /// frontier is empty or `stop` is met.
  int pop(Stop stop) {
    if (m_heap.empty() || settled(m_heap.front().first, stop)) return -1;
    std::pop_heap(m_heap.begin(), m_heap.end());
    const int supernode = m_heap.back().second;
    m_heap.pop_back();
    return supernode;
  }

  /// Counts a value solved.
  void count(double value) {
    const std::size_t b = bucket(value);
    ++m_bucket_count[b];
    m_touched_from = std::min(m_touched_from, b);
    m_touched_to = std::max(m_touched_to, b + 1);
    if (b >= m_floor) ++m_values_above;
  }

  /// Bytes of memory held.
  std::size_t bytes() const {
    return m_heap.capacity() * sizeof(m_heap[0]) +
           m_bucket_count.capacity() * sizeof(m_bucket_count[0]);
  }

 private:
  // The bucket of a value: its exponent and three leading mantissa bits
  // (nonpositive values in 0), so larger values have higher (or equal)
  // buckets.
  static constexpr std::size_t buckets = std::size_t{1} << 14;
  static std::size_t bucket(double value) {
    if (!(value > 0)) return 0;
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return static_cast<std::size_t>(bits >> 49);
  }

  bool settled(double bound, Stop stop) {
    if (stop.count == 0 || bound < stop.threshold) return true;
    if (!(bound < std::numeric_limits<double>::infinity())) return false;
    for (const std::size_t b = bucket(bound) + 1; m_floor > b;)
      m_values_above += m_bucket_count[--m_floor];
    return m_values_above >= stop.count;
  }

  std::vector<std::pair<double, int>> m_heap;  // (bound, supernode)
  // Values counted by bucket; the buckets touched since the last clear();
  // the lowest bucket whose values are counted as above the bounds left,
  // and how many values that is.
  std::vector<std::uint32_t> m_bucket_count;
  std::size_t m_touched_from = 0, m_touched_to = 0;
  std::size_t m_floor = 0, m_values_above = 0;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LARGEST_FIRST_FRONTIER_H
