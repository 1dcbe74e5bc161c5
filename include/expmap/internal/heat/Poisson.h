// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_POISSON_H
#define EXPMAP_INTERNAL_HEAT_POISSON_H

// Step 4 (manual, section 2): the distance, L phi = div X solved
// on the region, r = phi - phi(s).

#include <expmap/Errors.h>
#include <expmap/Heat_options.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <algorithm>
#include <cstddef>
#include <string>

namespace expmap {
namespace internal {
namespace heat {

// The potential at the source: at a vertex its own; at a point, the
// corners' potentials less their distances from the point, weighted like
// the point's heat (so it is continuous as the point moves and is the
// vertex's own at a vertex). Corners outside the region are left out.
inline double potential_at_source(const Context& c, const Workspace& ws) {
  const Source& source = c.source;
  if (source.is_vertex()) return ws.potential[0];
  double sum = 0, weight = 0;
  for (int k = 0; k < source.count; ++k) {
    const int v = source.corner[k];
    if (!ws.in_region.is_marked(v)) continue;
    const double d = norm(c.mesh.point[v] - source.position);
    sum += source.weight[k] * (ws.potential[static_cast<std::size_t>(ws.in_region.value(v))] - d);
    weight += source.weight[k];
  }
  return sum / weight;  // the lead is the region's first vertex
}

// Fills ws.potential with the distance of each region vertex from the
// source s (the first region vertex).
// \throws Computation_error if the distance is clearly smallest elsewhere.
inline Solve_statistics integrate_distance(const Context& c, int s, Workspace& ws) {
  const std::size_t kept = ws.region.size();
  // Filled in place: a pushed temporary is stored in pieces and reloaded
  // whole, a store-forwarding stall per entry.
  ws.rhs.resize(kept);
  std::size_t entries = 0;
  for (std::size_t i = 0; i < kept; ++i)
    if (ws.divergence[i] != 0.0 && !c.factors.is_pinned[ws.region[i]]) {
      Rhs_entry& e = ws.rhs[entries++];
      e.row = ws.region[i];
      e.column = 0;
      e.value = ws.divergence[i];
    }
  ws.rhs.resize(entries);
  ws.potential.resize(kept);
  const Solve_statistics stats = c.factors.poisson.solve(ws.rhs, 1, ws.region.data(), kept,
                                                         ws.potential.data(), ws.poisson_solve);
  // Slightly negative values next to the source are discretization error
  // and are clamped to 0; a clearly negative one means the heat was not
  // positive (negative cotan weights) and the whole field is unreliable.
  const double at_source = potential_at_source(c, ws);
  std::size_t lowest = 0;
  for (std::size_t i = 0; i < kept; ++i)
    if (ws.potential[i] < ws.potential[lowest]) lowest = i;
  if (ws.potential[lowest] - at_source < -0.5 * c.mesh.mean_edge_length) {
    // Intrinsic Delaunay flips cannot remove an obtuse angle opposite a
    // boundary edge. Where that breaks the heat (ALSTOM_TEST4's strips),
    // neither a larger time factor nor --repair helped: the geodesic
    // methods are the way out.
    const std::string cause =
        c.options.laplacian == Laplacian_mode::direct
            ? "on this mesh's non-Delaunay triangles; use Laplacian_mode::intrinsic_delaunay (the "
              "default) or a larger time factor"
            : "here, although the Laplacian is intrinsic Delaunay (obtuse angles opposite "
              "boundary edges, which edge flips cannot remove, can cause this); map this source "
              "with DGPC or the exact method";
    throw Computation_error(
        "the heat distance from source vertex " + std::to_string(c.mesh.to_original(s)) +
        " is smallest at vertex " + std::to_string(c.mesh.to_original(ws.region[lowest])) +
        ", not at the source: the heat diffusion is not positive " + cause);
  }
  for (double& phi : ws.potential) phi = std::max(0.0, phi - at_source);
  return stats;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_POISSON_H
