// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_GEODESIC_SHOOTING_H
#define EXPMAP_BENCHMARK_EVALUATION_GEODESIC_SHOOTING_H

/// \file Geodesic_shooting.h
/// Height fields z = f(x, y) with their derivatives (Gaussian bump,
/// saddle), and geodesics shot from their origin with Boost.Odeint: the
/// reference of the accuracy study where no closed form exists.

#include "Common.h"
#include "Reference_maps.h"
#include "Statistics.h"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace expmap_evaluation {

/// A height field z = f(x, y) with its derivatives.
struct Height_field {
  // f, f_x, f_y, f_xx, f_xy, f_yy
  std::function<std::array<double, 6>(double, double)> eval;
};

inline Height_field gaussian_bump_field(double amplitude, double sigma) {
  return {[=](double x, double y) {
    const double s2 = sigma * sigma;
    const double f = amplitude * std::exp(-(x * x + y * y) / (2 * s2));
    return std::array<double, 6>{{f, -x / s2 * f, -y / s2 * f, (x * x / s2 - 1) / s2 * f,
                                  x * y / (s2 * s2) * f, (y * y / s2 - 1) / s2 * f}};
  }};
}

inline Height_field saddle_field(double amplitude) {
  return {[=](double x, double y) {
    const double sx = std::sin(x), cx = std::cos(x), sy = std::sin(y), cy = std::cos(y);
    return std::array<double, 6>{{amplitude * sx * sy, amplitude * cx * sy, amplitude * sx * cy,
                                  -amplitude * sx * sy, amplitude * cx * cy, -amplitude * sx * sy}};
  }};
}

/// One sample of a geodesic from the origin of a height field.
struct Geodesic_sample {
  double x, y, s, theta;
};

struct Ode_report {
  double speed_residual = 0;   // max |g(x', x') - 1| over the samples
  double tolerance_change = 0; // max position change between tolerances 1e-10 and 1e-13
};

/// Geodesics from the origin of z = f(x, y) (a critical point: grad f = 0,
/// so the tangent plane is z = 0 and the initial direction at angle theta
/// is (cos theta, sin theta), of unit speed). The geodesic equation in the
/// parameter domain, with the metric g = I + grad f grad f^T, whose
/// Christoffel symbols are Gamma^k_ij = f_k f_ij / (1 + |grad f|^2):
///
///     x''^k = -f_k (x'^T Hess f x') / (1 + |grad f|^2),
///
/// integrated by Dormand-Prince 5(4) with dense output (Boost.Odeint) in the
/// arc-length parameter; samples at s = radius j / per_geodesic.
inline std::vector<Geodesic_sample> shoot_geodesics(const Height_field& field, int directions,
                                                    int per_geodesic, double radius, Ode_report& report) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 4>;
  auto rhs = [&](const State& q, State& dq, double) {
    const auto d = field.eval(q[0], q[1]);
    const double w = 1 + d[1] * d[1] + d[2] * d[2];
    const double hess = d[3] * q[2] * q[2] + 2 * d[4] * q[2] * q[3] + d[5] * q[3] * q[3];
    dq[0] = q[2];
    dq[1] = q[3];
    dq[2] = -d[1] * hess / w;
    dq[3] = -d[2] * hess / w;
  };
  std::vector<double> times;
  for (int j = 0; j <= per_geodesic; ++j) times.push_back(radius * j / per_geodesic);
  auto integrate = [&](double theta, double tolerance) {
    std::vector<State> states;
    State q{{0, 0, std::cos(theta), std::sin(theta)}};
    auto stepper = odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
    odeint::integrate_times(stepper, rhs, q, times.begin(), times.end(), 1e-3 * radius,
                            [&](const State& x, double) { states.push_back(x); });
    return states;
  };
  std::vector<Geodesic_sample> samples;
  for (int k = 0; k < directions; ++k) {
    // Offset by a quarter step so no geodesic runs exactly along a grid line.
    const double theta = wrap_angle(2 * pi * (k + 0.25) / directions);
    const auto fine = integrate(theta, 1e-13);
    const auto coarse = integrate(theta, 1e-10);
    for (int j = 1; j <= per_geodesic; ++j) {
      const State& q = fine[std::size_t(j)];
      const auto d = field.eval(q[0], q[1]);
      const double slope = d[1] * q[2] + d[2] * q[3];
      report.speed_residual =
          std::max(report.speed_residual, std::abs(q[2] * q[2] + q[3] * q[3] + slope * slope - 1));
      report.tolerance_change =
          std::max(report.tolerance_change, std::hypot(q[0] - coarse[std::size_t(j)][0],
                                                       q[1] - coarse[std::size_t(j)][1]));
      samples.push_back({q[0], q[1], times[std::size_t(j)], theta});
    }
  }
  return samples;
}

/// The samples of shot geodesics as reference points, located on a
/// height-field mesh by their (x, y); samples off the mesh are left out.
inline std::vector<Reference_point> sample_references(const Xy_locator& locator,
                                                      const std::vector<Geodesic_sample>& samples) {
  std::vector<Reference_point> ref;
  for (const auto& g : samples) {
    Reference_point p;
    if (!locator.locate(g.x, g.y, p)) continue;
    p.r = g.s;
    p.theta = g.theta;
    ref.push_back(p);
  }
  return ref;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_GEODESIC_SHOOTING_H
