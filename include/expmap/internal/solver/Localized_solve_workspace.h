// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LOCALIZED_SOLVE_WORKSPACE_H
#define EXPMAP_INTERNAL_SOLVER_LOCALIZED_SOLVE_WORKSPACE_H

#include <expmap/internal/solver/Huge_page_allocator.h>
#include <expmap/internal/solver/Largest_first_frontier.h>
#include <expmap/internal/solver/Supernode_kernels.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

class Largest_first_search;
class Localized_substitution;

/// Per-thread scratch memory of a `Localized_cholesky_solver`
/// (`Localized_cholesky_solver::Workspace`): a dense block of n rows by the
/// widest block it serves, kept zero between solves (only touched rows are
/// cleared), node lists and visit stamps (so no O(n) clearing is ever
/// needed per query), and the state of a solve left open for extension.
/// The block is most of it, so a workspace that only serves one-column
/// solves is made for that width.
class Localized_solve_workspace {
 public:
  /// A workspace for blocks of up to `Supernode_kernels::max_width` columns,
  /// sized by the first solve that uses it.
  Localized_solve_workspace() = default;

  /// Scratch for a factor of order `n` with `supernodes` supernodes, for
  /// blocks of up to `max_width` columns (see `max_width()`).
  /// \pre max_width >= 1 (else std::invalid_argument).
  Localized_solve_workspace(int n, std::size_t supernodes,
                            int max_width = Supernode_kernels::max_width)
      : m_width(block_width_for(max_width)) {
    resize(n, supernodes);
  }

  /// The widest block solved in one traversal with this workspace: the
  /// `max_width` it was made for, rounded up to the width of a kernel
  /// (`Supernode_kernels::width_for()`). `solve()` splits wider blocks into
  /// blocks of this width; `solve_extendable()` refuses them.
  int max_width() const { return m_width; }

  /// Bytes of memory the workspace holds.
  std::size_t bytes() const {
    return bytes_of(m_storage, m_forward_stamp, m_backward_stamp, m_forward_entry,
                    m_backward_entry, m_forward_nodes, m_backward_nodes, m_path,
                    m_kernel_scratch.kept, m_kernel_scratch.low_rank, m_previous_entry,
                    m_extension_nodes) +
           m_frontier.bytes();
  }

 private:
  // The two that solve in it; the solver itself only passes it on.
  friend class Largest_first_search;
  friend class Localized_substitution;

  static int block_width_for(int max_width) {
    if (max_width < 1)
      throw std::invalid_argument(
          "Localized_cholesky_solver: a workspace's max_width must be >= 1");
    return Supernode_kernels::width_for(std::min(max_width, Supernode_kernels::max_width));
  }
  template <class... Vector>
  static std::size_t bytes_of(const Vector&... v) {
    return (... + (v.capacity() * sizeof(typename Vector::value_type)));
  }

  bool fits(int n, std::size_t supernodes) const {
    return m_size == n && m_forward_stamp.size() == supernodes;
  }
  void resize(int n, std::size_t supernodes) {
    m_size = n;
    // Rows of the block start on cache lines (a row of 8 doubles is one line).
    constexpr std::size_t line = 64 / sizeof(double);
    m_storage.assign(static_cast<std::size_t>(n) * m_width + line, 0.0);
    const auto address = reinterpret_cast<std::uintptr_t>(m_storage.data());
    m_block = m_storage.data() + (line - (address / sizeof(double)) % line) % line;
    m_forward_stamp.assign(supernodes, 0);
    m_backward_stamp.assign(supernodes, 0);
    m_forward_entry.assign(supernodes, 0);
    m_backward_entry.assign(supernodes, 0);
    m_stamp = 0;
    m_open_width = 0;
  }
  std::uint32_t next_stamp() {
    if (++m_stamp == 0) {  // wrapped around: the stamps must start afresh
      std::fill(m_forward_stamp.begin(), m_forward_stamp.end(), 0);
      std::fill(m_backward_stamp.begin(), m_backward_stamp.end(), 0);
      m_stamp = 1;
    }
    return m_stamp;
  }

  std::vector<double, Huge_page_allocator<double>> m_storage;
  double* m_block = nullptr;  // m_storage, aligned
  std::vector<std::uint32_t> m_forward_stamp, m_backward_stamp;
  std::vector<int> m_forward_entry, m_backward_entry;  // first column needed
  std::vector<int> m_forward_nodes, m_backward_nodes, m_path;
  Supernode_kernels::Scratch m_kernel_scratch;
  // A solve left in the block for extension: its kernel width (0 if none)
  // and its number of columns; the entries of its supernodes before an
  // extension, and the supernodes the extension adds.
  int m_open_width = 0, m_open_columns = 0;
  std::vector<int> m_previous_entry, m_extension_nodes;
  // Whether that solve is an open solve_largest or solve_at_least, then its
  // frontier, how many values it wrote and its pruning (0: none).
  bool m_largest_open = false;
  Largest_first_frontier m_frontier;
  std::size_t m_largest_values = 0;
  double m_largest_drop_below = 0;
  std::uint32_t m_stamp = 0;
  int m_size = -1;
  int m_width = Supernode_kernels::max_width;  // of the block: a kernel width
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LOCALIZED_SOLVE_WORKSPACE_H
