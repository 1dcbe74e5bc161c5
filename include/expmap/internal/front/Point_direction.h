// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_POINT_DIRECTION_H
#define EXPMAP_INTERNAL_FRONT_POINT_DIRECTION_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Vector3.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace expmap {
namespace internal {

/// The native angle at the point `p` (the angle of `point_one_ring()`:
/// in the unfolding of the point's face into its plane, counter-clockwise
/// from the direction to the face's first corner) of a direction `d`
/// leaving the point along the surface. Inside the face, `d` is read in
/// the face's plane. For a point on an edge `d` may leave into either face
/// of the edge, and shortest paths may even report their first point
/// beyond it (CGAL's do): `d` is taken to the side of the edge whose face's
/// half-plane it is nearer to, and turned about the edge into the face's
/// plane, which keeps the angle it makes with the edge. So from either face
/// of an edge a direction gets native angles that differ by the same amount
/// as the two faces' ring angles.
inline double point_native_angle(const Mesh_arrays& m, const Point_source& p, const Vector3& d) {
  using P2 = std::array<double, 2>;
  const auto& c = p.corner;
  // The face's plane coordinates of point_one_ring().
  const Face_unfolding unfolded = unfold_face(m, p);
  const Vector3& ex = unfolded.ex;
  const Vector3& ey = unfolded.ey;
  const std::array<P2, 3>& q = unfolded.corner;
  const P2& s = unfolded.point;
  const double a0 = std::atan2(q[0][1] - s[1], q[0][0] - s[0]);

  P2 planar{{dot(d, ex), dot(d, ey)}};
  for (int k = 0; k < 3; ++k) {
    if (p.weight[(k + 2) % 3] != 0) continue;  // the point is on the edge (c[k], c[k+1])
    const int i = c[k], j = c[(k + 1) % 3];
    int apex = -1;
    for (int f = m.vertex_face_start[i]; f < m.vertex_face_start[i + 1]; ++f) {
      const auto& h = m.face[m.vertex_face[f]];
      if (m.vertex_face[f] == p.face || std::find(h.begin(), h.end(), j) == h.end()) continue;
      for (int x : h)
        if (x != i && x != j) apex = x;
    }
    if (apex < 0) break;  // a boundary edge: the face is the only side
    const Vector3 t = (1.0 / norm(m.point[j] - m.point[i])) * (m.point[j] - m.point[i]);
    // The unit vectors in each face's plane orthogonal to the edge,
    // pointing into the face.
    auto inward = [&](int corner) {
      const Vector3 w = m.point[corner] - m.point[i];
      const Vector3 across = w - dot(w, t) * t;
      return (1.0 / norm(across)) * across;
    };
    const double along = dot(d, t);
    const double across = norm(d - along * t);
    const double side = dot(d, inward(c[(k + 2) % 3])) >= dot(d, inward(apex)) ? 1.0 : -1.0;
    const P2 t2{{dot(t, ex), dot(t, ey)}};
    const P2 in2{{-t2[1], t2[0]}};  // the face is on the left of its edges
    planar = {{along * t2[0] + side * across * in2[0], along * t2[1] + side * across * in2[1]}};
    break;
  }
  return one_ring_detail::ccw(a0, std::atan2(planar[1], planar[0]));
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_POINT_DIRECTION_H
