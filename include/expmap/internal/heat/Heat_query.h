// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_HEAT_QUERY_H
#define EXPMAP_INTERNAL_HEAT_HEAT_QUERY_H

// A heat query, top to bottom: the steps of the manual's section 2, each
// from the file of its name in this folder.

#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Parallel_loop.h>
#include <expmap/internal/Star_gradient.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/heat/Candidates.h>
#include <expmap/internal/heat/Divergence.h>
#include <expmap/internal/heat/Patch_selection.h>
#include <expmap/internal/heat/Poisson.h>
#include <expmap/internal/heat/Polar_coordinates.h>
#include <expmap/internal/heat/Query_workspace.h>
#include <expmap/internal/heat/Region.h>
#include <expmap/internal/heat/Source_heat.h>
#include <expmap/internal/heat/Star_solve.h>

#include <cmath>
#include <cstddef>
#include <future>
#include <optional>
#include <system_error>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

// Steps 1 and 2: the candidates, the source heat and the region of a patch `growth` times
// larger than asked (marked in ws). A retry continues the first attempt's
// solve. Sets `whole_component` if the region is the source's whole
// component.
inline Solve_statistics find_region(const Context& c, int s, const Patch& patch,
                                    std::size_t target, const std::vector<int>& wanted,
                                    std::size_t component, double growth, bool retry,
                                    bool& whole_component, Workspace& ws) {
  Solve_statistics stats;
  // With an M-matrix, count, fraction and radius patches take the hottest
  // vertices of the component: no candidates to cut the region short. (A
  // vertex-set patch names no size its region could be cut to before the
  // distance is known.)
  const bool largest_first = patch.kind() != Patch::Kind::vertex_set && c.factors.heat_is_m_matrix;
  if (largest_first) {
    std::size_t kept = 0;
    stats += solve_region_largest_first(c, s, patch, target, component, growth, retry, kept, ws);
    whole_component = kept == component;
    choose_region(kept, ws);
  } else {
    grow_candidates(c, s, patch, target, wanted, growth, candidate_excess, ws);
    whole_component = ws.candidates.size() == component;
    stats += retry ? extend_source_heat(c, ws) : solve_source_heat(c, s, ws);
    const std::size_t kept =
        whole_component ? ws.candidates.size()
                        : static_cast<std::size_t>(std::ceil(
                              static_cast<double>(ws.candidates.size()) / candidate_excess));
    choose_region(kept, ws);
    // Breadth-first candidates: the hottest ones, as many as a disk
    // `margin` times the patch's radius holds, must not touch the
    // candidates' edge (checked on the heat, before the distance).
    const bool breadth_first =
        patch.kind() == Patch::Kind::fraction || patch.kind() == Patch::Kind::vertex_count;
    const double margin = patch_margin(c);
    const auto hottest_inside =
        static_cast<std::size_t>(std::ceil(margin * margin * static_cast<double>(target)));
    if (breadth_first && !whole_component && region_is_cut_short(c, hottest_inside, ws))
      stats += widen_candidates(c, target, growth, kept, component, whole_component, ws);
  }
  stats += confirm_pruned_source_heat(c, s, largest_first, ws);
  mark_region(ws);
  return stats;
}

/// The polar coordinates of `patch` around the query's source (c.source)
/// in the tangent frame `frame`: `target` and `wanted` as
/// `patch_target_count` and `checked_vertex_set` give them. A point source
/// takes `reference` (the query's reference direction) for its corners'
/// frames. Adds the solves' statistics to `stats`.
inline std::vector<Polar_entry> heat_polar_coordinates(const Context& c,
                                                       const Tangent_frame& frame,
                                                       const std::optional<Vector3>& reference,
                                                       const Patch& patch, std::size_t target,
                                                       const std::vector<int>& wanted,
                                                       Workspace& ws, Solve_statistics& stats) {
  const int s = c.source.lead;
  // The stencil the angles are read on, around the source in the caller's
  // tangent frame; a point's from its corners'.
  std::vector<Point_corner> corners;
  Star_gradient star;
  if (c.source.is_vertex()) {
    star = source_star_gradient(c, s, frame);
  } else {
    corners = point_corners(c.mesh, c.source, frame, reference,
                            [&](int v, const Vector3& normal) {
                              return near_source_zone(c, v, normal);
                            });
    star = point_star_gradient(c.mesh, c.source, frame, corners,
                               [&](int v, const Tangent_frame& corner_frame) {
                                 return source_star_gradient(c, v, corner_frame);
                               });
  }
  const auto component = static_cast<std::size_t>(c.mesh.component_size[c.mesh.component[s]]);
  for (double growth = c.query.region_growth;; growth *= 2) {
    const bool retry = growth > c.query.region_growth;
    if (retry) ++stats.region_retries;
    // Steps 1 and 2.
    bool whole_component = false;
    stats +=
        find_region(c, s, patch, target, wanted, component, growth, retry, whole_component, ws);

    // Step 2 near a boundary: the heat the distance is read from.
    stats += average_boundary_heat(c, target, ws);

    // Steps 3 and 4; with a second thread, step 6 beside them, on the whole region
    // (the patch is not known before the distance).
    bool star_beside = c.query.query_threads > 1 && !in_parallel_loop() &&
                       ws.region.size() >= min_region_beside_distance;
    {
      std::future<Solve_statistics> region_star;
      if (star_beside) {
        try {
          region_star = std::async(std::launch::async, [&c, &star, &ws] {
            return solve_star_heat(c, star, ws.region, ws.region_star, ws.region_star_solve, ws);
          });
        } catch (const std::system_error&) {
          star_beside = false;  // no thread to be had: the star after the distance
        }
      }
      // (If this throws, the future's destructor waits for the star solve,
      // which uses the workspace, before the workspace goes back.)
      normalized_heat_gradient_divergence(c, ws);
      stats += integrate_distance(c, s, ws);
      if (star_beside) stats += region_star.get();
    }

    // Step 5: the patch, clear of the region's edge, or a retry on a
    // region twice as large.
    const std::vector<std::size_t> order =
        select_patch(patch, target, wanted, c.source.is_vertex(), ws);
    if (!whole_component && !patch_is_complete(c, patch, target, wanted, order, ws))
      continue;
    ws.patch.clear();
    for (const std::size_t i : order) ws.patch.push_back(ws.region[i]);

    // Step 6. Where the region has no boundary vertex, the boundary's image
    // is at least two patch radii away and its heat negligible.
    if (star_beside)
      read_star_heat_on_patch(star_columns(c, star), order, ws);
    else
      stats += solve_star_heat(c, star, ws.patch, ws.star, ws.heat_solve, ws);
    ws.meets_boundary = c.factors.touches_boundary(ws.region);
    if (ws.meets_boundary) stats += solve_boundary_star_heat(c, star, ws);

    // Step 7.
    return polar_coordinates(c, frame, star, corners, order, ws);
  }
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_HEAT_QUERY_H
