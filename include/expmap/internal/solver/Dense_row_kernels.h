// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_DENSE_ROW_KERNELS_H
#define EXPMAP_INTERNAL_SOLVER_DENSE_ROW_KERNELS_H

#include <array>
#include <cstddef>

namespace expmap {
namespace internal {

// The dense kernels the triangular solves are made of, on row-major blocks
// of W right-hand sides: a row's dot product with the solved values, and
// four solved rows subtracted from the others at once, on the supernodes'
// dense blocks (Supernode_kernels).

/// out[w] -= sum over c in [begin, end) of l[c] * y[c * W + w]. Several
/// independent partial sums: without them every multiply-add waits for the
/// previous one (the compiler may not reassociate floating-point sums), and
/// a one-column solve runs at the latency of the adder, not its throughput.
template <int W, class T>
void subtract_dot(const T* l, const double* y, int begin, int end, double* out) {
  constexpr int lanes = W == 1 ? 4 : 2;
  std::array<std::array<double, W>, lanes> acc{};
  int c = begin;
  for (; c + lanes <= end; c += lanes)
    for (int j = 0; j < lanes; ++j)
      for (int w = 0; w < W; ++w) acc[j][w] += l[c + j] * y[(c + j) * W + w];
  for (; c < end; ++c)
    for (int w = 0; w < W; ++w) acc[0][w] += l[c] * y[c * W + w];
  for (int j = 1; j < lanes; ++j)
    for (int w = 0; w < W; ++w) acc[0][w] += acc[j][w];
  for (int w = 0; w < W; ++w) out[w] -= acc[0][w];
}

/// ys[a * W + w] -= sum over k < 4 of l[k][a] * x[k][w], for a in
/// [begin, end): four solved rows subtracted in one pass over ys (each of
/// its rows read and written once per four rows of L).
template <int W, class T>
void subtract_four_rows(const T* const (&l)[4], const std::array<std::array<double, W>, 4>& x,
                        int begin, int end, double* ys) {
  for (int a = begin; a < end; ++a)
    for (int w = 0; w < W; ++w)
      ys[a * W + w] -=
          l[0][a] * x[0][w] + l[1][a] * x[1][w] + l[2][a] * x[2][w] + l[3][a] * x[3][w];
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_DENSE_ROW_KERNELS_H
