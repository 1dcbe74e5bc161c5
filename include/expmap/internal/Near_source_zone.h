// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_NEAR_SOURCE_ZONE_H
#define EXPMAP_INTERNAL_NEAR_SOURCE_ZONE_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/operators/Triangulation_adjacency.h>

#include <cmath>
#include <vector>

namespace expmap {
namespace internal {

/// Where one query's coordinates turn from geometric into heat values:
/// geometric up to distance `begin`, heat from `end` on, a cubic
/// smoothstep in the distance between.
struct Near_source_zone {
  double begin = 0, end = 0;

  /// The weight of the heat's coordinates at distance r.
  double heat_weight(double r) const {
    if (r >= end) return 1.0;
    if (r <= begin) return 0.0;
    const double x = (r - begin) / (end - begin);
    return x * x * (3 - 2 * x);
  }
};

/// How fast the surface normal turns around s, in radians per unit length:
/// the root mean square, over the vertices v within two edges of s, of the
/// angle between the vertex normals at s and v divided by |p_v - p_s|.
/// 1 / R on a sphere of radius R; on a general surface about the larger
/// principal curvature. `normal_at_s` is the vertex normal of s.
inline double normal_turn_rate(const Mesh_arrays& m, int s, const Vector3& normal_at_s) {
  const std::vector<int> ring = ring_neighborhood(m.neighbor_start, m.neighbor, s, 2);
  double sum = 0;
  int count = 0;
  for (std::size_t c = 1; c < ring.size(); ++c) {
    const double distance = norm(m.point[ring[c]] - m.point[s]);
    if (!(distance > 0)) continue;
    // atan2 of sine and cosine: accurate for small angles, where acos is not.
    const Vector3 n = vertex_normal(m, ring[c]);
    const double rate = std::atan2(norm(cross(n, normal_at_s)), dot(n, normal_at_s)) / distance;
    sum += rate * rate;
    ++count;
  }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_NEAR_SOURCE_ZONE_H
