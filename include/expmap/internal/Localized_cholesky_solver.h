// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_LOCALIZED_CHOLESKY_SOLVER_H
#define EXPMAP_INTERNAL_LOCALIZED_CHOLESKY_SOLVER_H

#include <expmap/Cholesky_factor_view.h>
#include <expmap/Solve_statistics.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// One entry of a sparse right-hand side: `value` at `row` of column `column`.
struct Rhs_entry {
  int row;
  int column;
  double value;
};

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
/// All columns of the block share one traversal of L. The block is stored
/// row-major with a compile-time width so that the update of one row is a
/// short fixed-length loop the compiler vectorizes.
///
/// The object is immutable after construction; per-query scratch lives in a
/// `Workspace`, so many threads can solve at once with one workspace each.
class Localized_cholesky_solver {
 public:
  /// Widest block solved in one traversal; wider blocks are split.
  static constexpr int max_block_width = 16;

  /// Per-thread scratch memory: a dense block of size n x width that is
  /// kept zero between solves (only touched rows are cleared), node lists and
  /// visit stamps (so no O(n) clearing is ever needed per query).
  class Workspace {
   public:
    explicit Workspace(int n = 0) { resize(n); }

   private:
    friend class Localized_cholesky_solver;
    void resize(int n) {
      // Rows of the block start on cache lines (a row of 8 doubles is one line).
      constexpr std::size_t line = 64 / sizeof(double);
      m_storage.assign(static_cast<std::size_t>(n) * max_block_width + line, 0.0);
      const auto address = reinterpret_cast<std::uintptr_t>(m_storage.data());
      m_block = m_storage.data() + (line - (address / sizeof(double)) % line) % line;
      m_forward_stamp.assign(static_cast<std::size_t>(n), 0);
      m_backward_stamp.assign(static_cast<std::size_t>(n), 0);
      m_stamp = 0;
    }
    std::uint32_t next_stamp() {
      if (++m_stamp == 0) {  // wrapped around: the stamps must start afresh
        std::fill(m_forward_stamp.begin(), m_forward_stamp.end(), 0);
        std::fill(m_backward_stamp.begin(), m_backward_stamp.end(), 0);
        m_stamp = 1;
      }
      return m_stamp;
    }
    std::vector<double> m_storage;
    double* m_block = nullptr;  // m_storage, aligned
    std::vector<std::uint32_t> m_forward_stamp, m_backward_stamp;
    std::vector<int> m_forward_nodes, m_backward_nodes, m_path;
    std::uint32_t m_stamp = 0;
  };

  Localized_cholesky_solver() = default;

  /// Prepares the traversal data (elimination tree, scaling) of a factor.
  /// \pre the factor's owner outlives this object.
  explicit Localized_cholesky_solver(const Cholesky_factor_view& factor) : m_factor(factor) {
    const int n = factor.size;
    m_inverse_permutation.assign(static_cast<std::size_t>(n), -1);
    for (int k = 0; k < n; ++k) m_inverse_permutation[factor.permutation[k]] = k;
    m_parent.assign(static_cast<std::size_t>(n), -1);
    m_first_offdiagonal.resize(static_cast<std::size_t>(n));
    m_forward_scale.resize(static_cast<std::size_t>(n));
    m_result_scale.resize(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
      const int begin = factor.column_start[j] + (factor.unit_diagonal ? 0 : 1);
      m_first_offdiagonal[j] = begin;
      int parent = n;
      for (int p = begin; p < factor.column_start[j + 1]; ++p)
        parent = std::min(parent, factor.row_index[p]);
      m_parent[j] = parent == n ? -1 : parent;
      // LL^T: y_j = b_j / L_jj and x_j = (y_j - ...) / L_jj.
      // LDL^T: y_j = b_j / D_jj after propagating, and x_j = y_j - ... .
      if (factor.unit_diagonal) {
        m_forward_scale[j] = 1.0;
        m_result_scale[j] = 1.0 / factor.diagonal[j];
      } else {
        m_forward_scale[j] = 1.0 / factor.value[factor.column_start[j]];
        m_result_scale[j] = 1.0;
      }
    }
    compute_tree_height();
  }

