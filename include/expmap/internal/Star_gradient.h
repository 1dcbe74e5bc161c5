// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_STAR_GRADIENT_H
#define EXPMAP_INTERNAL_STAR_GRADIENT_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/solver/Pivoted_householder_qr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
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
  /// What the weights make of the quadratic monomials x^2, x y, y^2 of the
  /// tangent-plane coordinates (zero for a quadratic fit, which is exact
  /// for them). See `remove_cubic_leak()`.
  std::array<std::array<double, 2>, 3> quadratic_leak{};
  /// What the weights make of the cubic monomials x^3, x^2 y, x y^2, y^3
  /// (zero where unknown). See `remove_cubic_leak()`.
  std::array<std::array<double, 2>, 4> cubic_leak{};

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

/// Star vertex c placed in the tangent plane of s in the direction of its
/// projection, at its distance |p_c - p_s| (a geodesic distance to first
/// order, which the heat depends on); std::nullopt if a vertex projects
/// onto s.
inline std::optional<std::vector<std::array<double, 2>>> tangent_positions(
    const Mesh_arrays& m, const std::vector<int>& vertices, const Tangent_frame& frame) {
  const int s = vertices.front();
  std::vector<std::array<double, 2>> position(vertices.size(), {{0.0, 0.0}});
  for (std::size_t c = 1; c < vertices.size(); ++c) {
    const Vector3 d = m.point[vertices[c]] - m.point[s];
    const double x = dot(d, frame.e1), y = dot(d, frame.e2);
    const double projected = std::hypot(x, y);
    if (!(projected > 0)) return std::nullopt;
    const double length = norm(d);
    position[c] = {{x * length / projected, y * length / projected}};
  }
  return position;
}

/// Fills `g.quadratic_leak` and `g.cubic_leak`: the weights applied to the
/// monomials of the star's tangent positions.
inline void measure_leaks(Star_gradient& g, const std::vector<std::array<double, 2>>& position) {
  g.quadratic_leak = {};
  g.cubic_leak = {};
  for (std::size_t c = 0; c < g.vertices.size(); ++c) {
    const double x = position[c][0], y = position[c][1];
    const double quadratic[3] = {x * x, x * y, y * y};
    const double cubic[4] = {x * x * x, x * x * y, x * y * y, y * y * y};
    for (int k = 0; k < 3; ++k) {
      g.quadratic_leak[k][0] += g.along_e1[c] * quadratic[k];
      g.quadratic_leak[k][1] += g.along_e2[c] * quadratic[k];
    }
    for (int k = 0; k < 4; ++k) {
      g.cubic_leak[k][0] += g.along_e1[c] * cubic[k];
      g.cubic_leak[k][1] += g.along_e2[c] * cubic[k];
    }
  }
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
  if (const auto position = tangent_positions(m, g.vertices, frame)) measure_leaks(g, *position);
  return g;
}

/// Width of the weights of `quadratic_fit_star_gradient`, in units of the
/// star's mean distance from s (about 1.5 mean edge lengths on a two-ring).
/// Chosen on the accuracy study (doc/results.md, section 1): against the
/// unweighted fit, 0.8 lowered the mean angle error on every regular surface
/// (1-19%) and moved the jittered ones by -8% to +2%; 0.6 helped the regular
/// surfaces more and cost the jittered ones up to 8%.
constexpr double fit_weight_width = 0.8;

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
///
/// `star` names the vertices to fit on (s first): the input mesh's star by
/// default, or the star of s in the triangulation the heat lives on.
///
/// The fit weighs the squared residual of a vertex at distance r by
/// exp(-(r / (fit_weight_width * r_mean))^2 / 2), r_mean the star's mean
/// distance: still exact for quadratics, but the nearer vertices, whose
/// values carry less of the heat's quartic and higher Taylor terms, count
/// more (`weight_width`; infinity gives the unweighted fit).
inline std::optional<Star_gradient> quadratic_fit_star_gradient(
    const Mesh_arrays& m, Star_gradient g, const Tangent_frame& frame,
    double weight_width = fit_weight_width) {
  const int n = static_cast<int>(g.vertices.size());
  if (n < 6) return std::nullopt;
  const auto placed = tangent_positions(m, g.vertices, frame);
  if (!placed) return std::nullopt;
  const std::vector<std::array<double, 2>>& position = *placed;
  double scale = 0;
  for (std::size_t c = 1; c < g.vertices.size(); ++c)
    scale += norm(m.point[g.vertices[c]] - m.point[g.vertices.front()]);
  scale /= static_cast<double>(n - 1);
  // Design matrix in units of the star's mean distance (for conditioning),
  // each row times the square root of its vertex's weight; the weighted
  // least-squares solution is then the pseudo-inverse times the weighted
  // values. Its rows 1 and 2 are the fit's gradient.
  constexpr int monomials = 6;
  std::vector<double> X(static_cast<std::size_t>(n) * monomials);  // column-major
  std::vector<double> root_weight(g.vertices.size());
  for (int c = 0; c < n; ++c) {
    const double x = position[c][0] / scale, y = position[c][1] / scale;
    root_weight[c] = std::exp(-(x * x + y * y) / (4 * weight_width * weight_width));
    const double row[monomials] = {1.0, x, y, x * x, x * y, y * y};
    for (int k = 0; k < monomials; ++k)
      X[static_cast<std::size_t>(k) * n + c] = row[k] * root_weight[c];
  }
  const Pivoted_householder_qr<monomials> fit(std::move(X), n);
  if (!fit.full_rank()) return std::nullopt;
  g.along_e1.resize(g.vertices.size());
  g.along_e2.resize(g.vertices.size());
  fit.pseudo_inverse_row(1, g.along_e1.data());
  fit.pseudo_inverse_row(2, g.along_e2.data());
  for (int c = 0; c < n; ++c) {
    g.along_e1[c] *= root_weight[c] / scale;
    g.along_e2[c] *= root_weight[c] / scale;
  }
  measure_leaks(g, position);
  g.quadratic_leak = {};  // exact for quadratics: what is left is rounding
  return g;
}

