// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_PATCH_SELECTION_H
#define EXPMAP_INTERNAL_HEAT_PATCH_SELECTION_H

// Step 5 (manual, section 2): the patch, selected from the region by
// distance, and the check that it stays clear of the region's edge, where
// the Poisson step's cut-off error lives.

#include <expmap/Patch.h>
#include <expmap/internal/Nearest_first.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

// Region positions of the patch vertices, nearest first (ties by vertex).
// `source_row`: the source is a vertex, the region's first, and belongs to
// every patch (`wanted` then leaves it out).
inline std::vector<std::size_t> select_patch(const Patch& patch, std::size_t target,
                                             const std::vector<int>& wanted, bool source_row,
                                             const Workspace& ws) {
  std::vector<std::size_t> order;
  if (patch.kind() == Patch::Kind::vertex_set) {
    if (source_row) order.push_back(0);
    for (int v : wanted)  // distinct, without the source
      if (ws.in_region.is_marked(v))
        order.push_back(static_cast<std::size_t>(ws.in_region.value(v)));
  } else {
    order.resize(ws.region.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
  }
  if (patch.kind() == Patch::Kind::geodesic_radius)
    order.erase(std::remove_if(order.begin(), order.end(),
                               [&](std::size_t i) { return ws.potential[i] > patch.radius(); }),
                order.end());
  // Both keys side by side: a comparison through the region's arrays costs
  // two cache misses.
  struct Key {
    double distance;
    int vertex;
    std::size_t position;
    bool operator<(const Key& other) const {
      return distance < other.distance || (distance == other.distance && vertex < other.vertex);
    }
  };
  std::vector<Key> keys(order.size()), scratch;
  std::vector<std::size_t> bucket_start;
  for (std::size_t k = 0; k < order.size(); ++k)
    keys[k] = {ws.potential[order[k]], ws.region[order[k]], order[k]};
  const bool by_count =
      patch.kind() != Patch::Kind::geodesic_radius && patch.kind() != Patch::Kind::vertex_set;
  keep_nearest_sorted(keys, by_count ? target : keys.size(), scratch, bucket_start);
  order.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = keys[k].position;
  return order;
}

// How far from the source the region ends: `vertex`, the smallest distance
// at a region vertex with a neighbour outside the region; `edge`, the
// smallest distance to the middle of an edge leaving the region, where its
// vertices' cells end. Only vertices at most `horizon` from the source are
// looked at (both are infinity if no such vertex is that near).
struct Region_end {
  double vertex, edge;
};

inline Region_end region_end(const Context& c, double horizon, const Workspace& ws) {
  const auto& m = c.mesh;
  Region_end end{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const int v : ws.region_by_index) {
    // end.vertex <= end.edge: a vertex at least as far as end.edge lowers
    // neither, and its neighbours need not be looked at.
    const double d = ws.potential[static_cast<std::size_t>(ws.in_region.value(v))];
    if (d >= end.edge || d > horizon) continue;
    double shortest_out = std::numeric_limits<double>::infinity();
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
      const int u = m.neighbor[p];
      if (!ws.in_region.is_marked(u))
        shortest_out = std::min(shortest_out, norm(m.point[u] - m.point[v]));
    }
    if (shortest_out == std::numeric_limits<double>::infinity()) continue;
    end.vertex = std::min(end.vertex, d);
    end.edge = std::min(end.edge, d + 0.5 * shortest_out);
  }
  return end;
}

// The factor in distance by which the patch must stay clear of the
// region's edge: a geodesic disk with `region_growth` times the patch's
// vertices has sqrt(region_growth) times its radius; the margin is this
// share of it (1: 46-84% of queries retry; less: a larger cut-off
// error, doc/decisions.md).
constexpr double patch_margin_share = 0.85;

inline double patch_margin(const Context& c) {
  return std::max(1.0, patch_margin_share * std::sqrt(c.query.region_growth));
}

// Whether the patch at region positions `order` is the one asked for: all
// of it found, and patch_margin times its reach inside the region (a
// radius patch then holds every vertex within its radius).
inline bool patch_is_complete(const Context& c, const Patch& patch, std::size_t target,
                              const std::vector<int>& wanted,
                              const std::vector<std::size_t>& order, const Workspace& ws) {
  const double margin = patch_margin(c);
  const double reach = patch.kind() == Patch::Kind::geodesic_radius
                           ? patch.radius()
                           : (order.empty() ? 0.0 : ws.potential[order.back()]);
  const std::size_t source_row = c.source.is_vertex() ? 1 : 0;
  const bool all_found = patch.kind() == Patch::Kind::vertex_set
                             ? order.size() == wanted.size() + source_row
                         : patch.kind() == Patch::Kind::geodesic_radius ? true
                                                                         : order.size() == target;
  // A vertex farther than reach * margin (>= reach) passes both tests, so
  // region_end need not look beyond it.
  const Region_end end = region_end(c, reach * margin, ws);
  return all_found && reach < end.vertex && reach * margin <= end.edge;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_PATCH_SELECTION_H
