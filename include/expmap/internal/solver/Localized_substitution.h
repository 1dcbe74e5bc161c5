// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LOCALIZED_SUBSTITUTION_H
#define EXPMAP_INTERNAL_SOLVER_LOCALIZED_SUBSTITUTION_H

#include <expmap/Cholesky_factor_view.h>
#include <expmap/Factor_precision.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/solver/Localized_solve_workspace.h>
#include <expmap/internal/solver/Low_rank_rows_below.h>
#include <expmap/internal/solver/Rhs_entry.h>
#include <expmap/internal/solver/Supernodal_factor.h>
#include <expmap/internal/solver/Supernode_kernels.h>
#include <expmap/internal/solver/Supernode_tree.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// A supernodal factor of A = P^T L L^T P with the forward and back
/// substitutions of a localized solve on it (Herholz, Davis & Alexa 2017):
/// a block of W right-hand sides solved only where it is needed, and a
/// solve kept open to be extended to more rows.
///
/// Forward substitution L y = P b only touches the elimination-tree
/// ancestors of the nonzero rows of b (y is zero elsewhere); back
/// substitution L^T x = y for the rows in a set R only needs x on the
/// ancestors of R. Both node sets are found by walking up the tree from
/// their start nodes (`supernode_reach`), marking as we go, which also
/// yields a topological order without sorting: paths found later are placed
/// before paths found earlier.
///
/// All columns of the block share one traversal of L, supernode by
/// supernode (`Supernode_kernels`). The block is stored row-major with a
/// compile-time width W so that the update of one row is a short
/// fixed-length loop the compiler vectorizes.
///
/// The object is immutable after its setup (construction, then
/// `compress_rows_below()`); a solve's state lives in a `Workspace`.
/// Argument checks, the choice of W and timing are the caller's
/// (`Localized_cholesky_solver`).
class Localized_substitution {
 public:
  using Workspace = Localized_solve_workspace;

  Localized_substitution() = default;

  /// Regroups the factor into supernodes, its entries kept in `precision`,
  /// and keeps the inverse of its diagonal, which every substitution
  /// multiplies by.
  Localized_substitution(const Cholesky_factor_view& factor, Factor_precision precision)
      : m_factor(make_supernodal_factor(factor, precision)), m_tree(m_factor) {
    m_inverse_diagonal.resize(static_cast<std::size_t>(m_factor.size));
    for (const auto& sn : m_factor.supernode)
      m_factor.with_entries(sn, [this, &sn](const auto* entries) {
        for (int c = 0; c < sn.ncol; ++c)
          m_inverse_diagonal[sn.first_column + c] = 1.0 / static_cast<double>(
              entries[sn.diagonal + Supernodal_factor::triangle_row(c) + c]);
      });
  }

  const Supernodal_factor& factor() const { return m_factor; }
  const Supernode_tree& tree() const { return m_tree; }

  /// Keeps the rows below the large separators in low-rank form
  /// (`internal::compress_rows_below`; the diagonal blocks, and with them
  /// the inverse diagonal, are unchanged). Not while the factor is in use.
  /// \returns the number of supernodes compressed.
  std::size_t compress_rows_below(const Rows_below_compression& compression, unsigned threads) {
    return internal::compress_rows_below(m_factor, compression, threads);
  }

  /// The kernels of this factor, working in `ws`.
  Supernode_kernels kernels_in(Workspace& ws) const {
    return Supernode_kernels(m_factor, m_inverse_diagonal.data(), ws.m_kernel_scratch);
  }

  /// A workspace of the right size with a zero block (an extendable solve
  /// left in it is released).
  void prepare(Workspace& ws) const {
    if (!ws.fits(m_factor.size, m_factor.supernode.size()))
      ws.resize(m_factor.size, m_factor.supernode.size());
    else
      release(ws);
  }

