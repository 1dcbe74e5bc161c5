// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_BOUNDARY_LOOPS_H
#define EXPMAP_INTERNAL_OPERATORS_BOUNDARY_LOOPS_H

#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/Mesh_arrays.h>

#include <cstddef>
#include <numeric>
#include <vector>

namespace expmap {
namespace internal {

/// Per vertex, whether it lies on a boundary loop at least `min_perimeter`
/// long (a loop: the boundary edges connected through shared vertices);
/// empty if no vertex does. Boundary edges are the edges of exactly one
/// face. Only vertices with more neighbours than faces can have one, so a
/// closed mesh costs one pass over its vertices.
inline std::vector<char> vertices_on_long_boundary_loops(const Mesh_arrays& m,
                                                         double min_perimeter) {
  const std::size_t n = m.number_of_vertices();
  auto may_be_on_boundary = [&](int v) {
    const int faces = m.vertex_face_start[v + 1] - m.vertex_face_start[v];
    return faces > 0 && m.neighbor_start[v + 1] - m.neighbor_start[v] > faces;
  };
  std::vector<char> on_long_loop;
  int first = 0;
  while (first < static_cast<int>(n) && !may_be_on_boundary(first)) ++first;
  if (first == static_cast<int>(n)) return on_long_loop;
  std::vector<int> parent;
  reserve_on_huge_pages(parent, n);
  parent.resize(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<double> perimeter = filled_on_huge_pages(n, 0.0);
  bool any = false;
  for (int v = first; v < static_cast<int>(n); ++v) {
    if (!may_be_on_boundary(v)) continue;
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
      const int u = m.neighbor[p];
      if (u < v || !may_be_on_boundary(u)) continue;
      int shared = 0;
      for (int q = m.vertex_face_start[v]; q < m.vertex_face_start[v + 1]; ++q) {
        const auto& f = m.face[m.vertex_face[q]];
        shared += f[0] == u || f[1] == u || f[2] == u;
      }
      if (shared != 1) continue;
      any = true;
      const int a = root(v), b = root(u);
      if (a != b) {
        parent[a] = b;
        perimeter[b] += perimeter[a];
      }
      perimeter[b] += m.neighbor_distance[p];
    }
  }
  if (!any) return on_long_loop;
  on_long_loop.assign(n, 0);
  bool long_loop = false;
  for (int v = 0; v < static_cast<int>(n); ++v) {
    if (!may_be_on_boundary(v) || (root(v) == v && perimeter[v] == 0)) continue;
    if (perimeter[root(v)] >= min_perimeter) on_long_loop[v] = long_loop = 1;
  }
  if (!long_loop) on_long_loop.clear();
  return on_long_loop;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_BOUNDARY_LOOPS_H
