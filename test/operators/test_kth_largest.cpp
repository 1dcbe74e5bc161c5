// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The selection a query uses to keep its hottest candidates: the k-th
// largest value and the count of values above it, equal to a full sort's on
// heat-like values (many binades), with ties, zeros, negative and subnormal
// values, and for every k of small inputs.

#include <expmap/internal/Kth_largest.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace {

void check_every_k(const std::vector<double>& values) {
  std::vector<double> sorted = values, scratch;
  std::sort(sorted.begin(), sorted.end(), std::greater<double>());
  for (std::size_t k = 1; k <= values.size(); ++k) {
    std::size_t larger = 0;
    const double kth = expmap::internal::kth_largest(
        values.size(), k, [&](std::size_t i) { return values[i]; }, scratch, larger);
    const std::size_t expected_larger = static_cast<std::size_t>(
        std::count_if(values.begin(), values.end(), [&](double v) { return v > sorted[k - 1]; }));
    BOOST_TEST_CONTEXT("k " << k << " of " << values.size()) {
      BOOST_TEST(kth == sorted[k - 1]);
      BOOST_TEST(larger == expected_larger);
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(kth_largest_equals_a_full_sort) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Heat-like: exp(-distance / sqrt(t)) over 80 binades, a few repeated.
  for (const std::size_t size : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{300}}) {
    std::vector<double> values(size);
    for (double& v : values) v = std::exp(-55 * unit(rng));
    if (size > 3) values[1] = values[2] = values[size - 1];
    check_every_k(values);
  }
  // The lowest bin: zeros, negative values, subnormals, the smallest normal.
  std::vector<double> low{0.0,  -1e-3, 4.9e-324, 1e-310, std::numeric_limits<double>::min(),
                          1e-300, 0.0,  -2.0,     1e-310, 3.0};
  check_every_k(low);
  // One binade only: the selection runs on every value.
  std::vector<double> narrow(200);
  for (double& v : narrow) v = 1 + unit(rng);
  check_every_k(narrow);
  // A large region: spot checks.
  std::vector<double> large(20000), scratch;
  for (double& v : large) v = std::exp(-80 * unit(rng));
  std::vector<double> sorted = large;
  std::sort(sorted.begin(), sorted.end(), std::greater<double>());
  for (const std::size_t k : {std::size_t{1}, std::size_t{9999}, std::size_t{20000}}) {
    std::size_t larger = 0;
    const double kth = expmap::internal::kth_largest(
        large.size(), k, [&](std::size_t i) { return large[i]; }, scratch, larger);
    BOOST_TEST(kth == sorted[k - 1]);
    BOOST_TEST(larger == k - 1);  // distinct values
  }
}
