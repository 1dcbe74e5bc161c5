// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HIERARCHICAL_DIAGONAL_COMPRESSION_H
#define EXPMAP_INTERNAL_HIERARCHICAL_DIAGONAL_COMPRESSION_H

#include <expmap/internal/Hierarchical_diagonal.h>
#include <expmap/internal/Parallel_loop.h>
#include <expmap/internal/Supernodal_factor.h>
#include <expmap/internal/Vector3.h>

#include <Eigen/Core>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// Which supernodes' diagonal blocks are kept in hierarchical form, and how
/// closely.
struct Diagonal_compression {
  /// Singular values of an off-diagonal block at or below this times its
  /// largest are dropped; 0 leaves every diagonal block dense.
  double tolerance = 0;
  /// Only supernodes with at least this many columns: the top separators,
  /// which every solve crosses.
  int min_columns = 256;
  /// The recursion stops at dense triangles of at most this many columns.
  int leaf_columns = 128;
  /// A block is kept in hierarchical form only if a solve then reads at
  /// most this fraction of its triangle's entries.
  double max_fraction = 0.7;
};

/// Orders `column` (indices into `position`) by recursive bisection at the
/// median of the coordinate of largest extent, halving at (begin + end) / 2
/// as the hierarchical form does: each half of the form is then a compact
/// piece of the separator.
inline void order_by_bisection(std::vector<int>& column, int begin, int end,
                               const std::vector<Vector3>& position, int leaf) {
  if (end - begin <= leaf) return;
  Vector3 low = position[static_cast<std::size_t>(column[begin])], high = low;
  for (int i = begin; i < end; ++i)
    for (int a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], position[static_cast<std::size_t>(column[i])][a]);
      high[a] = std::max(high[a], position[static_cast<std::size_t>(column[i])][a]);
    }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (high[a] - low[a] > high[axis] - low[axis]) axis = a;
  const int mid = (begin + end) / 2;
  std::nth_element(column.begin() + begin, column.begin() + mid, column.begin() + end,
                   [&](int x, int y) {
                     return position[static_cast<std::size_t>(x)][axis] <
                            position[static_cast<std::size_t>(y)][axis];
                   });
  order_by_bisection(column, begin, mid, position, leaf);
  order_by_bisection(column, mid, end, position, leaf);
}

