// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LOCALIZED_CHOLESKY_SOLVER_H
#define EXPMAP_INTERNAL_SOLVER_LOCALIZED_CHOLESKY_SOLVER_H

/// \file Localized_cholesky_solver.h
/// The sparse engine of the heat method (include/expmap/internal/solver/):
/// localized forward and back substitution on a whole-mesh Cholesky factor.
/// It includes no mesh type; the heat query (internal/heat/) is its only
/// caller in the library. From the top down:
///
/// - `Localized_cholesky_solver.h` (this file): the driver, the one class
///   the rest of the library uses. It checks arguments, splits wide blocks,
///   picks the kernel width, times every solve and hands the work to:
/// - `Localized_substitution.h`: the factor with its elimination tree, and
///   the forward and back substitutions over the tree paths a right-hand
///   side and the requested rows reach, one block at a time, extendable.
/// - `Largest_first_search.h`: the back substitution that visits the tree
///   largest first and stops by the maximum principle (M-matrices, a
///   nonnegative right-hand side), with `Largest_first_frontier.h`, its
///   queue of subtrees and their bounds.
/// - `Pruning_threshold.h`: what `drop_below` means, why pruning pays and
///   how to choose it; `Timed_solve.h`: the timing; `Rhs_entry.h`: one entry
///   of a sparse right-hand side.
/// - `Localized_solve_workspace.h`: a thread's scratch, and the state of a
///   solve left open for extension.
/// - Storage and kernels: `Supernodal_factor.h` (the factor regrouped into
///   dense supernodes, in double or single precision), `Supernode_tree.h`
///   (children, height, the reach of a set of columns),
///   `Supernode_kernels.h` (one supernode's forward and back substitution,
///   full or pruned) on `Dense_row_kernels.h` (the dense row updates),
///   `Low_rank_rows_below.h` (rows below a separator kept as a truncated SVD,
///   by LAPACK's `dgesdd` declared in `Lapack.h`), `Huge_page_allocator.h`
///   (the large arrays in huge pages).
/// - `Pivoted_householder_qr.h`: a dense least-squares decomposition beside
///   the engine, not part of it: the star gradient fit
///   (internal/Star_gradient.h) uses it.

