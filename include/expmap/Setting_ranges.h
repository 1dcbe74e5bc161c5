// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_SETTING_RANGES_H
#define EXPMAP_SETTING_RANGES_H

/// \file Setting_ranges.h
/// The range and a line of help of every numeric setting of the heat
/// method, written once: `checked()` tests the settings against them and
/// says their range in its errors, and the command-line program's help and
/// the Python module's docstrings are made from them (a test checks that
/// the manual and the errors agree with the help).

#include <expmap/Errors.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace expmap {

/// \ingroup PkgExpmapRef
/// The values a numeric setting may take: finite and between `lowest` and
/// `highest`, each bound included or not.
struct Setting_range {
  /// Its name: the member of `Heat_options` or `Heat_query_options` and the
  /// Python keyword (the command-line flag is the same with '-' for '_').
  const char* name;
  double lowest;
  bool lowest_included;
  double highest;
  bool highest_included;
  /// The range as help texts and errors say it ("positive", "in [0, 1e-10]").
  const char* range;
  /// One line for help texts.
  const char* help;

  /// Whether `value` is finite and within the bounds.
  bool contains(double value) const {
    if (!std::isfinite(value)) return false;
    const bool above = lowest_included ? value >= lowest : value > lowest;
    const bool below = highest_included ? value <= highest : value < highest;
    return above && below;
  }
};

/// \ingroup PkgExpmapRef
/// The heat method's numeric settings (the precomputation's in
/// `Heat_options`, the query's in `Heat_query_options`).
namespace setting_ranges {

constexpr double unbounded = std::numeric_limits<double>::infinity();

inline constexpr Setting_range time_factor{
    "time_factor", 0, false, unbounded, false, "positive",
    "diffusion time t = time_factor * h^2, h the mean edge length; larger is smoother, smaller "
    "closer to exact geodesics"};
inline constexpr Setting_range poisson_compression_tolerance{
    "poisson_compression_tolerance", 0, true, 1e-10, true, "in [0, 1e-10]",
    "the Poisson factor's low-rank rows below its large separators truncated to this relative "
    "tolerance, so queries on meshes above about 100k vertices read fewer entries; 0 keeps them "
    "dense"};
inline constexpr Setting_range subdomain_min_vertices{
    "subdomain_min_vertices", 0, true, unbounded, false, "at least 0",
    "meshes of at least this many vertices factor nothing up front: a query solves on a geodesic "
    "ball a few patch radii wide around its source, factored when first needed and cached; 0 on "
    "every mesh"};
inline constexpr Setting_range subdomain_cache_bytes{
    "subdomain_cache_bytes", 0, true, unbounded, false, "at least 0",
    "the bytes the cached subdomains may hold; beyond it the least recently used are dropped"};
inline constexpr Setting_range region_growth{
    "region_growth", 1, true, unbounded, false, "at least 1",
    "a query solves on a region this many times larger (in vertices) than its patch; larger "
    "lowers the cut-off error at the region's edge at proportional cost"};
inline constexpr Setting_range pruning_tolerance{
    "pruning_tolerance", 0, true, 1e-10, true, "in [0, 1e-10]",
    "heat solves of small patches of meshes of 200,000+ vertices skip entries below this times "
    "the smallest heat read; 0 never prunes"};
inline constexpr Setting_range query_threads{
    "query_threads", 1, true, 2, true, "1 or 2",
    "threads one query runs on; with 2 the angles' solve runs beside the distance's (the same "
    "map up to round-off, 0.79-0.93x the time on patches of 750+ vertices)"};
/// Both ends of `Near_source_blend`, in mean edge lengths (and begin <= end).
inline constexpr Setting_range near_source_blend{
    "near_source_blend", 0, true, unbounded, false, "0 <= begin <= end, finite",
    "chord directions (and the source's neighbours' edge lengths) up to begin mean edge lengths "
    "from the source, heat coordinates from end on, blended between; (0, 0) for the paper's pure "
    "heat coordinates"};

}  // namespace setting_ranges

/// \ingroup PkgExpmapRef
/// `value` printed as help texts and errors print it (shortest form, "1e-10").
inline std::string setting_value_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// \ingroup PkgExpmapRef
/// `value` if `setting` allows it.
/// \throws Invalid_input "<name> must be <range> (got <value>)" otherwise.
inline double checked_setting(const Setting_range& setting, double value) {
  if (!setting.contains(value))
    throw Invalid_input(std::string(setting.name) + " must be " + setting.range + " (got " +
                        setting_value_text(value) + ")");
  return value;
}

}  // namespace expmap

#endif  // EXPMAP_SETTING_RANGES_H
