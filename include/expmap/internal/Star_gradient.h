// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_STAR_GRADIENT_H
#define EXPMAP_INTERNAL_STAR_GRADIENT_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace expmap {
namespace internal {

/// The gradient at a source vertex s of a piecewise linear function known on
/// the star of s, as a linear map (the paper's eq. 6, 9 and 10): the face
/// gradients of the faces around s, projected onto the tangent plane and
/// summed with area weights, in the coordinates of the source's frame.
///
/// Applied to the heat values (h_k)_j = (h_j)_k of the star vertices k it
/// yields the direction of the geodesic from s towards j (symmetry trick).
struct Star_gradient {
  std::vector<int> vertices;                  ///< s first, then its neighbours
  std::vector<double> along_e1, along_e2;     ///< one weight per star vertex

  /// Tangent gradient of the function with `values[c]` at `vertices[c]`.
  std::array<double, 2> apply(const double* values) const {
    double x = 0, y = 0;
    for (std::size_t c = 0; c < vertices.size(); ++c) {
      x += along_e1[c] * values[c];
      y += along_e2[c] * values[c];
    }
    return {{x, y}};
  }
};

/// The star of s (s first, then its neighbours), without weights yet.
inline Star_gradient star_of(const Mesh_arrays& m, int s) {
  Star_gradient g;
  g.vertices.push_back(s);
  for (int p = m.neighbor_start[s]; p < m.neighbor_start[s + 1]; ++p)
    g.vertices.push_back(m.neighbor[p]);
  return g;
}

inline Star_gradient star_gradient(const Mesh_arrays& m, int s, const Tangent_frame& frame) {
  Star_gradient g = star_of(m, s);
  g.along_e1.assign(g.vertices.size(), 0.0);
  g.along_e2.assign(g.vertices.size(), 0.0);
  auto column_of = [&](int v) {
    return static_cast<std::size_t>(std::find(g.vertices.begin(), g.vertices.end(), v) -
                                    g.vertices.begin());
  };
  for (int p = m.vertex_face_start[s]; p < m.vertex_face_start[s + 1]; ++p) {
    const auto& f = m.face[m.vertex_face[p]];
    const Vector3 twice_area = cross(m.point[f[1]] - m.point[f[0]], m.point[f[2]] - m.point[f[0]]);
    const Vector3 unit_normal = (1.0 / norm(twice_area)) * twice_area;
    for (int k = 0; k < 3; ++k) {
      // Area times gradient = 1/2 sum_k u_k (n x e_k), e_k the edge opposite
      // corner k, taken counter-clockwise.
      const Vector3 e = m.point[f[(k + 2) % 3]] - m.point[f[(k + 1) % 3]];
      const Vector3 w = 0.5 * cross(unit_normal, e);
      const std::size_t c = column_of(f[k]);
      g.along_e1[c] += dot(w, frame.e1);
      g.along_e2[c] += dot(w, frame.e2);
    }
  }
  return g;
}

/// The gradient at s of the quadratic that fits values on the star of s
/// best in the least-squares sense, as a linear map like `star_gradient`.
///
/// The area-weighted gradient of the piecewise linear interpolant is exact
/// for linear functions only: on a one-ring that is not point-symmetric the
/// second-order part of the function leaks into it. The logarithm of the
/// heat from a far vertex j has a Hessian at s of the order of its gradient
/// divided by the distance to j (the level sets are circles around j), so
/// the leak turns the direction by about (asymmetry x h / r): worst close to
/// the source, and the dominant angle error on irregular meshes. A fitted
/// quadratic has no such leak.
///
/// Star vertex c is placed in the tangent plane in the direction of its
/// projection, at its distance |p_c - p_s| (a geodesic distance to first
/// order, which the heat depends on). Needs at least five neighbours in
/// general position; returns std::nullopt otherwise.
inline std::optional<Star_gradient> quadratic_fit_star_gradient(const Mesh_arrays& m, int s,
                                                                const Tangent_frame& frame) {
  Star_gradient g = star_of(m, s);
  const Eigen::Index n = static_cast<Eigen::Index>(g.vertices.size());
  if (n < 6) return std::nullopt;
  std::vector<std::array<double, 2>> position(g.vertices.size(), {{0.0, 0.0}});
  double scale = 0;
  for (std::size_t c = 1; c < g.vertices.size(); ++c) {
    const Vector3 d = m.point[g.vertices[c]] - m.point[s];
    const double x = dot(d, frame.e1), y = dot(d, frame.e2);
    const double projected = std::hypot(x, y);
    if (!(projected > 0)) return std::nullopt;
    const double length = norm(d);
    position[c] = {{x * length / projected, y * length / projected}};
    scale += length;
  }
  scale /= static_cast<double>(n - 1);
  // Design matrix in units of the mean edge length (for conditioning).
  Eigen::MatrixXd X(n, 6);
  for (Eigen::Index c = 0; c < n; ++c) {
    const double x = position[c][0] / scale, y = position[c][1] / scale;
    X.row(c) << 1.0, x, y, x * x, x * y, y * y;
  }
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> fit(X);
  if (fit.rank() < 6) return std::nullopt;
  const Eigen::MatrixXd inverse = fit.pseudoInverse();  // 6 x n
  g.along_e1.resize(g.vertices.size());
  g.along_e2.resize(g.vertices.size());
  for (Eigen::Index c = 0; c < n; ++c) {
    g.along_e1[c] = inverse(1, c) / scale;
    g.along_e2[c] = inverse(2, c) / scale;
  }
  return g;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_STAR_GRADIENT_H