  int size() const { return m_factor.size; }

  /// Height of the elimination tree (number of nodes on its longest
  /// leaf-to-root path).
  int tree_height() const { return m_tree_height; }

  /// A workspace sized for this factor.
  std::unique_ptr<Workspace> make_workspace() const {
    return std::make_unique<Workspace>(m_factor.size);
  }

  /// Solves A X = B where B has `width` columns given by its nonzero
  /// `entries` (rows of A, duplicates are summed), and writes X(rows[i], c)
  /// to `out[i * width + c]`. Exact: the same numbers as a full solve.
  /// \returns what the solve touched.
  Solve_statistics solve(const std::vector<Rhs_entry>& entries, int width,
                         const int* rows, std::size_t row_count, double* out,
                         Workspace& ws) const {
    if (width < 1) throw std::invalid_argument("Localized_cholesky_solver: width < 1");
    if (ws.m_forward_stamp.size() != static_cast<std::size_t>(m_factor.size))
      ws.resize(m_factor.size);
    Solve_statistics total;
    std::vector<Rhs_entry> chunk;
    std::vector<double> chunk_out;
    for (int first = 0; first < width; first += max_block_width) {
      const int w = std::min(max_block_width, width - first);
      const std::vector<Rhs_entry>* part = &entries;
      if (width > max_block_width) {
        chunk.clear();
        for (const Rhs_entry& e : entries)
          if (e.column >= first && e.column < first + w)
            chunk.push_back({e.row, e.column - first, e.value});
        part = &chunk;
      }
      double* target = out;
      if (width > max_block_width) {
        chunk_out.assign(row_count * static_cast<std::size_t>(w), 0.0);
        target = chunk_out.data();
      }
      const Solve_statistics s = dispatch(*part, w, rows, row_count, target, ws);
      total += s;
      if (width > max_block_width)
        for (std::size_t i = 0; i < row_count; ++i)
          for (int c = 0; c < w; ++c)
            out[i * width + first + c] = chunk_out[i * w + c];
    }
    return total;
  }

 private:
  Solve_statistics dispatch(const std::vector<Rhs_entry>& entries, int width, const int* rows,
                            std::size_t row_count, double* out, Workspace& ws) const {
    if (width == 1) return solve_block<1>(entries, rows, row_count, out, ws);
    if (width <= 4) return solve_block<4>(entries, rows, row_count, out, ws, width);
    if (width <= 8) return solve_block<8>(entries, rows, row_count, out, ws, width);
    return solve_block<16>(entries, rows, row_count, out, ws, width);
  }

  // Appends to `nodes` the nodes on the path from `start` towards the root
  // that are not stamped yet, stamping them. Paths are kept in the order the
  // caller needs by `place_paths_first`.
  void collect_path(int start, std::vector<std::uint32_t>& stamp, std::uint32_t s,
                    std::vector<int>& path) const {
    for (int j = start; j != -1 && stamp[j] != s; j = m_parent[j]) {
      stamp[j] = s;
      path.push_back(j);
    }
  }

  // Builds a topological order (descendants before ancestors) of the union of
  // the tree paths from `starts` to the root: each new path goes in front of
  // the paths found before it, whose nodes it can only precede.
  template <class Start, class StartToNode>
  void reach(const Start* begin, const Start* end, StartToNode to_node,
             std::vector<std::uint32_t>& stamp, std::uint32_t s, std::vector<int>& order,
             std::vector<int>& path) const {
    order.clear();
    for (const Start* start = begin; start != end; ++start) {
      path.clear();
      collect_path(to_node(*start), stamp, s, path);
      order.insert(order.end(), path.rbegin(), path.rend());
    }
    std::reverse(order.begin(), order.end());
  }

