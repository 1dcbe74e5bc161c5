// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_STAR_SOLVE_H
#define EXPMAP_INTERNAL_HEAT_STAR_SOLVE_H

// Step 6 (manual, section 2): the heat from the patch vertices read on the
// star of the source, by the symmetry of the heat matrix one solve from the
// star for all of them (the paper's step 3).

#include <expmap/Angle_estimator.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Star_gradient.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/heat/Query_workspace.h>
#include <expmap/internal/operators/Triangulation_adjacency.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

// The linear map from heat values on the star of s to their gradient at s,
// for the query's angle estimator.
inline Star_gradient source_star_gradient(const Context& c, int s, const Tangent_frame& frame) {
  const Angle_estimator estimator = c.estimator;
  if (estimator == Angle_estimator::log_heat_quadratic_fit ||
      estimator == Angle_estimator::heat_quadratic_fit) {
    // Fitted on the triangulation the heat lives on: after intrinsic
    // Delaunay flips the input one-ring may hold slivers whose far corners
    // the heat never diffused along. The linear fit costs two columns
    // whatever its stencil, so it takes the two-ring: its samples average
    // out the heat's vertex-to-vertex discretization noise on irregular
    // meshes.
    Star_gradient star;
    star.vertices = ring_neighborhood(c.factors.neighbors, s,
                                      estimator == Angle_estimator::heat_quadratic_fit ? 2 : 1);
    // Next to a boundary the stencil is one-sided, and the fitted
    // quadratic's gradient at its edge follows the coarse, long fans
    // boundaries often have; the one-ring's area-weighted gradient has no
    // lever arm.
    if (c.factors.touches_boundary(star.vertices)) return star_gradient(c.mesh, s, frame);
    if (auto fitted = quadratic_fit_star_gradient(c.mesh, std::move(star), frame)) return *fitted;
  }
  return star_gradient(c.mesh, s, frame);
}

// Columns of the star solve: the two rows of the gradient weights for an
// estimator linear in the heat, else one per star vertex.
inline std::size_t star_columns(const Context& c, const Star_gradient& star) {
  return is_linear_in_heat(c.estimator) ? 2 : star.vertices.size();
}

// Columns of the Dirichlet star solve: a linear estimator also needs the
// Dirichlet heat from s, which the Neumann solve reads from the source heat.
inline std::size_t boundary_star_columns(const Context& c, const Star_gradient& star) {
  return is_linear_in_heat(c.estimator) ? 3 : star.vertices.size();
}

// The right-hand side of a star solve of `width` columns.
inline void star_right_hand_side(const Context& c, const Star_gradient& star, std::size_t width,
                                 std::vector<Rhs_entry>& rhs) {
  rhs.clear();
  if (is_linear_in_heat(c.estimator)) {
    for (std::size_t k = 0; k < star.vertices.size(); ++k) {
      rhs.push_back({star.vertices[k], 0, star.along_e1[k]});
      rhs.push_back({star.vertices[k], 1, star.along_e2[k]});
    }
    if (width == 3) c.source.add_heat(rhs, 2);  // the heat from the source
  } else {
    for (std::size_t k = 0; k < width; ++k)
      rhs.push_back({star.vertices[k], static_cast<int>(k), 1.0});
  }
}

// How far below the guessed gradient the star solve prunes: the guess is
// rough, and a failed check costs a second solve (1: 0.96-0.98x the factor
// entries on elephant_loop2, but 1.25-1.65x for 1-5 of 30 sources).
constexpr double star_pruning_safety = 1e-3;

// The star solve's pruning threshold (0: none), from the source heat on
// `rows`: a neighbour's heat at v is within a small factor of the source's,
// and the gradient of the heat from v at s is about that heat over sqrt(t).
inline double star_heat_drop_below(const Context& c, const std::vector<int>& rows,
                                   const Workspace& ws) {
  if (!ws.prune) return 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const int v : rows)
    smallest = std::min(smallest, ws.region_heat[static_cast<std::size_t>(ws.in_region.value(v))]);
  const double scale =
      is_linear_in_heat(c.estimator) ? 1 / std::sqrt(c.factors.time_step) : 1.0;
  return c.pruning_tolerance * star_pruning_safety * smallest * scale;
}

