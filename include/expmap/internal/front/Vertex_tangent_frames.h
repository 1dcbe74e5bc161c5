// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_VERTEX_TANGENT_FRAMES_H
#define EXPMAP_INTERNAL_FRONT_VERTEX_TANGENT_FRAMES_H

#include <expmap/Errors.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>

#include <array>
#include <cmath>
#include <vector>

namespace expmap {
namespace internal {

/// One tangent frame per vertex, orthogonal to its normal (the normal of
/// `vertex_normal()`, so the frame at a source agrees with the frame of
/// `tangent_frame()` up to a turn about the normal). The first axis is
/// arbitrary (DEM needs a frame, not a particular one); the second is
/// `normal x e1`.
struct Vertex_tangent_frames {
  std::vector<Vector3> normal, e1;

  Vector3 e2(int v) const { return cross(normal[v], e1[v]); }

  /// Coordinates, in the frame of `v`, of the edge vector `w` leaving `v`:
  /// its projection onto the tangent plane, stretched back to |w| so that
  /// the map keeps edge lengths (Schmidt et al. 2006).
  std::array<double, 2> local_edge(int v, const Vector3& w) const;
};

/// Coordinates of `w` in the tangent axes (a1, a2), stretched so that the
/// 2D vector is as long as `w` (zero if `w` is along the normal).
inline std::array<double, 2> stretched_coordinates(const Vector3& w, const Vector3& a1,
                                                   const Vector3& a2) {
  const double x = dot(w, a1), y = dot(w, a2);
  const double projected = std::sqrt(x * x + y * y);
  if (!(projected > 0)) return {{0.0, 0.0}};
  const double stretch = norm(w) / projected;
  return {{stretch * x, stretch * y}};
}

inline std::array<double, 2> Vertex_tangent_frames::local_edge(int v, const Vector3& w) const {
  return stretched_coordinates(w, e1[v], e2(v));
}

/// Unit vector orthogonal to the unit vector `n`: the world axis least
/// aligned with `n`, projected.
inline Vector3 any_orthogonal(const Vector3& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[axis])) axis = k;
  Vector3 a{{0, 0, 0}};
  a[axis] = 1;
  const Vector3 t = a - dot(a, n) * n;
  return (1.0 / norm(t)) * t;
}

/// Frames of every non-isolated vertex. A vertex whose faces cancel out
/// (no normal in the sense of `vertex_normal()`) gets the normal of its
/// first face instead of failing the whole mesh: only queries that reach it
/// see the difference.
inline Vertex_tangent_frames vertex_tangent_frames(const Mesh_arrays& m) {
  Vertex_tangent_frames frames;
  const std::size_t n = m.number_of_vertices();
  frames.normal.assign(n, Vector3{{0, 0, 1}});
  frames.e1.assign(n, Vector3{{1, 0, 0}});
  for (std::size_t i = 0; i < n; ++i) {
    const int v = static_cast<int>(i);
    if (m.is_isolated(v)) continue;
    Vector3 normal;
    try {
      normal = vertex_normal(m, v);
    } catch (const Invalid_input&) {
      const auto& f = m.face[m.vertex_face[m.vertex_face_start[v]]];
      const Vector3 a = cross(m.point[f[1]] - m.point[f[0]], m.point[f[2]] - m.point[f[0]]);
      normal = (1.0 / norm(a)) * a;
    }
    frames.normal[i] = normal;
    frames.e1[i] = any_orthogonal(normal);
  }
  return frames;
}

/// The turn (cos, sin) that takes coordinates in the frame (n_p, a1) of a
/// vertex to coordinates in the source frame `s`: the frame is carried
/// onto the source's tangent plane by the minimal rotation taking n_p onto
/// s.normal (on a sphere, parallel transport along the great circle), and
/// the angle of its first axis is read in (s.e1, s.e2).
inline std::array<double, 2> frame_rotation(const Vector3& n_p, const Vector3& a1,
                                            const Tangent_frame& s) {
  const double c = dot(n_p, s.normal);
  Vector3 r1;
  if (c > -1 + 1e-12) {
    // Rodrigues' formula for the minimal rotation, v = n_p x n_s.
    const Vector3 v = cross(n_p, s.normal);
    r1 = c * a1 + cross(v, a1) + (dot(v, a1) / (1 + c)) * v;
  } else {
    // Opposite normals: any half turn will do; the one about a1 keeps it.
    r1 = a1;
  }
  const double x = dot(r1, s.e1), y = dot(r1, s.e2);
  const double length = std::hypot(x, y);
  if (!(length > 0)) return {{1.0, 0.0}};
  return {{x / length, y / length}};
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_VERTEX_TANGENT_FRAMES_H
