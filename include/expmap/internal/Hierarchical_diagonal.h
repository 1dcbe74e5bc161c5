// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HIERARCHICAL_DIAGONAL_H
#define EXPMAP_INTERNAL_HIERARCHICAL_DIAGONAL_H

#include <expmap/internal/Dense_row_kernels.h>

#include <array>
#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {

/// A supernode's diagonal block kept as a hierarchical (HODLR) triangle
/// (`compress_diagonal_blocks`, Hierarchical_diagonal_compression.h).
///
/// The block L of a supernode is replaced by L' with L = P^T L' Q: P orders
/// the supernode's columns along the separator (`order`), Q is orthogonal
/// and folded into the rows below (which become B Q^T). A solve then works
/// on the rotated forward values y' = Q y = L'^-1 P b, which the rows below
/// read as they read y, and the back substitution returns x = P^T L'^-T (y'
/// - (B Q^T)^T x_below) in the columns' own order. Ordered along the
/// separator, the off-diagonal halves of L' couple far-apart pieces of it
/// and are of low numerical rank; they are kept as U V^T, recursively, down
/// to dense triangles of a few dozen columns.
///
/// The nodes are stored in preorder in `node`, their entries in the
/// supernode's own place (offsets from its diagonal block, which they never
/// outgrow).
struct Hierarchical_diagonal {
  struct Node {
    int begin = 0, mid = 0, end = 0;  // a leaf: mid == end
    int right = -1;                   // the right child's index (the left one follows the node)
    int rank = -1;                    // off-diagonal block: -1 dense (rows x columns, row-major),
                                      // else U^T (rank x rows) then V^T (rank x columns)
    std::size_t offset = 0;           // leaf: packed lower triangle, row r at r (r + 1) / 2,
                                      // its diagonal entry inverted
  };
  std::vector<int> order;  // position a holds the supernode's column order[a]
  std::vector<Node> node;
  std::size_t entries = 0;  // entries a solve through the block reads
};

/// z[c * W + w] -= sum over i < rows of a(i)[c] * x[i * W + w], for c <
/// count, four rows of `a` at a time (subtract_four_rows). `x` is copied per
/// group: it may lie in z's array (never in the part written).
template <int W, class T, class Row>
void subtract_rows(Row a, const double* x, int rows, int count, double* z) {
  int i = 0;
  for (; i + 4 <= rows; i += 4) {
    const T* r[4] = {a(i), a(i + 1), a(i + 2), a(i + 3)};
    std::array<std::array<double, W>, 4> s;
    for (int k = 0; k < 4; ++k)
      for (int w = 0; w < W; ++w) s[k][w] = x[(i + k) * W + w];
    subtract_four_rows<W>(r, s, 0, count, z);
  }
  for (; i < rows; ++i) {
    const T* r = a(i);
    double s[W];
    for (int w = 0; w < W; ++w) s[w] = x[i * W + w];
    for (int c = 0; c < count; ++c)
      for (int w = 0; w < W; ++w) z[c * W + w] -= r[c] * s[w];
  }
}

/// z_to -= A B^T z_from for an off-diagonal block kept as the low-rank
/// product A B^T, given as the `rank` rows of A^T (`to_count` long) and of
/// B^T (`from_count` long): the dots along B^T's rows first, then the
/// update along A^T's. The forward solve applies U V^T, the back
/// substitution its transpose V U^T.
template <int W, class T>
void subtract_low_rank(const T* At, int to_count, const T* Bt, int from_count, int rank,
                       const double* z_from, double* z_to) {
  double* v = zeroed_scratch(static_cast<std::size_t>(rank) * W);
  for (int j = 0; j < rank; ++j) {
    subtract_dot<W>(Bt + static_cast<std::size_t>(j) * from_count, z_from, 0, from_count,
                    v + j * W);
    for (int w = 0; w < W; ++w) v[j * W + w] = -v[j * W + w];
  }
  subtract_rows<W, T>([At, to_count](int j) { return At + static_cast<std::size_t>(j) * to_count; },
                      v, rank, to_count, z_to);
}

