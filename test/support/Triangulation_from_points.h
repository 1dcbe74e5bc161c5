// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Intrinsic triangulations built directly from points and faces, for tests
// of the operators that take one (no mesh, no reordering of the vertices).
#ifndef EXPMAP_TEST_TRIANGULATION_FROM_POINTS_H
#define EXPMAP_TEST_TRIANGULATION_FROM_POINTS_H

#include <expmap/internal/operators/Intrinsic_triangulation.h>

#include <array>
#include <cmath>
#include <vector>

namespace expmap_test {

/// The triangulation of `faces` with the Euclidean lengths of their edges
/// (length[f][k] from corner k to corner k + 1).
inline expmap::internal::Intrinsic_triangulation make_triangulation(
    const std::vector<std::array<double, 3>>& points,
    const std::vector<std::array<int, 3>>& faces) {
  expmap::internal::Intrinsic_triangulation tri;
  tri.number_of_vertices = points.size();
  tri.face = faces;
  for (const auto& f : faces) {
    std::array<double, 3> l{};
    for (int k = 0; k < 3; ++k) {
      const auto& a = points[f[k]];
      const auto& b = points[f[(k + 1) % 3]];
      l[k] = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                       (a[2] - b[2]) * (a[2] - b[2]));
    }
    tri.length.push_back(l);
  }
  return tri;
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_TRIANGULATION_FROM_POINTS_H
