// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_KTH_LARGEST_H
#define EXPMAP_INTERNAL_KTH_LARGEST_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

namespace expmap {
namespace internal {

/// The k-th largest (k from 1 to n) of the values value(0), ..., value(n - 1),
/// and in `larger` how many of them are strictly larger than it.
///
/// Heat values span many binades (they decay exponentially with distance),
/// so the binade of the answer is found first, by a histogram of the
/// exponents, and the selection runs on the values of that binade only:
/// about a tenth of them for a query's region, where a selection on all of
/// them costs several passes. Values that are not positive normal numbers
/// share the lowest bin and are ordered there by `std::greater`, as a
/// selection on all values would order them. `scratch` is reused.
template <class Value>
double kth_largest(std::size_t n, std::size_t k, Value value, std::vector<double>& scratch,
                   std::size_t& larger) {
  constexpr std::size_t bins = 2048;  // the exponent field of a double
  auto bin = [](double v) -> std::size_t {
    if (!(v > 0)) return 0;
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return static_cast<std::size_t>(bits >> 52);  // sign bit 0: the exponent
  };
  std::array<std::size_t, bins> count{};
  for (std::size_t i = 0; i < n; ++i) ++count[bin(value(i))];
  // The highest bin that brings the values seen from the top to k.
  std::size_t above = 0, b = bins;
  while (b > 0) {
    --b;
    if (above + count[b] >= k) break;
    above += count[b];
  }
  scratch.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (const double v = value(i); bin(v) == b) scratch.push_back(v);
  const auto nth = scratch.begin() + static_cast<std::ptrdiff_t>(k - above - 1);
  std::nth_element(scratch.begin(), nth, scratch.end(), std::greater<double>());
  const double threshold = *nth;
  larger = above + static_cast<std::size_t>(
                       std::count_if(scratch.begin(), nth, [&](double v) { return v > threshold; }));
  return threshold;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_KTH_LARGEST_H
