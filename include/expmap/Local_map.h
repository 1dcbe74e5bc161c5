// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_LOCAL_MAP_H
#define EXPMAP_LOCAL_MAP_H

/// \file Local_map.h
/// The result of one exponential-map query, the same for every method.

#include <expmap/Solve_statistics.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Geodesic polar coordinates around a source vertex for the vertices of a
/// patch, nearest first (the source itself comes first, at distance 0).
///
/// Angles are in radians in (-pi, pi], measured in the source's tangent
/// plane from the reference direction, counter-clockwise about the outward
/// normal. `u = r cos(theta)`, `v = r sin(theta)`.
template <class VertexDescriptor>
struct Local_map {
  VertexDescriptor source{};               ///< the source vertex
  std::vector<VertexDescriptor> vertices;  ///< patch vertices, nearest first
  std::vector<std::size_t> indices;        ///< their indices in `vertices(tm)`
  std::vector<double> distance;            ///< geodesic distance r
  std::vector<double> angle;               ///< polar angle theta
  std::array<double, 3> normal{};          ///< unit normal of the tangent plane
  std::array<double, 3> axis_u{};          ///< unit tangent axis of angle 0
  std::array<double, 3> axis_v{};          ///< unit tangent axis of angle pi/2
  Solve_statistics statistics;             ///< work of the localized solves (heat method)
  /// Where the map is one-to-one: the largest r such that no patch triangle
  /// with every corner nearer than r to the source is flipped or collapsed
  /// in (u, v) (`is_flipped()`). That is the smallest, over the flipped
  /// triangles, of their farthest corner's distance, or the largest distance
  /// in the map if none is flipped. Set when the query asked for it
  /// (`Query_options::find_fold_free_radius` or `trim_folds`, which cuts
  /// the map to that disk; the pass costs about a tenth of a query), else
  /// empty: `expmap::fold_free_radius(tm, map)` finds it afterwards.
  std::optional<double> fold_free_radius;

  /// Number of patch vertices (the source included).
  std::size_t size() const { return vertices.size(); }
  /// Cartesian coordinates (u, v) of the i-th patch vertex.
  std::array<double, 2> uv(std::size_t i) const {
    return {{distance[i] * std::cos(angle[i]), distance[i] * std::sin(angle[i])}};
  }
};

/// \ingroup PkgExpmapRef
/// Writes a local map into property maps keyed by vertex descriptor:
/// distances, angles, and (u, v) as any type constructible from two doubles
/// (e.g. `Point_2`, `std::array<double,2>` via braces).
/// Vertices outside the patch are left untouched.
template <class VertexDescriptor, class DistanceMap, class AngleMap, class UVMap>
void write_to_property_maps(const Local_map<VertexDescriptor>& map, DistanceMap distance_map,
                            AngleMap angle_map, UVMap uv_map) {
  using UV = typename boost::property_traits<UVMap>::value_type;
  for (std::size_t i = 0; i < map.size(); ++i) {
    put(distance_map, map.vertices[i], map.distance[i]);
    put(angle_map, map.vertices[i], map.angle[i]);
    const auto uv = map.uv(i);
    put(uv_map, map.vertices[i], UV{uv[0], uv[1]});
  }
}

}  // namespace expmap

#endif  // EXPMAP_LOCAL_MAP_H
