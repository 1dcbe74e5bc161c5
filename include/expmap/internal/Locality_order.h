// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_LOCALITY_ORDER_H
#define EXPMAP_INTERNAL_LOCALITY_ORDER_H

#include <expmap/internal/Mesh_arrays.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace expmap {
namespace internal {

/// The vertices of `m` along a Hilbert curve through their positions:
/// `order[i]` is the vertex placed i-th.
///
/// A query's patch is a geodesic disk; numbered this way, its vertices
/// occupy a few runs of consecutive indices instead of being scattered over
/// the whole index range as in a typical input file, so the per-vertex
/// arrays a query reads (neighbours, faces, marks) come in whole cache
/// lines. Deterministic (median splits, no random shuffle), so equal
/// meshes get equal orders.
inline std::vector<int> locality_order(const Mesh_arrays& m) {
  using Kernel = CGAL::Simple_cartesian<double>;
  std::vector<Kernel::Point_3> points;
  points.reserve(m.number_of_vertices());
  for (const Vector3& p : m.point) points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Traits = CGAL::Spatial_sort_traits_adapter_3<
      Kernel, typename CGAL::Pointer_property_map<Kernel::Point_3>::const_type>;
  const std::vector<Kernel::Point_3>& positions = points;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(positions)));
  std::vector<int> result(order.size());
  std::transform(order.begin(), order.end(), result.begin(),
                 [](std::size_t v) { return static_cast<int>(v); });
  return result;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_LOCALITY_ORDER_H
