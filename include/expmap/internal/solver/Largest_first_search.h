// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LARGEST_FIRST_SEARCH_H
#define EXPMAP_INTERNAL_SOLVER_LARGEST_FIRST_SEARCH_H

#include <expmap/Solve_statistics.h>
#include <expmap/internal/solver/Largest_first_frontier.h>
#include <expmap/internal/solver/Localized_solve_workspace.h>
#include <expmap/internal/solver/Localized_substitution.h>
#include <expmap/internal/solver/Rhs_entry.h>
#include <expmap/internal/solver/Supernode_kernels.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// The largest values of the solution x of A x = b in the parts of A (its
/// connected components) that b touches, found by a back substitution that
/// visits the elimination tree largest first and stops where nothing larger
/// can remain (`Localized_cholesky_solver::solve_largest`,
/// `solve_at_least` and their extensions); the values are those of a full
/// solve. Every supernode it visits is solved in whole.
///
/// Why it may stop early: A must be an M-matrix with nonnegative row sums
/// (positive diagonal, no positive off-diagonal entry, such as the heat
/// matrix M + tL of an intrinsic Delaunay Laplacian) and b nonnegative with
/// one column. The rows of a supernode's subtree S that b does not touch
/// satisfy A_SS x_S = -A_SR x_R, where R, the rows of A coupled to S from
/// outside, lie among the supernode's rows below its diagonal block (the
/// structure of L); -A_SS^-1 A_SR is nonnegative with row sums at most 1,
/// so x on S is at most the largest x on those rows (the discrete maximum
/// principle). A subtree whose rows below hold nothing larger than the
/// values already found holds nothing larger either, and is not visited
/// (`Largest_first_frontier` keeps the bounds and decides when to stop).
/// The caller vouches for the matrix: this is not checked here.
///
/// Pruned (`drop_below` > 0) both substitutions skip entries as a pruned
/// `Localized_cholesky_solver::solve()` does: pruning only lowers the
/// values of a nonnegative inverse, by about `drop_below` at most, so the
/// bounds and the order of the values are those of a full solve but for
/// ties within that.
///
/// The search is nothing but the order of a back substitution and when to
/// stop it; it holds no state of its own (the search left open lives in the
/// workspace), so one is made per call.
class Largest_first_search {
 public:
  using Stop = Largest_first_frontier::Stop;
  using Workspace = Localized_solve_workspace;

  /// A search on the factor of `substitution`, which must outlive it.
  explicit Largest_first_search(const Localized_substitution& substitution)
      : m_substitution(substitution) {}

  /// Refuses a threshold that is not positive and finite.
  /// \throws std::invalid_argument
  static void check_threshold(double threshold) {
    if (!(threshold > 0) || !std::isfinite(threshold))
      throw std::invalid_argument(
          "Localized_cholesky_solver: the threshold must be positive and finite");
  }

  /// Refuses a right-hand side the maximum principle does not cover: an
  /// entry outside column 0, negative or not finite.
  /// \throws std::invalid_argument
  static void check_right_hand_side(const std::vector<Rhs_entry>& entries) {
    for (const Rhs_entry& e : entries)
      if (e.column != 0 || !(e.value >= 0) || !std::isfinite(e.value))
        throw std::invalid_argument(
            "Localized_cholesky_solver: solve_largest needs one nonnegative column");
  }

  /// Solves L y = P b forward (pruned by `drop_below`), then back
  /// substitutes largest first from the roots of b's paths until `stop` is
  /// met, writing the rows solved to `rows` and their values to `values`
  /// (both cleared first) in the order solved. The search stays open in
  /// `ws` for `resume()` (and `Localized_substitution::extend()`) until the
  /// next solve on `ws` or its release.
  Solve_statistics start(const std::vector<Rhs_entry>& entries, Stop stop,
                         std::vector<int>& rows, std::vector<double>& values, Workspace& ws,
                         double drop_below) const {
    const auto& F = m_substitution.factor();
    m_substitution.prepare(ws);
    const std::uint32_t s = ws.next_stamp();
    double* y = ws.m_block;
    for (const Rhs_entry& e : entries)
      y[static_cast<std::size_t>(F.inverse_permutation[e.row])] += e.value;
    ws.m_largest_drop_below = drop_below;
    Solve_statistics stats = m_substitution.forward_substitution<1>(entries, ws, s, drop_below);
    ws.m_backward_nodes.clear();
    ws.m_frontier.clear();
    for (const int k : ws.m_forward_nodes)  // the roots of b's paths (one per part of A)
      if (F.supernode[k].parent == -1)
        ws.m_frontier.push(std::numeric_limits<double>::infinity(), k);
    ws.m_open_width = 1;
    ws.m_open_columns = 1;
    ws.m_largest_open = true;
    rows.clear();
    values.clear();
    return stats += visit(stop, rows, values, ws);
  }

  /// Continues the search left open in `ws` until `stop` is met, appending
  /// to `rows` and `values`, which must hold what the search wrote so far.
  /// \throws std::logic_error if `ws` holds no open search, or `rows` or
  /// `values` not its output.
  Solve_statistics resume(Stop stop, std::vector<int>& rows, std::vector<double>& values,
                          Workspace& ws) const {
    if (!ws.m_largest_open || ws.m_largest_values != values.size() ||
        ws.m_largest_values != rows.size())
      throw std::logic_error(
          "Localized_cholesky_solver: extend_largest() or extend_at_least() without an open "
          "solve_largest() or solve_at_least()");
    return visit(stop, rows, values, ws);
  }

 private:
  // Pops the frontier's supernode with the largest bound (the largest
  // solved value among its rows below; infinity on the right-hand side's
  // paths, where the bound does not hold) until `stop` is met, solving each
  // popped supernode in whole and pushing its children.
  Solve_statistics visit(Stop stop, std::vector<int>& rows, std::vector<double>& values,
                         Workspace& ws) const {
    const auto& F = m_substitution.factor();
    const Supernode_tree& tree = m_substitution.tree();
    Supernode_kernels kernels = m_substitution.kernels_in(ws);
    double* y = ws.m_block;
    const std::uint32_t s = ws.m_stamp;
    Solve_statistics stats;
    for (int k; (k = ws.m_frontier.pop(stop)) != -1;) {
      const auto& sn = F.supernode[k];
      double* ys = y + static_cast<std::size_t>(sn.first_column);
      stats.backward_nodes += static_cast<std::size_t>(sn.ncol);
      stats.factor_entries += kernels.backward<1>(sn, 0, y, ws.m_largest_drop_below);
      ws.m_backward_stamp[k] = s;
      ws.m_backward_entry[k] = 0;
      ws.m_backward_nodes.push_back(k);
      for (int c = 0; c < sn.ncol; ++c) {
        rows.push_back(F.permutation[sn.first_column + c]);
        values.push_back(ys[c]);
        ws.m_frontier.count(ys[c]);
      }
      for (const int* c = tree.children_begin(k); c != tree.children_end(k); ++c) {
        const int child = *c;
        double bound = std::numeric_limits<double>::infinity();
        if (ws.m_forward_stamp[child] != s) {
          const auto& cn = F.supernode[child];
          const int* below = F.row_index.data() + cn.below_rows;
          bound = -std::numeric_limits<double>::infinity();
          for (int t = 0; t < cn.nbelow; ++t) bound = std::max(bound, y[below[t]]);
        }
        ws.m_frontier.push(bound, child);
      }
    }
    ws.m_largest_values = values.size();
    return stats;
  }

  const Localized_substitution& m_substitution;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LARGEST_FIRST_SEARCH_H
