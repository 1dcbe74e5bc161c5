// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_HEAT_EXPONENTIAL_MAP_H
#define EXPMAP_HEAT_EXPONENTIAL_MAP_H

/// \file Heat_exponential_map.h
/// The smoothed exponential map of Herholz & Alexa: distances and angles
/// from heat diffusion, computed by localized solves on factorizations of
/// the whole mesh. The precomputation is in internal/heat/Heat_factors.h,
/// the query's steps (manual, section 2) in internal/heat/Heat_query.h.

#include <expmap/Angle_estimator.h>
#include <expmap/Cholmod_solver.h>
#include <expmap/Errors.h>
#include <expmap/Heat_options.h>
#include <expmap/Local_map.h>
#include <expmap/Option_names.h>
#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Locality_order.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Method_front.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Workspace_pool.h>
#include <expmap/internal/heat/Factor_inspection.h>
#include <expmap/internal/heat/Heat_factors.h>
#include <expmap/internal/heat/Heat_query.h>
#include <expmap/internal/heat/Map_choice.h>
#include <expmap/internal/heat/Polar_coordinates.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <CGAL/Default.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Precomputes the operators and factorizations of a mesh once and answers
/// exponential-map queries from any source vertex.
///
/// Queries are `const` and thread safe: many threads may call `compute()`
/// on one object. A query costs about the size of its patch, not of the
/// mesh: the heat and Poisson systems are solved by localized forward and
/// back substitution on the whole-mesh Cholesky factors.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (e.g. `CGAL::Surface_mesh`,
///         `CGAL::Polyhedron_3`); all faces must be triangles.
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertex descriptors to
///         points with `x()`, `y()`, `z()` convertible by `CGAL::to_double`.
///         Default: the internal `vertex_point` map.
/// \tparam Solver a model of `SparseCholeskySolver`. Default: `Cholmod_solver`.
///
/// \code
/// expmap::Heat_exponential_map<Mesh> heat(mesh);
/// auto map = heat.compute(source, expmap::Patch::fraction(0.05));
/// for (std::size_t i = 0; i < map.size(); ++i) use(map.vertices[i], map.uv(i));
/// \endcode
template <class TriangleMesh, class VertexPointMap = CGAL::Default,
          class Solver = Cholmod_solver>
