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
#include <expmap/Option_names.h>
#include <expmap/Patch.h>
#include <expmap/Precomputation_progress.h>
#include <expmap/Surface_point.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <memory>
#include <type_traits>
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
  /// The bytes of what it keeps that grow fastest with the mesh (heat's
  /// factors, and on subdomains their cache's bound), for deciding how many
  /// variants to keep; 0 for the others.
  virtual std::size_t held_bytes() const { return 0; }
  /// Whether a map with `patch` may first have to factor the whole mesh
  /// (heat on subdomains: `Heat_exponential_map::may_factor_whole_mesh()`).
  virtual bool may_factor_whole_mesh(const expmap::Patch&) const { return false; }
  /// Factors the whole mesh now, reporting to `progress`, where
  /// `may_factor_whole_mesh()` said a map might.
  virtual void factor_whole_mesh(const expmap::Precomputation_callback&) const {}
  /// The exact method's `region_faces()` for this query, counted up to
  /// `at_most` + 1, what its memory grows with; 0 for the other methods.
  virtual std::size_t region_faces(const Point_on_surface&, const expmap::Patch&,
                                   std::size_t /*at_most*/) const {
    return 0;
  }
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
  std::size_t held_bytes() const override {
    if constexpr (is_heat) {
      // The subdomains' cache counts at its bound: it grows with queries,
      // which may also change it between the two reads below.
      const std::size_t cached = m_method.subdomain_bytes();
      const std::size_t all = m_method.factor_bytes();
      const std::size_t bound = m_method.uses_subdomains() ? m_method.options().subdomain_cache_bytes : 0;
      return (all > cached ? all - cached : 0) + bound;
    }
    return 0;
  }
  bool may_factor_whole_mesh(const expmap::Patch& patch) const override {
    if constexpr (is_heat) return m_method.may_factor_whole_mesh(patch);
    return false;
  }
  void factor_whole_mesh(const expmap::Precomputation_callback& progress) const override {
    if constexpr (is_heat) m_method.factor_whole_mesh(progress);
  }
  std::size_t region_faces(const Point_on_surface& source, const expmap::Patch& patch,
                           std::size_t at_most) const override {
    if constexpr (std::is_same_v<Method, expmap::Exact_exponential_map<Mesh>>)
      return m_method.region_faces(source, patch, at_most);
    return 0;
  }

 private:
  static constexpr bool is_heat = std::is_same_v<Method, expmap::Heat_exponential_map<Mesh>>;
  Method m_method;
};

/// One row of the viewer's method table.
struct Method_info {
  const char* name;   ///< as in the URL and the API: the library's (expmap/Option_names.h)
  const char* label;  ///< for the page
  bool takes_time_factor;  ///< heat's m
  /// The most patch vertices one request may ask for (doc/viewer.md).
  std::size_t max_patch_vertices;
  /// The most faces of the exact method's submesh (`region_faces()`); 0:
  /// no such limit.
  std::size_t max_region_faces;
  /// Precomputes the method on `mesh` (which must outlive it), reporting
  /// its steps to `progress`; `time_factor` is used only where
  /// `takes_time_factor`.
  std::unique_ptr<Viewer_method> (*make)(const Mesh& mesh, double time_factor,
                                         const expmap::Precomputation_callback& progress);
};

/// The most patch vertices of a map of DEM, DGPC or heat: their queries
/// take a few hundred milliseconds there, and the answer is about 25 MB of
/// JSON for the page to read.
constexpr std::size_t max_fast_patch_vertices = 250000;
/// The most faces of an exact map's submesh: up to 1.1 GB each by
/// `expmap_cli::exact_query_mib()`, so that the two that may run at once
/// stay within 2.2 GB. Such a submesh holds the geodesics of 10,000 to
/// 18,000 patch vertices, fewer where the surface folds back within reach.
constexpr std::size_t max_exact_region_faces = 40000;
/// The most patch vertices of an exact map: a submesh of
/// `max_exact_region_faces` faces holds about half as many vertices, the
/// patch's and more (2.2 to 4 faces per patch vertex measured), so a request
/// beyond is refused before the graph search that counts its submesh.
constexpr std::size_t max_exact_patch_vertices = 20000;

namespace internal {
// DEM, DGPC and the exact method copy the mesh into their arrays, one step.
template <class Method>
std::unique_ptr<Viewer_method> make_method(const Mesh& mesh, double,
                                           const expmap::Precomputation_callback& progress) {
  if (progress) progress("copying the mesh into the method's arrays", 0);
  auto method = std::make_unique<Viewer_method_model<Method>>(mesh);
  if (progress) progress("done", 1);
  return method;
}
inline std::unique_ptr<Viewer_method> make_heat(const Mesh& mesh, double time_factor,
                                                const expmap::Precomputation_callback& progress) {
  expmap::Heat_options options;
  options.time_factor = time_factor;
  options.progress = progress;
  // On large meshes queries run on subdomains; a patch too large for them
  // factors the whole mesh first, as a precomputation of its own
  // (`Method_cache::acquire()`).
  return std::make_unique<Viewer_method_model<expmap::Heat_exponential_map<Mesh>>>(mesh, options);
}
template <class Method>
Method_info row(expmap::Map_method id, const char* label, std::size_t max_patch_vertices,
                std::size_t max_region_faces = 0) {
  return {expmap::named_value(id).name, label, false, max_patch_vertices, max_region_faces,
          make_method<Method>};
}
}  // namespace internal

/// The methods, in the order the page lists them: the library's.
inline const std::vector<Method_info>& viewer_methods() {
  using expmap::Map_method;
  static const std::vector<Method_info> table{
      {expmap::named_value(Map_method::heat).name, "heat method", true, max_fast_patch_vertices,
       0, internal::make_heat},
      internal::row<expmap::Discrete_exponential_map<Mesh>>(Map_method::dem, "DEM",
                                                            max_fast_patch_vertices),
      internal::row<expmap::Geodesic_polar_coordinates<Mesh>>(Map_method::dgpc, "DGPC",
                                                              max_fast_patch_vertices),
      internal::row<expmap::Exact_exponential_map<Mesh>>(Map_method::exact, "exact",
                                                         max_exact_patch_vertices,
                                                         max_exact_region_faces),
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
