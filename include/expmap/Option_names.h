// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_OPTION_NAMES_H
#define EXPMAP_OPTION_NAMES_H

/// \file Option_names.h
/// The names of the methods and of every setting chosen from a list, with
/// a line of help each, written once. The command-line program's options
/// and help, the Python module's enums and the viewer's method list are
/// made from these tables; a test checks the manual against them.

#include <expmap/Errors.h>
#include <expmap/Heat_options.h>

#include <cstddef>
#include <string>

namespace expmap {

/// \ingroup PkgExpmapRef
/// The methods, as the command-line program's `--method`, the viewer and
/// Python's `expmap.METHODS` name them.
enum class Map_method {
  heat,   ///< `Heat_exponential_map`
  dem,    ///< `Discrete_exponential_map`
  dgpc,   ///< `Geodesic_polar_coordinates`
  exact   ///< `Exact_exponential_map`
};

/// \ingroup PkgExpmapRef
/// One value of a setting chosen by name.
template <class Enum>
struct Named_value {
  Enum value;
  /// Its name: the command-line program's spelling; Python's enum member
  /// is the same with '_' for '-' (`python_name()`). Either is accepted.
  const char* name;
  /// A shorter spelling the command-line program also accepts, or nullptr.
  const char* alias;
  /// One line for help texts.
  const char* help;
};

/// \ingroup PkgExpmapRef
/// The names of `Enum`'s values (specialized for each setting below): the
/// setting's name `option` (the command-line option without "--"), its
/// `values` and a line of `help`.
template <class Enum>
struct Option_names;

/// \cond SKIP_IN_MANUAL
template <>
struct Option_names<Map_method> {
  static constexpr const char* option = "method";
  static constexpr const char* help = "the method that computes the map";
  static constexpr Named_value<Map_method> values[] = {
      {Map_method::heat, "heat", nullptr, "smoothed, by heat diffusion (Herholz & Alexa)"},
      {Map_method::dem, "dem", nullptr, "discrete exponential map (Schmidt et al.)"},
      {Map_method::dgpc, "dgpc", nullptr, "geodesic polar coordinates (Melvaer & Reimers)"},
      {Map_method::exact, "exact", nullptr, "exact polyhedral geodesics; slow, a reference"}};
};

template <>
struct Option_names<Laplacian_mode> {
  static constexpr const char* option = "laplacian";
  static constexpr const char* help = "which triangulation the Laplacian is built on";
  static constexpr Named_value<Laplacian_mode> values[] = {
      {Laplacian_mode::intrinsic_delaunay, "intrinsic-delaunay", nullptr,
       "the intrinsic Delaunay triangulation: robust on poorly shaped triangles"},
      {Laplacian_mode::direct, "direct", nullptr, "the input mesh as it is"}};
};

template <>
struct Option_names<Vertex_area> {
  static constexpr const char* option = "vertex-area";
  static constexpr const char* help = "the heat step's mass matrix";
  static constexpr Named_value<Vertex_area> values[] = {
      {Vertex_area::mixed_voronoi, "mixed-voronoi", nullptr,
       "mixed Voronoi areas: more accurate angles on irregular triangles"},
      {Vertex_area::barycentric, "barycentric", nullptr,
       "a third of each incident triangle, as the paper"}};
};

template <>
struct Option_names<Factor_precision> {
  static constexpr const char* option = "factor-precision";
  static constexpr const char* help = "how the factors are kept between queries";
  static constexpr Named_value<Factor_precision> values[] = {
      {Factor_precision::double_precision, "double-precision", "double", "as computed"},
      {Factor_precision::single_precision, "single-precision", "single",
       "about half the memory, faster on large meshes; moves the distances by about 2e-7 "
       "of the radius"}};
};

template <>
struct Option_names<Poisson_regularization> {
  static constexpr const char* option = "regularization";
  static constexpr const char* help = "how the singular Poisson system is made definite";
  static constexpr Named_value<Poisson_regularization> values[] = {
      {Poisson_regularization::pinned_vertex, "pinned-vertex", nullptr,
       "one vertex pinned per connected component (exact)"},
      {Poisson_regularization::cgal_compatible, "cgal-compatible", nullptr,
       "1e-8 per face corner on the diagonal, as CGAL's Heat_method_3"}};
};

template <>
struct Option_names<Angle_estimator> {
  static constexpr const char* option = "angles";
  static constexpr const char* help = "how the angle is read off the heat around the source";
  static constexpr Named_value<Angle_estimator> values[] = {
      {Angle_estimator::heat_quadratic_fit, "heat-quadratic-fit", nullptr,
       "least-squares quadratic of the heat on the two-ring; two solves"},
      {Angle_estimator::heat_gradient, "heat-gradient", nullptr,
       "the paper's area-weighted gradient; two solves"},
      {Angle_estimator::log_heat_gradient, "log-heat-gradient", nullptr,
       "gradient of the log-heat; one solve per neighbour"},
      {Angle_estimator::log_heat_quadratic_fit, "log-heat-quadratic-fit", nullptr,
       "quadratic fit of the log-heat; one solve per neighbour"}};
};

template <>
struct Option_names<Heat_fallback> {
  static constexpr const char* option = "fallback";
  static constexpr const char* help = "what a query returns where the heat's angles are blind";
  static constexpr Named_value<Heat_fallback> values[] = {
      {Heat_fallback::geodesic_front, "geodesic-front", nullptr,
       "where the heat's map folds over, meets a boundary or fails, the geodesic front's "
       "map if it folds less"},
      {Heat_fallback::none, "none", nullptr, "the paper's map always"}};
};
/// \endcond

/// \ingroup PkgExpmapRef
/// Python's spelling of the name `name`: '_' for '-'.
inline std::string python_name(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}

/// \ingroup PkgExpmapRef
/// The table's row of `value`.
template <class Enum, class = decltype(Option_names<Enum>::values)>
const Named_value<Enum>& named_value(Enum value) {
  for (const Named_value<Enum>& v : Option_names<Enum>::values)
    if (v.value == value) return v;
  throw Invalid_input("a value that has no name in expmap/Option_names.h");
}

/// \ingroup PkgExpmapRef
/// The name of `value` (see `Named_value::name`).
template <class Enum, class = decltype(Option_names<Enum>::values)>
std::string to_string(Enum value) {
  return named_value(value).name;
}

/// \ingroup PkgExpmapRef
/// The names of `Enum`'s values, in order, joined by `separator`.
template <class Enum>
std::string value_names(const std::string& separator = ", ") {
  std::string names;
  for (const Named_value<Enum>& v : Option_names<Enum>::values)
    names += (names.empty() ? "" : separator) + std::string(v.name);
  return names;
}

/// \ingroup PkgExpmapRef
/// The value of `Enum` named `name`: its name, its Python spelling or its
/// alias.
/// \throws Invalid_input for any other name, listing the valid ones.
template <class Enum>
Enum from_string(const std::string& name) {
  for (const Named_value<Enum>& v : Option_names<Enum>::values)
    if (name == v.name || name == python_name(v.name) || (v.alias && name == v.alias))
      return v.value;
  throw Invalid_input("unknown " + std::string(Option_names<Enum>::option) + " '" + name +
                      "' (valid: " + value_names<Enum>() + ")");
}

}  // namespace expmap

#endif  // EXPMAP_OPTION_NAMES_H
