// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_CANDIDATES_H
#define EXPMAP_INTERNAL_HEAT_CANDIDATES_H

// Step 1 (manual, section 2): the candidate vertices the source heat is
// solved for, where it cannot find its region largest first (vertex-set
// patches, or a heat matrix that is not an M-matrix).

#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/heat/Query_workspace.h>
#include <expmap/internal/heat/Region.h>
#include <expmap/internal/heat/Source_heat.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

// Graph distance allowed per geodesic distance for Dijkstra candidates (1:
// nearly every radius map on lion-head and bunny00 (direct) changes, r by up
// to 5-13% of the radius).
constexpr double candidate_graph_slack = 1.1;

// Fills ws.candidates, nearest first by graph distance, `excess` times as
// many as a patch `growth` times larger than asked: by Dijkstra for radius
// and vertex-set patches, breadth first for count patches. Graph distance
// bounds the geodesic distance from above, so they are taken generously;
// the query checks the result.
inline void grow_candidates(const Context& c, int s, const Patch& patch, std::size_t target,
                            const std::vector<int>& wanted, double growth, double excess,
                            Workspace& ws) {
  const double radius_scale = std::sqrt(growth * excess) * candidate_graph_slack;
  auto grow = [&](auto keep) {
    grow_region(c.mesh, s, ws.in_region, ws.seen, ws.tentative, ws.candidates, keep);
  };
  if (patch.kind() == Patch::Kind::geodesic_radius) {
    const double limit = patch.radius() * radius_scale;
    grow([&](int, double d, std::size_t) { return d <= limit; });
  } else if (patch.kind() == Patch::Kind::vertex_set) {
    // Reach every wanted vertex (distinct, source excluded), then keep going
    // to the same margin.
    ws.wanted.next_query();
    for (int v : wanted) ws.wanted.mark(v, 0);
    std::size_t reached = 0;
    double limit = wanted.empty() ? 0.0 : -1.0;
    grow([&](int v, double d, std::size_t) {
      if (limit >= 0) return d <= limit;
      if (ws.wanted.is_marked(v) && ++reached == wanted.size()) limit = d * radius_scale;
      return true;
    });
  } else {
    // Only the count matters here: the region is cut from the candidates by
    // heat, so a breadth-first search (no heap) is enough.
    ws.breadth_first_head = grow_region_by_hops(
        c.mesh, s, ws.in_region, breadth_first_budget(target, growth, excess), ws.candidates);
  }
}

// The candidates at `rows` with a neighbour outside the candidates, into
// ws.cut_short_at.
inline void edge_of_candidates(const Context& c, const std::vector<std::size_t>& rows,
                               Workspace& ws) {
  const auto& m = c.mesh;
  ws.cut_short_at.clear();
  for (const std::size_t row : rows) {
    const int v = ws.candidates[row];
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p)
      if (!ws.in_region.is_marked(m.neighbor[p])) {
        ws.cut_short_at.push_back(v);
        break;
      }
  }
}

// Whether one of the `hottest` candidates lies on the candidates' edge:
// breadth-first candidates, lopsided where edge lengths vary, then cut the
// heat's level sets short on that side, and a patch of `hottest` vertices
// would come too close to the region's edge. Needs the candidates marked
// and choose_region done.
inline bool region_is_cut_short(const Context& c, std::size_t hottest, Workspace& ws) {
  hottest_rows(ws.heat_row, hottest, ws.rows, ws);
  edge_of_candidates(c, ws.rows, ws);
  return !ws.cut_short_at.empty();
}

// Candidates per region vertex when rings around the cut-short vertices did
// not clear the region of the candidates' edge (2: 3 instead of 0 retried
// 5% queries on mech-holes-shark).
constexpr double widened_candidate_excess = 2.5;
// Rounds of rings before that (1: 5-10% more factor entries at 5% on
// lion-head and holes, 2: 2% more on average; 5: the same as 3).
constexpr int targeted_widening_rounds = 3;
// Rings added around the cut-short vertices per round, in patch radii
// (0.1, or always 2 rings: 1.7% more factor entries on average at 5% on
// lion-head).
constexpr double widening_rings_per_radius = 0.2;
// A disk of n vertices on a regular triangulation has a radius of about
// sqrt(n / 3) edge hops.
inline int targeted_widening_rings(std::size_t target) {
  return std::max(2, static_cast<int>(std::ceil(widening_rings_per_radius *
                                                std::sqrt(static_cast<double>(target) / 3))));
}

// For a region cut short: grows the candidates where the region touches
// their edge (at most targeted_widening_rounds rounds of rings), else
// everywhere to widened_candidate_excess times the region; extends the
// source heat and chooses the region (of `kept` vertices) again each time.
// This costs the back substitution of the new candidates only, where a
// retry after the distance costs a whole query.
inline Solve_statistics widen_candidates(const Context& c, std::size_t target, double growth,
                                         std::size_t kept, std::size_t component,
                                         bool& whole_component, Workspace& ws) {
  Solve_statistics stats;
  auto take_new_candidates = [&] {
    ++stats.candidate_widenings;
    whole_component = ws.candidates.size() == component;
    stats += extend_source_heat(c, ws);
    choose_region(whole_component ? ws.candidates.size() : kept, ws);
  };
  for (int round = 0;; ++round) {
    if (whole_component) return stats;
    edge_of_candidates(c, ws.heat_row, ws);
    if (ws.cut_short_at.empty()) return stats;
    if (round == targeted_widening_rounds) break;
    grow_rings_around(c.mesh, ws.in_region, ws.cut_short_at, targeted_widening_rings(target),
                      ws.candidates, ws.frontier, ws.next_frontier);
    take_new_candidates();
  }
  // Still on the edge (a mesh much finer one way than the other): the
  // breadth-first search continued everywhere.
  ws.breadth_first_head = continue_region_by_hops(
      c.mesh, ws.in_region, breadth_first_budget(target, growth, widened_candidate_excess),
      ws.candidates, ws.breadth_first_head);
  take_new_candidates();
  return stats;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_CANDIDATES_H
