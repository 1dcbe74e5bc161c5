// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_HEAT_OPTIONS_H
#define EXPMAP_HEAT_OPTIONS_H

/// \file Heat_options.h
/// The settings of `Heat_exponential_map`: its precomputation's and its
/// queries'. The measurements behind the defaults are in doc/results.md and
/// doc/performance.md.

#include <expmap/Angle_estimator.h>
#include <expmap/Errors.h>
#include <expmap/Factor_precision.h>
#include <expmap/Patch.h>
#include <expmap/Precomputation_progress.h>
#include <expmap/Setting_ranges.h>

#include <cstddef>
#include <string>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Which triangulation the Laplacian is built on (as in CGAL's Heat_method_3).
enum class Laplacian_mode {
  direct,             ///< the input mesh as it is
  intrinsic_delaunay  ///< its intrinsic Delaunay triangulation (robust on poor meshes)
};

/// \ingroup PkgExpmapRef
/// The area each vertex stands for in the heat step's lumped mass matrix.
enum class Vertex_area {
  /// A third of every incident triangle (CGAL's Heat_method_3, the paper).
  barycentric,
  /// The mixed Voronoi area of Meyer et al. (VisMath 2002). Exact for
  /// quadratics on non-obtuse Delaunay meshes, so irregular triangles bias
  /// the heat, and with it the angles, less.
  mixed_voronoi
};

/// \ingroup PkgExpmapRef
/// How the singular Poisson system of the distance step is made definite.
enum class Poisson_regularization {
  /// Pins one vertex per connected component. Exact: the distance is
  /// defined up to a constant.
  pinned_vertex,
  /// Adds 1e-8 per incident face corner to the diagonal, as CGAL's
  /// Heat_method_3 does. For comparisons with CGAL only.
  cgal_compatible
};

/// \ingroup PkgExpmapRef
/// What a heat query returns where the heat's reading of the angles at the
/// source is blind: at the tips of thin parts, next to boundaries and
/// holes, and across thin sheets, the heat from far-apart vertices reaches
/// the source from nearly one direction (or around an obstacle), and the
/// map folds over whole regions at any diffusion time (manual, section 2,
/// "Where the heat's angles are blind").
enum class Heat_fallback {
  /// Where the heat's map folds a triangle over, a boundary comes within
  /// 2 sqrt(t) of its patch, or the heat fails (not positive, or
  /// underflowing), the query also carries the distances and angles outward
  /// along the geodesic front (DGPC's propagation,
  /// `Geodesic_polar_coordinates`; away from boundaries held to the heat's
  /// map inside its fold-free disk) and returns that map if it folds fewer
  /// triangles over (next to a boundary, where the heat's angles are biased:
  /// at most twice as many plus 2% of the patch's), or the heat failed.
  /// `Solve_statistics::front_maps` counts these.
  geodesic_front,
  /// The heat's map everywhere, as the paper computes it; a failed heat is
  /// an error.
  none
};

/// \ingroup PkgExpmapRef
/// The precomputation's settings of a `Heat_exponential_map`: they change
/// the operators and factorizations its constructor builds.
struct Heat_options {
  /// Diffusion time t = time_factor * h^2, h the mean edge length. Larger
  /// values give smoother maps; smaller ones distances closer to geodesic.
  double time_factor = 10.0;
  /// The intrinsic Delaunay triangulation keeps the heat positive on meshes
  /// with obtuse triangles; on Delaunay meshes both modes are the same.
  Laplacian_mode laplacian = Laplacian_mode::intrinsic_delaunay;
  /// The mass matrix of the heat step.
  Vertex_area vertex_area = Vertex_area::mixed_voronoi;
  /// How the Poisson system is made definite.
  Poisson_regularization regularization = Poisson_regularization::pinned_vertex;
  /// Single precision about halves the factors' memory and speeds queries
  /// on large meshes, moving the distances by about 2e-7 of the radius.
  Factor_precision factor_precision = Factor_precision::double_precision;
  /// Truncation of the low-rank rows below the Poisson factor's large
  /// separators (meshes above about 100k vertices): fewer entries read per
  /// query. 0 keeps every block dense. Range: `setting_ranges`.
  double poisson_compression_tolerance = 1e-14;
  /// On meshes of at least this many vertices the constructor factors
  /// nothing: a query is answered on the factors of a geodesic ball a few
  /// patch radii wide around its source (a subdomain), built the first time
  /// a query needs it and kept for the queries around it. Patches whose
  /// ball would hold more than 262,144 vertices or a quarter of the mesh,
  /// and vertex-set patches, factor the whole mesh when first asked. 0
  /// uses subdomains on every mesh; `SIZE_MAX` never (manual, section 2,
  /// "Subdomains").
  std::size_t subdomain_min_vertices = 200000;
  /// The bytes the cached subdomains may hold: beyond it the least
  /// recently used are dropped (the one a query has just built stays).
  std::size_t subdomain_cache_bytes = std::size_t(1) << 30;
  /// Reports the precomputation's steps as it runs (see
  /// `Precomputation_callback`); empty: no reports. Only the constructor
  /// calls it: the object keeps no copy (its `options()` have none).
  Precomputation_callback progress;
};

