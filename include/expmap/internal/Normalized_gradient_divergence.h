// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_NORMALIZED_GRADIENT_DIVERGENCE_H
#define EXPMAP_INTERNAL_NORMALIZED_GRADIENT_DIVERGENCE_H

#include <expmap/internal/Intrinsic_triangulation.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace expmap {
namespace internal {

/// Step 2 of the heat method (Crane et al. 2013) on one face: the unit
/// vector field X = grad u / |grad u| of the piecewise linear heat u (eq. 6
/// and 7 of the paper), and its integrated divergence at the three corners,
/// div_a = 1/2 (cot c (X . e_ab) + cot b (X . e_ac)).
///
/// Works in the face's own planar layout, so it needs only edge lengths and
/// runs unchanged on intrinsic triangulations. The three contributions sum
/// to zero, so a right-hand side assembled from whole faces always
/// satisfies the compatibility condition of the Neumann Poisson problem.
/// A face where u is constant contributes nothing.
inline std::array<double, 3> normalized_gradient_divergence(const Triangle_shape& shape,
                                                            std::array<double, 3> u) {
  const double x1 = shape.layout[0], x2 = shape.layout[1], y2 = shape.layout[2];
  const std::array<std::array<double, 2>, 3> p{{{{0.0, 0.0}}, {{x1, 0.0}}, {{x2, y2}}}};
  // grad u = 1/(2A) sum_k u_k rot90(p_{k+2} - p_{k+1}) with the corners at
  // (0, 0), (x1, 0), (x2, y2); the 1/(2A) factor cancels in the
  // normalization.
  auto unnormalized_gradient = [&](const std::array<double, 3>& v) {
    return std::array<double, 2>{{y2 * (v[1] - v[0]), v[0] * (x2 - x1) - v[1] * x2 + v[2] * x1}};
  };
  std::array<double, 2> grad = unnormalized_gradient(u);
  double square = grad[0] * grad[0] + grad[1] * grad[1];
  if (!std::isnormal(square)) {
    // Heat decays exponentially: the square of a far, tiny-valued face's
    // gradient underflows (or a huge one overflows). Rescaled by the
    // largest value, only its direction is kept, which is all we need.
    const double largest = std::max({std::abs(u[0]), std::abs(u[1]), std::abs(u[2])});
    if (!(largest > 0) || !std::isfinite(largest)) return {{0, 0, 0}};
    for (double& value : u) value /= largest;
    grad = unnormalized_gradient(u);
    square = grad[0] * grad[0] + grad[1] * grad[1];
    if (!(square > 0) || !std::isfinite(square)) return {{0, 0, 0}};
  }
  const double inverse_length = 1.0 / std::sqrt(square);
  const double gx = grad[0] * inverse_length, gy = grad[1] * inverse_length;
  std::array<double, 3> div;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const double x_ab = gx * (p[b][0] - p[a][0]) + gy * (p[b][1] - p[a][1]);
    const double x_ac = gx * (p[c][0] - p[a][0]) + gy * (p[c][1] - p[a][1]);
    div[a] = 0.5 * (shape.cotangent[c] * x_ab + shape.cotangent[b] * x_ac);
  }
  return div;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_NORMALIZED_GRADIENT_DIVERGENCE_H
