// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_SUPERNODE_KERNELS_H
#define EXPMAP_INTERNAL_SOLVER_SUPERNODE_KERNELS_H

#include <expmap/internal/solver/Dense_row_kernels.h>
#include <expmap/internal/solver/Supernodal_factor.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace expmap {
namespace internal {

/// The triangular solves of one supernode of a `Supernodal_factor`, on a
/// row-major block `y` of W right-hand sides indexed by pivot: forward
/// substitution L y = b and back substitution L^T x = y through the
/// supernode's dense diagonal block and its rows below (dense, or low rank
/// as `compress_rows_below` keeps them), in full or pruned (entries whose
/// magnitude is at most a threshold in every column are not propagated).
///
/// Which supernodes are solved, and in which order, is the caller's
/// (`Localized_substitution`, `Largest_first_search`); these kernels only
/// see one at a time. W
/// is a compile-time width so that the update of a row is a fixed-length
/// loop the compiler vectorizes. The entries are those of the supernode in
/// the factor's precision (T is double or float); the sums are in double.
class Supernode_kernels {
 public:
  using Supernode = Supernodal_factor::Supernode;

  /// Widest block of right-hand sides a kernel is compiled for.
  static constexpr int max_width = 16;

  /// The width W of the kernel that solves a block of `columns` columns
  /// (1 to `max_width`): 1 and 2 have kernels of their own (the source heat
  /// and the Poisson solve; the star solve of an angle estimator linear in
  /// the heat), wider blocks are padded to 4, 8, 12 or 16.
  static constexpr int width_for(int columns) {
    return columns <= 2    ? columns
           : columns <= 4  ? 4
           : columns <= 8  ? 8
           : columns <= 12 ? 12
                           : 16;
  }

  /// Calls f(std::integral_constant<int, W>) with W = `width`, one of the
  /// widths `width_for()` returns.
  template <class F>
  static std::invoke_result_t<F, std::integral_constant<int, 1>> with_width(int width, F f) {
    switch (width) {
      case 1: return f(std::integral_constant<int, 1>{});
      case 2: return f(std::integral_constant<int, 2>{});
      case 4: return f(std::integral_constant<int, 4>{});
      case 8: return f(std::integral_constant<int, 8>{});
      case 12: return f(std::integral_constant<int, 12>{});
      default: return f(std::integral_constant<int, 16>{});
    }
  }

  /// Scratch memory of the kernels, kept by the caller per query (a
  /// solver's workspace) so that no solve allocates once warm.
  struct Scratch {
    std::vector<int> kept;         // pruned kernels: columns or rows propagated
    std::vector<double> low_rank;  // the r x W products of low-rank rows below
  };

  /// Kernels on `factor`, whose inverse diagonal (1 / L(j, j) by column) is
  /// `inverse_diagonal`, with `scratch` to work in; all three must outlive
  /// the kernels.
  Supernode_kernels(const Supernodal_factor& factor, const double* inverse_diagonal,
                    Scratch& scratch)
      : m_factor(factor), m_inverse_diagonal(inverse_diagonal), m_scratch(scratch) {}

  /// Forward substitution L y = b through `sn`, from its column `first` on
  /// (the earlier ones are zero), on the block `y` (row-major, W columns,
  /// by pivot). With `drop_below` > 0 it is pruned: the columns whose solved
  /// rows are at most `drop_below` in every column of the block are not
  /// propagated.
  /// \returns the factor entries read.
  template <int W>
  std::size_t forward(const Supernode& sn, int first, double* y, double drop_below) {
    double* ys = y + static_cast<std::size_t>(sn.first_column) * W;
    return m_factor.with_entries(sn, [&](const auto* entries) {
      if (drop_below > 0) return forward_pruned<W>(entries, sn, first, ys, y, drop_below);
      forward_full<W>(entries, sn, first, ys, y);
      return entries_read(sn, first, sn.ncol);
    });
  }

  /// Back substitution L^T x = y through `sn`, for its columns from `first`
  /// to `end` (-1: all the rest; the columns from `end` on are solved
  /// already), on the block `y`, whose rows of the supernode's ancestors are
  /// solved. With `drop_below` > 0 (and `end` = -1) it is pruned: the rows
  /// whose solutions are at most `drop_below` in every column of the block
  /// are not propagated.
  /// \returns the factor entries read.
  template <int W>
  std::size_t backward(const Supernode& sn, int first, double* y, double drop_below,
                       int end = -1) {
    double* ys = y + static_cast<std::size_t>(sn.first_column) * W;
    if (end < 0) end = sn.ncol;
    return m_factor.with_entries(sn, [&](const auto* entries) {
      if (drop_below > 0) return backward_pruned<W>(entries, sn, first, ys, y, drop_below);
      backward_full<W>(entries, sn, first, ys, y, end);
      return entries_read(sn, first, end);
    });
  }

