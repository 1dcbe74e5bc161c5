// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test geometry, shared by the test suites and the evaluation programs
// (benchmark/evaluation); not part of the library. The exact exponential
// maps (geodesic polar coordinates) of the analytic surfaces of
// Analytic_surfaces.h for which they are known in closed form: sphere,
// plane, cylinder, and the Gaussian bump seen from its apex.
#ifndef EXPMAP_TEST_ANALYTIC_EXPONENTIAL_MAPS_H
#define EXPMAP_TEST_ANALYTIC_EXPONENTIAL_MAPS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "Analytic_surfaces.h"

namespace expmap_analytic {

/// Exact geodesic polar coordinates of a point relative to a source point.
///
/// `r` is the geodesic distance from the source. `theta_unrotated` is the
/// polar angle in (-pi, pi] of the initial direction of the geodesic from the
/// source, measured in the tangent plane at the source from the caller's
/// reference direction `e1`, counter-clockwise about the outward normal `n`
/// (i.e. `atan2(<d, e2>, <d, e1>)` with `e2 = n x e1`). It is "unrotated" in
/// the sense that it is not aligned with the (arbitrary) angular reference of
/// a computed map: comparisons with a computed map must first remove the
/// constant rotation between the two. At the source itself r = 0 and
/// theta_unrotated = 0.
struct Polar {
  double r = 0;                ///< geodesic distance from the source
  double theta_unrotated = 0;  ///< polar angle from `e1`, in (-pi, pi]
};

namespace detail {

/// Polar angle of the tangent vector `d` at a point of unit normal `n`,
/// measured from `e1` (projected onto the tangent plane) counter-clockwise
/// about `n`.
inline double tangent_angle(const Vector3& d, const Vector3& n, const Vector3& e1,
                            const char* function) {
  require(is_finite(e1), std::string(function) + ": e1 must be finite");
  const Vector3 e1_tangent = e1 - dot(e1, n) * n;
  const double e1_norm = norm(e1);
  require(e1_norm > 0 && norm(e1_tangent) > 1e-12 * e1_norm,
          std::string(function) +
              ": e1 must not be zero or parallel to the surface normal at the source");
  const Vector3 u = (1.0 / norm(e1_tangent)) * e1_tangent;
  const Vector3 v = cross(n, u);
  return std::atan2(dot(d, v), dot(d, u));
}

/// Integrand of the meridian length of the Gaussian bump.
inline double gaussian_bump_speed(double t, double amplitude, double sigma) {
  const double u = t / sigma;
  const double slope = amplitude / sigma * u * std::exp(-0.5 * u * u);
  return std::sqrt(1.0 + slope * slope);
}

/// Composite 5-point Gauss-Legendre rule of `panels` equal panels on [0, rho].
inline double gaussian_bump_quadrature(double rho, double amplitude, double sigma,
                                       std::size_t panels) {
  const double a = std::sqrt(10.0 / 7.0);
  const double x1 = std::sqrt(5.0 - 2.0 * a) / 3.0, x2 = std::sqrt(5.0 + 2.0 * a) / 3.0;
  const double w0 = 128.0 / 225.0;
  const double w1 = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
  const double w2 = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
  const double h = rho / static_cast<double>(panels);
  double sum = 0;
  for (std::size_t k = 0; k < panels; ++k) {
    const double c = (static_cast<double>(k) + 0.5) * h, half = 0.5 * h;
    auto f = [&](double x) { return gaussian_bump_speed(c + half * x, amplitude, sigma); };
    sum += half * (w0 * f(0.0) + w1 * (f(-x1) + f(x1)) + w2 * (f(-x2) + f(x2)));
  }
  return sum;
}

}  // namespace detail

/// Exact exponential map of the sphere of radius `radius` centred at the
/// origin.
///
/// `source` and `p` are projected radially onto the sphere. The distance is
/// `radius * angle(source, p)` (computed with atan2, accurate everywhere).
/// The angle is that of the initial direction of the minimizing great
/// circle from the source, measured from `e1` (projected onto the tangent
/// plane at the source) counter-clockwise about the outward normal
/// n = source / |source|. At the antipode the direction is undefined (the
/// returned angle is then meaningless, r = pi radius).
///
/// \param source source point (non-zero)
/// \param p query point (non-zero)
/// \param radius sphere radius, positive
/// \param e1 angular reference direction, not parallel to the normal at the source
/// \throws std::invalid_argument for zero points, a non-positive radius or a bad e1
inline Polar sphere_exponential_map(const std::array<double, 3>& source,
                                    const std::array<double, 3>& p, double radius,
                                    const std::array<double, 3>& e1) {
  using namespace detail;
  require_positive(radius, "sphere_exponential_map", "radius");
  const Vector3 n = normalized(source, "sphere_exponential_map: source");
  const Vector3 q = normalized(p, "sphere_exponential_map: p");
  const double angle = std::atan2(norm(cross(n, q)), dot(n, q));
  Polar result;
  result.r = radius * angle;
  // The log direction is the tangential part of q; its normal part does not
  // change the angle.
  const double theta = tangent_angle(q, n, e1, "sphere_exponential_map");
  result.theta_unrotated = angle > 0 ? theta : 0.0;
  return result;
}

/// Exact exponential map of the plane z = 0 (normal +z).
///
/// `source` and `p` are projected onto the plane (their z is ignored);
/// r = |p - source| and the angle is measured from `e1` (projected onto the
/// plane) counter-clockwise about +z, i.e. in the frame (e1, e2 = z x e1).
///
/// \throws std::invalid_argument if e1 is zero or vertical
inline Polar plane_exponential_map(const std::array<double, 3>& source,
                                   const std::array<double, 3>& p,
                                   const std::array<double, 3>& e1) {
  using namespace detail;
  const Vector3 d = {{p[0] - source[0], p[1] - source[1], 0.0}};
  Polar result;
  result.r = std::hypot(d[0], d[1]);
  const double theta = tangent_angle(d, {{0.0, 0.0, 1.0}}, e1, "plane_exponential_map");
  result.theta_unrotated = result.r > 0 ? theta : 0.0;
  return result;
}

/// Exact exponential map of the infinite cylinder of axis z (through the
/// origin) and radius `radius`, computed by unrolling.
///
/// `source` and `p` are projected radially onto the cylinder (only their
/// azimuths and heights are used). With dphi the azimuth difference wrapped
/// to (-pi, pi] and dz the height difference, the unrolled vector is
/// (radius dphi, dz) in the tangent frame (azimuthal direction, +z) at the
/// source: r = hypot(radius dphi, dz) and the angle is measured from `e1`
/// (projected onto the tangent plane) counter-clockwise about the outward
/// normal (away from the axis). This is the minimizing geodesic, valid as
/// long as it does not wrap more than half the circumference.
///
/// \throws std::invalid_argument if radius is not positive, a point is on
///         the axis, or e1 is zero or parallel to the normal
inline Polar cylinder_exponential_map(const std::array<double, 3>& source,
                                      const std::array<double, 3>& p, double radius,
                                      const std::array<double, 3>& e1) {
  using namespace detail;
  require_positive(radius, "cylinder_exponential_map", "radius");
  require(std::hypot(source[0], source[1]) > 0 && std::hypot(p[0], p[1]) > 0,
          "cylinder_exponential_map: points must not lie on the axis");
  const double pi = std::acos(-1.0);
  const double phi_s = std::atan2(source[1], source[0]);
  double dphi = std::atan2(p[1], p[0]) - phi_s;
  if (dphi > pi) dphi -= 2 * pi;
  if (dphi <= -pi) dphi += 2 * pi;
  const double u = radius * dphi, v = p[2] - source[2];
  const Vector3 n = {{std::cos(phi_s), std::sin(phi_s), 0.0}};
  const Vector3 azimuthal = {{-std::sin(phi_s), std::cos(phi_s), 0.0}};
  const Vector3 d = u * azimuthal + Vector3{{0.0, 0.0, v}};
  Polar result;
  result.r = std::hypot(u, v);
  const double theta = tangent_angle(d, n, e1, "cylinder_exponential_map");
  result.theta_unrotated = result.r > 0 ? theta : 0.0;
  return result;
}

/// Length of the meridian of the Gaussian bump z = A exp(-rho^2 / (2 sigma^2))
/// from the apex to the parallel of radius `rho`, i.e. the integral of
/// sqrt(1 + z'(t)^2) over [0, rho].
///
/// Computed with composite 5-point Gauss-Legendre quadrature, doubling the
/// number of panels until two successive results agree to 1e-13 relative
/// (the integrand is analytic, so the result is accurate to ~1e-13, far below
/// the required 1e-10).
///
/// \throws std::invalid_argument if rho is negative or sigma not positive
inline double gaussian_bump_meridian_length(double rho, double amplitude, double sigma) {
  using namespace detail;
  require(std::isfinite(rho) && rho >= 0,
          "gaussian_bump_meridian_length: rho must be non-negative and finite");
  require_finite(amplitude, "gaussian_bump_meridian_length", "amplitude");
  require_positive(sigma, "gaussian_bump_meridian_length", "sigma");
  if (rho == 0) return 0;
  // Panels about sigma / 4 wide, and narrow enough for steep flanks.
  const double steepness = 1.0 + std::abs(amplitude) / sigma;
  std::size_t panels =
      static_cast<std::size_t>(std::ceil(std::min(4.0 * rho / sigma * steepness, 1e4))) + 1;
  double previous = gaussian_bump_quadrature(rho, amplitude, sigma, panels);
  for (int refinement = 0; refinement < 12; ++refinement) {
    panels *= 2;
    const double current = gaussian_bump_quadrature(rho, amplitude, sigma, panels);
    if (std::abs(current - previous) <= 1e-13 * current) return current;
    previous = current;
  }
  return previous;
}

/// Exact exponential map of the Gaussian bump
/// z = amplitude exp(-(x^2 + y^2) / (2 sigma^2)) with the source at the apex
/// (0, 0, amplitude) (vertex `grid_origin_vertex(n, n)` of
/// `make_gaussian_bump()`).
///
/// The bump is a surface of revolution and the source is its pole, so the
/// geodesics from the source are the meridians: r is the meridian arc length
/// `gaussian_bump_meridian_length(hypot(x, y), amplitude, sigma)` and the
/// angle is the azimuth of (x, y) measured from `e1` counter-clockwise about
/// +z (the tangent plane at the apex is horizontal; `e1` is projected onto
/// it). Only the x and y coordinates of `p` are used.
///
/// \throws std::invalid_argument if sigma is not positive or e1 is zero or vertical
inline Polar gaussian_bump_exponential_map(const std::array<double, 3>& p, double amplitude,
                                           double sigma, const std::array<double, 3>& e1) {
  using namespace detail;
  const double rho = std::hypot(p[0], p[1]);
  Polar result;
  result.r = gaussian_bump_meridian_length(rho, amplitude, sigma);
  const double theta =
      tangent_angle({{p[0], p[1], 0.0}}, {{0.0, 0.0, 1.0}}, e1, "gaussian_bump_exponential_map");
  result.theta_unrotated = rho > 0 ? theta : 0.0;
  return result;
}

}  // namespace expmap_analytic

#endif  // EXPMAP_TEST_ANALYTIC_EXPONENTIAL_MAPS_H
