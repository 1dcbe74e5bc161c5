// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_NEAREST_FIRST_H
#define EXPMAP_INTERNAL_NEAREST_FIRST_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// Keeps the `count` smallest of `keys` (all of them if there are fewer),
/// sorted ascending: the same keys in the same order as a full std::sort
/// cut to `count`.
///
/// `Key` has a `double distance` and a strict total order (`operator<`)
/// that sorts by distance first (ties broken by any other field). With
/// distances nonnegative and finite, the keys are distributed into as many
/// buckets as there are keys, by distance in equal steps up to the largest
/// (a monotone map, so the buckets come in key order), and only the buckets
/// up to the `count`-th key are sorted, each on its own. Distances of a
/// patch spread evenly enough that a bucket holds a few keys: the work is
/// linear, where a comparison sort of a few thousand keys spends most of its
/// time on the logarithmic factor. Any other distance (negative, infinite
/// or NaN) falls back to a comparison sort.
template <class Key>
void keep_nearest_sorted(std::vector<Key>& keys, std::size_t count, std::vector<Key>& scratch,
                         std::vector<std::size_t>& bucket_start) {
  count = std::min(count, keys.size());
  double largest = 0;
  bool bucketable = true;
  for (const Key& k : keys) {
    bucketable = bucketable && k.distance >= 0 && k.distance <= std::numeric_limits<double>::max();
    largest = std::max(largest, k.distance);
  }
  constexpr std::size_t few = 64;  // below this a comparison sort is as fast
  const double scale = static_cast<double>(keys.size()) / largest;
  if (!bucketable || !(largest > 0) || !(scale <= std::numeric_limits<double>::max()) ||
      keys.size() < few) {
    if (count < keys.size()) {
      std::nth_element(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(count), keys.end());
      keys.resize(count);
    }
    std::sort(keys.begin(), keys.end());
    return;
  }
  const std::size_t buckets = keys.size();
  // The largest key lands in the last bucket (rounding may put it one
  // further; clamped).
  auto bucket_of = [&](double distance) {
    return std::min(buckets - 1, static_cast<std::size_t>(distance * scale));
  };
  bucket_start.assign(buckets + 1, 0);
  for (const Key& k : keys) ++bucket_start[bucket_of(k.distance) + 1];
  for (std::size_t b = 0; b < buckets; ++b) bucket_start[b + 1] += bucket_start[b];
  scratch.resize(keys.size());
  // The scatter moves each start to its bucket's end, the next one's start;
  // shifted back by one bucket they are the starts again.
  for (const Key& k : keys) scratch[bucket_start[bucket_of(k.distance)]++] = k;
  for (std::size_t b = buckets; b > 0; --b) bucket_start[b] = bucket_start[b - 1];
  bucket_start[0] = 0;
  for (std::size_t b = 0; b < buckets && bucket_start[b] < count; ++b)
    if (bucket_start[b + 1] - bucket_start[b] > 1)
      std::sort(scratch.begin() + static_cast<std::ptrdiff_t>(bucket_start[b]),
                scratch.begin() + static_cast<std::ptrdiff_t>(bucket_start[b + 1]));
  scratch.resize(count);
  keys.swap(scratch);
}

/// Sorts [first, last) by `less`, a strict total order. By insertion while
/// few entries are out of place (linear work for input sorted but for a few
/// entries, where a comparison sort would still take n log n); once the
/// insertions have moved more than a few entries per entry, by std::sort.
template <class Iterator, class Less>
void sort_nearly_sorted(Iterator first, Iterator last, Less less) {
  if (last - first < 2) return;
  auto moves_left = 4 * (last - first) + 64;
  for (Iterator i = first + 1; i != last; ++i) {
    if (!less(*i, *(i - 1))) continue;
    auto value = std::move(*i);
    Iterator j = i;
    do {
      *j = std::move(*(j - 1));
      --j;
    } while (j != first && less(value, *(j - 1)) && --moves_left > 0);
    *j = std::move(value);
    if (moves_left <= 0) {
      std::sort(first, last, less);
      return;
    }
  }
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_NEAREST_FIRST_H