/// Appends the hierarchical form of the lower triangle `L` (rows and
/// columns [begin, end)) to `h.node` and its entries to `values`.
inline void build_hierarchical_triangle(const Eigen::MatrixXd& L, int begin, int end,
                                        const Diagonal_compression& c, Hierarchical_diagonal& h,
                                        std::vector<double>& values) {
  Hierarchical_diagonal::Node node;
  node.begin = begin;
  node.end = end;
  node.offset = values.size();
  const std::size_t index = h.node.size();
  if (end - begin <= c.leaf_columns) {
    node.mid = end;
    // The diagonal as its inverse: a solve multiplies by it, and a
    // division on the solve's chain of dependent rows would wait 3-4 times
    // as long.
    for (int r = begin; r < end; ++r)
      for (int col = begin; col <= r; ++col) values.push_back(col == r ? 1 / L(r, r) : L(r, col));
    h.node.push_back(node);
    return;
  }
  node.mid = (begin + end) / 2;
  const int rows = end - node.mid, columns = node.mid - begin;
  const Eigen::MatrixXd block = L.block(node.mid, begin, rows, columns);
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(block, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& sigma = svd.singularValues();
  int r = 0;
  while (r < sigma.size() && sigma[r] > c.tolerance * sigma[0]) ++r;
  if (static_cast<double>(r) * (rows + columns) < static_cast<double>(rows) * columns) {
    node.rank = r;
    for (int j = 0; j < r; ++j)
      for (int t = 0; t < rows; ++t) values.push_back(svd.matrixU()(t, j) * sigma[j]);
    for (int j = 0; j < r; ++j)
      for (int q = 0; q < columns; ++q) values.push_back(svd.matrixV()(q, j));
  } else {
    for (int t = 0; t < rows; ++t)
      for (int q = 0; q < columns; ++q) values.push_back(block(t, q));
  }
  h.node.push_back(node);
  build_hierarchical_triangle(L, begin, node.mid, c, h, values);
  h.node[index].right = static_cast<int>(h.node.size());
  build_hierarchical_triangle(L, node.mid, end, c, h, values);
}

/// Keeps the diagonal blocks of the large double-precision supernodes of
/// `f` in hierarchical form (`Hierarchical_diagonal`), where that reads at
/// most `c.max_fraction` of the triangle. `position[row]` is where the row
/// of A (a mesh vertex) lies: a supernode's columns are ordered by
/// bisection of their positions, P, and its triangle L refactored as
/// P L = L' Q (an LQ decomposition, Householder, so as accurate as L
/// itself; L' L'^T = P L L^T P^T, the same Schur complement in the new
/// order); Q goes into the rows below. Must come before the rows below are
/// compressed (compress_rows_below), which then compresses the rotated
/// ones; those already compressed are left alone.
///
/// Why: in the order nested dissection leaves them, a separator's columns
/// mix near and far vertices and the triangle has no low-rank blocks
/// (elephant_loop3's root: rank 407 of 1,012 at 1e-12 in its lower-left
/// quadrant); ordered along the separator, its off-diagonal halves couple
/// far-apart pieces and have ranks of a few dozen (70 of 1,012 at 1e-14),
/// and the triangles every solve crosses read 2.5-4 times fewer entries
/// (doc/paper_scale.md).
///
/// The decompositions run on `threads` threads (0: the hardware's count).
/// \returns the number of supernodes put in hierarchical form.
/// \pre 0 <= c.tolerance < 1, 2 <= c.leaf_columns < c.min_columns,
///      0 < c.max_fraction <= 1, position holds every row of A.
inline std::size_t compress_diagonal_blocks(Supernodal_factor& f, const Diagonal_compression& c,
                                            const std::vector<Vector3>& position,
                                            unsigned threads = 0) {
  if (!(c.tolerance >= 0 && c.tolerance < 1) || !(c.max_fraction > 0 && c.max_fraction <= 1) ||
      c.leaf_columns < 2 || c.min_columns <= c.leaf_columns)
    throw std::invalid_argument("compress_diagonal_blocks: the tolerance must lie in [0, 1), "
                                "max_fraction in (0, 1], and 2 <= leaf_columns < min_columns");
  if (position.size() < static_cast<std::size_t>(f.size))
    throw std::invalid_argument("compress_diagonal_blocks: a position for every row is needed");
  if (c.tolerance == 0) return 0;
  std::vector<std::size_t> candidates;
  for (std::size_t k = 0; k < f.supernode.size(); ++k) {
    const auto& sn = f.supernode[k];
    if (!sn.single && sn.rank < 0 && sn.hierarchical < 0 && sn.ncol >= c.min_columns)
      candidates.push_back(k);
  }
  // Largest first: the last ones to start are the quick ones.
  std::sort(candidates.begin(), candidates.end(), [&f](std::size_t a, std::size_t b) {
    return f.supernode[a].ncol > f.supernode[b].ncol;
  });
  std::vector<Hierarchical_diagonal> form(candidates.size());
  std::vector<char> kept(candidates.size(), 0);
  parallel_loop(candidates.size(), batch_thread_count(threads, candidates.size()),
                [&](std::size_t i) {
    const auto& sn = f.supernode[candidates[i]];
    const int n = sn.ncol;
    double* triangle = f.value.data() + sn.diagonal;
    Hierarchical_diagonal& h = form[i];
    h.order.resize(static_cast<std::size_t>(n));
    std::iota(h.order.begin(), h.order.end(), 0);
    std::vector<Vector3> where(static_cast<std::size_t>(n));
    for (int col = 0; col < n; ++col)
      where[static_cast<std::size_t>(col)] =
          position[static_cast<std::size_t>(f.permutation[sn.first_column + col])];
    order_by_bisection(h.order, 0, n, where, std::min(16, c.leaf_columns));
    // (P L)^T = Q^T R: then P L = R^T Q, L' = R^T.
    Eigen::MatrixXd PLt = Eigen::MatrixXd::Zero(n, n);
    for (int a = 0; a < n; ++a) {
      const int r = h.order[static_cast<std::size_t>(a)];
      const double* row = triangle + Supernodal_factor::triangle_row(r);
      for (int col = 0; col <= r; ++col) PLt(col, a) = row[col];
    }
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(PLt);
    Eigen::MatrixXd Lp = qr.matrixQR().triangularView<Eigen::Upper>().transpose();
    // Positive diagonal, as a Cholesky factor has: L' D and D Q (D = D^-1).
    Eigen::VectorXd sign(n);
    for (int a = 0; a < n; ++a) sign[a] = Lp(a, a) < 0 ? -1.0 : 1.0;
    Lp = Lp * sign.asDiagonal();
    std::vector<double> values;
    build_hierarchical_triangle(Lp, 0, n, c, h, values);
    h.entries = values.size();
    if (static_cast<double>(values.size()) >
        c.max_fraction * static_cast<double>(Supernodal_factor::triangle_row(n)))
      return;
    // The rows below become B Q^T = B Qh D (Qh = householderQ(), Q = D Qh^T).
    if (sn.nbelow > 0) {
      using Row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      Eigen::Map<Row_major> below(f.value.data() + sn.below, sn.nbelow, n);
      Row_major rotated = below * qr.householderQ();
      below = rotated * sign.asDiagonal();
    }
    std::copy(values.begin(), values.end(), triangle);
    kept[i] = 1;
  });
  std::size_t count = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!kept[i]) continue;
    f.supernode[candidates[i]].hierarchical = static_cast<int>(f.hierarchical.size());
    f.hierarchical.push_back(std::move(form[i]));
    ++count;
  }
  return count;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HIERARCHICAL_DIAGONAL_COMPRESSION_H