 private:
  // Forward substitution through one supernode from its column `first` on:
  // the diagonal block row by row (a row of the row-major block is
  // contiguous), then the rows below it, each one dot product. `ys` are the
  // supernode's own rows of the block `y`; `entries` its entries.
  template <int W, class T>
  void forward_full(const T* entries, const Supernode& sn, int first, double* ys, double* y) {
    const T* diagonal = entries + sn.diagonal;
    for (int r = first; r < sn.ncol; ++r) {
      double* yr = ys + r * W;
      subtract_dot<W>(diagonal + Supernodal_factor::triangle_row(r), ys, first, r, yr);
      const double inverse = m_inverse_diagonal[sn.first_column + r];
      for (int w = 0; w < W; ++w) yr[w] *= inverse;
    }
    const T* below = entries + sn.below;
    const int* below_rows = rows_below(sn);
    if (sn.rank >= 0) {
      const int run[2] = {first, sn.ncol};
      return low_rank_forward<W>(below, sn, run, 2, ys, below_rows, y);
    }
    for (int t = 0; t < sn.nbelow; ++t)
      subtract_dot<W>(below + static_cast<std::size_t>(t) * sn.ncol, ys, first, sn.ncol,
                      y + static_cast<std::size_t>(below_rows[t]) * W);
  }

  // forward_full() pruned: only the columns whose solved rows are above
  // `drop_below` are propagated, to the later rows of the diagonal block and
  // to the rows below. They are kept as [begin, end) runs: in a separator
  // the columns near the right-hand side tend to be consecutive, so a dot
  // product over a run is as contiguous as the unpruned one. Returns the
  // factor entries read.
  template <int W, class T>
  std::size_t forward_pruned(const T* entries, const Supernode& sn, int first, double* ys,
                             double* y, double drop_below) {
    std::vector<int>& runs = m_scratch.kept;  // [begin, end) pairs, flattened
    const T* diagonal = entries + sn.diagonal;
    runs.clear();
    std::size_t kept = 0, read = 0;
    for (int r = first; r < sn.ncol; ++r) {
      double* yr = ys + r * W;
      const T* l = diagonal + Supernodal_factor::triangle_row(r);
      for (std::size_t q = 0; q < runs.size(); q += 2)
        subtract_dot<W>(l, ys, runs[q], runs[q + 1], yr);
      read += kept + 1;
      const double inverse = m_inverse_diagonal[sn.first_column + r];
      for (int w = 0; w < W; ++w) yr[w] *= inverse;
      if (!above<W>(yr, drop_below)) continue;
      ++kept;
      if (!runs.empty() && runs.back() == r)
        runs.back() = r + 1;
      else
        runs.insert(runs.end(), {r, r + 1});
    }
    if (runs.empty()) return read;
    const T* below = entries + sn.below;
    const int* below_rows = rows_below(sn);
    if (sn.rank >= 0) {
      low_rank_forward<W>(below, sn, runs.data(), runs.size(), ys, below_rows, y);
      return read +
             (kept + static_cast<std::size_t>(sn.nbelow)) * static_cast<std::size_t>(sn.rank);
    }
    for (int t = 0; t < sn.nbelow; ++t) {
      const T* l = below + static_cast<std::size_t>(t) * sn.ncol;
      double* target = y + static_cast<std::size_t>(below_rows[t]) * W;
      for (std::size_t q = 0; q < runs.size(); q += 2)
        subtract_dot<W>(l, ys, runs[q], runs[q + 1], target);
    }
    return read + kept * static_cast<std::size_t>(sn.nbelow);
  }

