// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOURCE_ONE_RING_H
#define EXPMAP_INTERNAL_SOURCE_ONE_RING_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace expmap {
namespace internal {

/// The neighbours of a DGPC source in counter-clockwise order (the order of
/// the faces' corners) with their "native" polar angles: the corner angles
/// at the source summed from the first neighbour. Around an interior source
/// the sum is rescaled to 2 pi (Melvaer & Reimers), so angles wrap modulo
/// 2 pi. Around a boundary source the fan starts at a boundary neighbour and
/// angles are the plain corner sums, in [0, total angle], never wrapped: no
/// geodesic crosses the missing wedge, and rescaling would spread the
/// surface's angles over directions that do not exist.
struct Source_one_ring {
  std::vector<int> vertex;
  std::vector<double> angle;
  bool closed = false;
  /// The native angle of the tangent frame's first axis e1: native angles
  /// minus this value are angles in the frame of `tangent_frame()`.
  double reference_angle = 0;
  /// Each neighbour's direction projected onto the tangent plane, as an
  /// angle in the frame.
  std::vector<double> projected;
  /// The corner angle at the source after each neighbour (0 after the end
  /// of an open chain).
  std::vector<double> wedge_angle;

  /// The native angle of a direction whose projection onto the tangent
  /// plane has angle `projected_angle` in the frame: the wedge (pair of
  /// consecutive neighbours) whose projection contains it is found, and the
  /// angle is interpolated linearly into the wedge's native angles. On a
  /// plane native and projected angles agree, so the conversion is exact
  /// there. Beyond the last neighbour of a boundary source the projected
  /// angle is extrapolated from it; where every wedge around the direction
  /// folds over in projection, the nearest neighbour's offset is used.
  double native_angle(double projected_angle) const;

  /// The position of `v` among the neighbours, or -1 if it is not one.
  int position(int v) const {
    const auto it = std::find(vertex.begin(), vertex.end(), v);
    return it == vertex.end() ? -1 : static_cast<int>(it - vertex.begin());
  }
};

namespace one_ring_detail {

// Counter-clockwise angle from a to b, in [0, 2 pi).
inline double ccw(double a, double b) {
  double d = std::fmod(b - a, 2 * M_PI);
  if (d < 0) d += 2 * M_PI;
  return d;
}

}  // namespace one_ring_detail

/// Orders the one-ring of `s` and computes its native angles, and the
/// native angle of `frame.e1`: the wedge (pair of consecutive neighbours)
/// whose projection onto the tangent plane contains e1 is found, and e1's
/// projected angle is interpolated linearly into the wedge's native angles.
/// On a plane native and projected angles agree, so the conversion is
/// exact there. If e1 points into the missing wedge of a boundary source
/// it is extrapolated from the last neighbour with the plain projected
/// angle. A non-manifold source (several fans) is treated like a boundary
/// source whose fans follow each other.
inline Source_one_ring source_one_ring(const Mesh_arrays& m, int s, const Tangent_frame& frame) {
  using one_ring_detail::ccw;
  struct Wedge {
    int from, to;
    double angle;
    bool used;
  };
  std::vector<Wedge> wedges;
  for (int p = m.vertex_face_start[s]; p < m.vertex_face_start[s + 1]; ++p) {
    const auto& f = m.face[m.vertex_face[p]];
    const int k = f[0] == s ? 0 : (f[1] == s ? 1 : 2);
    const int a = f[(k + 1) % 3], b = f[(k + 2) % 3];
    const Vector3 da = m.point[a] - m.point[s], db = m.point[b] - m.point[s];
    wedges.push_back({a, b, std::atan2(norm(cross(da, db)), dot(da, db)), false});
  }
  // Deterministic whatever the face order of the mesh: chains start at a
  // neighbour that no wedge ends at (a boundary), else at the smallest index.
  std::sort(wedges.begin(), wedges.end(),
            [](const Wedge& x, const Wedge& y) { return x.from < y.from || (x.from == y.from && x.to < y.to); });
  auto is_wedge_end = [&](int v) {
    for (const Wedge& w : wedges)
      if (!w.used && w.to == v) return true;
    return false;
  };

  Source_one_ring ring;
  std::vector<double> wedge_angle;  // angle of the wedge after ring.vertex[i]
  int chains = 0;
  bool cycle = false;
  for (;;) {
    int start = -1;
    for (std::size_t i = 0; i < wedges.size() && start < 0; ++i)
      if (!wedges[i].used && !is_wedge_end(wedges[i].from)) start = static_cast<int>(i);
    for (std::size_t i = 0; i < wedges.size() && start < 0; ++i)
      if (!wedges[i].used) {
        start = static_cast<int>(i);
        cycle = true;
      }
    if (start < 0) break;
    ++chains;
    int current = start;
    const int first = wedges[start].from;
    while (current >= 0) {
      Wedge& w = wedges[current];
      w.used = true;
      ring.vertex.push_back(w.from);
      wedge_angle.push_back(w.angle);
      current = -1;
      for (std::size_t i = 0; i < wedges.size(); ++i)
        if (!wedges[i].used && wedges[i].from == w.to) {
          current = static_cast<int>(i);
          break;
        }
      if (current < 0 && w.to != first) {
        ring.vertex.push_back(w.to);  // end of an open chain
        wedge_angle.push_back(0.0);
      }
    }
  }
  ring.closed = chains == 1 && cycle;

  // Native angles; wedge_angle[i] is 0 after the end of an open chain (the
  // next chain continues at the same angle).
  const std::size_t n = ring.vertex.size();
  ring.angle.resize(n);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ring.angle[i] = total;
    total += wedge_angle[i];
  }
  const double scale = ring.closed && total > 0 ? 2 * M_PI / total : 1.0;
  for (double& a : ring.angle) a *= scale;

  ring.projected.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    ring.projected[i] = frame.angle_of(m.point[ring.vertex[i]] - m.point[s]);
  ring.wedge_angle = std::move(wedge_angle);
  ring.reference_angle = ring.native_angle(0.0);  // e1's projected angle is 0
  return ring;
}

inline double Source_one_ring::native_angle(double projected_angle) const {
  using one_ring_detail::ccw;
  const std::size_t n = vertex.size();
  const std::size_t wedge_count = closed ? n : n - 1;
  for (std::size_t i = 0; i < wedge_count; ++i) {
    const std::size_t next = (i + 1) % n;
    if (wedge_angle[i] == 0) continue;  // between chains
    const double span = ccw(projected[i], projected[next]);
    const double offset = ccw(projected[i], projected_angle);
    // A corner angle is below pi and projects to below pi unless the wedge
    // folds over in projection; such wedges cannot locate a direction.
    if (!(span > 0 && span < M_PI) || offset > span) continue;
    const double end = next == 0 ? 2 * M_PI : angle[next];
    return angle[i] + (offset / span) * (end - angle[i]);
  }
  if (!closed) return angle[n - 1] + ccw(projected[n - 1], projected_angle);
  std::size_t nearest = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (std::abs(std::remainder(projected[i] - projected_angle, 2 * M_PI)) <
        std::abs(std::remainder(projected[nearest] - projected_angle, 2 * M_PI)))
      nearest = i;
  return angle[nearest] - std::remainder(projected[nearest] - projected_angle, 2 * M_PI);
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOURCE_ONE_RING_H
