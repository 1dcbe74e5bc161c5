// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The radix sort of vertex indices a query uses to walk its region in
// memory order: equal to std::sort on random inputs of every size regime
// (one, two and three 11-bit passes), with duplicates, and on edge cases.

#include <expmap/internal/Radix_sort.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <climits>
#include <random>
#include <vector>

BOOST_AUTO_TEST_SUITE(radix_sort)

BOOST_AUTO_TEST_CASE(radix_sort_equals_std_sort) {
  std::mt19937 rng(3);
  std::vector<int> scratch;
  for (const int largest : {0, 1, 2047, 2048, 100000, 4194303, 4194304, INT_MAX}) {
    for (const std::size_t size : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{17},
                                   std::size_t{5000}}) {
      BOOST_TEST_CONTEXT("largest " << largest << ", size " << size) {
        std::uniform_int_distribution<int> value(0, largest);
        std::vector<int> values(size);
        for (int& v : values) v = value(rng);
        if (size > 2) values[size / 2] = values[0];  // a duplicate
        std::vector<int> expected = values;
        std::sort(expected.begin(), expected.end());
        expmap::internal::radix_sort_indices(values, scratch);
        BOOST_TEST(values == expected, boost::test_tools::per_element());
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
