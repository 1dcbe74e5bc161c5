// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_STATISTICS_H
#define EXPMAP_BENCHMARK_EVALUATION_STATISTICS_H

/// \file Statistics.h
/// Statistics of samples: means, medians, nearest-rank percentiles, angle
/// errors up to a constant rotation (circular mean), and the portable random
/// integers the studies draw their sources with.

#include "Common.h"
#include "../Sample_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace expmap_evaluation {

inline double mean(const std::vector<double>& v) {
  if (v.empty()) return std::nan("");
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

/// Mean of the finite values (NaN if there are none).
inline double mean_finite(const std::vector<double>& v) {
  double sum = 0;
  std::size_t n = 0;
  for (double x : v)
    if (std::isfinite(x)) {
      sum += x;
      ++n;
    }
  return n ? sum / static_cast<double>(n) : std::nan("");
}

// Median and nearest-rank percentile (p in percent) are the harness's own.
using expmap_bench::median;
using expmap_bench::percentile;

inline double wrap_angle(double a) {
  a = std::remainder(a, 2 * pi);
  return a <= -pi ? a + 2 * pi : a;
}

/// |theta - theta_exact - rotation| per pair, where `rotation` (returned) is
/// the circular mean of the differences: the maps may use different
/// reference directions, and this constant is not an error.
inline std::vector<double> angle_errors_up_to_rotation(const std::vector<double>& computed,
                                                       const std::vector<double>& exact,
                                                       double& rotation) {
  double c = 0, s = 0;
  for (std::size_t i = 0; i < computed.size(); ++i) {
    c += std::cos(computed[i] - exact[i]);
    s += std::sin(computed[i] - exact[i]);
  }
  rotation = std::atan2(s, c);
  std::vector<double> errors;
  for (std::size_t i = 0; i < computed.size(); ++i)
    errors.push_back(std::abs(wrap_angle(computed[i] - exact[i] - rotation)));
  return errors;
}

/// Portable uniform integer in [0, n) from std::mt19937's raw output.
inline std::size_t uniform_below(std::mt19937& rng, std::size_t n) {
  const std::uint32_t m = static_cast<std::uint32_t>(n);
  const std::uint32_t threshold = (0u - m) % m;
  for (;;) {
    const std::uint32_t x = static_cast<std::uint32_t>(rng());
    if (x >= threshold) return x % m;
  }
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_STATISTICS_H