  /// Ends a solve left open in `ws` (extendable or largest first), leaving
  /// the block zero.
  void release(Workspace& ws) const {
    if (ws.m_open_width == 0) return;
    Supernode_kernels::with_width(ws.m_open_width,
                                  [&](auto width) { clear_block<decltype(width)::value>(ws); });
    ws.m_open_width = 0;
    ws.m_largest_open = false;
  }

  /// Forward substitution L y = b over the ancestors of the nonzeros of b
  /// (`entries`, scattered into the block already); finds them first,
  /// stamped `s`. Pruned if `drop_below` > 0.
  template <int W>
  Solve_statistics forward_substitution(const std::vector<Rhs_entry>& entries, Workspace& ws,
                                        std::uint32_t s, double drop_below) const {
    const auto& F = m_factor;
    Supernode_kernels kernels = kernels_in(ws);
    Solve_statistics stats;
    supernode_reach(F, entries.data(), entries.data() + entries.size(),
                    [&F](const Rhs_entry& e) { return F.inverse_permutation[e.row]; },
                    ws.m_forward_stamp, ws.m_forward_entry, s, ws.m_forward_nodes, ws.m_path);
    for (const int k : ws.m_forward_nodes) {
      const auto& sn = F.supernode[k];
      const int first = ws.m_forward_entry[k];
      stats.forward_nodes += static_cast<std::size_t>(sn.ncol - first);
      stats.factor_entries += kernels.forward<W>(sn, first, ws.m_block, drop_below);
    }
    return stats;
  }

  /// Solves the block of `width` <= W columns whose nonzeros are `entries`
  /// in a prepared workspace, writing X(rows[i], c) to `out[i * width + c]`;
  /// pruned if `drop_below` > 0. With `keep` the solution stays in `ws` for
  /// `extend()`, else the block is left zero.
  template <int W>
  Solve_statistics solve_block(const std::vector<Rhs_entry>& entries, const int* rows,
                               std::size_t row_count, double* out, Workspace& ws,
                               double drop_below, bool keep, int width = W) const {
    const auto& F = m_factor;
    Supernode_kernels kernels = kernels_in(ws);
    double* y = ws.m_block;  // row-major n x W by pivot, zero on entry and exit
    auto row_of = [y](int pivot) { return y + static_cast<std::size_t>(pivot) * W; };

    // Scatter b (permuted) into the block, then forward.
    const std::uint32_t s = ws.next_stamp();
    for (const Rhs_entry& e : entries) row_of(F.inverse_permutation[e.row])[e.column] += e.value;
    Solve_statistics stats = forward_substitution<W>(entries, ws, s, drop_below);

    // Backward: L^T x = y over the ancestors of the requested rows, in place.
    supernode_reach(F, rows, rows + row_count,
                    [&F](int row) { return F.inverse_permutation[row]; }, ws.m_backward_stamp,
                    ws.m_backward_entry, s, ws.m_backward_nodes, ws.m_path);
    for (auto it = ws.m_backward_nodes.rbegin(); it != ws.m_backward_nodes.rend(); ++it) {
      const auto& sn = F.supernode[*it];
      const int first = ws.m_backward_entry[*it];
      stats.backward_nodes += static_cast<std::size_t>(sn.ncol - first);
      stats.factor_entries += kernels.backward<W>(sn, first, y, drop_below);
    }

    read_rows<W>(rows, row_count, out, ws, width);
    if (keep) {
      ws.m_open_width = W;
      ws.m_open_columns = width;
    } else {
      clear_block<W>(ws);
    }
    return stats;
  }

  /// The solution of the solve kept open in `ws` at `rows`, written as
  /// `solve_block()` writes it; only the back substitution of the
  /// supernodes the new rows need beyond those already solved is done.
  /// \throws std::logic_error if `ws` holds no open solve.
  Solve_statistics extend(const int* rows, std::size_t row_count, double* out,
                          Workspace& ws) const {
    if (ws.m_open_width == 0)
      throw std::logic_error("Localized_cholesky_solver: extend() without an extendable solve");
    return Supernode_kernels::with_width(ws.m_open_width, [&](auto width) {
      return extend_block<decltype(width)::value>(rows, row_count, out, ws);
    });
  }

