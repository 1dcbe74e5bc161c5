// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_TRIANGULATION_ADJACENCY_H
#define EXPMAP_INTERNAL_OPERATORS_TRIANGULATION_ADJACENCY_H

#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/operators/Intrinsic_triangulation.h>

#include <algorithm>
#include <array>
#include <vector>

namespace expmap {
namespace internal {

/// The neighbours of every vertex in a triangulation (compressed rows,
/// sorted, without duplicates): after intrinsic Delaunay flips they differ
/// from the input mesh's, and the heat lives on them.
struct Vertex_adjacency {
  std::vector<int> start, neighbor;

  const int* begin(int v) const { return neighbor.data() + start[v]; }
  const int* end(int v) const { return neighbor.data() + start[v + 1]; }
};

/// The neighbours of `n` vertices in the triangles `faces`.
inline Vertex_adjacency vertex_adjacency(std::size_t n,
                                         const std::vector<std::array<int, 3>>& faces) {
  Vertex_adjacency a;
  reserve_on_huge_pages(a.start, n + 1);
  a.start.assign(n + 1, 0);
  std::vector<int>& count = a.start;
  for (const auto& f : faces)
    for (int v : f) count[static_cast<std::size_t>(v) + 1] += 2;
  for (std::size_t v = 0; v < n; ++v) count[v + 1] += count[v];
  // Every face's other two corners under each corner, then each vertex's
  // list sorted, deduplicated and moved down in place: the rows are built
  // in the memory they end in.
  std::vector<int>& all = a.neighbor;
  reserve_on_huge_pages(all, static_cast<std::size_t>(count[n]));
  all.resize(static_cast<std::size_t>(count[n]));
  std::vector<int> fill;
  reserve_on_huge_pages(fill, n);
  fill.assign(count.begin(), count.end() - 1);
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) {
      all[static_cast<std::size_t>(fill[f[k]]++)] = f[(k + 1) % 3];
      all[static_cast<std::size_t>(fill[f[k]]++)] = f[(k + 2) % 3];
    }
  int kept = 0;
  for (std::size_t v = 0; v < n; ++v) {
    auto first = all.begin() + count[v], last = all.begin() + count[v + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    const auto to = all.begin() + kept;
    count[v] = kept;
    kept += static_cast<int>(last - first);
    if (to != first) std::copy(first, last, to);  // to < first: moving down is safe
  }
  count[n] = kept;
  all.resize(static_cast<std::size_t>(kept));
  return a;
}

inline Vertex_adjacency vertex_adjacency(const Intrinsic_triangulation& tri) {
  return vertex_adjacency(tri.number_of_vertices, tri.face);
}

/// s, then its neighbours, then (if `rings` is 2) their other neighbours:
/// the vertices within `rings` edges of s, nearest ring first. `start` and
/// `neighbor` are compressed rows of any vertex adjacency (a
/// `Vertex_adjacency`'s, or the input mesh's in `Mesh_arrays`).
inline std::vector<int> ring_neighborhood(const std::vector<int>& start,
                                          const std::vector<int>& neighbor, int s, int rings) {
  std::vector<int> vertices{s};
  vertices.insert(vertices.end(), neighbor.begin() + start[s], neighbor.begin() + start[s + 1]);
  if (rings < 2) return vertices;
  const std::size_t one_ring = vertices.size();
  for (std::size_t c = 1; c < one_ring; ++c)
    for (int p = start[vertices[c]]; p < start[vertices[c] + 1]; ++p)
      if (std::find(vertices.begin(), vertices.end(), neighbor[p]) == vertices.end())
        vertices.push_back(neighbor[p]);
  return vertices;
}

inline std::vector<int> ring_neighborhood(const Vertex_adjacency& a, int s, int rings) {
  return ring_neighborhood(a.start, a.neighbor, s, rings);
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_TRIANGULATION_ADJACENCY_H