#include <expmap/Cholesky_factor_view.h>
#include <expmap/Factor_precision.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/solver/Largest_first_frontier.h>
#include <expmap/internal/solver/Largest_first_search.h>
#include <expmap/internal/solver/Localized_solve_workspace.h>
#include <expmap/internal/solver/Localized_substitution.h>
#include <expmap/internal/solver/Low_rank_rows_below.h>
#include <expmap/internal/solver/Pruning_threshold.h>
#include <expmap/internal/solver/Rhs_entry.h>
#include <expmap/internal/solver/Supernode_kernels.h>
#include <expmap/internal/solver/Timed_solve.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// Solves A X = B for a block of sparse right-hand sides with a prefactored
/// A = P^T L D L^T P, computing X only where it is needed (Herholz, Davis &
/// Alexa 2017; the substitutions are `Localized_substitution`'s).
///
/// Every solve takes a pruning threshold `drop_below` (0: exact, the same
/// numbers as a full solve; see Pruning_threshold.h for its meaning and how
/// to choose it) and returns what it touched, timed. A solve can be kept
/// open and extended to more rows (`solve_extendable()`, `extend()`), and
/// on an M-matrix the largest values of the solution can be found without
/// solving the rest (`solve_largest()`, `solve_at_least()`;
/// `Largest_first_search`).
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
      : m_substitution(factor, precision) {}

  int size() const { return factor().size; }

  /// Height of the elimination tree (number of nodes on its longest
  /// leaf-to-root path).
  int tree_height() const { return m_substitution.tree().height(); }

  /// Stored entries of the supernodal factor (dense blocks included).
  std::size_t number_of_entries() const { return factor().number_of_entries(); }

  /// The precision the factor's entries are kept in.
  Factor_precision precision() const { return factor().precision; }

  /// Bytes held by the factor's entries.
  std::size_t entry_bytes() const { return factor().value_bytes(); }

  /// The factor's ordering: `permutation()[k]` is the row of A that became
  /// pivot k. A matrix with the same sparsity can be factored with it
  /// (`Cholmod_solver::factor(A, ordering)`) without ordering it again.
  const std::vector<int>& permutation() const { return factor().permutation; }

  /// Number of supernodes (dense column blocks) of the factor.
  std::size_t number_of_supernodes() const { return factor().supernode.size(); }

  /// Keeps the rows below the factor's large separators in low-rank form
  /// as `compression` asks (`internal::compress_rows_below`), on `threads`
  /// threads (0: the hardware's count). Part of the setup: not to be called
  /// while the solver is in use. Called after the solver model's factor is
  /// released, the decompositions' scratch does not add to the
  /// precomputation's peak memory.
  /// \returns the number of supernodes compressed by this call.
  std::size_t compress_rows_below(const Rows_below_compression& compression,
                                  unsigned threads = 0) {
    const std::size_t count = m_substitution.compress_rows_below(compression, threads);
    m_compressed_supernodes += count;
    return count;
  }

  /// Number of supernodes whose rows below are kept in low-rank form.
  std::size_t number_of_compressed_supernodes() const { return m_compressed_supernodes; }

  /// A workspace sized for this factor, for blocks of up to `max_width`
  /// columns (see `Workspace::max_width()`).
  /// \pre max_width >= 1 (else std::invalid_argument).
  std::unique_ptr<Workspace> make_workspace(int max_width = max_block_width) const {
    return std::make_unique<Workspace>(size(), number_of_supernodes(), max_width);
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
    if (width < 1) throw std::invalid_argument("Localized_cholesky_solver: width < 1");
    return timed_solve([&] {
      m_substitution.prepare(ws);
      const int block = ws.max_width();
      if (width <= block) return solve_block(entries, width, rows, row_count, out, ws, drop_below);
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
        total += solve_block(chunk, w, rows, row_count, chunk_out.data(), ws, drop_below);
        for (std::size_t i = 0; i < row_count; ++i)
          for (int c = 0; c < w; ++c) out[i * width + first + c] = chunk_out[i * w + c];
      }
      return total;
    });
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
    if (width < 1 || width > ws.max_width())
      throw std::invalid_argument(
          "Localized_cholesky_solver: an extendable solve's width must be from 1 to its "
          "workspace's max_width()");
    return timed_solve([&] {
      m_substitution.prepare(ws);
      return solve_block(entries, width, rows, row_count, out, ws, drop_below, /*keep=*/true);
    });
  }

  /// The solution of the last `solve_extendable()` on `ws` at `rows` (which
  /// may repeat rows returned before), written as `solve()` writes it: the
  /// same numbers as a full solve. Only the back substitution of the
  /// supernodes the new rows need beyond those already solved is done.
  /// \pre `ws` holds an extendable solve (else std::logic_error).
  Solve_statistics extend(const int* rows, std::size_t row_count, double* out,
                          Workspace& ws) const {
    return timed_solve([&] { return m_substitution.extend(rows, row_count, out, ws); });
  }

  /// Ends an extendable solve: the workspace is ready for any solve (which
  /// would release it too).
  void release(Workspace& ws) const { m_substitution.release(ws); }

  /// Smallest |value| among `count` values (infinity if there are none): the
  /// scale a pruned solve's `drop_below` is checked against
  /// (Pruning_threshold.h).
  static double smallest_magnitude(const double* values, std::size_t count) {
    return internal::smallest_magnitude(values, count);
  }

  /// The `count` largest values of the solution x of A x = b in the parts
  /// of A (its connected components) that b touches, by a back substitution
  /// that visits the elimination tree largest first and stops where nothing
  /// larger can remain (`Largest_first_search`: why, and what A must be);
  /// the values are those of a full solve. Writes every row it solved (the
  /// supernodes visited, in whole) to `rows` and its value to `values`
  /// (cleared first), in the order solved: the `count` largest among them
  /// (or all of those parts, if they have fewer rows) are the largest
  /// there. The solve stays open for `extend_largest()` (and `extend()`)
  /// until the next solve on `ws` or `release()`. Pruned if `drop_below` > 0.
  /// \pre A an M-matrix with nonnegative row sums (not checked); every
  /// entry of b nonnegative, in column 0; drop_below >= 0 and finite.
  Solve_statistics solve_largest(const std::vector<Rhs_entry>& entries, std::size_t count,
                                 std::vector<int>& rows, std::vector<double>& values,
                                 Workspace& ws, double drop_below = 0) const {
    return start_largest_first(entries, Stop{count, 0.0}, rows, values, ws, drop_below);
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
    Largest_first_search::check_threshold(threshold);
    return start_largest_first(entries, Stop{Largest_first_frontier::no_count, threshold}, rows,
                               values, ws, drop_below);
  }

  /// Continues the last `solve_largest()` or `solve_at_least()` on `ws`
  /// until every value at least `threshold` is known.
  /// \pre as `extend_largest()`; threshold > 0 and finite.
  Solve_statistics extend_at_least(double threshold, std::vector<int>& rows,
                                   std::vector<double>& values, Workspace& ws) const {
    Largest_first_search::check_threshold(threshold);
    return resume_largest_first(Stop{Largest_first_frontier::no_count, threshold}, rows, values,
                                ws);
  }

  /// Continues the last `solve_largest()` on `ws` until the `count` largest
  /// values are known, appending the rows it solves to `rows` and `values`
  /// (which must hold what the earlier calls wrote).
  /// \pre `ws` holds an open `solve_largest()` (else std::logic_error).
  Solve_statistics extend_largest(std::size_t count, std::vector<int>& rows,
                                  std::vector<double>& values, Workspace& ws) const {
    return resume_largest_first(Stop{count, 0.0}, rows, values, ws);
  }

 private:
  using Stop = Largest_first_frontier::Stop;

  const Supernodal_factor& factor() const { return m_substitution.factor(); }

  // One block of at most ws.max_width() columns, by the kernel of the
  // narrowest width that holds it.
  Solve_statistics solve_block(const std::vector<Rhs_entry>& entries, int width,
                               const int* rows, std::size_t row_count, double* out,
                               Workspace& ws, double drop_below, bool keep = false) const {
    return Supernode_kernels::with_width(Supernode_kernels::width_for(width), [&](auto kernel) {
      return m_substitution.solve_block<decltype(kernel)::value>(entries, rows, row_count, out,
                                                                 ws, drop_below, keep, width);
    });
  }

  Solve_statistics start_largest_first(const std::vector<Rhs_entry>& entries, Stop stop,
                                       std::vector<int>& rows, std::vector<double>& values,
                                       Workspace& ws, double drop_below) const {
    check_drop_below(drop_below);
    Largest_first_search::check_right_hand_side(entries);
    return timed_solve([&] {
      return Largest_first_search(m_substitution).start(entries, stop, rows, values, ws,
                                                         drop_below);
    });
  }

  Solve_statistics resume_largest_first(Stop stop, std::vector<int>& rows,
                                        std::vector<double>& values, Workspace& ws) const {
    return timed_solve(
        [&] { return Largest_first_search(m_substitution).resume(stop, rows, values, ws); });
  }

  Localized_substitution m_substitution;
  std::size_t m_compressed_supernodes = 0;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LOCALIZED_CHOLESKY_SOLVER_H
