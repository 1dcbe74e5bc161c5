// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_RADIX_SORT_H
#define EXPMAP_INTERNAL_RADIX_SORT_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {

/// Sorts non-negative ints ascending by least-significant-digit radix sort,
/// 11 bits per pass, as many passes as the largest value needs (two up to
/// 4,194,303). A query sorts a few thousand vertex indices this way in
/// linear time, where std::sort spends most of its comparisons on the
/// logarithmic factor. `scratch` is resized as needed and may be reused.
inline void radix_sort_indices(std::vector<int>& values, std::vector<int>& scratch) {
  constexpr int bits = 11;
  constexpr int buckets = 1 << bits;
  if (values.size() < 2) return;
  const int largest = *std::max_element(values.begin(), values.end());
  scratch.resize(values.size());
  std::array<std::size_t, buckets> start;
  for (int shift = 0; shift < 31 && (largest >> shift) > 0; shift += bits) {
    start.fill(0);
    for (const int v : values) ++start[static_cast<std::size_t>((v >> shift) & (buckets - 1))];
    std::size_t sum = 0;
    for (std::size_t& s : start) {
      const std::size_t count = s;
      s = sum;
      sum += count;
    }
    for (const int v : values) scratch[start[static_cast<std::size_t>((v >> shift) & (buckets - 1))]++] = v;
    values.swap(scratch);
  }
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_RADIX_SORT_H
