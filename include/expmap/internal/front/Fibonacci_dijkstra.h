// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_FIBONACCI_DIJKSTRA_H
#define EXPMAP_INTERNAL_FRONT_FIBONACCI_DIJKSTRA_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/front/Fibonacci_vertex_queue.h>

#include <vector>

namespace expmap {
namespace internal {

/// Scratch memory of `fibonacci_dijkstra()`, sized once for a mesh and
/// reused by every query without clearing (stamps tell what is current).
struct Dijkstra_workspace {
  explicit Dijkstra_workspace(std::size_t n) : distance(n) {
    queue.resize(n);
    settled.resize(n);
    reached.resize(n);
  }
  Fibonacci_vertex_queue queue;
  Vertex_marks settled;          ///< value: position in `order`
  Vertex_marks reached;          ///< `distance` is valid
  std::vector<double> distance;  ///< tentative, then final, graph distance
  std::vector<int> order;        ///< settled vertices, nearest first
};

/// A vertex where `fibonacci_dijkstra()` starts, at a given distance.
struct Dijkstra_seed {
  int vertex;
  double distance;
};

/// Dijkstra over the mesh edges (Euclidean lengths) from the seeds in
/// [`first`, `last`) (a point of a face starts at its corners, at their
/// distances from the point), written out rather than through
/// `boost::dijkstra_shortest_paths` because that one allocates and
/// initializes property maps of the whole mesh per call and can only be
/// stopped by throwing.
///
/// Each popped vertex `v` at graph distance `d` is offered to
/// `visit(v, d)` before it is settled, while every vertex settled so far is
/// marked in `ws.settled`: returning false ends the search with `v`
/// unsettled; returning true settles it and relaxes its edges.
/// Only the visited part of the mesh is touched.
template <class Visit>
void fibonacci_dijkstra(const Mesh_arrays& m, const Dijkstra_seed* first, const Dijkstra_seed* last,
                        Dijkstra_workspace& ws, Visit visit) {
  ws.queue.clear();
  ws.settled.next_query();
  ws.reached.next_query();
  ws.order.clear();
  for (const Dijkstra_seed* seed = first; seed != last; ++seed) {
    if (ws.reached.is_marked(seed->vertex) && ws.distance[seed->vertex] <= seed->distance) continue;
    ws.reached.mark(seed->vertex, 0);
    ws.distance[seed->vertex] = seed->distance;
    ws.queue.push_or_decrease(seed->vertex, seed->distance);
  }
  while (!ws.queue.empty()) {
    const auto [v, d] = ws.queue.pop();
    if (!visit(v, d)) return;
    ws.settled.mark(v, static_cast<int>(ws.order.size()));
    ws.order.push_back(v);
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
      const int w = m.neighbor[p];
      if (ws.settled.is_marked(w)) continue;
      const double dw = d + norm(m.point[w] - m.point[v]);
      if (!ws.reached.is_marked(w) || dw < ws.distance[w]) {
        ws.reached.mark(w, 0);
        ws.distance[w] = dw;
        ws.queue.push_or_decrease(w, dw);
      }
    }
  }
}

/// As above, from the single vertex `source` at distance 0.
template <class Visit>
void fibonacci_dijkstra(const Mesh_arrays& m, int source, Dijkstra_workspace& ws, Visit visit) {
  const Dijkstra_seed seed{source, 0.0};
  fibonacci_dijkstra(m, &seed, &seed + 1, ws, visit);
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_FIBONACCI_DIJKSTRA_H
