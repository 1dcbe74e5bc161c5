// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LOCALIZED_CHOLESKY_SOLVER_H
#define EXPMAP_INTERNAL_SOLVER_LOCALIZED_CHOLESKY_SOLVER_H

#include <expmap/Cholesky_factor_view.h>
#include <expmap/Factor_precision.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/solver/Largest_first_frontier.h>
#include <expmap/internal/solver/Localized_solve_workspace.h>
#include <expmap/internal/solver/Low_rank_rows_below.h>
#include <expmap/internal/solver/Pruning_threshold.h>
#include <expmap/internal/solver/Rhs_entry.h>
#include <expmap/internal/solver/Supernodal_factor.h>
#include <expmap/internal/solver/Supernode_kernels.h>
#include <expmap/internal/solver/Supernode_tree.h>
#include <expmap/internal/solver/Timed_solve.h>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// Solves A X = B for a block of sparse right-hand sides with a prefactored
/// A = P^T L D L^T P, computing X only where it is needed (Herholz, Davis &
/// Alexa 2017).
///
/// Forward substitution L y = P b only touches the elimination-tree
/// ancestors of the nonzero rows of b (y is zero elsewhere); back
/// substitution L^T x = y for the rows in a set R only needs x on the
/// ancestors of R. Both node sets are found by walking up the tree from their
/// start nodes, marking as we go, which also yields a topological order
/// without sorting: paths found later are placed before paths found earlier.
///
/// All columns of the block share one traversal of L, supernode by
/// supernode (`Supernode_kernels`). The block is stored row-major with a
/// compile-time width so that the update of one row is a short
/// fixed-length loop the compiler vectorizes.
///
/// The object is immutable after construction; per-query scratch lives in a
/// `Workspace`, so many threads can solve at once with one workspace each.
class Localized_cholesky_solver {
 public:
  /// Widest block solved in one traversal, and a workspace's width unless
  /// it is made narrower; wider blocks are split.
  static constexpr int max_block_width = Supernode_kernels::max_width;

  /// Per-thread scratch memory of the solves, and a solve left open.
  using Workspace = Localized_solve_workspace;

  Localized_cholesky_solver() = default;

  /// Regroups the factor into supernodes for the traversals, its entries
  /// kept in `precision` (the solves accumulate in double either way); the
  /// factor's owner may be destroyed afterwards (the supernodal copy is
  /// self-contained).
  explicit Localized_cholesky_solver(
      const Cholesky_factor_view& factor,
      Factor_precision precision = Factor_precision::double_precision)
      : m_factor(make_supernodal_factor(factor, precision)), m_tree(m_factor) {
    m_inverse_diagonal.resize(static_cast<std::size_t>(m_factor.size));
    for (const auto& sn : m_factor.supernode)
      m_factor.with_entries(sn, [this, &sn](const auto* entries) {
        for (int c = 0; c < sn.ncol; ++c)
          m_inverse_diagonal[sn.first_column + c] = 1.0 / static_cast<double>(
              entries[sn.diagonal + Supernodal_factor::triangle_row(c) + c]);
      });
  }

  int size() const { return m_factor.size; }

  /// Height of the elimination tree (number of nodes on its longest
  /// leaf-to-root path).
  int tree_height() const { return m_tree.height(); }

  /// Stored entries of the supernodal factor (dense blocks included).
  std::size_t number_of_entries() const { return m_factor.number_of_entries(); }

  /// The precision the factor's entries are kept in.
  Factor_precision precision() const { return m_factor.precision; }

  /// Bytes held by the factor's entries.
  std::size_t entry_bytes() const { return m_factor.value_bytes(); }

  /// The factor's ordering: `permutation()[k]` is the row of A that became
  /// pivot k. A matrix with the same sparsity can be factored with it
  /// (`Cholmod_solver::factor(A, ordering)`) without ordering it again.
  const std::vector<int>& permutation() const { return m_factor.permutation; }

  /// Number of supernodes (dense column blocks) of the factor.
  std::size_t number_of_supernodes() const { return m_factor.supernode.size(); }

  /// Keeps the rows below the factor's large separators in low-rank form
  /// as `compression` asks (`internal::compress_rows_below`), on `threads`
  /// threads (0: the hardware's count). Part of the setup: not to be called
  /// while the solver is in use. Called after the solver model's factor is
  /// released, the decompositions' scratch does not add to the
  /// precomputation's peak memory.
  /// \returns the number of supernodes compressed by this call.
  std::size_t compress_rows_below(const Rows_below_compression& compression,
                                  unsigned threads = 0) {
    const std::size_t count = internal::compress_rows_below(m_factor, compression, threads);
    m_compressed_supernodes += count;
    return count;
  }

