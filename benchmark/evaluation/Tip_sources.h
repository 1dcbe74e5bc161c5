// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_TIP_SOURCES_H
#define EXPMAP_BENCHMARK_EVALUATION_TIP_SOURCES_H

/// \file Tip_sources.h
/// Source vertices where a surface is least like a plane: the tips of thin
/// parts (fingers, claws, ears, horns), eyes and sharp creases, found by
/// the curvature concentrated around them. There geodesics to far-apart
/// vertices leave the source within a narrow range of directions, or wrap
/// around a thin part, and a method reading directions at the source alone
/// is blind: the tip study and its test measure these sources.

#include "Boundary_sources.h"
#include "Common.h"

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace expmap_evaluation {

/// Each vertex's angle defect: 2 pi minus the sum of its corner angles
/// (pi minus it at a boundary vertex), the Gaussian curvature it carries.
inline std::vector<double> angle_defects(const Mesh& mesh, const Vertex_graph& graph) {
  std::vector<double> angle_sum(num_vertices(mesh), 0.0);
  for (auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const std::array<Vertex, 3> v{{target(h, mesh), target(next(h, mesh), mesh),
                                   target(prev(h, mesh), mesh)}};
    for (int k = 0; k < 3; ++k) {
      const Point& p = mesh.point(v[k]);
      const Point& a = mesh.point(v[(k + 1) % 3]);
      const Point& b = mesh.point(v[(k + 2) % 3]);
      const auto da = a - p, db = b - p;
      const double c = CGAL::to_double(da * db) /
                       std::sqrt(CGAL::to_double(da.squared_length() * db.squared_length()));
      angle_sum[v[k]] += std::acos(std::clamp(c, -1.0, 1.0));
    }
  }
  std::vector<double> defect(angle_sum.size());
  for (std::size_t v = 0; v < defect.size(); ++v)
    defect[v] = (graph.on_boundary[v] ? pi : 2 * pi) - angle_sum[v];
  return defect;
}

/// The vertices within `hops` graph hops of `v` (v included).
inline std::vector<std::size_t> vertices_within_hops(const Vertex_graph& graph, std::size_t v,
                                                     int hops) {
  std::vector<std::size_t> found{v}, frontier{v}, next;
  std::vector<bool> seen(graph.neighbours.size(), false);
  seen[v] = true;
  for (int d = 0; d < hops; ++d) {
    next.clear();
    for (std::size_t x : frontier)
      for (std::size_t y : graph.neighbours[x])
        if (!seen[y]) {
          seen[y] = true;
          next.push_back(y);
          found.push_back(y);
        }
    frontier.swap(next);
  }
  return found;
}

/// Up to `count` interior vertices of largest |angle defect summed over
/// their `ring`-ring|, greedily, each at least `spacing` hops from those
/// chosen before; ties to the smaller index.
inline std::vector<std::size_t> tip_sources(const Mesh& mesh, std::size_t count, int ring = 3,
                                            int spacing = 6) {
  const Vertex_graph graph = vertex_graph(mesh);
  const std::vector<double> defect = angle_defects(mesh, graph);
  const std::size_t n = defect.size();
  std::vector<double> score(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    double sum = 0;
    for (std::size_t w : vertices_within_hops(graph, v, ring)) sum += defect[w];
    score[v] = std::abs(sum);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return score[a] > score[b]; });
  std::vector<bool> blocked(n, false);
  std::vector<std::size_t> chosen;
  for (std::size_t v : order) {
    if (chosen.size() == count) break;
    if (blocked[v] || graph.on_boundary[v] || graph.neighbours[v].empty()) continue;
    chosen.push_back(v);
    for (std::size_t w : vertices_within_hops(graph, v, spacing - 1)) blocked[w] = true;
  }
  return chosen;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_TIP_SOURCES_H