/// Solves L' z = z in place (`z`: positions x W, row-major) on the values
/// `l` (the supernode's entries from its diagonal block's offset on).
template <int W, class T>
void hierarchical_forward(const Hierarchical_diagonal& h, const T* l, double* z, int i = 0) {
  const auto& n = h.node[static_cast<std::size_t>(i)];
  const T* e = l + n.offset;
  double* zb = z + static_cast<std::size_t>(n.begin) * W;
  if (n.mid == n.end) {  // a dense triangle, row by row
    for (int r = 0; r < n.end - n.begin; ++r) {
      const T* row = e + static_cast<std::size_t>(r) * (r + 1) / 2;
      subtract_dot<W>(row, zb, 0, r, zb + r * W);
      for (int w = 0; w < W; ++w) zb[r * W + w] *= row[r];
    }
    return;
  }
  hierarchical_forward<W>(h, l, z, i + 1);
  const int rows = n.end - n.mid, columns = n.mid - n.begin;
  double* zm = z + static_cast<std::size_t>(n.mid) * W;
  if (n.rank < 0) {
    for (int t = 0; t < rows; ++t)
      subtract_dot<W>(e + static_cast<std::size_t>(t) * columns, zb, 0, columns, zm + t * W);
  } else if (n.rank > 0) {  // z[mid, end) -= U V^T z[begin, mid)
    const T* Ut = e;
    const T* Vt = e + static_cast<std::size_t>(rows) * n.rank;
    subtract_low_rank<W, T>(Ut, rows, Vt, columns, n.rank, zb, zm);
  }
  hierarchical_forward<W>(h, l, z, n.right);
}

/// Solves L'^T z = z in place (as `hierarchical_forward`).
template <int W, class T>
void hierarchical_backward(const Hierarchical_diagonal& h, const T* l, double* z, int i = 0) {
  const auto& n = h.node[static_cast<std::size_t>(i)];
  const T* e = l + n.offset;
  double* zb = z + static_cast<std::size_t>(n.begin) * W;
  if (n.mid == n.end) {  // a dense triangle, bottom-up, four rows at a time
    auto row = [e](int r) { return e + static_cast<std::size_t>(r) * (r + 1) / 2; };
    int r = n.end - n.begin - 1;
    for (; r >= 3; r -= 4) {
      // The four rows' own triangle, then the rows above them in one pass.
      for (int k = 0; k < 4; ++k) {
        const T* lr = row(r - k);
        for (int w = 0; w < W; ++w) zb[(r - k) * W + w] *= lr[r - k];
        for (int j = k + 1; j < 4; ++j)
          for (int w = 0; w < W; ++w) zb[(r - j) * W + w] -= lr[r - j] * zb[(r - k) * W + w];
      }
      subtract_rows<W, T>([&row, r](int k) { return row(r - 3 + k); }, zb + (r - 3) * W, 4,
                          r - 3, zb);
    }
    for (; r >= 0; --r) {
      const T* lr = row(r);
      for (int w = 0; w < W; ++w) zb[r * W + w] *= lr[r];
      subtract_rows<W, T>([lr](int) { return lr; }, zb + r * W, 1, r, zb);
    }
    return;
  }
  hierarchical_backward<W>(h, l, z, n.right);
  const int rows = n.end - n.mid, columns = n.mid - n.begin;
  const double* zm = z + static_cast<std::size_t>(n.mid) * W;
  if (n.rank < 0) {
    subtract_rows<W, T>(
        [e, columns](int t) { return e + static_cast<std::size_t>(t) * columns; }, zm, rows,
        columns, zb);
  } else if (n.rank > 0) {  // z[begin, mid) -= V U^T z[mid, end)
    const T* Ut = e;
    const T* Vt = e + static_cast<std::size_t>(rows) * n.rank;
    subtract_low_rank<W, T>(Vt, columns, Ut, rows, n.rank, zm, zb);
  }
  hierarchical_backward<W>(h, l, z, i + 1);
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HIERARCHICAL_DIAGONAL_H
