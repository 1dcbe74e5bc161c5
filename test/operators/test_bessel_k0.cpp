// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's K0 (the heat kernel the heat method's radius threshold
// comes from): within 2e-7 relative of tabulated values and of the
// standard library's `std::cyl_bessel_k` where that exists, and defined for
// every argument, where `std::cyl_bessel_k` throws for large ones.

#include <expmap/internal/Bessel_k0.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

using expmap::internal::bessel_k0;

BOOST_AUTO_TEST_CASE(bessel_k0_matches_tabulated_values) {
  // K0 to 10 digits (Abramowitz & Stegun, table 9.8, and DLMF 10.25).
  const struct {
    double x, k0;
  } table[] = {{0.1, 2.4270690247}, {0.5, 0.9244190712}, {1.0, 0.4210244382},
               {2.0, 0.1138938727}, {5.0, 0.0036910983}, {10.0, 1.778006232e-5}};
  for (const auto& row : table)
    BOOST_TEST(std::abs(bessel_k0(row.x) - row.k0) <= 2e-7 * row.k0,
               "K0(" << row.x << ") = " << bessel_k0(row.x) << ", expected " << row.k0);
}

#if defined(__cpp_lib_math_special_functions) || defined(__STDCPP_MATH_SPEC_FUNCS__)
BOOST_AUTO_TEST_CASE(bessel_k0_matches_the_standard_library) {
  // Nine decades of argument, up to where K0 is near the smallest normal.
  double worst = 0, worst_x = 0;
  for (double x = 1e-6; x < 700; x *= 1.01) {
    const double expected = std::cyl_bessel_k(0.0, x);
    const double error = std::abs(bessel_k0(x) - expected) / expected;
    if (error > worst) worst = error, worst_x = x;
  }
  BOOST_TEST(worst <= 2e-7, "largest relative error " << worst << " at x = " << worst_x);
}
#endif

BOOST_AUTO_TEST_CASE(bessel_k0_is_defined_for_every_argument) {
  const double inf = std::numeric_limits<double>::infinity();
  BOOST_TEST(bessel_k0(0.0) == inf);
  BOOST_TEST(bessel_k0(1e-300) > 690.0);  // -log(x/2) - gamma
  BOOST_TEST(bessel_k0(700.0) > 0.0);
  for (double x : {800.0, 1e5, 1e9, 1e300, inf}) BOOST_TEST(bessel_k0(x) == 0.0);
  BOOST_TEST(std::isnan(bessel_k0(-1.0)));
  BOOST_TEST(std::isnan(bessel_k0(std::numeric_limits<double>::quiet_NaN())));
}
