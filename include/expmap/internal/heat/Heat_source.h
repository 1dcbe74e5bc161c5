// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_HEAT_SOURCE_H
#define EXPMAP_INTERNAL_HEAT_HEAT_SOURCE_H

// The source of a heat query: a vertex, or a point of a face. The heat
// equation is linear, so the heat of a point is the barycentric combination
// of its corners' heat: a right-hand side of two or three entries instead
// of one, solved at the cost of one (doc/surface_points.md).

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include <array>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

struct Source {
  /// The vertex, or the point's corner of largest weight: the region is
  /// grown from it and it leads the region.
  int lead = -1;
  /// The vertex (count 1), or the point's corners of positive weight, the
  /// lead first.
  std::array<int, 3> corner{};
  std::array<double, 3> weight{};
  int count = 0;
  Vector3 position{};

  bool is_vertex() const { return count == 1; }

  /// Appends the unit heat of the source, as column `column`, to `rhs`;
  /// without the rows `skip` marks (a boundary's Dirichlet rows).
  template <class Skip>
  void add_heat(std::vector<Rhs_entry>& rhs, int column, const Skip& skip) const {
    for (int k = 0; k < count; ++k)
      if (!skip(corner[k])) rhs.push_back({corner[k], column, weight[k]});
  }
  void add_heat(std::vector<Rhs_entry>& rhs, int column) const {
    add_heat(rhs, column, [](int) { return false; });
  }
};

inline Source vertex_source(const Mesh_arrays& m, int s) {
  Source source;
  source.lead = s;
  source.corner[0] = s;
  source.weight[0] = 1.0;
  source.count = 1;
  source.position = m.point[s];
  return source;
}

inline Source point_source(const Point_source& p) {
  Source source;
  source.lead = p.nearest_corner();
  source.position = p.position;
  auto add = [&](int k) {
    source.corner[source.count] = p.corner[k];
    source.weight[source.count] = p.weight[k];
    ++source.count;
  };
  for (int k = 0; k < 3; ++k)
    if (p.corner[k] == source.lead) add(k);
  for (int k = 0; k < 3; ++k)
    if (p.corner[k] != source.lead && p.weight[k] > 0) add(k);
  return source;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_HEAT_SOURCE_H