  // Back substitution through one supernode, for its columns from `first`
  // to `end` (the columns from `end` on are solved already): the rows below
  // it (already solved: they belong to ancestors) are subtracted, then the
  // diagonal block is solved bottom-up, each solved row subtracted from the
  // rows above it (row-contiguous in the row-major block).
  template <int W, class T>
  void backward_full(const T* entries, const Supernode& sn, int first, double* ys,
                     const double* y, int end) {
    backward_below<W>(entries, sn, first, ys, y, end);
    const T* diagonal = entries + sn.diagonal;
    for (int r = sn.ncol - 1; r >= end; --r) {  // solved rows, subtracted from the new ones
      const T* l = diagonal + Supernodal_factor::triangle_row(r);
      for (int a = first; a < end; ++a)
        for (int w = 0; w < W; ++w) ys[a * W + w] -= l[a] * ys[r * W + w];
    }
    // Four rows at a time: their own 4 x 4 triangle first, then the rows
    // above them updated by all four in one pass (each row of ys read and
    // written once per four rows of L instead of once per row).
    int r = end - 1;
    for (; r - 3 >= first; r -= 4) {
      const T* l[4];
      std::array<std::array<double, W>, 4> x;
      for (int k = 0; k < 4; ++k) {
        const int row = r - k;
        l[k] = diagonal + Supernodal_factor::triangle_row(row);
        double* yr = ys + row * W;
        const double inverse = m_inverse_diagonal[sn.first_column + row];
        for (int w = 0; w < W; ++w) x[k][w] = yr[w] *= inverse;
        for (int j = k + 1; j < 4; ++j)  // the rows r - j below row r - k's diagonal
          for (int w = 0; w < W; ++w) ys[(r - j) * W + w] -= l[k][r - j] * x[k][w];
      }
      subtract_four_rows<W>(l, x, first, r - 3, ys);
    }
    for (; r >= first; --r) {
      double* yr = ys + r * W;
      const double inverse = m_inverse_diagonal[sn.first_column + r];
      std::array<double, W> xr;
      for (int w = 0; w < W; ++w) xr[w] = yr[w] *= inverse;
      const T* l = diagonal + Supernodal_factor::triangle_row(r);
      for (int a = first; a < r; ++a)
        for (int w = 0; w < W; ++w) ys[a * W + w] -= l[a] * xr[w];
    }
  }

  // backward_full() pruned, for all the columns from `first` on: only the
  // rows below (solved ancestors) and the rows of the diagonal block whose
  // solutions are above `drop_below` are subtracted. Both go four rows of L
  // at a time, as in the full kernel: the kept rows below in groups of four,
  // the diagonal block in its groups of four rows with the solutions at or
  // below the threshold propagated as zeros, and a group skipped when all
  // four are. Returns the factor entries read.
  template <int W, class T>
  std::size_t backward_pruned(const T* entries, const Supernode& sn, int first, double* ys,
                              const double* y, double drop_below) {
    std::vector<int>& kept = m_scratch.kept;  // the rows below propagated
    const int* below_rows = rows_below(sn);
    kept.clear();
    for (int t = 0; t < sn.nbelow; ++t)
      if (above<W>(y + static_cast<std::size_t>(below_rows[t]) * W, drop_below)) kept.push_back(t);
    const std::size_t width = static_cast<std::size_t>(sn.ncol - first);
    std::size_t read = sn.rank >= 0 ? (kept.size() + width) * static_cast<std::size_t>(sn.rank)
                                    : kept.size() * width;
    auto kept_row = [&kept](int i) { return kept[static_cast<std::size_t>(i)]; };
    if (sn.rank >= 0) {
      low_rank_backward<W>(entries + sn.below, sn, first, sn.ncol, ys, y, below_rows,
                           static_cast<int>(kept.size()), kept_row);
    } else if (static_cast<int>(kept.size()) == sn.nbelow) {
      // Nothing to skip below: the register-blocked kernel of the full solve.
      backward_below<W>(entries, sn, first, ys, y, sn.ncol);
    } else {
      subtract_rows_below<W>(entries, sn, first, ys, y, sn.ncol, static_cast<int>(kept.size()),
                             kept_row);
    }
    const T* diagonal = entries + sn.diagonal;
    int r = sn.ncol - 1;
    for (; r - 3 >= first; r -= 4) {
      const T* l[4];
      std::array<std::array<double, W>, 4> x;
      bool any = false;
      for (int k = 0; k < 4; ++k) {
        const int row = r - k;
        l[k] = diagonal + Supernodal_factor::triangle_row(row);
        double* yr = ys + row * W;
        const double inverse = m_inverse_diagonal[sn.first_column + row];
        for (int w = 0; w < W; ++w) yr[w] *= inverse;
        ++read;
        const bool propagated = above<W>(yr, drop_below);
        any = any || propagated;
        for (int w = 0; w < W; ++w) x[k][w] = propagated ? yr[w] : 0.0;
        if (!propagated) continue;
        for (int j = k + 1; j < 4; ++j)  // the rows r - j below row r - k's diagonal
          for (int w = 0; w < W; ++w) ys[(r - j) * W + w] -= l[k][r - j] * x[k][w];
        read += static_cast<std::size_t>(3 - k);
      }
      if (!any) continue;
      subtract_four_rows<W>(l, x, first, r - 3, ys);
      read += 4 * static_cast<std::size_t>(r - 3 - first);
    }
    for (; r >= first; --r) {
      double* yr = ys + r * W;
      const double inverse = m_inverse_diagonal[sn.first_column + r];
      for (int w = 0; w < W; ++w) yr[w] *= inverse;
      ++read;
      if (!above<W>(yr, drop_below)) continue;
      const T* l = diagonal + Supernodal_factor::triangle_row(r);
      for (int a = first; a < r; ++a)
        for (int w = 0; w < W; ++w) ys[a * W + w] -= l[a] * yr[w];
      read += static_cast<std::size_t>(r - first);
    }
    return read;
  }

