// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_SUPERNODE_TREE_H
#define EXPMAP_INTERNAL_SOLVER_SUPERNODE_TREE_H

#include <expmap/internal/solver/Supernodal_factor.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace expmap {
namespace internal {

/// The elimination tree of a `Supernodal_factor`, supernode by supernode
/// (a supernode's parent holds the parent of its last column): the
/// children of every supernode and the tree's height, and
/// `supernode_reach()` for the paths from given columns to the root.
class Supernode_tree {
 public:
  Supernode_tree() = default;

  explicit Supernode_tree(const Supernodal_factor& factor) {
    const auto& sns = factor.supernode;
    // Parents come after their children, so one descending sweep gives every
    // supernode the number of columns on its path to the root.
    std::vector<int> depth(sns.size(), 0);
    for (std::size_t k = sns.size(); k-- > 0;) {
      depth[k] = sns[k].ncol + (sns[k].parent == -1 ? 0 : depth[sns[k].parent]);
      m_height = std::max(m_height, depth[k]);
    }
    // The children, compressed by parent.
    m_child_start.assign(sns.size() + 1, 0);
    for (const auto& sn : sns)
      if (sn.parent != -1) ++m_child_start[static_cast<std::size_t>(sn.parent) + 1];
    for (std::size_t k = 0; k < sns.size(); ++k) m_child_start[k + 1] += m_child_start[k];
    m_child.resize(static_cast<std::size_t>(m_child_start.back()));
    std::vector<int> next(m_child_start.begin(), m_child_start.end() - 1);
    for (std::size_t k = 0; k < sns.size(); ++k)
      if (sns[k].parent != -1)
        m_child[static_cast<std::size_t>(next[sns[k].parent]++)] = static_cast<int>(k);
  }

  /// Columns on the tree's longest leaf-to-root path.
  int height() const { return m_height; }

  /// The children of supernode `k`: `children_begin(k)` to `children_end(k)`.
  const int* children_begin(int k) const { return m_child.data() + m_child_start[k]; }
  const int* children_end(int k) const { return m_child.data() + m_child_start[k + 1]; }

 private:
  std::vector<int> m_child_start, m_child;
  int m_height = 0;
};

/// Lists in `order` the supernodes of `factor` on the tree paths from the
/// pivots `to_pivot(*start)` of `begin..end` to the root, in a topological
/// order (descendants before ancestors): each new path goes in front of the
/// paths found before it, whose nodes it can only precede. A supernode is
/// found once per `s`: `stamp[k] == s` marks it (paths stop there), and
/// `entry[k]` receives the first of its columns a path enters at (the
/// columns before it are not needed: zero in forward substitution, unused
/// in back substitution). Supernodes stamped `s` before the call are known
/// already: not listed again, only their entries may move down. `path` is
/// scratch.
template <class Start, class StartToPivot>
void supernode_reach(const Supernodal_factor& factor, const Start* begin, const Start* end,
                     StartToPivot to_pivot, std::vector<std::uint32_t>& stamp,
                     std::vector<int>& entry, std::uint32_t s, std::vector<int>& order,
                     std::vector<int>& path) {
  order.clear();
  for (const Start* start = begin; start != end; ++start) {
    path.clear();
    int column = to_pivot(*start);
    int k = factor.supernode_of_column[column];
    while (true) {
      const int offset = column - factor.supernode[k].first_column;
      if (stamp[k] == s) {  // known: only its entry may move down
        entry[k] = std::min(entry[k], offset);
        break;
      }
      stamp[k] = s;
      entry[k] = offset;
      path.push_back(k);
      const auto& sn = factor.supernode[k];
      if (sn.parent == -1) break;
      column = factor.row_index[sn.below_rows];  // the parent of the last column
      k = sn.parent;
    }
    order.insert(order.end(), path.rbegin(), path.rend());
  }
  std::reverse(order.begin(), order.end());
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_SUPERNODE_TREE_H