 private:
  // Writes the solution at `rows` from the block (row-major, `width` columns).
  template <int W>
  void read_rows(const int* rows, std::size_t row_count, double* out, const Workspace& ws,
                 int width = W) const {
    for (std::size_t i = 0; i < row_count; ++i) {
      const std::size_t pivot = static_cast<std::size_t>(m_factor.inverse_permutation[rows[i]]);
      const double* x = ws.m_block + pivot * W;
      for (int c = 0; c < width; ++c) out[i * width + c] = x[c];
    }
  }

  // Leaves the block zero for the next solve: only touched rows are cleared
  // (a supernode's own rows; rows below it belong to ancestors, also listed).
  template <int W>
  void clear_block(Workspace& ws) const {
    auto clear = [&](int k, int first) {
      const auto& sn = m_factor.supernode[k];
      std::fill_n(ws.m_block + static_cast<std::size_t>(sn.first_column + first) * W,
                  static_cast<std::size_t>(sn.ncol - first) * W, 0.0);
    };
    for (const int k : ws.m_forward_nodes) clear(k, ws.m_forward_entry[k]);
    for (const int k : ws.m_backward_nodes) clear(k, ws.m_backward_entry[k]);
  }

  // extend() for a block of width W. The new rows' paths reach supernodes
  // already solved (then at most their entry column moves down: only the
  // columns above the old entry are solved) or new ones (below the solved
  // ones in the tree: solved after them, top-down).
  template <int W>
  Solve_statistics extend_block(const int* rows, std::size_t row_count, double* out,
                                Workspace& ws) const {
    const auto& F = m_factor;
    Supernode_kernels kernels = kernels_in(ws);
    double* y = ws.m_block;
    Solve_statistics stats;
    ws.m_previous_entry.resize(ws.m_backward_nodes.size());
    for (std::size_t i = 0; i < ws.m_backward_nodes.size(); ++i)
      ws.m_previous_entry[i] = ws.m_backward_entry[ws.m_backward_nodes[i]];
    supernode_reach(F, rows, rows + row_count,
                    [&F](int row) { return F.inverse_permutation[row]; }, ws.m_backward_stamp,
                    ws.m_backward_entry, ws.m_stamp, ws.m_extension_nodes, ws.m_path);
    auto solve_columns = [&](int k, int first, int end) {
      stats.backward_nodes += static_cast<std::size_t>(end - first);
      stats.factor_entries += kernels.backward<W>(F.supernode[k], first, y, 0, end);
    };
    for (std::size_t i = ws.m_backward_nodes.size(); i-- > 0;) {
      const int k = ws.m_backward_nodes[i];
      if (ws.m_backward_entry[k] < ws.m_previous_entry[i])
        solve_columns(k, ws.m_backward_entry[k], ws.m_previous_entry[i]);
    }
    for (auto it = ws.m_extension_nodes.rbegin(); it != ws.m_extension_nodes.rend(); ++it)
      solve_columns(*it, ws.m_backward_entry[*it], F.supernode[*it].ncol);
    // The new nodes are descendants of the old ones: in front, the list
    // stays a topological order for the next extension.
    ws.m_backward_nodes.insert(ws.m_backward_nodes.begin(), ws.m_extension_nodes.begin(),
                               ws.m_extension_nodes.end());
    read_rows<W>(rows, row_count, out, ws, ws.m_open_columns);
    return stats;
  }

  Supernodal_factor m_factor;
  Supernode_tree m_tree;
  std::vector<double> m_inverse_diagonal;  // 1 / L(j, j)
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LOCALIZED_SUBSTITUTION_H
