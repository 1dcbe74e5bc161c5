// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_DIVERGENCE_H
#define EXPMAP_INTERNAL_HEAT_DIVERGENCE_H

// Step 3 (manual, section 2): the divergence of the normalized
// heat gradient X = grad h / |grad h| on the region.

#include <expmap/internal/Normalized_gradient_divergence.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <array>
#include <cstddef>

namespace expmap {
namespace internal {
namespace heat {

// Fills ws.divergence (one value per region vertex) from the faces whose
// three corners lie in the region, so that it sums to zero as the Poisson
// system's right-hand side must.
inline void normalized_heat_gradient_divergence(const Context& c, Workspace& ws) {
  ws.divergence.assign(ws.region.size(), 0.0);
  const std::vector<double>& heat = ws.distance_heat.empty() ? ws.region_heat : ws.distance_heat;
  for (const int v : ws.region_by_index) {
    for (auto f = c.factors.faces.begin(v); f != c.factors.faces.end(v); ++f) {
      const auto& corner = f->corner;
      if (!ws.in_region.is_marked(corner[0]) || !ws.in_region.is_marked(corner[1]) ||
          !ws.in_region.is_marked(corner[2]))
        continue;
      std::array<int, 3> at;
      std::array<double, 3> u;
      for (int k = 0; k < 3; ++k) {
        at[k] = ws.in_region.value(corner[k]);
        u[k] = heat[static_cast<std::size_t>(at[k])];
      }
      const auto div = normalized_gradient_divergence(f->divergence, u);
      for (int k = 0; k < 3; ++k) ws.divergence[static_cast<std::size_t>(at[k])] += div[k];
    }
  }
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_DIVERGENCE_H
