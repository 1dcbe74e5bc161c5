// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_REGION_GROWING_H
#define EXPMAP_INTERNAL_REGION_GROWING_H

#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Vector3.h>

#include <cstdint>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// Marks vertices of the current query without clearing an O(n) array per
/// query: a vertex is marked when its stamp equals the current one.
class Vertex_marks {
 public:
  void resize(std::size_t n) {
    reserve_on_huge_pages(m_entry, n);
    m_entry.assign(n, Entry{});
    m_current = 0;
  }
  void next_query() {
    if (++m_current == 0) {
      std::fill(m_entry.begin(), m_entry.end(), Entry{});
      m_current = 1;
    }
  }
  bool is_marked(int v) const { return m_entry[v].stamp == m_current; }
  void mark(int v, int value) { m_entry[v] = Entry{m_current, value}; }
  void unmark(int v) { m_entry[v].stamp = m_current - 1; }
  /// Marks `v` with `value` unless it is marked already; returns 1 if it
  /// was new. Branch-free: searches find about half their neighbours
  /// already visited, a coin toss for the branch predictor.
  int mark_if_new(int v, int value) {
    const Entry old = m_entry[v];
    const int fresh = old.stamp != m_current;
    m_entry[v] = fresh ? Entry{m_current, value} : old;
    return fresh;
  }
  /// The value stored with a marked vertex.
  int value(int v) const { return m_entry[v].value; }

 private:
  struct Entry {  // stamp and value side by side: one cache line per lookup
    std::uint32_t stamp = 0;
    int value = 0;
  };
  std::vector<Entry> m_entry;
  std::uint32_t m_current = 0;
};

/// Dijkstra over the mesh edges (Euclidean edge lengths) from `source`,
/// appending settled vertices to `region` nearest first and marking each
/// with its position in `region`. Stops before the first vertex for which
/// `keep(vertex, graph_distance, region_size)` is false. Only the visited
/// part of the mesh is touched.
template <class Keep>
void grow_region(const Mesh_arrays& m, int source, Vertex_marks& in_region,
                 Vertex_marks& seen, std::vector<double>& tentative, std::vector<int>& region,
                 Keep keep) {
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  region.clear();
  in_region.next_query();
  seen.next_query();
  seen.mark(source, 0);
  tentative[source] = 0;
  heap.push({0.0, source});
  while (!heap.empty()) {
    const auto [d, v] = heap.top();
    heap.pop();
    if (in_region.is_marked(v) || d > tentative[v]) continue;
    if (!keep(v, d, region.size())) break;
    in_region.mark(v, static_cast<int>(region.size()));
    region.push_back(v);
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
      const int w = m.neighbor[p];
      if (in_region.is_marked(w)) continue;
      const double dw = d + m.neighbor_distance[p];
      if (!seen.is_marked(w) || dw < tentative[w]) {
        seen.mark(w, 0);
        tentative[w] = dw;
        heap.push({dw, w});
      }
    }
  }
}

/// Continues a breadth-first search whose vertices `region` holds (marked in
/// `in_region` with their positions, nearest first in edge hops) from the
/// vertex at position `head`, until `budget` vertices are found or the
/// component is exhausted. Returns the position to continue from later: the
/// vertex whose neighbours were being added when the budget was reached
/// (they are added again, and only the unmarked ones are new).
inline std::size_t continue_region_by_hops(const Mesh_arrays& m, Vertex_marks& in_region,
                                           std::size_t budget, std::vector<int>& region,
                                           std::size_t head) {
  std::size_t size = region.size();
  if (size >= budget) return head;
  // Room for the last vertex's whole neighbourhood: every neighbour is
  // written, and only a new one is kept (no branch to mispredict on the
  // half of the neighbours a search finds already visited).
  region.resize(budget + static_cast<std::size_t>(m.max_degree) + 1);
  for (; head < size && size < budget; ++head) {
    const int v = region[head];
    const int end = m.neighbor_start[v + 1];
    for (int p = m.neighbor_start[v]; p < end; ++p) {
      const int w = m.neighbor[p];
      region[size] = w;
      size += in_region.mark_if_new(w, static_cast<int>(size));
    }
  }
  const bool budget_reached = size >= budget;
  for (std::size_t i = budget; i < size; ++i) in_region.unmark(region[i]);
  region.resize(std::min(size, budget));
  return budget_reached ? head - 1 : head;
}

/// Appends to `region` every vertex within `rings` edge hops of `seeds` that
/// is not marked yet, marking each with its position: a breadth-first
/// search from several seeds at once, one ring at a time. `frontier` and
/// `next` are scratch space.
inline void grow_rings_around(const Mesh_arrays& m, Vertex_marks& in_region,
                              const std::vector<int>& seeds, int rings, std::vector<int>& region,
                              std::vector<int>& frontier, std::vector<int>& next) {
  frontier.assign(seeds.begin(), seeds.end());
  for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
    next.clear();
    for (const int v : frontier)
      for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
        const int w = m.neighbor[p];
        if (in_region.is_marked(w)) continue;
        in_region.mark(w, static_cast<int>(region.size()));
        region.push_back(w);
        next.push_back(w);
      }
    frontier.swap(next);
  }
}

/// Breadth-first search from `source` over the mesh edges, appending up to
/// `budget` vertices to `region` (nearest first in edge hops) and marking
/// each with its position. Cheaper than `grow_region` (no heap, no lengths)
/// where only the size of the region matters. Returns where
/// `continue_region_by_hops` can take it up.
inline std::size_t grow_region_by_hops(const Mesh_arrays& m, int source, Vertex_marks& in_region,
                                       std::size_t budget, std::vector<int>& region) {
  in_region.next_query();
  in_region.mark(source, 0);
  region.assign(1, source);
  return continue_region_by_hops(m, in_region, budget, region, 0);
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_REGION_GROWING_H
