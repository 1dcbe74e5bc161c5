// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_POLAR_COORDINATES_H
#define EXPMAP_INTERNAL_HEAT_POLAR_COORDINATES_H

// Step 7 (manual, section 2): the polar coordinates of the patch vertices,
// the angle from the star solve's heat directions, blended with geometric
// directions next to the source, and the distance from step 4.

#include <expmap/Angle_estimator.h>
#include <expmap/Errors.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Near_source_zone.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Star_gradient.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/heat/Point_corners.h>
#include <expmap/internal/heat/Query_workspace.h>
#include <expmap/internal/heat/Star_solve.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

/// The near-source blend is stretched by up to this factor where the
/// surface is flat at its scale (measured on the accuracy study,
/// doc/decisions.md: 3h-9h instead of 2h-6h lowers the mean angle error on
/// every surface; 4h-12h raises the regular saddle's).
constexpr double max_near_source_widening = 1.5;
/// The normal's turn (rad) across the blend's end at which the blend keeps
/// its nominal width; it is narrower where the normal turns more. On a
/// coarse, curved one-ring the projected chords disagree with the heat's
/// directions of the next rings, and a blend between them shears the
/// triangles in between over (doc/folds.md).
constexpr double blend_normal_turn = 1.0;

// The query's blend from geometric into heat coordinates: the query's
// Near_source_blend in mean edge lengths, scaled by blend_normal_turn over
// the normal's turn across the blend's end (at most
// max_near_source_widening). `normal`: the vertex normal of s.
inline Near_source_zone near_source_zone(const Context& c, int s, const Vector3& normal) {
  const double h = c.mesh.mean_edge_length;
  Near_source_zone zone{c.query.near_source_blend.begin * h,
                        c.query.near_source_blend.end * h};
  if (zone.end > 0) {
    const double turn = normal_turn_rate(c.mesh, s, normal) * zone.end;
    const double scale = turn > 0 ? std::min(blend_normal_turn / turn, max_near_source_widening)
                                  : max_near_source_widening;
    zone.begin *= scale;
    zone.end *= scale;
  }
  return zone;
}

/// Next to the source a chord stands in for the geodesic only where it is
/// about as long: one much shorter than the heat distance cuts through
/// space, from one sheet of a thin part to the other (a plate's two faces
/// around its rim), and its direction is not the geodesic's. Where the
/// blend ends the normal has turned by at most 1 rad (`blend_normal_turn`),
/// so a chord that follows the surface is at least 0.96 of its arc.
constexpr double min_chord_over_distance = 0.8;

// The heat's weight in the coordinates of v at heat distance r: the zone's,
// or all of it where the chord from `from` (the source's position) cuts
// through space. `on_surface`: v's chord is an edge, or lies in a face.
inline double near_source_heat_weight(const Context& c, const Vector3& from, int v, double r,
                                      bool on_surface, const Near_source_zone& zone) {
  const double w = zone.heat_weight(r);
  if (w == 1.0 || on_surface) return w;
  return norm(c.mesh.point[v] - from) >= min_chord_over_distance * r ? w : 1.0;
}

// The distance of v at heat distance r and heat weight w. A neighbour of the source takes its
// edge's length (the exact polyhedral distance), blended into r like the
// angle: the heat distance is off by about 0.1 h anywhere, a tenth of a
// neighbour's distance. Farther vertices keep r: chords there cut through
// space on coarse curved meshes and fold triangles over.
inline double blended_distance(const Context& c, int s, int v, double r, double w,
                               const Source_one_ring& ring) {
  if (w == 1.0 || ring.position(v) < 0) return r;
  const double edge = norm(c.mesh.point[v] - c.mesh.point[s]);
  return w * r + (1 - w) * edge;
}

// The geometric direction of v next to the source: a neighbour's edge at
// its intrinsic angle (the corner angles at s rescaled to 2 pi, as DGPC
// starts), any other vertex's chord projected onto the tangent plane and
// carried into the same intrinsic angles by the wedge of neighbours it
// projects into. A projection alone shrinks or widens the corners of a
// curved one-ring unevenly and can take them out of their cyclic order.
inline double near_source_angle(const Context& c, int s, int v, const Tangent_frame& frame,
                                const Source_one_ring& ring) {
  if (const int k = ring.position(v); k >= 0)
    return ring.angle[static_cast<std::size_t>(k)] - ring.reference_angle;
  const double projected = frame.angle_of(c.mesh.point[v] - c.mesh.point[s]);
  return ring.native_angle(projected) - ring.reference_angle;
}