  // Entries of the supernode's columns [first, end) that forward_full() or
  // backward_full() reads: rows below in low-rank form are r per row and
  // column.
  static std::size_t entries_read(const Supernode& sn, int first, int end) {
    const std::size_t c = static_cast<std::size_t>(end - first);
    const std::size_t diagonal = c * (c + 1) / 2 + static_cast<std::size_t>(sn.ncol - end) * c;
    const std::size_t nbelow = static_cast<std::size_t>(sn.nbelow);
    if (sn.rank >= 0) return diagonal + (nbelow + c) * static_cast<std::size_t>(sn.rank);
    return diagonal + nbelow * c;
  }

  const int* rows_below(const Supernode& sn) const {
    return m_factor.row_index.data() + sn.below_rows;
  }

  // Whether a row of the block is propagated by a pruned solve.
  template <int W>
  static bool above(const double* row, double drop_below) {
    for (int w = 0; w < W; ++w)
      if (std::abs(row[w]) > drop_below) return true;
    return false;
  }

  // The rows below a supernode (solved ancestors) subtracted from its rows
  // from `first` on. Up to one block of columns: their sums in registers
  // over all rows below (updating ys in memory once per row below would
  // chain every update of a column through a store and a load). Wider:
  // by rows, since a block at a time walks the row-major rows below once
  // per block, a few entries from each row.
  template <int W, class T>
  void backward_below(const T* entries, const Supernode& sn, int first, double* ys,
                      const double* y, int end) {
    constexpr int block = W == 1 ? 8 : W <= 4 ? 4 : 2;
    const T* below = entries + sn.below;
    const int* below_rows = rows_below(sn);
    if (sn.rank >= 0)
      return low_rank_backward<W>(below, sn, first, end, ys, y, below_rows, sn.nbelow,
                                  [](int i) { return i; });
    // By rows: read in memory order, four at a time, each group updating
    // the columns' partial solutions in ys once (ys stays in the first-level
    // cache). Per solve on a 711k-vertex mesh this read the rows below at
    // about twice the speed of the blocked kernel (doc/performance.md).
    if (end - first > block)
      return subtract_rows_below<W>(entries, sn, first, ys, y, end, sn.nbelow,
                                    [](int i) { return i; });
    int c = first;
    for (; c + block <= end; c += block)
      subtract_below<W, block>(below + c, sn.ncol, below_rows, sn.nbelow, y, ys + c * W);
    // The rest in halving blocks: each pass gathers every solved row below
    // once, and most supernodes are narrower than a block.
    if constexpr (block > 4) {
      if (c + 4 <= end) {
        subtract_below<W, 4>(below + c, sn.ncol, below_rows, sn.nbelow, y, ys + c * W);
        c += 4;
      }
    }
    if constexpr (block > 2) {
      if (c + 2 <= end) {
        subtract_below<W, 2>(below + c, sn.ncol, below_rows, sn.nbelow, y, ys + c * W);
        c += 2;
      }
    }
    for (; c < end; ++c)
      subtract_below<W, 1>(below + c, sn.ncol, below_rows, sn.nbelow, y, ys + c * W);
  }

