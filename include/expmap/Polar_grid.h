// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_POLAR_GRID_H
#define EXPMAP_POLAR_GRID_H

/// \file Polar_grid.h
/// The polar grid a patch of a geodesic convolutional network is sampled
/// on (`polar_patch_operator()`).

#include <expmap/Errors.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace expmap {

/// \ingroup PkgExpmapRef
/// The points a patch is sampled at: `rings` x `rays` points of the
/// source's (u, v) plane at radii rho_i = (i + 1/2) radius / rings and
/// angles theta_j = 2 pi j / rays (theta = 0 along the map's reference
/// direction, `Query_options::reference_direction`).
struct Polar_grid {
  double radius = 0;       ///< R, in mesh units
  std::size_t rings = 5;   ///< points along each ray
  std::size_t rays = 16;   ///< points around each ring

  /// rho_i.
  double ring_radius(std::size_t i) const { return (double(i) + 0.5) * radius / double(rings); }
  /// theta_j.
  double ray_angle(std::size_t j) const {
    return 2 * 3.14159265358979323846 * double(j) / double(rays);
  }
  /// The grid point (i, j) in the (u, v) plane.
  std::array<double, 2> point(std::size_t i, std::size_t j) const {
    return {{ring_radius(i) * std::cos(ray_angle(j)), ring_radius(i) * std::sin(ray_angle(j))}};
  }
};

/// \ingroup PkgExpmapRef
/// `grid` if it can be sampled.
/// \throws Invalid_input for a radius that is not positive and finite, no
///         rings or rays, or more than 2^20 points per patch.
inline const Polar_grid& checked(const Polar_grid& grid) {
  if (!(grid.radius > 0) || !std::isfinite(grid.radius))
    throw Invalid_input("the polar grid's radius must be positive and finite (got " +
                        std::to_string(grid.radius) + ")");
  if (grid.rings == 0 || grid.rays == 0)
    throw Invalid_input("the polar grid needs at least one ring and one ray (got " +
                        std::to_string(grid.rings) + " x " + std::to_string(grid.rays) + ")");
  if (grid.rings > (std::size_t(1) << 20) / grid.rays)
    throw Invalid_input("the polar grid has more than 2^20 points (" +
                        std::to_string(grid.rings) + " x " + std::to_string(grid.rays) + ")");
  return grid;
}

}  // namespace expmap

#endif  // EXPMAP_POLAR_GRID_H