/// \ingroup PkgExpmapRef
/// The settings of one heat query: those all methods share
/// (`Query_options`) and the heat method's own. Converts from
/// `Query_options`, with the heat method's settings at their defaults.
struct Heat_query_options : Query_options {
  Heat_query_options() = default;
  /// The shared settings `shared`, the heat method's at their defaults.
  Heat_query_options(const Query_options& shared) : Query_options(shared) {}

  /// A query solves on a region this many times larger (in vertices) than
  /// its patch; the Poisson step's cut-off error stays in the margin.
  /// Range: `setting_ranges`, as for every numeric setting.
  double region_growth = 2.0;
  /// On small patches of meshes of 200,000 vertices or more, heat below
  /// this tolerance times the smallest value read is not propagated
  /// (values move by about this relative amount). 0 never prunes.
  double pruning_tolerance = 1e-12;
  /// How the direction of the geodesic is read off the heat.
  Angle_estimator angle_estimator = Angle_estimator::heat_quadratic_fit;
  /// Geometric directions next to the source, heat directions beyond.
  Near_source_blend near_source_blend;
  /// With 2 the query's star solve runs on a second thread beside
  /// the distance: for one query at a time, as in an interactive tool
  /// (`compute_many()` already keeps every core busy).
  int query_threads = 1;
  /// Where the heat's reading of the angles is blind, the geodesic front's
  /// map instead (see `Heat_fallback`).
  Heat_fallback fallback = Heat_fallback::geodesic_front;
};

/// \ingroup PkgExpmapRef
/// `options` if every setting is in its range (`setting_ranges`).
/// \throws Invalid_input naming the first setting that is not.
inline const Heat_options& checked(const Heat_options& options) {
  checked_setting(setting_ranges::time_factor, options.time_factor);
  checked_setting(setting_ranges::poisson_compression_tolerance,
                  options.poisson_compression_tolerance);
  return options;
}

/// \ingroup PkgExpmapRef
/// `query` if every heat setting is in its range (`setting_ranges`; the
/// shared ones are checked where they are used).
/// \throws Invalid_input naming the first setting that is not.
inline const Heat_query_options& checked(const Heat_query_options& query) {
  const Near_source_blend& blend = query.near_source_blend;
  const Setting_range& blend_range = setting_ranges::near_source_blend;
  if (!blend_range.contains(blend.begin) || !blend_range.contains(blend.end) ||
      !(blend.begin <= blend.end))
    throw Invalid_input(std::string(blend_range.name) + " must be " + blend_range.range +
                        " (got begin " + setting_value_text(blend.begin) + ", end " +
                        setting_value_text(blend.end) + ")");
  checked_setting(setting_ranges::pruning_tolerance, query.pruning_tolerance);
  checked_setting(setting_ranges::query_threads, query.query_threads);
  checked_setting(setting_ranges::region_growth, query.region_growth);
  return query;
}

}  // namespace expmap

#endif  // EXPMAP_HEAT_OPTIONS_H