  template <int W>
  Solve_statistics solve_block(const std::vector<Rhs_entry>& entries, const int* rows,
                               std::size_t row_count, double* out, Workspace& ws,
                               int width = W) const {
    const int* colp = m_factor.column_start;
    const int* rowi = m_factor.row_index;
    const double* val = m_factor.value;
    double* y = ws.m_block;  // row-major n x W, zero on entry and exit
    Solve_statistics stats;

    // Scatter b (permuted) into the block and find the forward node set.
    const std::uint32_t s = ws.next_stamp();
    for (const Rhs_entry& e : entries) {
      const int k = m_inverse_permutation[e.row];
      y[static_cast<std::size_t>(k) * W + e.column] += e.value;
    }
    reach(entries.data(), entries.data() + entries.size(), [this](const Rhs_entry& e) { return m_inverse_permutation[e.row]; },
          ws.m_forward_stamp, s, ws.m_forward_nodes, ws.m_path);

    // Forward: L y = b over the ancestors of the nonzeros of b.
    for (const int j : ws.m_forward_nodes) {
      double* yj = y + static_cast<std::size_t>(j) * W;
      std::array<double, W> t;
      for (int c = 0; c < W; ++c) t[c] = yj[c] * m_forward_scale[j];
      const int end = colp[j + 1];
      for (int p = m_first_offdiagonal[j]; p < end; ++p) {
        double* yi = y + static_cast<std::size_t>(rowi[p]) * W;
        const double l = val[p];
        for (int c = 0; c < W; ++c) yi[c] -= l * t[c];
      }
      const double r = m_result_scale[j];
      for (int c = 0; c < W; ++c) yj[c] = t[c] * r;
      stats.factor_entries += static_cast<std::size_t>(end - colp[j]);
    }
    stats.forward_nodes = ws.m_forward_nodes.size();

    // Backward: L^T x = y over the ancestors of the requested rows, in place.
    reach(rows, rows + row_count, [this](int row) { return m_inverse_permutation[row]; },
          ws.m_backward_stamp, s, ws.m_backward_nodes, ws.m_path);
    for (auto it = ws.m_backward_nodes.rbegin(); it != ws.m_backward_nodes.rend(); ++it) {
      const int j = *it;
      double* yj = y + static_cast<std::size_t>(j) * W;
      std::array<double, W> acc;
      for (int c = 0; c < W; ++c) acc[c] = yj[c];
      const int end = colp[j + 1];
      for (int p = m_first_offdiagonal[j]; p < end; ++p) {
        const double* xi = y + static_cast<std::size_t>(rowi[p]) * W;
        const double l = val[p];
        for (int c = 0; c < W; ++c) acc[c] -= l * xi[c];
      }
      const double f = m_forward_scale[j];
      for (int c = 0; c < W; ++c) yj[c] = acc[c] * f;
      stats.factor_entries += static_cast<std::size_t>(end - colp[j]);
    }
    stats.backward_nodes = ws.m_backward_nodes.size();

    for (std::size_t i = 0; i < row_count; ++i) {
      const double* x = y + static_cast<std::size_t>(m_inverse_permutation[rows[i]]) * W;
      for (int c = 0; c < width; ++c) out[i * width + c] = x[c];
    }

    // Leave the block zero for the next solve: only touched rows are cleared.
    for (const int j : ws.m_forward_nodes)
      std::fill_n(y + static_cast<std::size_t>(j) * W, W, 0.0);
    for (const int j : ws.m_backward_nodes)
      std::fill_n(y + static_cast<std::size_t>(j) * W, W, 0.0);
    return stats;
  }

  void compute_tree_height() {
    // Parents have larger indices than their children, so one descending
    // sweep assigns every node its depth.
    const int n = m_factor.size;
    std::vector<int> depth(static_cast<std::size_t>(n), 1);
    m_tree_height = 0;
    for (int j = n - 1; j >= 0; --j) {
      if (m_parent[j] != -1) depth[j] = depth[m_parent[j]] + 1;
      m_tree_height = std::max(m_tree_height, depth[j]);
    }
  }

  Cholesky_factor_view m_factor;
  std::vector<int> m_inverse_permutation;  // row of A -> pivot
  std::vector<int> m_parent;               // elimination tree
  std::vector<int> m_first_offdiagonal;
  std::vector<double> m_forward_scale, m_result_scale;
  int m_tree_height = 0;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_LOCALIZED_CHOLESKY_SOLVER_H
