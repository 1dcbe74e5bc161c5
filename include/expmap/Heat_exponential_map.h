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
#include <expmap/internal/heat/Subdomain_cache.h>

#include <CGAL/Default.h>

#include <boost/graph/graph_traits.hpp>

#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Precomputes the operators and factorizations of a mesh once and answers
/// exponential-map queries from any source vertex.
///
/// Queries are `const` and thread safe: many threads may call `compute()`
/// on one object. The heat and Poisson systems are solved by localized
/// forward and back substitution on Cholesky factors: of the whole mesh,
/// or, on meshes of `Heat_options::subdomain_min_vertices` or more, of a
/// geodesic ball around the source a few patch radii wide, factored when
/// a query first needs it and cached, so that the first map comes without
/// factoring the whole mesh and a small patch costs about its own size.
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
      : Front(tm, vpm), m_options(checked(options)), m_whole(std::make_unique<Whole_factors>()) {
    using Step = internal::heat::Precomputation_step;
    if (number_of_vertices() >= m_options.subdomain_min_vertices) {
      // Subdomains keep the user's order: their vertices are found in it.
      m_subdomains = std::make_unique<internal::heat::Subdomain_cache<Solver>>(m_indexed.arrays,
                                                                               m_options);
    } else {
      // Queries work on vertices renumbered along a space-filling curve
      // (see internal::locality_order); sources, patches and results use
      // the user's indices.
      internal::heat::report(m_options, Step::locality_order);
      m_indexed.arrays = internal::renumbered_mesh_arrays(
          m_indexed.arrays, internal::locality_order(m_indexed.arrays));
      whole_factors();
      // One workspace ready for the first query: touching its O(n) memory
      // for the first time costs page faults that belong to the
      // precomputation.
      internal::heat::report(m_options, Step::query_workspace);
      m_whole->workspaces.acquire(
          [this] { return make_workspace(m_whole->factors, m_indexed.arrays); });
    }
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
    const internal::Checked_query q =
        internal::checked_query(m_indexed.arrays, source, patch, query);
    return answer(checked_query, q, patch, nullptr);
  }

  /// Diffusion time t = time_factor * h^2.
  double time_step() const {
    const double h = m_indexed.arrays.mean_edge_length;
    return m_options.time_factor * (h * h);
  }
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
    const internal::heat::Heat_factors no_factors;  // the zone is the mesh's geometry
    const internal::heat::Context c(m_indexed.arrays, no_factors, m_options, checked_query, vertex);
    const internal::Near_source_zone zone =
        internal::heat::near_source_zone(c, s, internal::vertex_normal(m_indexed.arrays, s));
    const double h = m_indexed.arrays.mean_edge_length;
    return {zone.begin / h, zone.end / h};
  }
  /// Bytes held by the factors' entries, the bulk of the object's memory
  /// between queries: 8 per entry, 4 per entry kept in single precision;
  /// with the cached subdomains' whole memory (`subdomain_bytes()`).
  std::size_t factor_bytes() const {
    std::size_t bytes = subdomain_bytes();
    if (m_whole->built) {
      const internal::heat::Heat_factors& f = m_whole->factors;
      bytes += f.heat.entry_bytes() + f.poisson.entry_bytes() + f.boundary_heat.entry_bytes();
    }
    return bytes;
  }
  /// Bytes the cached subdomains hold (at most about
  /// `Heat_options::subdomain_cache_bytes` plus the latest one's).
  std::size_t subdomain_bytes() const { return m_subdomains ? m_subdomains->bytes() : 0; }
  /// Whether queries are answered on subdomains (see `Heat_options::subdomain_min_vertices`).
  bool uses_subdomains() const { return m_subdomains != nullptr; }
  /// Whether a query with `patch` may first factor the whole mesh (a
  /// minute on millions of vertices): on subdomains, before that is done,
  /// for vertex-set patches and patches whose ball may hold more vertices
  /// than a subdomain (estimated from the mesh's mean area per vertex).
  bool may_factor_whole_mesh(const Patch& patch) const {
    return m_subdomains && !m_whole->built &&
           m_subdomains->may_need_whole_mesh(m_indexed.arrays, patch,
                                             patch.target_count(number_of_vertices()));
  }
  /// Factors the whole mesh now, as the first query that needs it would,
  /// reporting its steps to `progress` (see `Heat_options::progress`); does
  /// nothing if it is factored. Front ends call it before a query for which
  /// `may_factor_whole_mesh()` holds, so that nothing waits unannounced.
  void factor_whole_mesh(const Precomputation_callback& progress = {}) const {
    Heat_options options = m_options;
    options.progress = progress;
    if (factor_whole(options))
      internal::heat::report(options, internal::heat::Precomputation_step::done);
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
    const internal::Checked_query q =
        internal::checked_point_query(m_indexed.arrays, point, patch, query);
    return answer(checked_query, q, patch, &point);
  }

  // Where a query is solved: the whole mesh, or a subdomain of it.
  struct Domain {
    const internal::Mesh_arrays& mesh;
    const internal::heat::Heat_factors& factors;
    internal::Workspace_pool<internal::heat::Workspace>& workspaces;
    const internal::heat::Subdomain* subdomain;  // null for the whole mesh
  };

  // The query `q` (checked on the whole mesh) from its source vertex, or
  // from `point` if not null: on its ball's subdomain (Subdomain_cache.h),
  // one twice as wide while its region reaches the cut, else on the whole
  // mesh.
  Result answer(const Query& query, const internal::Checked_query& q, const Patch& patch,
                const internal::Point_source* point) const {
    if (m_subdomains && patch.kind() != Patch::Kind::vertex_set &&
        !m_subdomains->surely_too_large(m_indexed.arrays, q.target)) {
      const double radius = m_subdomains->patch_radius(patch, q.target);
      for (double scale = 1;; scale *= 2) {
        const std::shared_ptr<const internal::heat::Subdomain> sub =
            m_subdomains->holding(m_indexed.arrays, q.source, radius, scale);
        if (!sub) break;
        const Domain domain{sub->mesh, sub->factors, sub->workspaces, sub.get()};
        if (std::optional<Result> result = run(domain, query, q, patch, point))
          return std::move(*result);
      }
    }
    const Domain whole{m_indexed.arrays, whole_factors(), m_whole->workspaces, nullptr};
    return std::move(*run(whole, query, q, patch, point));
  }

  // The factors of the whole mesh, built on first use.
  const internal::heat::Heat_factors& whole_factors() const {
    factor_whole(m_options);
    return m_whole->factors;
  }
  // Factors the whole mesh with `options` unless it is; whether it did.
  bool factor_whole(const Heat_options& options) const {
    bool factored = false;
    std::call_once(m_whole->once, [&] {
      m_whole->factors = internal::heat::factor_heat_operators<Solver>(m_indexed.arrays, options);
      m_whole->built = true;
      factored = true;
    });
    return factored;
  }
  static std::optional<internal::Vector3> reference_of(const Query& query) {
    std::optional<internal::Vector3> reference;
    if (query.reference_direction) reference = *query.reference_direction;
    return reference;
  }
  // The query on `domain`, with `q` and `whole_point` in the whole mesh's
  // indices; empty if its region reached the subdomain's cut.
  std::optional<Result> run(const Domain& domain, const Query& query, internal::Checked_query q,
                            const Patch& patch, const internal::Point_source* whole_point) const {
    std::optional<internal::Point_source> point;
    if (whole_point) point = *whole_point;
    if (domain.subdomain) {
      q.source = domain.subdomain->vertex_of(q.source);
      if (point && !(point = domain.subdomain->point_of(*point))) return std::nullopt;
    }
    const internal::Mesh_arrays& mesh = domain.mesh;
    const internal::heat::Source source =
        point ? internal::heat::point_source(*point) : internal::heat::vertex_source(mesh, q.source);
    const internal::heat::Context c(mesh, domain.factors, m_options, query, source);
    auto ws = domain.workspaces.acquire([&] { return make_workspace(domain.factors, mesh); });
    ws->fit_star_solves(domain.factors, c.estimator);
    Solve_statistics statistics;
    std::optional<Result> heat_map;
    try {
      std::vector<internal::Polar_entry> entries = internal::heat::heat_polar_coordinates(
          c, q.frame, reference_of(query), patch, q.target, q.wanted, *ws, statistics);
      heat_map = internal::sorted_local_map(static_cast<int>(mesh.to_original(c.source.lead)),
                                            entries, m_indexed.descriptors, q.frame,
                                            c.source.is_vertex());
    } catch (const Computation_error&) {
      if (c.query.fallback != Heat_fallback::geodesic_front) throw;
    }
    if (domain.subdomain && domain.subdomain->reaches_cut(ws->region)) return std::nullopt;
    const auto front_start = [&] {
      return point ? internal::point_front_start(mesh, *point, q.frame)
                   : internal::vertex_front_start(mesh, q.source, q.frame);
    };
    Result result = internal::heat::sounder_map(c, q, patch, std::move(heat_map), front_start,
                                                m_indexed.descriptors, *ws, statistics);
    result.statistics = statistics;
    return result;
  }
  static std::unique_ptr<internal::heat::Workspace> make_workspace(
      const internal::heat::Heat_factors& factors, const internal::Mesh_arrays& mesh) {
    return std::make_unique<internal::heat::Workspace>(factors, mesh.number_of_vertices());
  }

  // The whole mesh's factors and query workspaces (built on first use
  // where queries use subdomains).
  struct Whole_factors {
    std::once_flag once;
    std::atomic<bool> built{false};
    internal::heat::Heat_factors factors;
    internal::Workspace_pool<internal::heat::Workspace> workspaces;
  };

  using Front::m_indexed;
  Heat_options m_options;
  std::unique_ptr<Whole_factors> m_whole;
  std::unique_ptr<internal::heat::Subdomain_cache<Solver>> m_subdomains;
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
