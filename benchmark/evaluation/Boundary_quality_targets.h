// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_QUALITY_TARGETS_H
#define EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_QUALITY_TARGETS_H

/// \file Boundary_quality_targets.h
/// The targets the heat method must meet at sources on and near a mesh
/// boundary, relative to DGPC (which handles boundaries) on the same
/// sources and patches:
///
/// 1. flips: heat's flipped triangles over the sources at most
///    max(2 x DGPC's, DGPC's + 2% of heat's patch triangles);
/// 2. no collapse: no source where heat flips more than 30% of its patch
///    triangles while DGPC flips less than 5%;
/// 3. angles: heat's median (over the sources) mean |dtheta| against the
///    exact map, after the best rotation, at most max(0.05 rad, 3 x DGPC's).
///
/// The boundary study reports them per mesh and ring, the boundary quality
/// test checks them; both take the numbers from here.

#include "Map_agreement.h"
#include "Statistics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace expmap_evaluation {

/// Heat's and DGPC's maps of one source.
struct Heat_and_dgpc {
  Map_agreement heat, dgpc;
};

/// The thresholds of the targets.
struct Boundary_quality_thresholds {
  double flip_ratio = 2;                ///< heat flips <= this x DGPC's, or
  double flip_allowance = 0.02;         ///< <= DGPC's + this fraction of the triangles
  double collapsed_heat = 0.30;         ///< a source is collapsed with heat above this fraction
  double collapsed_dgpc = 0.05;         ///< while DGPC is below this one
  double angle_floor = 0.05;            ///< radians
  double angle_ratio = 3;               ///< heat's median angle error <= max(floor, this x DGPC's)
};

/// The targets over a set of sources (a mesh and ring, or a test's sources).
struct Boundary_quality {
  std::size_t sources = 0;
  std::size_t heat_flipped = 0, dgpc_flipped = 0;
  std::size_t heat_triangles = 0;    ///< heat's patch triangles, summed
  std::size_t collapsed_sources = 0; ///< heat > 30% flipped where DGPC < 5%
  /// Medians over the sources of mean |dtheta| (sources without an exact
  /// map left out; NaN if none has one).
  double heat_angle_error = std::nan(""), dgpc_angle_error = std::nan("");
  double flip_limit = 0, angle_limit = 0;  ///< the limits the targets set
  bool flips_pass = true, collapse_pass = true, angles_pass = true;

  bool pass() const { return flips_pass && collapse_pass && angles_pass; }
};

/// Whether heat collapses on this source by target 2.
inline bool collapsed(const Heat_and_dgpc& s, const Boundary_quality_thresholds& t = {}) {
  return s.heat.flipped_fraction() > t.collapsed_heat &&
         s.dgpc.flipped_fraction() < t.collapsed_dgpc;
}

/// Evaluates the three targets over `sources`. The angle target passes
/// vacuously when no source has an exact map to compare with.
inline Boundary_quality boundary_quality(const std::vector<Heat_and_dgpc>& sources,
                                         const Boundary_quality_thresholds& t = {}) {
  Boundary_quality q;
  std::vector<double> heat_angles, dgpc_angles;
  for (const auto& s : sources) {
    ++q.sources;
    q.heat_flipped += s.heat.flipped;
    q.dgpc_flipped += s.dgpc.flipped;
    q.heat_triangles += s.heat.triangles;
    if (collapsed(s, t)) ++q.collapsed_sources;
    // Only sources where both have an exact comparison, so the two medians
    // are over the same sources.
    if (std::isfinite(s.heat.angle_error) && std::isfinite(s.dgpc.angle_error)) {
      heat_angles.push_back(s.heat.angle_error);
      dgpc_angles.push_back(s.dgpc.angle_error);
    }
  }
  const double dgpc_flips = static_cast<double>(q.dgpc_flipped);
  q.flip_limit = std::max(t.flip_ratio * dgpc_flips,
                          dgpc_flips + t.flip_allowance * static_cast<double>(q.heat_triangles));
  q.flips_pass = static_cast<double>(q.heat_flipped) <= q.flip_limit;
  q.collapse_pass = q.collapsed_sources == 0;
  if (!heat_angles.empty()) {
    q.heat_angle_error = median(heat_angles);
    q.dgpc_angle_error = median(dgpc_angles);
    q.angle_limit = std::max(t.angle_floor, t.angle_ratio * q.dgpc_angle_error);
    q.angles_pass = q.heat_angle_error <= q.angle_limit;
  }
  return q;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_BOUNDARY_QUALITY_TARGETS_H
