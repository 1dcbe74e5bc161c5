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

/// The positions of `points` along a Hilbert curve through them:
/// `order[i]` is the point placed i-th. Deterministic (median splits, no
/// random shuffle), so equal inputs get equal orders.
inline std::vector<std::size_t> hilbert_order(const std::vector<Vector3>& points) {
  using Kernel = CGAL::Simple_cartesian<double>;
  std::vector<Kernel::Point_3> positions;
  positions.reserve(points.size());
  for (const Vector3& p : points) positions.emplace_back(p[0], p[1], p[2]);
  std::vector<std::size_t> order(positions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Traits = CGAL::Spatial_sort_traits_adapter_3<
      Kernel, typename CGAL::Pointer_property_map<Kernel::Point_3>::const_type>;
  const std::vector<Kernel::Point_3>& view = positions;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(view)));
  return order;
}

/// The order of `vertices` (indices in the user's mesh, as `Mesh_arrays::
/// from_original()` takes them) along a Hilbert curve through their
/// positions in `m`, for a batch (`run_batch`); an index out of range
/// (whose query fails) goes anywhere.
inline std::vector<std::size_t> hilbert_order(const Mesh_arrays& m,
                                              const std::vector<std::size_t>& vertices) {
  std::vector<Vector3> points(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (vertices[i] < m.number_of_vertices())
      points[i] = m.point[static_cast<std::size_t>(m.from_original(vertices[i]))];
  return hilbert_order(points);
}

/// The vertices of `m` along a Hilbert curve through their positions
/// (`hilbert_order`): `order[i]` is the vertex placed i-th.
///
/// A query's patch is a geodesic disk; numbered this way, its vertices
/// occupy a few runs of consecutive indices instead of being scattered over
/// the whole index range as in a typical input file, so the per-vertex
/// arrays a query reads (neighbours, faces, marks) come in whole cache
/// lines.
inline std::vector<int> locality_order(const Mesh_arrays& m) {
  const std::vector<std::size_t> order = hilbert_order(m.point);
  std::vector<int> result(order.size());
  std::transform(order.begin(), order.end(), result.begin(),
                 [](std::size_t v) { return static_cast<int>(v); });
  return result;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_LOCALITY_ORDER_H
