// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_POINT_SOURCE_H
#define EXPMAP_INTERNAL_POINT_SOURCE_H

#include <expmap/Errors.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace expmap {
namespace internal {

/// A `Surface_point` resolved against the stored mesh.
struct Point_source {
  int face = -1;                 // position in `Mesh_arrays::face`
  std::array<int, 3> corner{};   // stored indices, in the order of that face
  std::array<double, 3> weight{};  // barycentric coordinates of the corners, sum 1
  Vector3 position{};
  int vertex = -1;               // the stored corner if the point is one, else -1
  std::size_t user_face = 0;     // the face index, for messages

  /// The corner of largest weight (the first of equals).
  int nearest_corner() const {
    const int k = static_cast<int>(std::max_element(weight.begin(), weight.end()) - weight.begin());
    return corner[k];
  }
};

/// Checks and normalizes the coordinates `w` of a point of the face of
/// index `user_face`, and finds the face among the stored ones. The
/// coordinates follow the user's order of the corners (`Surface_point`'s),
/// a rotation of the stored one: listed from its smallest user's index on,
/// the user's first corner is the `face_rotation[user_face]`-th.
/// \throws Invalid_input for a face out of range or bad coordinates.
inline Point_source resolve_point_source(const Mesh_arrays& m, const std::vector<int>& face_of_index,
                                         const std::vector<std::uint8_t>& face_rotation,
                                         std::size_t user_face, const std::array<double, 3>& w) {
  if (user_face >= face_of_index.size() || face_of_index[user_face] < 0)
    throw Invalid_input("source face " + std::to_string(user_face) + " is out of range (the mesh has " +
                        std::to_string(face_of_index.size()) + " faces)");
  double sum = 0;
  for (double x : w) {
    // A location computed in floating point may be a rounding below zero.
    if (!std::isfinite(x) || x < -1e-12)
      throw Invalid_input("the barycentric coordinates of the source point in face " +
                          std::to_string(user_face) + " are not finite or negative");
    sum += std::max(0.0, x);
  }
  if (!(sum > 0) || !std::isfinite(sum))
    throw Invalid_input("the barycentric coordinates of the source point in face " +
                        std::to_string(user_face) + (sum > 0 ? " are too large to sum" : " sum to zero"));
  Point_source p;
  p.user_face = user_face;
  p.face = face_of_index[user_face];
  p.corner = m.face[p.face];
  int smallest = 0;
  for (int k = 1; k < 3; ++k)
    if (m.to_original(p.corner[k]) < m.to_original(p.corner[smallest])) smallest = k;
  for (int k = 0; k < 3; ++k)
    p.weight[(smallest + face_rotation[user_face] + k) % 3] = std::max(0.0, w[k]) / sum;
  p.position = Vector3{{0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    p.position += p.weight[k] * m.point[p.corner[k]];
    if (p.weight[k] == 1.0) p.vertex = p.corner[k];
  }
  return p;
}

/// The tangent frame at a point: the normal is the barycentric combination
/// of the corners' `vertex_normal()`s, normalized (so it turns continuously
/// as the point moves over the surface, across edges included, and is the
/// vertex's normal at a vertex); where that combination vanishes, the
/// face's normal. e1 and e2 as in `tangent_frame()`.
/// \throws Invalid_input if `reference` is (nearly) parallel to the normal.
inline Tangent_frame point_tangent_frame(const Mesh_arrays& m, const Point_source& p,
                                         const std::optional<Vector3>& reference) {
  Vector3 n{{0, 0, 0}};
  for (int k = 0; k < 3; ++k)
    if (p.weight[k] > 0) n += p.weight[k] * vertex_normal(m, p.corner[k]);
  if (!(norm(n) > 1e-6)) {
    const auto& c = p.corner;
    n = cross(m.point[c[1]] - m.point[c[0]], m.point[c[2]] - m.point[c[0]]);
  }
  return frame_from_normal((1.0 / norm(n)) * n, reference,
                           "the source point in face " + std::to_string(p.user_face));
}

/// A point's face laid into its plane: corner 0 at the origin, corner 1 on
/// the x axis (along `ex`), corner 2 above it (`ey` the plane's y axis).
struct Face_unfolding {
  Vector3 ex, ey;
  std::array<std::array<double, 2>, 3> corner;
  std::array<double, 2> point;
};

inline Face_unfolding unfold_face(const Mesh_arrays& m, const Point_source& p) {
  const auto& c = p.corner;
  const Vector3 ab = m.point[c[1]] - m.point[c[0]], ac = m.point[c[2]] - m.point[c[0]];
  const double lab = norm(ab);
  Face_unfolding u;
  u.ex = (1.0 / lab) * ab;
  const double cx = dot(ac, u.ex);
  const Vector3 up = ac - cx * u.ex;
  const double cy = norm(up);
  u.ey = (1.0 / cy) * up;
  u.corner = {{{{0, 0}}, {{lab, 0}}, {{cx, cy}}}};
  u.point = {{p.weight[1] * u.corner[1][0] + p.weight[2] * u.corner[2][0],
              p.weight[2] * u.corner[2][1]}};
  return u;
}

/// The vertices around a point source whose distances and native angles
/// are exact in the unfolding of the face into its plane: the three
/// corners, and the apex of each neighbouring face (across a manifold
/// edge) whose straight segment from the point crosses that edge (so the
/// segment lies in the two faces, and is the geodesic through them).
/// Native angles are the unfolded plane's angles at the point, counted
/// counter-clockwise from the face's first corner; they sum to 2 pi, so
/// the ring is closed and needs no rescaling. With the apexes a point on an
/// edge sees both faces of the edge, whose directions would otherwise lie
/// in one wedge of pi.
///
/// The native angle of e1 (`Source_one_ring::reference_angle`) is
/// interpolated from the corners' projections (on an edge, and the apex
/// across it): then it is the same from both faces of an edge. It jumps by
/// the curvature's distortion of a wedge (about 1e-6 rad on a 10k-vertex
/// unit sphere) when the point reaches an edge from inside a face.
struct Point_ring {
  Source_one_ring ring;
  std::vector<double> distance;  // of each ring vertex from the point
  /// Whether each ring vertex is in the ring whichever face names the
  /// point: the corners, and for a point on an edge the apex across it.
  std::vector<bool> face_independent;
};

inline Point_ring point_one_ring(const Mesh_arrays& m, const Point_source& p,
                                 const Tangent_frame& frame) {
  using P2 = std::array<double, 2>;
  const auto& c = p.corner;
  const Face_unfolding unfolded = unfold_face(m, p);
  const std::array<P2, 3>& q = unfolded.corner;
  const P2& s = unfolded.point;

  struct Entry {
    int vertex;
    double native, distance;
    bool reference;  // locates e1 (see below)
  };
  std::vector<Entry> entries;
  const double a0 = std::atan2(q[0][1] - s[1], q[0][0] - s[0]);
  auto add = [&](int v, const P2& x, bool reference) {
    const double dx = x[0] - s[0], dy = x[1] - s[1];
    entries.push_back(
        {v, one_ring_detail::ccw(a0, std::atan2(dy, dx)), std::hypot(dx, dy), reference});
  };
  for (int k = 0; k < 3; ++k) add(c[k], q[k], true);
  entries[0].native = 0;  // exactly, whatever the rounding of atan2
  for (int k = 0; k < 3; ++k) {
    const int i = c[k], j = c[(k + 1) % 3];
    int apex = -1, faces = 0;
    for (int f = m.vertex_face_start[i]; f < m.vertex_face_start[i + 1]; ++f) {
      const int g = m.vertex_face[f];
      const auto& h = m.face[g];
      if (g == p.face || std::find(h.begin(), h.end(), j) == h.end()) continue;
      ++faces;
      for (int x : h)
        if (x != i && x != j) apex = x;
    }
    if (faces != 1 || std::find(c.begin(), c.end(), apex) != c.end()) continue;
    // The apex unfolded across the edge (i, j), on its right: the face is
    // counter-clockwise, so its inside is on the left.
    const P2& qi = q[k];
    const P2& qj = q[(k + 1) % 3];
    const double e = std::hypot(qj[0] - qi[0], qj[1] - qi[1]);
    const P2 t{{(qj[0] - qi[0]) / e, (qj[1] - qi[1]) / e}};
    const double di = norm(m.point[apex] - m.point[i]), dj = norm(m.point[apex] - m.point[j]);
    const double along = (di * di - dj * dj + e * e) / (2 * e);
    const double across = -std::sqrt(std::max(0.0, di * di - along * along));
    const P2 x{{qi[0] + along * t[0] - across * t[1], qi[1] + along * t[1] + across * t[0]}};
    // Where the segment from the point to the apex crosses the edge's line.
    const double side = t[0] * (s[1] - qi[1]) - t[1] * (s[0] - qi[0]);  // >= 0
    if (!(across < 0)) continue;
    const double f = std::max(0.0, side) / (std::max(0.0, side) - across);
    const P2 cross_at{{s[0] + f * (x[0] - s[0]), s[1] + f * (x[1] - s[1])}};
    const double u = (cross_at[0] - qi[0]) * t[0] + (cross_at[1] - qi[1]) * t[1];
    if (u > 0 && u < e) add(apex, x, p.weight[(k + 2) % 3] == 0);
  }
  std::sort(entries.begin() + 1, entries.end(),
            [](const Entry& x, const Entry& y) { return x.native < y.native; });

  Point_ring out;
  Source_one_ring& ring = out.ring;
  ring.closed = true;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    ring.vertex.push_back(entries[i].vertex);
    ring.angle.push_back(entries[i].native);
    out.distance.push_back(entries[i].distance);
    out.face_independent.push_back(entries[i].reference);
    const double next = i + 1 < entries.size() ? entries[i + 1].native : 2 * M_PI;
    ring.wedge_angle.push_back(next - entries[i].native);
    ring.projected.push_back(frame.angle_of(m.point[entries[i].vertex] - p.position));
  }
  // e1 is located among the corners, and on an edge also the apex across
  // it: the same vertices whichever of the edge's faces names the point,
  // so both give the same map. (The other apexes would move e1's native
  // angle by the curvature's distortion of their wedges.)
  Source_one_ring locator;
  locator.closed = true;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (!entries[i].reference) continue;
    locator.vertex.push_back(entries[i].vertex);
    locator.angle.push_back(entries[i].native);
    locator.projected.push_back(ring.projected[i]);
  }
  for (std::size_t i = 0; i < locator.angle.size(); ++i)
    locator.wedge_angle.push_back(
        (i + 1 < locator.angle.size() ? locator.angle[i + 1] : 2 * M_PI) - locator.angle[i]);
  ring.reference_angle = locator.native_angle(0.0);
  return out;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_POINT_SOURCE_H
