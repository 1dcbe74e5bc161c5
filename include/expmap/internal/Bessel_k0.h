// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_BESSEL_K0_H
#define EXPMAP_INTERNAL_BESSEL_K0_H

#include <cmath>
#include <limits>

namespace expmap {
namespace internal {

/// The modified Bessel function of the second kind of order zero, K0(x),
/// to about 2e-7 relative error, for every x: +infinity at 0, 0 where it
/// underflows (x above about 700) and at +infinity, NaN for x < 0 or NaN.
///
/// Own code rather than `std::cyl_bessel_k`: libc++ does not provide the
/// special functions, and libstdc++'s throws `std::runtime_error` for large
/// arguments instead of underflowing. The heat method only needs K0 for a
/// threshold (the heat at a distance), so the classic approximations of
/// Abramowitz & Stegun (1964) are accurate enough:
/// 9.8.1 (I0) and 9.8.5 (K0, |error| < 1e-8) for x <= 2, and
/// 9.8.6 (sqrt(x) e^x K0(x), |error| < 1.9e-7) above.
inline double bessel_k0(double x) {
  if (std::isnan(x) || x < 0) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0) return std::numeric_limits<double>::infinity();
  if (x <= 2) {
    const double u = x / 3.75, u2 = u * u;  // A&S 9.8.1: I0 on [-3.75, 3.75]
    const double i0 =
        1 + u2 * (3.5156229 + u2 * (3.0899424 + u2 * (1.2067492 + u2 * (0.2659732 +
            u2 * (0.0360768 + u2 * 0.0045813)))));
    const double y = x * x / 4;  // A&S 9.8.5, in powers of (x/2)^2
    return -std::log(x / 2) * i0 +
           (-0.57721566 + y * (0.42278420 + y * (0.23069756 + y * (0.03488590 + y * (0.00262698 +
            y * (0.00010750 + y * 0.00000740))))));
  }
  const double y = 2 / x;  // A&S 9.8.6; e^-x underflows to 0 for large x
  const double scaled =
      1.25331414 + y * (-0.07832358 + y * (0.02189568 + y * (-0.01062446 + y * (0.00587872 +
      y * (-0.00251540 + y * 0.00053208)))));
  return std::exp(-x) / std::sqrt(x) * scaled;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_BESSEL_K0_H
