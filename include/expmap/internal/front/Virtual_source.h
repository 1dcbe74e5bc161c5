// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_VIRTUAL_SOURCE_H
#define EXPMAP_INTERNAL_FRONT_VIRTUAL_SOURCE_H

#include <expmap/internal/Vector3.h>

#include <algorithm>
#include <cmath>

namespace expmap {
namespace internal {

/// A candidate distance for a vertex j of a triangle (i, k, j) from the
/// distances known at i and k, and where its angle lies between theirs.
struct Triangle_update {
  double distance;
  /// Weight of k in the angle: 0 takes the angle of i, 1 that of k.
  /// Computed on demand: most candidates are rejected, and the angle
  /// costs two arc tangents.
  double alpha() const {
    if (m_fixed_alpha >= 0) return m_fixed_alpha;
    // Angles at the source from the ray towards i: to j, and to k.
    const double to_j = std::atan2(std::abs(m_ix * m_dy - m_iy * m_dx), m_ix * m_dx + m_iy * m_dy);
    const double to_k = std::atan2(std::abs(m_ix * m_ky - m_iy * m_kx), m_ix * m_kx + m_iy * m_ky);
    return to_k > 0 ? std::min(1.0, to_j / to_k) : m_crossing;
  }

  double m_fixed_alpha = -1;  // 0 or 1 for the Dijkstra fallback
  double m_ix = 0, m_iy = 0, m_kx = 0, m_ky = 0, m_dx = 0, m_dy = 0, m_crossing = 0;
};

/// The update of Melvaer & Reimers (DGPC, 2012). The triangle is unfolded
/// into the plane with the edge (i, k) on the x axis and j above it; the
/// virtual source is the point below the edge at distance `u_i` from i and
/// `u_k` from k, and the candidate is its distance to j. It is used when
/// the straight line from the virtual source to j crosses the edge (i, k);
/// `alpha` is then the fraction of the angle i-source-k at which j is seen.
/// Otherwise (no such point: the distances violate the triangle inequality
/// with the edge, or j is seen outside the edge) the update falls back to
/// Dijkstra through the better of i and k, as the authors do.
///
/// On a plane with exact distances at i and k, the virtual source is the
/// true source, so the update is exact: this is why DGPC reproduces planar
/// polar coordinates to rounding error.
inline Triangle_update virtual_source_update(const Vector3& pi, const Vector3& pk,
                                             const Vector3& pj, double u_i, double u_k) {
  auto dijkstra = [&] {
    const double through_i = u_i + norm(pj - pi), through_k = u_k + norm(pj - pk);
    Triangle_update t;
    t.distance = std::min(through_i, through_k);
    t.m_fixed_alpha = through_i <= through_k ? 0.0 : 1.0;
    return t;
  };

  const Vector3 edge = pk - pi;
  const double e = norm(edge);
  if (!(e > 0)) return dijkstra();
  const Vector3 ex = (1.0 / e) * edge;
  const Vector3 w = pj - pi;
  const double xj = dot(w, ex);
  const double yj = norm(w - xj * ex);

  // 16 area^2 of the triangle with sides (e, u_i, u_k), in the form of
  // Heron's formula that stays accurate for needle-like triangles.
  double a = e, b = u_i, c = u_k;
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  const double heron = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  if (!(heron >= 0)) return dijkstra();
  const double xs = (u_i * u_i - u_k * u_k + e * e) / (2 * e);
  const double ys = -std::sqrt(heron) / (2 * e);

  // Where the line from the source to j crosses the x axis.
  const double dy = yj - ys;
  if (!(dy > 0)) return dijkstra();
  const double xc = xs + (xj - xs) * (-ys / dy);
  if (!(xc >= 0 && xc <= e)) return dijkstra();

  Triangle_update t;
  t.m_dx = xj - xs;
  t.m_dy = dy;
  t.distance = std::sqrt(t.m_dx * t.m_dx + dy * dy);
  t.m_ix = -xs;
  t.m_iy = -ys;
  t.m_kx = e - xs;
  t.m_ky = -ys;
  t.m_crossing = xc / e;
  return t;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_VIRTUAL_SOURCE_H
