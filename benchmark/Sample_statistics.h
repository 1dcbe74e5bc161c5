// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_SAMPLE_STATISTICS_H
#define EXPMAP_BENCHMARK_SAMPLE_STATISTICS_H

/// \file Sample_statistics.h
/// Median and percentiles of a sample of timings.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace expmap_bench {

/// The median (the mean of the two middle values for an even count);
/// NaN for an empty sample.
inline double median(std::vector<double> xs) {
  if (xs.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(xs.begin(), xs.end());
  const std::size_t n = xs.size();
  return n % 2 == 1 ? xs[n / 2] : 0.5 * (xs[n / 2 - 1] + xs[n / 2]);
}

/// The p-th percentile by the nearest-rank method (p in (0, 100]): the
/// smallest value with at least p% of the sample at or below it. With 20
/// samples the 90th percentile is the 18th smallest. NaN for an empty sample.
inline double percentile(std::vector<double> xs, double p) {
  if (xs.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(xs.begin(), xs.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(xs.size()));
  const std::size_t k = static_cast<std::size_t>(std::max(1.0, rank)) - 1;
  return xs[std::min(k, xs.size() - 1)];
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_SAMPLE_STATISTICS_H
