// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_POINT_CORNERS_H
#define EXPMAP_INTERNAL_HEAT_POINT_CORNERS_H

// What a point source takes from its corners (doc/surface_points.md): the
// gradient stencil the angles are read with (step 6) and the geometric
// coordinates next to the source (step 7) are the corners' own, turned into
// the point's frame and weighted like the point's heat. So they move
// continuously with the point, across edges too (a corner of weight zero
// drops out), and at a corner they are that vertex's.

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Near_source_zone.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Star_gradient.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/heat/Heat_source.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <unordered_map>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

/// A corner of a point source: its vertex frame and ring, and the linear
/// map from its frame's tangent coordinates into the point's (the minimal
/// rotation of its normal onto the point's, then the point's axes).
struct Point_corner {
  int vertex;
  double weight;
  Tangent_frame frame;
  Source_one_ring ring;
  std::array<std::array<double, 2>, 2> into_point;  // row: point axis, column: corner axis
  /// The angle of the point's e1 in the corner's native angles, relative to
  /// the corner's e1: the turn from the corner's angles to the point's.
  double turn;
  Near_source_zone zone;
};

// The minimal rotation taking unit vector a onto unit vector b, applied to t.
inline Vector3 rotate_onto(const Vector3& a, const Vector3& b, const Vector3& t) {
  const Vector3 axis = cross(a, b);
  const double c = dot(a, b);
  if (!(1 + c > 1e-12)) return (-1.0) * t;  // opposite normals: a half turn
  return t + cross(axis, t) + (1.0 / (1 + c)) * cross(axis, cross(axis, t));
}

/// The corners of `source`, with the frames `tangent_frame()` gives
/// vertices (for `reference`) and the near-source zones
/// `zone_at(vertex, normal)` gives them.
template <class ZoneAt>
std::vector<Point_corner> point_corners(const Mesh_arrays& m, const Source& source,
                                        const Tangent_frame& frame,
                                        const std::optional<Vector3>& reference,
                                        const ZoneAt& zone_at) {
  std::vector<Point_corner> corners;
  for (int k = 0; k < source.count; ++k) {
    Point_corner corner;
    corner.vertex = source.corner[k];
    corner.weight = source.weight[k];
    corner.frame = tangent_frame(m, corner.vertex, reference);
    corner.ring = source_one_ring(m, corner.vertex, corner.frame);
    const Vector3 axes[2] = {corner.frame.e1, corner.frame.e2};
    for (int j = 0; j < 2; ++j) {
      const Vector3 turned = rotate_onto(corner.frame.normal, frame.normal, axes[j]);
      corner.into_point[0][j] = dot(turned, frame.e1);
      corner.into_point[1][j] = dot(turned, frame.e2);
    }
    corner.turn = corner.ring.native_angle(corner.frame.angle_of(frame.e1)) -
                  corner.ring.reference_angle;
    corner.zone = zone_at(corner.vertex, corner.frame.normal);
    corners.push_back(std::move(corner));
  }
  return corners;
}

/// The corners' zones, weighted.
inline Near_source_zone point_zone(const std::vector<Point_corner>& corners) {
  Near_source_zone zone{0, 0};
  for (const Point_corner& corner : corners) {
    zone.begin += corner.weight * corner.zone.begin;
    zone.end += corner.weight * corner.zone.end;
  }
  return zone;
}

/// The gradient at the point of a function known on the corners' stencils:
/// the corners' gradients (`corner_star(vertex, frame)`), turned into the
/// point's frame and weighted. Exact for quadratic functions on a plane
/// (the weights are barycentric: the corners' gradients of a quadratic
/// average to its gradient at the point). The leaks are measured around
/// the point.
template <class CornerStar>
Star_gradient point_star_gradient(const Mesh_arrays& m, const Source& source,
                                  const Tangent_frame& frame,
                                  const std::vector<Point_corner>& corners,
                                  const CornerStar& corner_star) {
  Star_gradient star;
  std::unordered_map<int, std::size_t> column;
  for (const Point_corner& corner : corners) {
    const Star_gradient own = corner_star(corner.vertex, corner.frame);
    const auto& a = corner.into_point;
    for (std::size_t k = 0; k < own.vertices.size(); ++k) {
      const auto inserted = column.emplace(own.vertices[k], star.vertices.size());
      if (inserted.second) {
        star.vertices.push_back(own.vertices[k]);
        star.along_e1.push_back(0.0);
        star.along_e2.push_back(0.0);
      }
      const std::size_t c = inserted.first->second;
      star.along_e1[c] += corner.weight * (a[0][0] * own.along_e1[k] + a[0][1] * own.along_e2[k]);
      star.along_e2[c] += corner.weight * (a[1][0] * own.along_e1[k] + a[1][1] * own.along_e2[k]);
    }
  }
  std::vector<std::array<double, 2>> position(star.vertices.size());
  for (std::size_t c = 0; c < star.vertices.size(); ++c) {
    const Vector3 d = m.point[star.vertices[c]] - source.position;
    const double x = dot(d, frame.e1), y = dot(d, frame.e2);
    const double projected = std::hypot(x, y);
    if (!(projected > 0)) return star;  // no leaks known
    const double length = norm(d);
    position[c] = {{x * length / projected, y * length / projected}};
  }
  measure_leaks(star, position);
  return star;
}

/// Geometric polar coordinates next to a point source.
///
/// Corner i sees v at the chord from the point, carried into its native
/// angles like `near_source_angle()` does from a vertex, less its turn;
/// the directions are averaged as unit vectors with the corners' weights.
/// The chord |p_v - x| is the distance of v in the share of the weight of
/// the corners whose closed star holds v (from a vertex: its neighbours
/// take their edge's length), the heat distance `r` in the rest.
struct Point_near_source {
  const Mesh_arrays& mesh;
  const Source& source;
  const std::vector<Point_corner>& corners;

  double distance(int v, double r) const {
    double share = 0;
    for (const Point_corner& corner : corners)
      if (v == corner.vertex || corner.ring.position(v) >= 0) share += corner.weight;
    if (share == 0) return r;
    return share * norm(mesh.point[v] - source.position) + (1 - share) * r;
  }

  double angle(int v) const {
    const Vector3 d = mesh.point[v] - source.position;
    double x = 0, y = 0;
    for (const Point_corner& corner : corners) {
      const double native = corner.ring.native_angle(corner.frame.angle_of(d));
      const double theta = native - corner.ring.reference_angle - corner.turn;
      x += corner.weight * std::cos(theta);
      y += corner.weight * std::sin(theta);
    }
    return std::atan2(y, x);
  }
};

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_POINT_CORNERS_H