  /// Number of supernodes whose rows below are kept in low-rank form.
  std::size_t number_of_compressed_supernodes() const { return m_compressed_supernodes; }

  /// A workspace sized for this factor, for blocks of up to `max_width`
  /// columns (see `Workspace::max_width()`).
  /// \pre max_width >= 1 (else std::invalid_argument).
  std::unique_ptr<Workspace> make_workspace(int max_width = max_block_width) const {
    return std::make_unique<Workspace>(m_factor.size, number_of_supernodes(), max_width);
  }

  /// Solves A X = B where B has `width` columns given by its nonzero
  /// `entries` (rows of A, duplicates are summed), and writes X(rows[i], c)
  /// to `out[i * width + c]`. Blocks wider than `ws.max_width()` are solved
  /// in blocks of that width. With `drop_below` = 0 the solve is exact: the
  /// same numbers as a full solve; with `drop_below` > 0 it is pruned
  /// (Pruning_threshold.h: what that means, why it pays, how to choose it).
  /// \pre drop_below >= 0 and finite (else std::invalid_argument).
  /// \returns what the solve touched.
  Solve_statistics solve(const std::vector<Rhs_entry>& entries, int width,
                         const int* rows, std::size_t row_count, double* out,
                         Workspace& ws, double drop_below = 0) const {
    check_drop_below(drop_below);
    return solve_in_blocks(entries, width, rows, row_count, out, ws, drop_below);
  }

  /// As `solve()` (at most `ws.max_width()` columns, else
  /// std::invalid_argument), but keeps the
  /// solution in the workspace so that `extend()` can return it on more
  /// rows, redoing neither the forward substitution nor the back substitution
  /// of the nodes already solved. The workspace stays busy until the next
  /// solve of any kind on it, or `release()`.
  ///
  /// Pruned (`drop_below` > 0), `extend()` then solves the new supernodes
  /// in full, from the pruned values above them: the new rows' values carry
  /// the pruning error of those values (at most about `drop_below`), so a
  /// caller checking the choice of `drop_below` checks it on the extended
  /// rows too.
  /// \pre as `solve()`.
  Solve_statistics solve_extendable(const std::vector<Rhs_entry>& entries, int width,
                                    const int* rows, std::size_t row_count, double* out,
                                    Workspace& ws, double drop_below = 0) const {
    check_drop_below(drop_below);
    return solve_and_keep(entries, width, rows, row_count, out, ws, drop_below);
  }

  /// The solution of the last `solve_extendable()` on `ws` at `rows` (which
  /// may repeat rows returned before), written as `solve()` writes it: the
  /// same numbers as a full solve. Only the back substitution of the
  /// supernodes the new rows need beyond those already solved is done.
  /// \pre `ws` holds an extendable solve (else std::logic_error).
  Solve_statistics extend(const int* rows, std::size_t row_count, double* out,
                          Workspace& ws) const {
    if (ws.m_open_width == 0)
      throw std::logic_error("Localized_cholesky_solver: extend() without an extendable solve");
    return timed_solve([&] {
      return Supernode_kernels::with_width(ws.m_open_width, [&](auto width) {
        return extend_block<decltype(width)::value>(rows, row_count, out, ws);
      });
    });
  }

  /// Ends an extendable solve: the workspace is ready for any solve (which
  /// would release it too).
  void release(Workspace& ws) const {
    if (ws.m_open_width == 0) return;
    Supernode_kernels::with_width(ws.m_open_width,
                                  [&](auto width) { clear_block<decltype(width)::value>(ws); });
    ws.m_open_width = 0;
    ws.m_largest_open = false;
  }

  /// Smallest |value| among `count` values (infinity if there are none): the
  /// scale a pruned solve's `drop_below` is checked against
  /// (Pruning_threshold.h).
  static double smallest_magnitude(const double* values, std::size_t count) {
    return internal::smallest_magnitude(values, count);
  }

