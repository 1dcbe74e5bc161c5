// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_ANGLE_ESTIMATOR_H
#define EXPMAP_ANGLE_ESTIMATOR_H

/// \file Angle_estimator.h
/// How the heat method reads the polar angle off the heat (the paper's
/// step 3), and where it takes the geometry's direction instead.

namespace expmap {

/// \ingroup PkgExpmapRef
/// How the direction of the geodesic is read off the heat at the source.
enum class Angle_estimator {
  /// The paper's eq. (9)-(10): area-weighted tangent gradient of the heat.
  heat_gradient,
  /// The same gradient of the logarithm of the heat. Same direction in the
  /// continuum, but the log of the heat kernel is nearly linear in the
  /// distance, so the piecewise linear gradient over an irregular one-ring
  /// picks up less bias from the kernel's curvature.
  /// Falls back to `heat_gradient` where some heat value is not positive.
  log_heat_gradient,
  /// The gradient of the logarithm of the heat from a quadratic fitted by
  /// least squares on the star of the source, instead of the area-weighted
  /// piecewise linear gradient: exact for quadratics, so an irregular
  /// one-ring does not bias the direction. On a unit sphere of 10,242
  /// vertices, each moved by up to 0.35 mean edge lengths, without the
  /// near-source blend, its mean angle error is 5.8e-3 rad against
  /// `log_heat_gradient`'s 1.7e-2 (test/heat_map/test_angle_estimators.cpp);
  /// on real meshes it gave more patches with fold-overs (doc/decisions.md).
  /// Falls back to `log_heat_gradient` at sources with fewer than five
  /// neighbours.
  log_heat_quadratic_fit,
  /// The gradient of a least-squares quadratic fitted to the heat itself
  /// (not its logarithm) on the two-ring of the source in the triangulation
  /// the heat lives on, with the fit's leak of the heat's cubic Taylor terms
  /// removed (`internal::remove_cubic_leak`: the heat from a far vertex is
  /// nearly the exponential of a known quadratic). Linear in the heat, so by
  /// symmetry two right-hand sides give it for every patch vertex at once,
  /// where the logarithmic estimators solve one per star vertex. With the
  /// near-source blend (the defaults) its mean angle error on the jittered
  /// sphere above is 1.5e-3 rad (test/heat_map/test_angle_estimators.cpp).
  /// Falls back to `heat_gradient` at sources with fewer than five
  /// neighbours, and to `log_heat_quadratic_fit` at time factors below 4,
  /// where the heat varies too fast across the two-ring
  /// (`Heat_exponential_map::angle_estimator()` tells). The default.
  heat_quadratic_fit
};

/// \ingroup PkgExpmapRef
/// Whether an angle estimator is linear in the heat values on the star of
/// the source. A linear estimator G h_v, G the 2 x (k+1) gradient weights
/// and h_v the heat from v on the star, equals (A^-1 G^T)(v) by the symmetry
/// of the heat matrix A: two solves, one per row of G, answer every patch
/// vertex. The logarithmic ones need the heat from every star vertex.
inline bool is_linear_in_heat(Angle_estimator estimator) {
  return estimator == Angle_estimator::heat_gradient ||
         estimator == Angle_estimator::heat_quadratic_fit;
}

/// \ingroup PkgExpmapRef
/// Where angles come from the geometry instead of the heat: next to the
/// source the heat from a patch vertex is least resolved (its kernel is a
/// few edges wide), while the direction of the chord from the source to a
/// vertex, projected onto the tangent plane, is the direction of the
/// geodesic to second order in the distance. Vertices at heat distance up
/// to `begin` mean edge lengths take the chord's direction; from `begin` to
/// `end` it turns smoothly (a cubic smoothstep in the distance) into the
/// heat's direction. `end = 0` gives the paper's pure heat angles. A query
/// scales `begin` and `end` so that the blend ends where the surface normal
/// has turned by 1 rad, by at most 1.5x
/// (`Heat_exponential_map::near_source_blend_at()` gives a source's): chords are
/// good directions where the surface is flat at the blend's scale, and
/// fold triangles over where it bends (a coarse, curved one-ring).
/// The chord's direction is read in the source's intrinsic angles: a
/// neighbour of the source takes its edge's angle as DGPC does (corner
/// angles summed and rescaled to 2 pi), any other vertex its projected
/// chord carried into those angles by the wedge of neighbours it projects
/// into. A neighbour's distance is likewise its edge's length up to
/// `begin`, blended into the heat distance by `end`; so with a geodesic
/// radius below about 2h a neighbour's reported distance can exceed the
/// radius its heat distance was selected by.
struct Near_source_blend {
  double begin = 2.0;  ///< in mean edge lengths h; at least 0
  double end = 6.0;    ///< in mean edge lengths h; at least `begin`
};

}  // namespace expmap

#endif  // EXPMAP_ANGLE_ESTIMATOR_H
