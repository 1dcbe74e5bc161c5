// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_DIVERGENCE_H
#define EXPMAP_INTERNAL_HEAT_DIVERGENCE_H

// Step 3 (manual, section 2): the divergence of the normalized
// heat gradient X = grad h / |grad h| on the region.

#include <expmap/internal/heat/Query_workspace.h>
#include <expmap/internal/operators/Normalized_gradient_divergence.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace expmap {
namespace internal {
namespace heat {

// The integral over a face of the unit vectors pointing from the point at
// `x` away, in the face's layout (`stencil`'s: corners at (0, 0), (x1, 0),
// (x2, y2)): over each corner-to-corner wedge at x in closed form, so it
// moves continuously with x (a wedge whose edge passes through x adds 0).
inline std::array<double, 2> outward_unit_integral(const Divergence_stencil& stencil,
                                                   const std::array<double, 2>& x) {
  const std::array<std::array<double, 2>, 3> p{
      {{{0.0, 0.0}}, {{stencil.x1, 0.0}}, {{stencil.x2, stencil.y2}}}};
  std::array<double, 2> sum{{0, 0}};
  for (int k = 0; k < 3; ++k) {
    const auto& a = p[k];
    const auto& b = p[(k + 1) % 3];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const std::array<double, 2> t{{(b[0] - a[0]) / length, (b[1] - a[1]) / length}};
    const std::array<double, 2> n{{t[1], -t[0]}};  // away from the inside (counter-clockwise)
    const double d = (a[0] - x[0]) * n[0] + (a[1] - x[1]) * n[1];  // x's distance to the edge
    if (!(d > 0)) continue;
    const double sa = (a[0] - x[0]) * t[0] + (a[1] - x[1]) * t[1];
    const double sb = sa + length;
    // Polar coordinates about x: the wedge's integral of (cos, sin) r dr
    // dphi up to the edge, r = d / cos(phi - phi_n).
    const double along_n = 0.5 * d * d * (std::asinh(sb / d) - std::asinh(sa / d));
    const double along_t = 0.5 * d * (std::hypot(d, sb) - std::hypot(d, sa));
    for (int i = 0; i < 2; ++i) sum[i] += along_n * n[i] + along_t * t[i];
  }
  return sum;
}

// The radial field's share of X in the face of a point source, per unit of
// the point's smallest barycentric coordinate there: all of it where that
// is at least 1/6.
constexpr double radial_share_per_weight = 6.0;

// The divergence of the face holding a point source strictly inside: the
// heat's gradient there turns with the point (its corners' heat is nearly
// equal where the point is near the middle), so X is taken as the unit field
// towards the point averaged over the face, the exact integrated divergence
// of the geodesic directions in the face's plane. Returns false if `corner`
// is not that face (which intrinsic edge flips may have removed).
inline bool source_face_divergence(const Context& c, const std::array<int, 3>& corner,
                                   const Divergence_stencil& stencil,
                                   const std::array<double, 3>& u, std::array<double, 3>& div) {
  const Source& source = c.source;
  if (source.count != 3) return false;
  std::array<double, 3> w{};
  for (int k = 0; k < 3; ++k) {
    int found = -1;
    for (int j = 0; j < 3; ++j)
      if (source.corner[j] == corner[k]) found = j;
    if (found < 0) return false;
    w[k] = source.weight[found];
  }
  const std::array<double, 2> x{{w[1] * stencil.x1 + w[2] * stencil.x2, w[2] * stencil.y2}};
  const std::array<double, 2> outward = outward_unit_integral(stencil, x);
  const double area = 0.5 * stencil.x1 * stencil.y2;
  std::array<double, 2> unit{{-outward[0] / area, -outward[1] / area}};
  // Towards an edge the corners' heat orders itself (the far corner's
  // falls behind) and the heat's direction is the better one: the two are
  // blended so that the face's divergence comes to the heat's continuously
  // as the point reaches an edge, where the next face takes over.
  const double radial = std::min(1.0, radial_share_per_weight * std::min({w[0], w[1], w[2]}));
  if (radial < 1) {
    const std::array<double, 2> heat = normalized_gradient(stencil, u);
    for (int i = 0; i < 2; ++i) unit[i] = radial * unit[i] + (1 - radial) * heat[i];
  }
  for (int a = 0; a < 3; ++a)
    div[a] = unit[0] * stencil.corner_weight[a][0] + unit[1] * stencil.corner_weight[a][1];
  return true;
}

// Fills ws.divergence (one value per region vertex) from the faces whose
// three corners lie in the region, so that it sums to zero as the Poisson
// system's right-hand side must.
inline void normalized_heat_gradient_divergence(const Context& c, Workspace& ws) {
  ws.divergence.assign(ws.region.size(), 0.0);
  const std::vector<double>& heat = ws.distance_heat.empty() ? ws.region_heat : ws.distance_heat;
  const bool inside_a_face = c.source.count == 3;
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
      std::array<double, 3> div;
      if (!inside_a_face || !source_face_divergence(c, corner, f->divergence, u, div))
        div = normalized_gradient_divergence(f->divergence, u);
      for (int k = 0; k < 3; ++k) ws.divergence[static_cast<std::size_t>(at[k])] += div[k];
    }
  }
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_DIVERGENCE_H
