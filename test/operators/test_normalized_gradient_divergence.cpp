// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Step 3 of a heat query on one face, from its precomputed stencil, against
// the same quantity computed in space from the triangle's corners: the unit
// gradient X of the linear interpolant of u, and the integrated divergence
// at a corner a as the flux of X through the half edges next to it,
// 1/2 (cot c (X . e_ab) + cot b (X . e_ac)), with the cotangents from dot and
// cross products. Nothing is shared with the stencil but the edge lengths.

#include <expmap/internal/operators/Normalized_gradient_divergence.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <random>

namespace {

using Point = std::array<double, 3>;

Point minus(const Point& a, const Point& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point cross(const Point& a, const Point& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
double norm(const Point& a) { return std::sqrt(dot(a, a)); }

// X and the divergence in space.
std::array<double, 3> divergence_in_space(const std::array<Point, 3>& p,
                                          const std::array<double, 3>& u) {
  const Point normal = cross(minus(p[1], p[0]), minus(p[2], p[0]));
  const double twice_area = norm(normal);
  Point gradient{{0, 0, 0}};
  for (int a = 0; a < 3; ++a) {
    // grad of the hat function of a: N x e_bc / (2 A), e_bc opposite a.
    const Point e = minus(p[(a + 2) % 3], p[(a + 1) % 3]);
    const Point g = cross(normal, e);
    for (int k = 0; k < 3; ++k) gradient[k] += u[a] * g[k] / (twice_area * twice_area);
  }
  const double length = norm(gradient);
  for (double& x : gradient) x /= length;
  auto cotangent = [&](int k) {  // at corner k
    const Point e1 = minus(p[(k + 1) % 3], p[k]), e2 = minus(p[(k + 2) % 3], p[k]);
    return dot(e1, e2) / norm(cross(e1, e2));
  };
  std::array<double, 3> div{};
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    div[a] = 0.5 * (cotangent(c) * dot(gradient, minus(p[b], p[a])) +
                    cotangent(b) * dot(gradient, minus(p[c], p[a])));
  }
  return div;
}

}  // namespace

BOOST_AUTO_TEST_CASE(divergence_stencil_matches_the_divergence_computed_in_space) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int faces = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::array<Point, 3> p;
    for (auto& q : p) q = {{unit(rng), unit(rng), unit(rng)}};
    const std::array<double, 3> length{{norm(minus(p[1], p[0])), norm(minus(p[2], p[1])),
                                        norm(minus(p[0], p[2]))}};
    const expmap::internal::Triangle_shape shape = expmap::internal::triangle_shape(length);
    if (!(shape.area > 1e-3)) continue;  // slivers: the reference loses digits, not the stencil
    ++faces;
    // Heat-like values: positive, of one scale, in no particular order.
    const std::array<double, 3> u{{1 + unit(rng), 1 + unit(rng), 1 + unit(rng)}};
    const auto expected = divergence_in_space(p, u);
    const expmap::internal::Divergence_stencil stencil(shape);
    const auto div = expmap::internal::normalized_gradient_divergence(stencil, u);
    BOOST_TEST_CONTEXT("trial " << trial) {
      for (int a = 0; a < 3; ++a) BOOST_TEST(std::abs(div[a] - expected[a]) < 1e-9);
      // Whole faces keep the Poisson problem compatible.
      BOOST_TEST(std::abs(div[0] + div[1] + div[2]) < 1e-12);
      // Only the direction of grad u enters: a heat 1e-300 times smaller
      // (its gradient's square underflows) gives the same divergence.
      const auto tiny = expmap::internal::normalized_gradient_divergence(
          stencil, {{u[0] * 1e-300, u[1] * 1e-300, u[2] * 1e-300}});
      for (int a = 0; a < 3; ++a) BOOST_TEST(std::abs(tiny[a] - div[a]) < 1e-12);
    }
  }
  BOOST_TEST(faces > 300);
  // A constant heat has no direction: the face contributes nothing.
  const expmap::internal::Divergence_stencil flat(
      expmap::internal::triangle_shape({{1.0, 1.0, 1.0}}));
  const auto none = expmap::internal::normalized_gradient_divergence(flat, {{2.0, 2.0, 2.0}});
  BOOST_TEST((none[0] == 0 && none[1] == 0 && none[2] == 0));
}