  // The rows below a supernode numbered `row(0)`, ..., `row(count - 1)`
  // (ascending) subtracted from its columns [first, end), four rows at a
  // time: a full back substitution takes them all, a pruned one the kept
  // ones.
  template <int W, class T, class Row>
  void subtract_rows_below(const T* entries, const Supernode& sn, int first, double* ys,
                           const double* y, int end, int count, Row row) const {
    const T* below = entries + sn.below;
    const int* below_rows = rows_below(sn);
    const std::size_t stride = static_cast<std::size_t>(sn.ncol);
    int i = 0;
    for (; i + 4 <= count; i += 4) {
      const T* l[4];
      std::array<std::array<double, W>, 4> x;
      for (int k = 0; k < 4; ++k) {
        const int t = row(i + k);
        l[k] = below + static_cast<std::size_t>(t) * stride;
        const double* xk = y + static_cast<std::size_t>(below_rows[t]) * W;
        for (int w = 0; w < W; ++w) x[k][w] = xk[w];
      }
      subtract_four_rows<W>(l, x, first, end, ys);
    }
    for (; i < count; ++i) {
      const int t = row(i);
      const T* l = below + static_cast<std::size_t>(t) * stride;
      std::array<double, W> a;
      for (int w = 0; w < W; ++w) a[w] = y[static_cast<std::size_t>(below_rows[t]) * W + w];
      for (int c = first; c < end; ++c)
        for (int w = 0; w < W; ++w) ys[c * W + w] -= l[c] * a[w];
    }
  }

  // out[j * W + w] -= sum over t < nbelow of l[t * stride + j] * y[rows[t] * W + w]
  // for the C columns j of a supernode's rows below (row-major, `stride`
  // columns per row).
  template <int W, int C, class T>
  static void subtract_below(const T* l, int stride, const int* rows, int nbelow,
                             const double* y, double* out) {
    std::array<std::array<double, W>, C> acc{};
    for (int t = 0; t < nbelow; ++t) {
      const T* lt = l + static_cast<std::size_t>(t) * stride;
      const double* xt = y + static_cast<std::size_t>(rows[t]) * W;
      for (int j = 0; j < C; ++j)
        for (int w = 0; w < W; ++w) acc[j][w] += lt[j] * xt[w];
    }
    for (int j = 0; j < C; ++j)
      for (int w = 0; w < W; ++w) out[j * W + w] -= acc[j][w];
  }

  // The forward update of the rows below kept as U V^T (rank r): y[rows[t]]
  // -= U[t] (V^T ys), the columns of V^T taken from the [begin, end) pairs
  // of `runs` (the columns propagated).
  template <int W, class T>
  void low_rank_forward(const T* below, const Supernode& sn, const int* runs,
                        std::size_t run_values, const double* ys, const int* below_rows,
                        double* y) {
    const int r = sn.rank;
    const T* U = below;
    const T* V = below + static_cast<std::size_t>(sn.nbelow) * r;
    double* z = zeroed_low_rank_scratch(static_cast<std::size_t>(r) * W);
    for (std::size_t q = 0; q < run_values; q += 2)
      for (int c = runs[q]; c < runs[q + 1]; ++c) {
        const T* v = V + static_cast<std::size_t>(c) * r;
        const double* yc = ys + static_cast<std::size_t>(c) * W;
        for (int j = 0; j < r; ++j)
          for (int w = 0; w < W; ++w) z[j * W + w] += v[j] * yc[w];
      }
    for (int t = 0; t < sn.nbelow; ++t)
      subtract_dot<W>(U + static_cast<std::size_t>(t) * r, z, 0, r,
                      y + static_cast<std::size_t>(below_rows[t]) * W);
  }

  // The backward update from the rows below kept as U V^T: ys[c] -= V[c]
  // (U^T x) for the columns c in [first, end), over the rows below
  // `row(0)`, ..., `row(count - 1)` (the others taken as zero).
  template <int W, class T, class Row>
  void low_rank_backward(const T* below, const Supernode& sn, int first, int end, double* ys,
                         const double* y, const int* below_rows, int count, Row row) {
    const int r = sn.rank;
    const T* U = below;
    const T* V = below + static_cast<std::size_t>(sn.nbelow) * r;
    double* z = zeroed_low_rank_scratch(static_cast<std::size_t>(r) * W);
    for (int i = 0; i < count; ++i) {
      const int t = row(i);
      const T* u = U + static_cast<std::size_t>(t) * r;
      const double* x = y + static_cast<std::size_t>(below_rows[t]) * W;
      for (int j = 0; j < r; ++j)
        for (int w = 0; w < W; ++w) z[j * W + w] += u[j] * x[w];
    }
    for (int c = first; c < end; ++c)
      subtract_dot<W>(V + static_cast<std::size_t>(c) * r, z, 0, r,
                      ys + static_cast<std::size_t>(c) * W);
  }

  // `size` zeros of the scratch, valid until the next low-rank update.
  double* zeroed_low_rank_scratch(std::size_t size) {
    m_scratch.low_rank.assign(size, 0.0);
    return m_scratch.low_rank.data();
  }

  const Supernodal_factor& m_factor;
  const double* m_inverse_diagonal;
  Scratch& m_scratch;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_SUPERNODE_KERNELS_H