inline std::optional<Star_gradient> quadratic_fit_star_gradient(const Mesh_arrays& m, int s,
                                                                const Tangent_frame& frame) {
  return quadratic_fit_star_gradient(m, star_of(m, s), frame);
}

/// Steps of the fixed point in `remove_cubic_leak`.
constexpr int max_leak_steps = 5;
/// A step of `remove_cubic_leak` that turns the direction by less than this
/// (rad) has settled: far below the estimator's own angle error (1e-4 and
/// more on the accuracy study's surfaces).
constexpr double leak_settled_turn = 1e-7;
/// A last step of `remove_cubic_leak` that still turns the direction by more
/// than this (rad) shows an iteration that swings or diverges.
constexpr double leak_swinging_turn = 1e-2;

/// `remove_cubic_leak` (below) for many vertices of one star: `gradient[i]` (the
/// fitted gradient of the heat from a vertex at distance `r[i]`, divided by
/// that heat at s) is replaced by its result. Equal, bit for bit, to one
/// call per vertex.
///
/// Each vertex's fixed point is a chain of dependent operations, so a few
/// vertices (lanes) are iterated side by side, laid out as arrays that the
/// compiler turns into packed arithmetic. Most vertices take every step
/// (they settle to leak_swinging_turn, not to leak_settled_turn), so a lane
/// that has settled simply stops being read until its whole group has; the
/// rare gradient whose square is not a normal number takes the
/// overflow-safe route on its own.
inline void remove_cubic_leak(const Star_gradient& star, std::array<double, 2>* gradient,
                              const double* r, std::size_t count, double time) {
  constexpr std::size_t lanes = 8;
  const double inverse_sqrt_time = 1 / std::sqrt(time);
  for (std::size_t first = 0; first < count; first += lanes) {
    const std::size_t width = std::min(lanes, count - first);
    // Per lane: the fitted gradient, the iterate g, and the Hessian model's
    // curvatures across (a) and along (b) g. Lanes past `width` repeat the
    // first and are never read.
    double fitted_x[lanes], fitted_y[lanes], gx[lanes], gy[lanes], a[lanes], b[lanes];
    bool running[lanes];
    for (std::size_t l = 0; l < lanes; ++l) {
      const std::size_t i = first + (l < width ? l : 0);
      fitted_x[l] = gx[l] = gradient[i][0];
      fitted_y[l] = gy[l] = gradient[i][1];
      a[l] = -(inverse_sqrt_time + 1 / (2 * r[i])) / r[i];
      b[l] = 1 / (2 * r[i] * r[i]);
      running[l] = l < width;
    }
    for (int step = 0; step < max_leak_steps && std::any_of(running, running + lanes,
                                                            [](bool on) { return on; });
         ++step) {
      // Q needs only n n^T = g g^T / |g|^2: one division per step, no square
      // root (a square root or a division costs as much as the rest of a
      // step). Squares that are not normal numbers are redone below.
      double square[lanes], xx[lanes], xy[lanes], yy[lanes];
      for (std::size_t l = 0; l < lanes; ++l) {
        square[l] = gx[l] * gx[l] + gy[l] * gy[l];
        const double inverse = 1 / square[l];
        xx[l] = gx[l] * gx[l] * inverse;
        xy[l] = gx[l] * gy[l] * inverse;
        yy[l] = gy[l] * gy[l] * inverse;
      }
      for (std::size_t l = 0; l < lanes; ++l) {
        if (!running[l] || std::isnormal(square[l])) continue;
        const double length = std::hypot(gx[l], gy[l]);
        if (!(length > 0) || !std::isfinite(length)) {
          gradient[first + l] = {{fitted_x[l], fitted_y[l]}};
          running[l] = false;
          continue;
        }
        const double nx = gx[l] / length, ny = gy[l] / length;
        xx[l] = nx * nx;
        xy[l] = nx * ny;
        yy[l] = ny * ny;
      }
      double turn[lanes], along[lanes];
      for (std::size_t l = 0; l < lanes; ++l) {
        const double qxx = a[l] + (b[l] - a[l]) * xx[l], qxy = (b[l] - a[l]) * xy[l],
                     qyy = a[l] + (b[l] - a[l]) * yy[l];
        const double x = gx[l], y = gy[l];
        // Coefficients of x^3, x^2 y, x y^2, y^3.
        constexpr double sixth = 1.0 / 6;
        const double coefficient[4] = {x * x * x * sixth + 0.5 * x * qxx,
                                       x * x * y * 0.5 + 0.5 * (2 * x * qxy + y * qxx),
                                       x * y * y * 0.5 + 0.5 * (x * qyy + 2 * y * qxy),
                                       y * y * y * sixth + 0.5 * y * qyy};
        double leak_x = 0, leak_y = 0;
        for (int k = 0; k < 4; ++k) {
          leak_x += coefficient[k] * star.cubic_leak[k][0];
          leak_y += coefficient[k] * star.cubic_leak[k][1];
        }
        // Coefficients of x^2, x y, y^2 (a leak for the area-weighted
        // gradient only: a quadratic fit's quadratic_leak is zero).
        const double quadratic[3] = {0.5 * (x * x + qxx), x * y + qxy, 0.5 * (y * y + qyy)};
        for (int k = 0; k < 3; ++k) {
          leak_x += quadratic[k] * star.quadratic_leak[k][0];
          leak_y += quadratic[k] * star.quadratic_leak[k][1];
        }
        const double next_x = fitted_x[l] - leak_x, next_y = fitted_y[l] - leak_y;
        // Only the direction is used: it has settled when a step turns it
        // by less than leak_settled_turn.
        turn[l] = x * next_y - y * next_x;
        along[l] = x * next_x + y * next_y;
        gx[l] = next_x;
        gy[l] = next_y;
      }
      for (std::size_t l = 0; l < lanes; ++l) {
        if (!running[l]) continue;
        if (along[l] > 0 && std::abs(turn[l]) <= leak_settled_turn * along[l]) {
          gradient[first + l] = {{gx[l], gy[l]}};
          running[l] = false;
        } else if (step + 1 == max_leak_steps) {
          // Still swinging: the model's cubic terms are too large for this
          // star and distance (coarse meshes, far vertices), and the last
          // step is an arbitrary direction (measured: up to pi from the
          // fixed point on dino). The fitted gradient, leak and all, is the
          // better estimate.
          const bool swinging =
              !(along[l] > 0 && std::abs(turn[l]) <= leak_swinging_turn * along[l]);
          gradient[first + l] = swinging ? std::array<double, 2>{{fitted_x[l], fitted_y[l]}}
                                         : std::array<double, 2>{{gx[l], gy[l]}};
        }
      }
    }
  }
}