// Polar angle at heat weight w (the zone's at the vertex's distance) from
// the heat direction, blended with the `geometric()` angle next to the
// source.
template <class Geometric>
double polar_angle(double w, const std::array<double, 2>& direction, const Geometric& geometric) {
  if (w == 0.0) return geometric();
  const double heat_angle = std::atan2(direction[1], direction[0]);
  if (w == 1.0) return heat_angle;
  const double g = geometric();
  // Blend unit vectors, not angles, so that the wrap at +-pi does not matter.
  return std::atan2(w * std::sin(heat_angle) + (1 - w) * std::sin(g),
                    w * std::cos(heat_angle) + (1 - w) * std::cos(g));
}

// The gradient at s of the heat from patch vertex v, from its star solve
// row `h`: the direction of the geodesic from s to v (the paper's step 3,
// by the heat's symmetry). For `heat_quadratic_fit` it is divided by
// `at_source`, the heat from v at s, and still carries the fit's cubic leak.
inline std::array<double, 2> heat_direction(const Context& c, double at_source,
                                            const Star_gradient& star, const double* h,
                                            std::vector<double>& values) {
  const Angle_estimator estimator = c.estimator;
  if (is_linear_in_heat(estimator)) {
    // The solve applied the gradient weights already.
    if (estimator == Angle_estimator::heat_quadratic_fit && at_source > 0)
      return {{h[0] / at_source, h[1] / at_source}};
    return {{h[0], h[1]}};
  }
  const std::size_t width = star.vertices.size();
  const bool use_log = std::all_of(h, h + width, [](double x) { return x > 0; });
  for (std::size_t k = 0; k < width; ++k) values[k] = use_log ? std::log(h[k]) : h[k];
  return star.apply(values.data());
}

// The heat from a patch vertex at the source, from its row `h` of a star
// solve of one column per star vertex: at a point, its corners' weighted.
inline double heat_at_source(const Context& c, const Star_gradient& star, const double* h) {
  if (c.source.is_vertex()) return h[0];
  double sum = 0;
  for (int k = 0; k < c.source.count; ++k) {
    const auto column = static_cast<std::size_t>(
        std::find(star.vertices.begin(), star.vertices.end(), c.source.corner[k]) -
        star.vertices.begin());
    sum += c.source.weight[k] * h[column];
  }
  return sum;
}

// The (u, v) of `entry`: from its heat direction where that is its angle
// (no sine and cosine needed), else from the angle.
inline std::array<double, 2> uv_of(const Polar_entry& entry, double heat_weight,
                                   const std::array<double, 2>& direction) {
  const double length = std::hypot(direction[0], direction[1]);
  if (heat_weight == 1.0 && length > 0)
    return {{entry.distance * direction[0] / length, entry.distance * direction[1] / length}};
  return {{entry.distance * std::cos(entry.angle), entry.distance * std::sin(entry.angle)}};
}