// The smallest magnitude a star solve read: of the gradient (a vector) or
// of the heat.
inline double smallest_star_value(const Context& c, std::size_t width,
                                  const std::vector<double>& heat) {
  double smallest = std::numeric_limits<double>::infinity();
  if (is_linear_in_heat(c.estimator)) {
    for (std::size_t i = 0; i + width <= heat.size(); i += width)
      smallest = std::min(smallest, heat[i] * heat[i] + heat[i + 1] * heat[i + 1]);
    return std::sqrt(smallest);
  }
  for (const double h : heat) smallest = std::min(smallest, h);
  return smallest;
}

// Solves the heat from the star of s for `rows` (the patch's, or the whole
// region's beside the distance) into out.heat. Reads only ws's region and
// its source heat, so it may run beside integrate_distance.
inline Solve_statistics solve_star_heat(const Context& c, const Star_gradient& star,
                                        const std::vector<int>& rows, Star_solve& out,
                                        Localized_cholesky_solver::Workspace& solver,
                                        const Workspace& ws) {
  const std::size_t width = star_columns(c, star);
  star_right_hand_side(c, star, width, out.rhs);
  out.heat.resize(rows.size() * width);
  const Localized_cholesky_solver& heat = c.factors.heat;
  const double drop_below = star_heat_drop_below(c, rows, ws);
  Solve_statistics stats = heat.solve(out.rhs, static_cast<int>(width), rows.data(), rows.size(),
                                      out.heat.data(), solver, drop_below);
  if (drop_below == 0) return stats;
  // The gradient columns change sign, so pruning need not lower them: the
  // check is that every value read stays far above the threshold.
  if (drop_below > c.pruning_tolerance * smallest_star_value(c, width, out.heat))
    stats += heat.solve(out.rhs, static_cast<int>(width), rows.data(), rows.size(),
                        out.heat.data(), solver);
  return stats;
}

// On a surface with a boundary the heat solves carry the natural (Neumann)
// boundary condition, under which the heat from v is the free heat kernel
// plus its mirror image across the boundary (method of images). At a source
// on the boundary the image doubles the gradient's tangential part and
// cancels its normal part, so every direction read there collapses onto the
// boundary's tangent; near it, the image pulls the directions towards their
// mirror images. The heat with a zero (Dirichlet) boundary is the kernel
// minus its image: the sum of the two is twice the free kernel wherever the
// boundary is locally straight (Crane et al. 2013, section 3.3). This solve
// gives the Dirichlet half on the patch (ws.boundary_star), which the polar
// coordinates add to the Neumann star solve.
inline Solve_statistics solve_boundary_star_heat(const Context& c, const Star_gradient& star,
                                                 Workspace& ws) {
  // The boundary rows are identity: their entries would only copy
  // themselves into the boundary's heat, which is zero.
  const std::size_t width = boundary_star_columns(c, star);
  Star_solve& out = ws.boundary_star;
  star_right_hand_side(c, star, width, out.rhs);
  out.rhs.erase(std::remove_if(out.rhs.begin(), out.rhs.end(),
                               [&](const Rhs_entry& e) {
                                 return c.factors.is_boundary[static_cast<std::size_t>(e.row)] != 0;
                               }),
                out.rhs.end());
  out.heat.assign(ws.patch.size() * width, 0.0);
  if (out.rhs.empty()) return {};
  return c.factors.boundary_heat.solve(out.rhs, static_cast<int>(width), ws.patch.data(),
                                       ws.patch.size(), out.heat.data(), ws.boundary_heat_solve);
}

// A second thread starts (16 microseconds, up to 60) only for regions of at
// least this many vertices (500: 0.91-1.10x the time at 1%; the same maps).
constexpr std::size_t min_region_beside_distance = 1500;

// The region's star solve read at the patch's rows (`order`, into the
// region): fills ws.star.heat as the patch's own solve would.
inline void read_star_heat_on_patch(std::size_t width, const std::vector<std::size_t>& order,
                                    Workspace& ws) {
  ws.star.heat.resize(order.size() * width);
  for (std::size_t p = 0; p < order.size(); ++p)
    std::copy_n(ws.region_star.heat.data() + order[p] * width, width,
                ws.star.heat.data() + p * width);
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_STAR_SOLVE_H
