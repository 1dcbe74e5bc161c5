// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_SOURCES_H
#define EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_SOURCES_H

/// \file Boundary_sources.h
/// Source vertices on and near the boundary of a mesh, chosen
/// deterministically: spread evenly along the boundary loops, plus for each
/// of them the nearest vertex one and two rings (graph hops) inside; and,
/// to compare with, interior sources whose patch stays clear of the
/// boundary, spread over the mesh.
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
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <utility>
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

/// The length of every edge of `g`, in the order of `g.neighbours`.
using Edge_lengths = std::vector<std::vector<double>>;

/// The `Edge_lengths` of `g`, the `Vertex_graph` of `tm`.
template <class TriangleMesh>
Edge_lengths edge_lengths(const TriangleMesh& tm, const Vertex_graph& g) {
  const auto index = CGAL::get_initialized_vertex_index_map(tm);
  const auto points = get(CGAL::vertex_point, tm);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> by_index(
      g.neighbours.size());
  for (auto v : vertices(tm)) by_index[static_cast<std::size_t>(get(index, v))] = v;
  Edge_lengths lengths(g.neighbours.size());
  for (std::size_t v = 0; v < g.neighbours.size(); ++v)
    for (std::size_t w : g.neighbours[v]) {
      const auto& p = get(points, by_index[v]);
      const auto& q = get(points, by_index[w]);
      const double dx = CGAL::to_double(p.x() - q.x()), dy = CGAL::to_double(p.y() - q.y()),
                   dz = CGAL::to_double(p.z() - q.z());
      lengths[v].push_back(std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  return lengths;
}

/// The length of the shortest edge path from each vertex to the boundary
/// (infinity for vertices of closed components, which no boundary reaches).
inline std::vector<double> edge_path_distance_from_boundary(const Vertex_graph& g,
                                                            const Edge_lengths& lengths) {
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  std::vector<double> distance(g.neighbours.size(), std::numeric_limits<double>::infinity());
  for (std::size_t v = 0; v < distance.size(); ++v)
    if (g.on_boundary[v]) {
      distance[v] = 0;
      queue.push({0.0, v});
    }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;  // a stale entry
    for (std::size_t i = 0; i < g.neighbours[v].size(); ++i) {
      const std::size_t w = g.neighbours[v][i];
      if (d + lengths[v][i] < distance[w]) {
        distance[w] = d + lengths[v][i];
        queue.push({distance[w], w});
      }
    }
  }
  return distance;
}

/// Whether a patch grown from a vertex along shortest edge paths gathers
/// its vertices before it reaches a given distance; one search per vertex,
/// sharing one array of distances.
class Edge_path_balls {
 public:
  Edge_path_balls(const Vertex_graph& g, const Edge_lengths& lengths)
      : m_graph(g),
        m_lengths(lengths),
        m_distance(g.neighbours.size(), std::numeric_limits<double>::infinity()) {}

  /// Whether the `count` vertices nearest to `v` along edge paths all lie
  /// nearer to it than `limit` (false where its component has fewer).
  bool fit_within(std::size_t v, std::size_t count, double limit) {
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    std::size_t settled = 0;
    bool fits = false;
    reach(v, 0.0, queue);
    while (!queue.empty()) {
      const auto [d, u] = queue.top();
      queue.pop();
      if (d > m_distance[u]) continue;  // a stale entry
      if (d >= limit) break;
      if (++settled >= count) {
        fits = true;
        break;
      }
      for (std::size_t i = 0; i < m_graph.neighbours[u].size(); ++i)
        reach(m_graph.neighbours[u][i], d + m_lengths[u][i], queue);
    }
    for (std::size_t u : m_touched) m_distance[u] = std::numeric_limits<double>::infinity();
    m_touched.clear();
    return fits;
  }

 private:
  template <class Queue>
  void reach(std::size_t u, double d, Queue& queue) {
    if (d >= m_distance[u]) return;
    if (std::isinf(m_distance[u])) m_touched.push_back(u);
    m_distance[u] = d;
    queue.push({d, u});
  }

  const Vertex_graph& m_graph;
  const Edge_lengths& m_lengths;
  std::vector<double> m_distance;      // infinity outside the current search
  std::vector<std::size_t> m_touched;  // the vertices the current search reached
};

/// Up to `budget` of `candidates` that `accept` takes, spread over the mesh
/// by farthest-point sampling in hops: first `candidates.front()`, then
/// each time the candidate with the most hops to those already taken (a
/// candidate none of them reaches, in another component, counts as
/// farthest; ties to the earlier candidate). A candidate `accept` turns
/// down is passed over and does not push the others away.
template <class Accept>
std::vector<std::size_t> farthest_point_sample(const Vertex_graph& g,
                                               const std::vector<std::size_t>& candidates,
                                               std::size_t budget, Accept accept) {
  constexpr std::size_t unreached = static_cast<std::size_t>(-1);
  std::vector<std::size_t> hops_to_taken(g.neighbours.size(), unreached);
  std::vector<bool> declined(candidates.size(), false);
  std::vector<std::size_t> taken;
  while (taken.size() < budget) {
    std::optional<std::size_t> best;  // position in candidates
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const std::size_t hops = hops_to_taken[candidates[i]];
      if (!declined[i] && hops > 0 && (!best || hops > hops_to_taken[candidates[*best]]))
        best = i;
    }
    if (!best) break;
    const std::size_t v = candidates[*best];
    if (!accept(v)) {
      declined[*best] = true;
      continue;
    }
    taken.push_back(v);
    // Lower the hops to the taken vertices by a search from the new one;
    // it stops where the earlier ones are as near.
    std::deque<std::size_t> queue{v};
    hops_to_taken[v] = 0;
    while (!queue.empty()) {
      const std::size_t u = queue.front();
      queue.pop_front();
      for (std::size_t w : g.neighbours[u])
        if (hops_to_taken[w] == unreached || hops_to_taken[w] > hops_to_taken[u] + 1) {
          hops_to_taken[w] = hops_to_taken[u] + 1;
          queue.push_back(w);
        }
    }
  }
  return taken;
}

