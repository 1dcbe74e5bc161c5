// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The allocator of the factors' arrays: large arrays start on a huge-page
// boundary, small ones are ordinary; either way a std::vector using it keeps
// its contents through growth, shrinking and copies.

#include <expmap/internal/solver/Huge_page_allocator.h>

#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <numeric>
#include <vector>

BOOST_AUTO_TEST_SUITE(huge_page_allocator)

using Allocator = expmap::internal::Huge_page_allocator<double>;
using Vector = std::vector<double, Allocator>;

namespace {
std::uintptr_t offset_in_huge_page(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % Allocator::huge_page;
}
}  // namespace

BOOST_AUTO_TEST_CASE(large_arrays_start_on_a_huge_page_and_keep_their_values) {
  const std::size_t large = 3 * Allocator::huge_page / sizeof(double) + 5;  // not a whole page
  Vector values(large);
  std::iota(values.begin(), values.end(), 0.5);
  BOOST_TEST(offset_in_huge_page(values.data()) == 0u);
  values.resize(2 * large);  // reallocates: the old half must come along
  BOOST_TEST(offset_in_huge_page(values.data()) == 0u);
  BOOST_TEST(values[large - 1] == static_cast<double>(large - 1) + 0.5);
  BOOST_TEST(values[2 * large - 1] == 0.0);
  const Vector copy = values;
  BOOST_TEST(copy == values);
  values.resize(3);
  values.shrink_to_fit();  // now below the threshold: an ordinary allocation
  BOOST_TEST(values == (Vector{0.5, 1.5, 2.5}), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(small_arrays_are_ordinary) {
  std::vector<int, expmap::internal::Huge_page_allocator<int>> small(1000);
  std::iota(small.begin(), small.end(), -7);
  BOOST_TEST(small.front() == -7);
  BOOST_TEST(small.back() == 992);
  BOOST_TEST(1000 * sizeof(int) < expmap::internal::Huge_page_allocator<int>::threshold);
}

BOOST_AUTO_TEST_CASE(impossible_sizes_throw) {
  Allocator allocator;
  BOOST_CHECK_THROW(allocator.allocate(static_cast<std::size_t>(-1) / 4), std::bad_array_new_length);
}

BOOST_AUTO_TEST_SUITE_END()
