// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_VIEWER_METHODS_H
#define EXPMAP_TOOLS_VIEWER_VIEWER_METHODS_H

/// \file Viewer_methods.h
/// The methods the viewer offers, behind one interface: a map from a
/// surface point. The table is the one place that knows them.

#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/Surface_point.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace expmap_view {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Map = expmap::Local_map<Mesh::Vertex_index>;
using Point_on_surface = expmap::Surface_point<Mesh::Face_index>;

/// A precomputed method, as the viewer uses it. Queries are thread safe.
class Viewer_method {
 public:
  virtual ~Viewer_method() = default;
  /// The map around `source` (its fold-free radius filled).
  virtual Map compute(const Point_on_surface& source, const expmap::Patch& patch) const = 0;
};

/// `Viewer_method` for a method class of the library.
template <class Method>
class Viewer_method_model final : public Viewer_method {
 public:
  template <class... Args>
  explicit Viewer_method_model(Args&&... args) : m_method(std::forward<Args>(args)...) {}

  Map compute(const Point_on_surface& source, const expmap::Patch& patch) const override {
    expmap::Query_options shared;
    shared.find_fold_free_radius = true;
    const typename Method::Query query(shared);
    return m_method.compute(source, patch, query);
  }

 private:
  Method m_method;
};

/// One row of the viewer's method table.
struct Method_info {
  const char* name;   ///< as in the URL and the API: heat, dem, dgpc, exact
  const char* label;  ///< for the page
  bool takes_time_factor;  ///< heat's m
  /// Precomputes the method on `mesh` (which must outlive it); `time_factor`
  /// is used only where `takes_time_factor`.
  std::unique_ptr<Viewer_method> (*make)(const Mesh& mesh, double time_factor);
};

namespace internal {
template <class Method>
std::unique_ptr<Viewer_method> make_method(const Mesh& mesh, double) {
  return std::make_unique<Viewer_method_model<Method>>(mesh);
}
inline std::unique_ptr<Viewer_method> make_heat(const Mesh& mesh, double time_factor) {
  expmap::Heat_options options;
  options.time_factor = time_factor;
  return std::make_unique<Viewer_method_model<expmap::Heat_exponential_map<Mesh>>>(mesh, options);
}
template <class Method>
constexpr Method_info row(const char* name, const char* label) {
  return {name, label, false, make_method<Method>};
}
}  // namespace internal

/// The methods, in the order the page lists them.
inline const std::vector<Method_info>& viewer_methods() {
  static const std::vector<Method_info> table{
      {"heat", "heat method", true, internal::make_heat},
      internal::row<expmap::Discrete_exponential_map<Mesh>>("dem", "DEM"),
      internal::row<expmap::Geodesic_polar_coordinates<Mesh>>("dgpc", "DGPC"),
      internal::row<expmap::Exact_exponential_map<Mesh>>("exact", "exact"),
  };
  return table;
}

/// The method called `name`, or nullptr.
inline const Method_info* find_method(const std::string& name) {
  for (const Method_info& m : viewer_methods())
    if (name == m.name) return &m;
  return nullptr;
}

/// The default time factor of the heat method.
inline double default_time_factor() { return expmap::Heat_options().time_factor; }

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_VIEWER_METHODS_H
