// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_NORMALIZED_GRADIENT_DIVERGENCE_H
#define EXPMAP_INTERNAL_OPERATORS_NORMALIZED_GRADIENT_DIVERGENCE_H

#include <expmap/internal/operators/Intrinsic_triangulation.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace expmap {
namespace internal {

/// Step 3 of a heat query (manual, section 2; Crane et al. 2013) on one face, prepared once
/// per face: the unit vector field X = grad u / |grad u| of the piecewise
/// linear heat u (eq. 6 and 7 of the paper), and its integrated divergence at
/// the three corners, div_a = 1/2 (cot c (X . e_ab) + cot b (X . e_ac)).
///
/// Works in the face's own planar layout (corner 0 at the origin, corner 1
/// at (x1, 0), corner 2 at (x2, y2)), so it needs only edge lengths and runs
/// unchanged on intrinsic triangulations. Everything that depends on the
/// face alone is folded into constants here (ten numbers per face, three
/// more than its `Triangle_shape`): a query evaluates the divergence on every
/// face of its region, and then only the heat's gradient, its length and
/// three dot products remain.
struct Divergence_stencil {
  /// grad u, up to the positive factor 1 / (2 area):
  /// (y2 (u1 - u0), u0 (x2 - x1) - u1 x2 + u2 x1).
  double y2 = 0, x2_minus_x1 = 0, x2 = 0, x1 = 0;
  /// div_a = X . corner_weight[a].
  std::array<std::array<double, 2>, 3> corner_weight{};

  Divergence_stencil() = default;
  explicit Divergence_stencil(const Triangle_shape& shape)
      : y2(shape.layout[2]),
        x2_minus_x1(shape.layout[1] - shape.layout[0]),
        x2(shape.layout[1]),
        x1(shape.layout[0]) {
    const std::array<std::array<double, 2>, 3> p{
        {{{0.0, 0.0}}, {{shape.layout[0], 0.0}}, {{shape.layout[1], shape.layout[2]}}}};
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (int k = 0; k < 2; ++k)
        corner_weight[a][k] = 0.5 * (shape.cotangent[c] * (p[b][k] - p[a][k]) +
                                     shape.cotangent[b] * (p[c][k] - p[a][k]));
    }
  }

  std::array<double, 2> unnormalized_gradient(const std::array<double, 3>& u) const {
    return {{y2 * (u[1] - u[0]), u[0] * x2_minus_x1 - u[1] * x2 + u[2] * x1}};
  }
};

/// The unit vector along a face's heat gradient when the squared length of
/// the gradient is not a normal number: the square of a far, tiny-valued
/// face's gradient underflows (heat decays exponentially), or a huge one
/// overflows. Rescaled by the largest value, the gradient keeps its
/// direction, which is all the divergence needs. {0, 0} where u is constant
/// or not finite.
///
/// Out of line on purpose: kept apart, the common case of
/// `normalized_gradient_divergence` is small enough for the compiler to
/// inline it into the loop over a region's faces at -O2 as well as at -O3
/// (at -O2 it was a call per face, the heat values passed through the stack).
[[gnu::noinline]] inline std::array<double, 2> rescaled_unit_gradient(
    const Divergence_stencil& stencil, std::array<double, 3> u) {
  const double largest = std::max({std::abs(u[0]), std::abs(u[1]), std::abs(u[2])});
  if (!(largest > 0) || !std::isfinite(largest)) return {{0, 0}};
  for (double& value : u) value /= largest;
  const std::array<double, 2> grad = stencil.unnormalized_gradient(u);
  const double square = grad[0] * grad[0] + grad[1] * grad[1];
  if (!(square > 0) || !std::isfinite(square)) return {{0, 0}};
  const double inverse_length = 1.0 / std::sqrt(square);
  return {{grad[0] * inverse_length, grad[1] * inverse_length}};
}

/// X = grad u / |grad u| in the face's layout ({0, 0} where u is constant).
inline std::array<double, 2> normalized_gradient(const Divergence_stencil& stencil,
                                                 const std::array<double, 3>& u) {
  std::array<double, 2> unit = stencil.unnormalized_gradient(u);
  const double square = unit[0] * unit[0] + unit[1] * unit[1];
  if (!std::isnormal(square)) return rescaled_unit_gradient(stencil, u);
  const double inverse_length = 1.0 / std::sqrt(square);
  return {{unit[0] * inverse_length, unit[1] * inverse_length}};
}

/// The integrated divergence of X = grad u / |grad u| at the three corners
/// of the face of `stencil`. The three contributions sum to zero (up to
/// round-off), so a right-hand side assembled from whole faces satisfies the
/// compatibility condition of the Neumann Poisson problem. A face where u is
/// constant contributes nothing.
inline std::array<double, 3> normalized_gradient_divergence(const Divergence_stencil& stencil,
                                                            const std::array<double, 3>& u) {
  const std::array<double, 2> unit = normalized_gradient(stencil, u);
  std::array<double, 3> div;
  for (int a = 0; a < 3; ++a)
    div[a] = unit[0] * stencil.corner_weight[a][0] + unit[1] * stencil.corner_weight[a][1];
  return div;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_NORMALIZED_GRADIENT_DIVERGENCE_H
