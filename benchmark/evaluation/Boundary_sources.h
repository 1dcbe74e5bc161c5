// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_SOURCES_H
#define EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_SOURCES_H

/// \file Boundary_sources.h
/// Source vertices on and near the boundary of a mesh, chosen
/// deterministically: spread evenly along the boundary loops, plus for each
/// of them the nearest vertex one and two rings (graph hops) inside.
///
/// A map from a boundary vertex sees only a half disk (or less) of
/// neighbours; the sources one and two rings in see the boundary inside
/// their patch. Both are where a method that assumes a full disk of
/// neighbours around the source breaks first, so the boundary study and the
/// boundary quality test measure exactly these sources.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace expmap_evaluation {

/// The vertex graph of a mesh by vertex index (the order of `vertices(tm)`,
/// the indices `compute_by_index()` takes): each vertex's neighbours,
/// sorted, and whether it lies on a boundary.
struct Vertex_graph {
  std::vector<std::vector<std::size_t>> neighbours;
  std::vector<bool> on_boundary;
  /// The boundary loops, each as the vertex indices met walking its border
  /// halfedges, starting at its smallest index; loops ordered by length
  /// (longest first), then by their smallest index.
  std::vector<std::vector<std::size_t>> boundary_loops;
};

/// Builds the `Vertex_graph` of `tm`.
/// \tparam TriangleMesh a model of `FaceGraph` (a `HalfedgeListGraph`).
template <class TriangleMesh>
Vertex_graph vertex_graph(const TriangleMesh& tm) {
  using Traits = boost::graph_traits<TriangleMesh>;
  const auto index = CGAL::get_initialized_vertex_index_map(tm);
  const auto id = [&](typename Traits::vertex_descriptor v) {
    return static_cast<std::size_t>(get(index, v));
  };
  Vertex_graph g;
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  g.neighbours.resize(n);
  g.on_boundary.assign(n, false);
  for (auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    const std::size_t a = id(source(h, tm)), b = id(target(h, tm));
    g.neighbours[a].push_back(b);
    g.neighbours[b].push_back(a);
  }
  for (auto& list : g.neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }

  std::vector<bool> walked(static_cast<std::size_t>(num_halfedges(tm)), false);
  const auto halfedge_index = CGAL::get_initialized_halfedge_index_map(tm);
  for (auto h : halfedges(tm)) {
    if (!is_border(h, tm) || walked[get(halfedge_index, h)]) continue;
    std::vector<std::size_t> loop;
    auto walk = h;
    do {
      walked[get(halfedge_index, walk)] = true;
      loop.push_back(id(target(walk, tm)));
      g.on_boundary[loop.back()] = true;
      walk = next(walk, tm);
    } while (walk != h);
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    g.boundary_loops.push_back(std::move(loop));
  }
  std::sort(g.boundary_loops.begin(), g.boundary_loops.end(),
            [](const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
              if (a.size() != b.size()) return a.size() > b.size();
              return a.front() < b.front();
            });
  return g;
}

/// Up to `budget` boundary vertices spread evenly along the loops of `g`.
/// Long loops get more sources: every loop one (the longest loops first
/// when there are more loops than the budget), the rest one at a time to
/// the loop with the longest stretch per source (largest length / (count +
/// 1), ties to the earlier loop). On a loop of length L with k sources they
/// sit at positions floor(i L / k) from its smallest vertex index.
inline std::vector<std::size_t> spread_along_boundary(const Vertex_graph& g, std::size_t budget) {
  const auto& loops = g.boundary_loops;
  std::vector<std::size_t> count(loops.size(), 0);
  std::size_t given = 0;
  for (std::size_t l = 0; l < loops.size() && given < budget; ++l, ++given) count[l] = 1;
  while (given < budget) {
    std::optional<std::size_t> best;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (count[l] >= loops[l].size()) continue;  // every vertex of the loop taken
      const auto stretch = [&](std::size_t k) {
        return static_cast<double>(loops[k].size()) / static_cast<double>(count[k] + 1);
      };
      if (!best || stretch(l) > stretch(*best)) best = l;
    }
    if (!best) break;
    ++count[*best];
    ++given;
  }
  std::vector<std::size_t> sources;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t i = 0; i < count[l]; ++i) {
      const std::size_t v = loops[l][i * loops[l].size() / count[l]];
      // A vertex where two loops touch can be picked twice.
      if (std::find(sources.begin(), sources.end(), v) == sources.end()) sources.push_back(v);
    }
  return sources;
}

/// Hops from each vertex to the nearest boundary vertex (0 on the boundary;
/// -1 for vertices of closed components, which no boundary reaches).
inline std::vector<int> hops_from_boundary(const Vertex_graph& g) {
  std::vector<int> hops(g.neighbours.size(), -1);
  std::deque<std::size_t> queue;
  for (std::size_t v = 0; v < hops.size(); ++v)
    if (g.on_boundary[v]) {
      hops[v] = 0;
      queue.push_back(v);
    }
  while (!queue.empty()) {
    const std::size_t v = queue.front();
    queue.pop_front();
    for (std::size_t w : g.neighbours[v])
      if (hops[w] < 0) {
        hops[w] = hops[v] + 1;
        queue.push_back(w);
      }
  }
  return hops;
}

/// The vertex `ring` hops from the boundary (by `hops`) that is fewest hops
/// from `start`; among equally near ones the smallest index. None if no
/// such vertex is connected to `start`.
inline std::optional<std::size_t> nearest_at_ring(const Vertex_graph& g,
                                                  const std::vector<int>& hops, std::size_t start,
                                                  int ring) {
  std::vector<bool> seen(g.neighbours.size(), false);
  std::vector<std::size_t> level{start};
  seen[start] = true;
  while (!level.empty()) {
    std::optional<std::size_t> found;
    for (std::size_t v : level)
      if (hops[v] == ring && (!found || v < *found)) found = v;
    if (found) return found;
    std::vector<std::size_t> next_level;
    for (std::size_t v : level)
      for (std::size_t w : g.neighbours[v])
        if (!seen[w]) {
          seen[w] = true;
          next_level.push_back(w);
        }
    level = std::move(next_level);
  }
  return std::nullopt;
}

/// A source of the boundary study.
struct Boundary_source {
  std::size_t vertex = 0;           ///< index in `vertices(tm)`
  int ring = 0;                     ///< hops to the boundary: 0 (on it), 1 or 2
  std::size_t boundary_vertex = 0;  ///< the boundary source it was chosen for
};

/// The study's sources of `tm`: up to `budget` boundary vertices
/// (`spread_along_boundary()`), and after each of them the nearest vertex
/// one ring in and the nearest two rings in (`nearest_at_ring()`), where
/// the mesh has such vertices. Empty for a closed mesh.
template <class TriangleMesh>
std::vector<Boundary_source> boundary_sources(const TriangleMesh& tm, std::size_t budget = 12) {
  const Vertex_graph g = vertex_graph(tm);
  const std::vector<int> hops = hops_from_boundary(g);
  std::vector<Boundary_source> sources;
  for (std::size_t b : spread_along_boundary(g, budget)) {
    sources.push_back({b, 0, b});
    for (int ring : {1, 2})
      if (const auto v = nearest_at_ring(g, hops, b, ring)) sources.push_back({*v, ring, b});
  }
  return sources;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_SOURCES_H