/// The gradient g of log h at s from `fitted`, the quadratic fit's gradient
/// of the heat h from a vertex at distance r divided by that heat at s.
///
/// The heat from a far vertex is nearly h(s) exp(g.x + x^T Q x / 2) about
/// s: one implicit step of diffusion time t has the kernel of the screened
/// Poisson equation, whose logarithm falls off like -rho / sqrt(t) -
/// log(rho) / 2 with the distance rho from its centre, so Q = a (I - n n^T)
/// + b n n^T with n = g / |g|, a = -(1 / sqrt(t) + 1 / (2 r)) / r and
/// b = 1 / (2 r^2). A quadratic fit of h is exact up to second order; its
/// response to the model's cubic Taylor terms, (g.x)^3 / 6 + (g.x) x^T Q x / 2,
/// follows from `star.cubic_leak` and is subtracted (for the area-weighted
/// gradient of a one-sided star next to a boundary, the response to the
/// quadratic terms x^T (Q + g g^T) x / 2 too, from `star.quadratic_leak`),
/// a fixed point in g
/// approached in at most `max_leak_steps` steps (where the last one still
/// turns the direction by more than `leak_swinging_turn`, the fitted
/// gradient is returned unchanged). This is what the logarithmic fit achieves with one
/// solve per star vertex, from two solves (measured on spheres: the same
/// mean angle error as `log_heat_quadratic_fit`).
inline std::array<double, 2> remove_cubic_leak(const Star_gradient& star,
                                               const std::array<double, 2>& fitted, double r,
                                               double time) {
  std::array<double, 2> g = fitted;
  remove_cubic_leak(star, &g, &r, 1, time);
  return g;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_STAR_GRADIENT_H