class Heat_exponential_map
    : public internal::Method_front<Heat_exponential_map<TriangleMesh, VertexPointMap, Solver>,
                                    TriangleMesh, VertexPointMap, Heat_query_options> {
  using Front = internal::Method_front<Heat_exponential_map, TriangleMesh, VertexPointMap,
                                       Heat_query_options>;

 public:
  using typename Front::Query;
  using typename Front::Result;
  using typename Front::vertex_descriptor;
  using typename Front::Vertex_point_map;

  /// Precomputes operators and factorizations.
  /// \throws Invalid_input for meshes that cannot be used (empty, not
  ///         triangulated, degenerate faces, non-finite coordinates) or
  ///         options out of range.
  /// \throws Computation_error if the solver model cannot factor one of the
  ///         systems (numerically indefinite on nearly degenerate faces);
  ///         the message names the system and carries the model's own.
  explicit Heat_exponential_map(const TriangleMesh& tm, const Heat_options& options = {})
      : Heat_exponential_map(tm, options, get(CGAL::vertex_point, tm)) {}

  /// As above, with an explicit vertex point map.
  Heat_exponential_map(const TriangleMesh& tm, const Heat_options& options, Vertex_point_map vpm)
      : Front(tm, vpm), m_options(checked(options)) {
    using Step = internal::heat::Precomputation_step;
    // Queries work on vertices renumbered along a space-filling curve (see
    // internal::locality_order); sources, patches and results use the
    // user's indices.
    internal::heat::report(m_options, Step::locality_order);
    m_indexed.arrays = internal::renumbered_mesh_arrays(m_indexed.arrays,
                                                        internal::locality_order(m_indexed.arrays));
    m_factors = internal::heat::factor_heat_operators<Solver>(m_indexed.arrays, m_options);
    // One workspace ready for the first query: touching its O(n) memory for
    // the first time costs page faults that belong to the precomputation.
    internal::heat::report(m_options, Step::query_workspace);
    m_workspaces.acquire([this] { return make_workspace(); });
    internal::heat::report(m_options, Step::done);
    // The callback may refer to its caller's objects, which may not outlive
    // the constructor; the object never calls it again.
    m_options.progress = nullptr;
  }

  /// Geodesic polar coordinates around the vertex of index `source` in
  /// `vertices(tm)` for the vertices of `patch`; `compute()` takes a vertex
  /// descriptor, `compute_many()` and `compute_many_by_index()` many sources.
  /// \throws Invalid_input if the index is out of range, the source is
  ///         isolated, the patch names vertices out of range or outside
  ///         the source's component, or a setting of `query` is out of
  ///         range.
  /// \throws Computation_error with `fallback = Heat_fallback::none`, if
  ///         the heat underflows or is not positive inside the patch
  ///         (choose a larger time factor or a smaller patch); by default
  ///         the geodesic front maps the source instead.
  Result compute_by_index(std::size_t source, const Patch& patch,
                          const Query& query = {}) const {
    const Query& checked_query = checked(query);
    const internal::Mesh_arrays& mesh = m_indexed.arrays;
    const internal::Checked_query q = internal::checked_query(mesh, source, patch, query);
    const internal::heat::Source vertex = internal::heat::vertex_source(mesh, q.source);
    return run(context(checked_query, vertex), q, reference_of(query), patch,
               [&] { return internal::vertex_front_start(mesh, q.source, q.frame); });
  }

  /// Diffusion time t = time_factor * h^2.
  double time_step() const { return m_factors.time_step; }
  /// Mean edge length h of the input mesh.
  double mean_edge_length() const { return m_indexed.arrays.mean_edge_length; }
  /// The near-source blend a query with settings `query` from the vertex
  /// of index `source` uses, in mean edge lengths like
  /// `Heat_query_options::near_source_blend`: the query's, scaled so that
  /// the blend ends where the surface normal has turned by 1 rad (by at
  /// most 1.5x; see `Near_source_blend`).
  /// \throws Invalid_input if the index is out of range, the source is
  ///         isolated or a setting of `query` is out of range.
  Near_source_blend near_source_blend_at(std::size_t source, const Query& query = {}) const {
    const Query& checked_query = checked(query);
    const int s = internal::checked_source(m_indexed.arrays, source);
    const internal::heat::Source vertex = internal::heat::vertex_source(m_indexed.arrays, s);
    const internal::heat::Context c = context(checked_query, vertex);
    const internal::Near_source_zone zone =
        internal::heat::near_source_zone(c, s, internal::vertex_normal(m_indexed.arrays, s));
    const double h = m_indexed.arrays.mean_edge_length;
    return {zone.begin / h, zone.end / h};
  }
  /// Bytes held by the factors' entries, the bulk of the object's memory
  /// between queries: 8 per entry, 4 per entry kept in single precision.
  std::size_t factor_bytes() const {
    return m_factors.heat.entry_bytes() + m_factors.poisson.entry_bytes() +
           m_factors.boundary_heat.entry_bytes();
  }
  using Front::number_of_vertices;
  /// The settings the object was built with.
  const Heat_options& options() const { return m_options; }
  /// The estimator a query asking for `requested` uses: `requested`, except
  /// that `heat_quadratic_fit` at a time factor below 4 becomes
  /// `log_heat_quadratic_fit`: there the heat falls by more than a factor e
  /// across the two-ring, beyond what a quadratic of it models.
  Angle_estimator angle_estimator(
      Angle_estimator requested = Heat_query_options().angle_estimator) const {
    return internal::heat::angle_estimator_at(requested, m_options.time_factor);
  }

 private:
  friend Front;  // calls compute_at_point()
  friend internal::heat::Factor_inspection;  // the benchmarks' view of the factors

  /// Polar coordinates around a point of a face that is no vertex (see
  /// `compute(const Surface_point&, ...)`): its heat is its corners'
  /// combined, the gradient stencil and the geometric coordinates next to
  /// it are its corners' (doc/surface_points.md).
  Result compute_at_point(const internal::Point_source& point, const Patch& patch,
                          const Query& query = {}) const {
    const Query& checked_query = checked(query);
    const internal::Mesh_arrays& mesh = m_indexed.arrays;
    const internal::Checked_query q = internal::checked_point_query(mesh, point, patch, query);
    const internal::heat::Source source = internal::heat::point_source(point);
    return run(context(checked_query, source), q, reference_of(query), patch,
               [&] { return internal::point_front_start(mesh, point, q.frame); });
  }

  internal::heat::Context context(const Query& query, const internal::heat::Source& source) const {
    return {m_indexed.arrays, m_factors, m_options, query, source};
  }
  static std::optional<internal::Vector3> reference_of(const Query& query) {
    std::optional<internal::Vector3> reference;
    if (query.reference_direction) reference = *query.reference_direction;
    return reference;
  }
  // The query from c.source, once its frame and patch are known (q);
  // `front_start()` gives the geodesic front's start around the source.
  template <class MakeStart>
  Result run(const internal::heat::Context& c, const internal::Checked_query& q,
             const std::optional<internal::Vector3>& reference, const Patch& patch,
             MakeStart front_start) const {
    const internal::Mesh_arrays& mesh = m_indexed.arrays;
    auto ws = m_workspaces.acquire([this] { return make_workspace(); });
    ws->fit_star_solves(m_factors, c.estimator);
    Solve_statistics statistics;
    std::optional<Result> heat_map;
    try {
      std::vector<internal::Polar_entry> entries = internal::heat::heat_polar_coordinates(
          c, q.frame, reference, patch, q.target, q.wanted, *ws, statistics);
      heat_map = internal::sorted_local_map(static_cast<int>(mesh.to_original(c.source.lead)),
                                            entries, m_indexed.descriptors, q.frame,
                                            c.source.is_vertex());
    } catch (const Computation_error&) {
      if (c.query.fallback != Heat_fallback::geodesic_front) throw;
    }
    Result result = internal::heat::sounder_map(c, q, patch, std::move(heat_map), front_start,
                                                m_indexed.descriptors, *ws, statistics);
    result.statistics = statistics;
    return result;
  }
  std::unique_ptr<internal::heat::Workspace> make_workspace() const {
    return std::make_unique<internal::heat::Workspace>(m_factors, number_of_vertices());
  }

  using Front::m_indexed;
  Heat_options m_options;
  internal::heat::Heat_factors m_factors;
  mutable internal::Workspace_pool<internal::heat::Workspace> m_workspaces;
};

/// \ingroup PkgExpmapRef
/// One-shot heat exponential map: precomputes for `tm` and answers a single
/// query. Same defaults as `Heat_exponential_map`. Build the class instead
/// when computing more than one map on a mesh.
template <class TriangleMesh>
Local_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> estimate_exponential_map(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    const Patch& patch, const Heat_options& options = {}, const Heat_query_options& query = {}) {
  return Heat_exponential_map<TriangleMesh>(tm, options).compute(source, patch, query);
}

}  // namespace expmap

#endif  // EXPMAP_HEAT_EXPONENTIAL_MAP_H