  /// The `count` largest values of the solution x of A x = b in the parts
  /// of A (its connected components) that b touches, found by a back
  /// substitution that
  /// visits the elimination tree largest first and stops where nothing
  /// larger can remain; the values are those of a full solve. Writes every
  /// row it solved (the supernodes visited, in whole) to `rows` and its
  /// value to `values` (cleared first), in the order solved: the `count`
  /// largest among them (or all of those parts, if they have fewer rows)
  /// are the largest there. The solve stays open for `extend_largest()`
  /// (and `extend()`) until the next solve on `ws` or `release()`.
  ///
  /// Why it may stop early: A must be an M-matrix with nonnegative row sums
  /// (positive diagonal, no positive off-diagonal entry, such as the heat
  /// matrix M + tL of an intrinsic Delaunay Laplacian) and b nonnegative
  /// with one column. The rows of a supernode's subtree S that b does not
  /// touch satisfy A_SS x_S = -A_SR x_R, where R, the rows of A coupled to
  /// S from outside, lie among the supernode's rows below its diagonal
  /// block (the structure of L); -A_SS^-1 A_SR is nonnegative with row
  /// sums at most 1, so x on S is at most the largest x on those rows
  /// (the discrete maximum principle). A subtree whose rows below hold
  /// nothing larger than the `count`-th value found holds nothing larger
  /// either, and is not visited. The caller vouches for the matrix: this
  /// is not checked here.
  ///
  /// With `drop_below` > 0 both substitutions are pruned as `solve()`
  /// prunes them: pruning only lowers the values of a nonnegative inverse,
  /// by about `drop_below` at most, so the bounds and the order of the
  /// values are those of a full solve but for ties within that.
  /// \pre every entry of b nonnegative, in column 0; drop_below >= 0 and
  /// finite.
  Solve_statistics solve_largest(const std::vector<Rhs_entry>& entries, std::size_t count,
                                 std::vector<int>& rows, std::vector<double>& values,
                                 Workspace& ws, double drop_below = 0) const {
    return solve_largest_until(entries, Stop{count, 0.0}, rows, values, ws, drop_below);
  }

  /// As `solve_largest()`, but for every value at least `threshold` (> 0)
  /// instead of a count: the search stops once every subtree left is
  /// bounded below `threshold`. `rows` and `values` hold every row solved;
  /// those of value at least `threshold` are all there are in the parts of
  /// A that b touches. Stays open for `extend_at_least()`.
  /// \pre as `solve_largest()`; threshold > 0 and finite.
  Solve_statistics solve_at_least(const std::vector<Rhs_entry>& entries, double threshold,
                                  std::vector<int>& rows, std::vector<double>& values,
                                  Workspace& ws, double drop_below = 0) const {
    check_threshold(threshold);
    return solve_largest_until(entries, Stop{Largest_first_frontier::no_count, threshold}, rows,
                               values, ws, drop_below);
  }

  /// Continues the last `solve_largest()` or `solve_at_least()` on `ws`
  /// until every value at least `threshold` is known.
  /// \pre as `extend_largest()`; threshold > 0 and finite.
  Solve_statistics extend_at_least(double threshold, std::vector<int>& rows,
                                   std::vector<double>& values, Workspace& ws) const {
    check_threshold(threshold);
    return extend_largest_until(Stop{Largest_first_frontier::no_count, threshold}, rows, values,
                                ws);
  }

  /// Continues the last `solve_largest()` on `ws` until the `count` largest
  /// values are known, appending the rows it solves to `rows` and `values`
  /// (which must hold what the earlier calls wrote).
  /// \pre `ws` holds an open `solve_largest()` (else std::logic_error).
  Solve_statistics extend_largest(std::size_t count, std::vector<int>& rows,
                                  std::vector<double>& values, Workspace& ws) const {
    return extend_largest_until(Stop{count, 0.0}, rows, values, ws);
  }

 private:
  using Stop = Largest_first_frontier::Stop;

  static void check_threshold(double threshold) {
    if (!(threshold > 0) || !std::isfinite(threshold))
      throw std::invalid_argument(
          "Localized_cholesky_solver: the threshold must be positive and finite");
  }

  Solve_statistics solve_largest_until(const std::vector<Rhs_entry>& entries, Stop stop,
                                       std::vector<int>& rows, std::vector<double>& values,
                                       Workspace& ws, double drop_below) const {
    check_drop_below(drop_below);
    for (const Rhs_entry& e : entries)
      if (e.column != 0 || !(e.value >= 0) || !std::isfinite(e.value))
        throw std::invalid_argument(
            "Localized_cholesky_solver: solve_largest needs one nonnegative column");
    return timed_solve([&] {
      prepare(ws);
      const std::uint32_t s = ws.next_stamp();
      double* y = ws.m_block;
      for (const Rhs_entry& e : entries)
        y[static_cast<std::size_t>(m_factor.inverse_permutation[e.row])] += e.value;
      ws.m_largest_drop_below = drop_below;
      Solve_statistics stats = forward_substitution<1>(entries, ws, s, drop_below);
      ws.m_backward_nodes.clear();
      ws.m_frontier.clear();
      for (const int k : ws.m_forward_nodes)  // the roots of b's paths (one per part of A)
        if (m_factor.supernode[k].parent == -1)
          ws.m_frontier.push(std::numeric_limits<double>::infinity(), k);
      ws.m_open_width = 1;
      ws.m_open_columns = 1;
      ws.m_largest_open = true;
      rows.clear();
      values.clear();
      return stats += largest_first(stop, rows, values, ws);
    });
  }