/// The study's interior sources of `tm`: up to `budget` vertices whose
/// patch of `patch_count` vertices stays clear of the boundary, spread
/// over the mesh. Measured alongside the boundary sources, they tell what
/// the mesh costs a method from what the boundary costs it.
///
/// The candidates are the vertices whose patch grown along shortest edge
/// paths gathers its vertices nearer than the boundary
/// (`Edge_path_balls`), the farthest from the boundary first; sampling
/// them (`farthest_point_sample()`) takes those `patch_clears_boundary(v)`
/// accepts. Edge paths are longer than geodesics by a factor that depends
/// on the triangles, so only that check, which can look at the patches the
/// methods grow by their own distances, decides. Hops would be a worse
/// guess: they ignore edge lengths, and on meshes of very uneven triangles
/// a patch grown ring by ring reaches the boundary where the geodesic one
/// does not.
/// Empty for a closed mesh or where no vertex is far enough in. Costs a
/// search of up to `patch_count` vertices from each vertex, plus the checks.
template <class TriangleMesh, class Accept>
std::vector<std::size_t> interior_sources(const TriangleMesh& tm, std::size_t patch_count,
                                          std::size_t budget, Accept patch_clears_boundary) {
  if (budget == 0) return {};
  const Vertex_graph g = vertex_graph(tm);
  const Edge_lengths lengths = edge_lengths(tm, g);
  const std::vector<double> to_boundary = edge_path_distance_from_boundary(g, lengths);
  Edge_path_balls balls(g, lengths);
  std::vector<std::size_t> candidates;
  for (std::size_t v = 0; v < to_boundary.size(); ++v)
    if (std::isfinite(to_boundary[v]) && balls.fit_within(v, patch_count, to_boundary[v]))
      candidates.push_back(v);
  std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
    return to_boundary[a] > to_boundary[b];
  });
  return farthest_point_sample(g, candidates, budget, patch_clears_boundary);
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_SOURCES_H
