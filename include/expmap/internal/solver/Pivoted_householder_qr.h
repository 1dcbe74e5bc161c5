// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_PIVOTED_HOUSEHOLDER_QR_H
#define EXPMAP_INTERNAL_SOLVER_PIVOTED_HOUSEHOLDER_QR_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// X P = Q R for a tall matrix X of `Columns` columns, by Householder
/// reflections with column pivoting (the decomposition Eigen's
/// ColPivHouseholderQR and CompleteOrthogonalDecomposition start from,
/// written out: the fits solved with it have a handful of columns, and the
/// Eigen templates would be compiled in every translation unit that
/// includes the library). For a matrix of full column rank it gives the
/// rows of the least-squares pseudo-inverse (X^T X)^-1 X^T = P R^-1 Q^T
/// without squaring the condition number as the normal equations would.
template <int Columns>
class Pivoted_householder_qr {
 public:
  /// `x`: the `rows` x Columns matrix, column-major (column j at
  /// x[j * rows]).
  /// \pre rows >= Columns.
  Pivoted_householder_qr(std::vector<double> x, int rows) : m_qr(std::move(x)), m_rows(rows) {
    std::array<double, Columns> squared_norm{};
    for (int j = 0; j < Columns; ++j) m_column[j] = j;
    for (int k = 0; k < Columns; ++k) {
      // The remaining column of largest norm below row k goes first.
      for (int j = k; j < Columns; ++j) {
        squared_norm[j] = 0;
        for (int i = k; i < rows; ++i) squared_norm[j] += at(i, j) * at(i, j);
      }
      const int pivot = static_cast<int>(
          std::max_element(squared_norm.begin() + k, squared_norm.end()) - squared_norm.begin());
      if (pivot != k) {
        std::swap(m_column[k], m_column[pivot]);
        std::swap_ranges(&at(0, k), &at(0, k) + rows, &at(0, pivot));
      }
      // The reflection I - tau v v^T, v = (1, essential part below row k),
      // that maps column k below row k onto beta e_k.
      const double head = at(k, k);
      double tail = 0;
      for (int i = k + 1; i < rows; ++i) tail += at(i, k) * at(i, k);
      double beta = head, tau = 0;
      if (tail > std::numeric_limits<double>::min()) {
        beta = -std::copysign(std::sqrt(head * head + tail), head);
        for (int i = k + 1; i < rows; ++i) at(i, k) /= head - beta;
        tau = (beta - head) / beta;
      }
      at(k, k) = beta;
      m_tau[k] = tau;
      for (int j = k + 1; j < Columns; ++j) {
        double dot = at(k, j);
        for (int i = k + 1; i < rows; ++i) dot += at(i, k) * at(i, j);
        dot *= tau;
        at(k, j) -= dot;
        for (int i = k + 1; i < rows; ++i) at(i, j) -= dot * at(i, k);
      }
      m_largest_pivot = std::max(m_largest_pivot, std::abs(beta));
    }
  }

  /// Whether every diagonal entry of R exceeds Columns times the machine
  /// epsilon times the largest (Eigen's default rank threshold).
  bool full_rank() const {
    const double threshold =
        Columns * std::numeric_limits<double>::epsilon() * m_largest_pivot;
    for (int k = 0; k < Columns; ++k)
      if (!(std::abs(at(k, k)) > threshold)) return false;
    return true;
  }

  /// Row `i` of the pseudo-inverse P R^-1 Q^T into `out` (`rows` values):
  /// (Q R^-T e_k)^T, k the position column i was pivoted to.
  /// \pre full_rank().
  void pseudo_inverse_row(int i, double* out) const {
    const int k = static_cast<int>(std::find(m_column.begin(), m_column.end(), i) -
                                   m_column.begin());
    std::array<double, Columns> z{};  // R^T z = e_k
    for (int a = k; a < Columns; ++a) {
      double sum = a == k ? 1.0 : 0.0;
      for (int b = k; b < a; ++b) sum -= at(b, a) * z[b];
      z[a] = sum / at(a, a);
    }
    std::fill(out, out + m_rows, 0.0);
    std::copy(z.begin(), z.end(), out);
    for (int a = Columns - 1; a >= 0; --a) {  // Q = H_0 H_1 ... H_{Columns-1}
      double dot = out[a];
      for (int r = a + 1; r < m_rows; ++r) dot += at(r, a) * out[r];
      dot *= m_tau[a];
      out[a] -= dot;
      for (int r = a + 1; r < m_rows; ++r) out[r] -= dot * at(r, a);
    }
  }

 private:
  double& at(int i, int j) { return m_qr[static_cast<std::size_t>(j) * m_rows + i]; }
  double at(int i, int j) const { return m_qr[static_cast<std::size_t>(j) * m_rows + i]; }

  std::vector<double> m_qr;  // R on and above the diagonal, the reflections' v below
  int m_rows;
  std::array<int, Columns> m_column;  // position k holds column m_column[k] of X
  std::array<double, Columns> m_tau{};
  double m_largest_pivot = 0;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_PIVOTED_HOUSEHOLDER_QR_H