  Solve_statistics extend_largest_until(Stop stop, std::vector<int>& rows,
                                        std::vector<double>& values, Workspace& ws) const {
    if (!ws.m_largest_open || ws.m_largest_values != values.size() ||
        ws.m_largest_values != rows.size())
      throw std::logic_error(
          "Localized_cholesky_solver: extend_largest() or extend_at_least() without an open "
          "solve_largest() or solve_at_least()");
    return timed_solve([&] { return largest_first(stop, rows, values, ws); });
  }

  // solve_extendable: one block, kept in `ws`. Pruned if drop_below > 0,
  // as are the others below.
  Solve_statistics solve_and_keep(const std::vector<Rhs_entry>& entries, int width,
                                  const int* rows, std::size_t row_count, double* out,
                                  Workspace& ws, double drop_below) const {
    if (width < 1 || width > ws.max_width())
      throw std::invalid_argument(
          "Localized_cholesky_solver: an extendable solve's width must be from 1 to its "
          "workspace's max_width()");
    return timed_solve([&] {
      prepare(ws);
      return dispatch(entries, width, rows, row_count, out, ws, drop_below, /*keep=*/true);
    });
  }

  Solve_statistics solve_in_blocks(const std::vector<Rhs_entry>& entries, int width,
                                   const int* rows, std::size_t row_count, double* out,
                                   Workspace& ws, double drop_below) const {
    if (width < 1) throw std::invalid_argument("Localized_cholesky_solver: width < 1");
    return timed_solve([&] {
      prepare(ws);
      const int block = ws.max_width();
      if (width <= block) return dispatch(entries, width, rows, row_count, out, ws, drop_below);
      Solve_statistics total;
      std::vector<Rhs_entry> chunk;
      std::vector<double> chunk_out;
      for (int first = 0; first < width; first += block) {
        const int w = std::min(block, width - first);
        chunk.clear();
        for (const Rhs_entry& e : entries)
          if (e.column >= first && e.column < first + w)
            chunk.push_back({e.row, e.column - first, e.value});
        chunk_out.assign(row_count * static_cast<std::size_t>(w), 0.0);
        total += dispatch(chunk, w, rows, row_count, chunk_out.data(), ws, drop_below);
        for (std::size_t i = 0; i < row_count; ++i)
          for (int c = 0; c < w; ++c) out[i * width + first + c] = chunk_out[i * w + c];
      }
      return total;
    });
  }

  // A workspace of the right size with a zero block (an extendable solve
  // left in it is released).
  void prepare(Workspace& ws) const {
    if (!ws.fits(m_factor.size, number_of_supernodes()))
      ws.resize(m_factor.size, number_of_supernodes());
    else
      release(ws);
  }

  Solve_statistics dispatch(const std::vector<Rhs_entry>& entries, int width, const int* rows,
                            std::size_t row_count, double* out, Workspace& ws,
                            double drop_below, bool keep = false) const {
    return Supernode_kernels::with_width(Supernode_kernels::width_for(width), [&](auto kernel) {
      return solve_block<decltype(kernel)::value>(entries, rows, row_count, out, ws, drop_below,
                                                  keep, width);
    });
  }

  // Forward: L y = b over the ancestors of the nonzeros of b (scattered
  // into the block already); finds them first, stamped `s`.
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

  // The back substitution of solve_largest and solve_at_least: pops the
  // frontier's supernode with the largest bound (the largest solved value
  // among its rows below; infinity on the right-hand side's paths, where the
  // bound does not hold) until `stop` is met, solving each popped supernode
  // in whole and pushing its children.
  Solve_statistics largest_first(Stop stop, std::vector<int>& rows, std::vector<double>& values,
                                 Workspace& ws) const {
    const auto& F = m_factor;
    Supernode_kernels kernels = kernels_in(ws);
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
      for (const int* c = m_tree.children_begin(k); c != m_tree.children_end(k); ++c) {
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

  // The kernels of this factor, working in `ws`.
  Supernode_kernels kernels_in(Workspace& ws) const {
    return Supernode_kernels(m_factor, m_inverse_diagonal.data(), ws.m_kernel_scratch);
  }

  Supernodal_factor m_factor;
  Supernode_tree m_tree;
  std::vector<double> m_inverse_diagonal;  // 1 / L(j, j)
  std::size_t m_compressed_supernodes = 0;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LOCALIZED_CHOLESKY_SOLVER_H