// The polar coordinates of the patch (region positions `order`, the source
// first) in original vertex indices, the source left out; their (u, v) in
// ws.patch_uv (the source's too), for the fold check of step 8. `corners`: a
// point source's (empty for a vertex).
inline std::vector<Polar_entry> polar_coordinates(const Context& c, const Tangent_frame& frame,
                                                  const Star_gradient& star,
                                                  const std::vector<Point_corner>& corners,
                                                  const std::vector<std::size_t>& order,
                                                  Workspace& ws) {
  const Angle_estimator estimator = c.estimator;
  const bool linear = is_linear_in_heat(estimator);
  const std::size_t width = star_columns(c, star);
  const std::size_t boundary_width = boundary_star_columns(c, star);
  const bool at_vertex = c.source.is_vertex();
  // A point source is no vertex of the patch.
  const int s = at_vertex ? c.source.lead : -1;
  const Near_source_zone zone =
      at_vertex ? near_source_zone(c, s, frame.normal) : point_zone(corners);
  std::vector<double> values(star.vertices.size());
  std::vector<double> both(width);  // the Neumann and Dirichlet heat, summed
  // The heat's weight in each patch vertex's coordinates.
  Source_one_ring ring;
  if (at_vertex) ring = source_one_ring(c.mesh, s, frame);
  const Vector3 from = at_vertex ? c.mesh.point[s] : c.source.position;
  std::vector<double> weight(order.size());
  for (std::size_t p = 0; p < order.size(); ++p) {
    const int v = ws.region[order[p]];
    bool on_surface = false;
    if (at_vertex)
      on_surface = v == s || ring.position(v) >= 0;
    else
      for (const Point_corner& corner : corners)
        on_surface = on_surface || v == corner.vertex || corner.ring.position(v) >= 0;
    weight[p] = near_source_heat_weight(c, from, v, ws.potential[order[p]], on_surface, zone);
  }
  // The heat directions of the patch vertices (where the blend wants them),
  // then, for the quadratic fit, their cubic leak removed for all at once.
  std::vector<std::array<double, 2>> direction(order.size());
  std::vector<std::array<double, 2>> leaking;
  std::vector<double> leak_radius;
  std::vector<std::size_t> leaking_at;
  for (std::size_t p = 0; p < order.size(); ++p) {
    const std::size_t i = order[p];
    const int v = ws.region[i];
    const double* h = ws.star.heat.data() + p * width;
    // The heat from v at the source: its own column for a logarithmic
    // estimator, the source heat of step 2 otherwise.
    double at_source = linear ? ws.region_heat[i] : heat_at_source(c, star, h);
    if (ws.meets_boundary) {
      const double* dirichlet = ws.boundary_star.heat.data() + p * boundary_width;
      for (std::size_t k = 0; k < width; ++k) both[k] = h[k] + dirichlet[k];
      at_source = linear ? at_source + dirichlet[2] : heat_at_source(c, star, both.data());
      h = both.data();
    }
    if (!(std::abs(at_source) > std::numeric_limits<double>::min()))
      throw Computation_error("heat diffusion underflows at vertex " +
                              std::to_string(c.mesh.to_original(v)) + " (distance " +
                              std::to_string(ws.potential[i]) +
                              "); increase the time factor or request a smaller patch");
    if (v == s || weight[p] == 0.0) continue;  // no heat direction needed
    direction[p] = heat_direction(c, at_source, star, h, values);
    if (estimator == Angle_estimator::heat_quadratic_fit && at_source > 0) {
      leaking.push_back(direction[p]);
      leak_radius.push_back(std::max(ws.potential[i], c.mesh.mean_edge_length));
      leaking_at.push_back(p);
    }
  }
  remove_cubic_leak(star, leaking.data(), leak_radius.data(), leaking.size(), c.factors.time_step);
  for (std::size_t k = 0; k < leaking_at.size(); ++k) direction[leaking_at[k]] = leaking[k];

  std::vector<Polar_entry> entries;
  entries.reserve(order.size());
  ws.patch_uv.clear();
  if (at_vertex) {
    ws.patch_uv.push_back({s, {{0.0, 0.0}}});
    for (std::size_t p = 0; p < order.size(); ++p) {
      const std::size_t i = order[p];
      const int v = ws.region[i];
      if (v == s) continue;
      const double r = ws.potential[i];
      entries.push_back(
          {static_cast<int>(c.mesh.to_original(v)), blended_distance(c, s, v, r, weight[p], ring),
           polar_angle(weight[p], direction[p],
                       [&] { return near_source_angle(c, s, v, frame, ring); })});
      ws.patch_uv.push_back({v, uv_of(entries.back(), weight[p], direction[p])});
    }
    return entries;
  }
  const Point_near_source near{c.mesh, c.source, corners};
  for (std::size_t p = 0; p < order.size(); ++p) {
    const std::size_t i = order[p];
    const int v = ws.region[i];
    const double r = ws.potential[i];
    const double w = weight[p];
    entries.push_back({static_cast<int>(c.mesh.to_original(v)),
                       w == 1.0 ? r : w * r + (1 - w) * near.distance(v, r),
                       polar_angle(w, direction[p], [&] { return near.angle(v); })});
    ws.patch_uv.push_back({v, uv_of(entries.back(), w, direction[p])});
  }
  return entries;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_POLAR_COORDINATES_H
