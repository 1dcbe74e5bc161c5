// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_HEAT_EXPONENTIAL_MAP_H
#define EXPMAP_HEAT_EXPONENTIAL_MAP_H

/// \file Heat_exponential_map.h
/// The smoothed exponential map of Herholz & Alexa: distances and angles
/// from heat diffusion, computed by localized solves on factorizations of
/// the whole mesh.

#include <expmap/Angle_estimator.h>
#include <expmap/Cholmod_solver.h>
#include <expmap/Errors.h>
#include <expmap/Factor_precision.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Bessel_k0.h>
#include <expmap/internal/Boundary_loops.h>
#include <expmap/internal/Cotan_operators.h>
#include <expmap/internal/Faces_by_smallest_corner.h>
#include <expmap/internal/Intrinsic_delaunay.h>
#include <expmap/internal/Kth_largest.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Localized_cholesky_solver.h>
#include <expmap/internal/Radix_sort.h>
#include <expmap/internal/Locality_order.h>
#include <expmap/internal/Method_front.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Near_source_zone.h>
#include <expmap/internal/Nearest_first.h>
#include <expmap/internal/Normalized_gradient_divergence.h>
#include <expmap/internal/Parallel_loop.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Star_gradient.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Triangulation_adjacency.h>
#include <expmap/internal/Workspace_pool.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <future>
#include <limits>
#include <memory>
#include <numeric>
#include <string>
#include <system_error>
#include <vector>

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
  /// Consistent with the cotan Laplacian only where the triangles are
  /// regular: elsewhere M^-1 L misreads even a quadratic, and the heat
  /// carries that error into the angles.
  barycentric,
  /// The mixed Voronoi area of Meyer et al. (VisMath 2002): the vertex's
  /// Voronoi cell within each non-obtuse triangle, and a half (at the
  /// obtuse corner) or a quarter of an obtuse one. On a planar Delaunay
  /// mesh of non-obtuse triangles M^-1 L is exact for quadratics. The same
  /// total area; on regular triangles the same as `barycentric`.
  mixed_voronoi
};

/// \ingroup PkgExpmapRef
/// How the singular Poisson system of the distance step is made definite.
enum class Poisson_regularization {
  /// Pins one vertex per connected component. Exact: the distance is
  /// defined up to a constant, and the right-hand side always sums to zero.
  pinned_vertex,
  /// Adds 1e-8 per incident face corner to the diagonal of the cotan matrix
  /// in both solves, as CGAL's Heat_method_3 does. Only for comparisons:
  /// it perturbs distances by about 1e-4 relative on 25k-vertex meshes.
  cgal_compatible
};

/// \ingroup PkgExpmapRef
/// Settings fixed at precomputation (they change the factorizations).
struct Heat_options {
  /// Diffusion time t = time_factor * h^2, h the mean edge length of the
  /// input mesh. Larger values give smoother maps; see the manual for the
  /// measurements behind the default.
  double time_factor = 10.0;
  /// Time factor of the heat solve the distance is integrated from, when it
  /// should differ from the one the angles are read from (a smaller value
  /// keeps distances closer to geodesic while the angles stay smooth).
  /// Costs one more factorization: about 50% more precomputation time and
  /// memory. Default: `time_factor`.
  std::optional<double> distance_time_factor;
  /// The intrinsic Delaunay triangulation keeps the heat positive and the
  /// distance minimal at the source on meshes with obtuse triangles, and
  /// gave fewer fold-overs on real meshes (doc/folds.md); on Delaunay meshes
  /// both modes are the same.
  Laplacian_mode laplacian = Laplacian_mode::intrinsic_delaunay;
  /// The heat step's mass matrix, on the triangulation the Laplacian is
  /// built on. The mixed Voronoi area gave 4-43% smaller angle errors on
  /// jittered analytic surfaces and the same on real meshes (manual,
  /// section 4).
  Vertex_area vertex_area = Vertex_area::mixed_voronoi;
  /// How the Poisson system of the distance step is made definite.
  Poisson_regularization regularization = Poisson_regularization::pinned_vertex;
  /// A query solves on a region about this many times larger (in vertex
  /// count) than the patch; the Poisson step's cut-off error lives in the
  /// margin. Must be at least 1.
  double region_growth = 2.0;
  /// The heat from the source decays exponentially with distance, and so do
  /// the triangular solves' intermediate values: on small patches of large
  /// meshes (a component of at least 200,000 vertices, 2.6 times the patch
  /// at most 1/10 of it), entries of the heat solves below this tolerance times the
  /// smallest value read are not propagated
  /// (`Localized_cholesky_solver::solve_pruned`), which skips most of the
  /// dense top separators. Every value read stays within about this
  /// tolerance of the unpruned one, relative to itself (the query checks its
  /// guess of the threshold and solves again if it was too bold). Used when
  /// the heat matrix is an M-matrix (intrinsic Delaunay Laplacian and no
  /// obtuse angle opposite a boundary edge); 0 never prunes. At most 1e-10.
  ///
  /// Why 1e-12: a relative change δ of the heat turns a face's direction by
  /// at most about 2 m δ (m = `time_factor`: the log-heat's slope is d / 2t,
  /// its change across an edge δ / h), so the distance moves by at most
  /// about 2e-11 of the radius at m = 10, below the 1e-10 the library
  /// allows itself; measured, the maps move by about 1e-15. Against 1e-14,
  /// 0.1% patches of a 2.85M-vertex mesh take 0.93x the time
  /// (doc/paper_scale.md).
  double pruning_tolerance = 1e-12;
  /// The precision the factors are kept in between queries. Single
  /// precision stores in floats every supernode whose entries a float holds
  /// to full precision (the heat factors' top separators, whose entries
  /// decay below the float range, stay double): about half the memory, and
  /// queries 1.1-1.2x faster on meshes of 711k and 2.85M vertices, moving
  /// distances by at most 4e-7 of the patch radius and angles by at most
  /// 1.7e-5 rad (doc/performance.md).
  Factor_precision factor_precision = Factor_precision::double_precision;
  /// The rows below the Poisson factor's large separators (at least 128
  /// columns and 128 rows below) are kept as truncated singular value
  /// decompositions, singular values at or below this tolerance times the
  /// block's largest dropped, where that takes at most 0.7 of the block's
  /// entries. Every solve reads the separators on its path to the root, and
  /// those rows couple far-apart parts of the mesh at low numerical rank;
  /// in low-rank form a solve reads fewer entries: 0.85x the query time at
  /// 0.1% patches of a 2.85M-vertex mesh, 0.96x at 1-5% of a 711k-vertex
  /// one, where the maps moved by at most 1.1e-14 of the radius
  /// (doc/paper_scale.md); meshes below about 100k vertices have no such
  /// blocks. The heat factors stay dense: their pruned solves need every
  /// value accurate relative to itself, however small, which an absolute
  /// truncation does not give. With single-precision factors
  /// (`factor_precision`) the Poisson blocks kept in floats are truncated at
  /// 1e-7 instead, about their rounding: 0.82x / 0.94x the query time of
  /// single precision alone at 0.1% / 1% patches of the 2.85M-vertex mesh,
  /// the maps moved by at most 6.6e-8 of the radius.
  ///
  /// 0 keeps every block dense. At most 1e-10.
  double poisson_compression_tolerance = 1e-14;
  /// How the direction of the geodesic is read off the heat.
  Angle_estimator angle_estimator = Angle_estimator::heat_quadratic_fit;
  /// Geometric directions next to the source, heat directions beyond.
  Near_source_blend near_source_blend;
  /// Threads one query runs on: 1 or 2. With 2, the star solve of the
  /// angles (manual, section 2, step 6) runs on a second thread, for the
  /// whole region, while the calling thread integrates the distance on it
  /// (step 4); the patch then reads its rows. Where no thread can be
  /// started, the query runs on one. The maps are those of one thread up
  /// to round-off (1e-15), and a query takes 0.89-0.97x the time at 2-25%
  /// patches of meshes of 26k-44k vertices, 0.84-0.87x at 1-25% of a
  /// 711k-vertex one and 0.79x at 0.1% of a 2.85M-vertex one
  /// (doc/performance.md); regions of fewer than 1,500 vertices stay on one
  /// thread. The second thread's workspace, another n x 16 doubles, is made
  /// with the object (for its first query) and by any other query that
  /// uses it. For one query at a time, as in an interactive tool:
  /// `compute_many()` on more than one thread already keeps every core busy
  /// with a query each, and runs each on one.
  int query_threads = 1;
};

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
                                    TriangleMesh, VertexPointMap> {
  using Front = internal::Method_front<Heat_exponential_map, TriangleMesh, VertexPointMap>;

 public:
  using typename Front::Result;
  using typename Front::vertex_descriptor;
  using typename Front::Vertex_point_map;

  /// Precomputes operators and both factorizations.
  /// \throws Invalid_input for meshes that cannot be used (empty, not
  ///         triangulated, degenerate faces, non-finite coordinates) or a
  ///         non-positive time factor.
  /// \throws Computation_error if the solver model cannot factor one of the
  ///         systems (numerically indefinite on nearly degenerate faces);
  ///         the message names the system and carries the model's own.
  explicit Heat_exponential_map(const TriangleMesh& tm, const Heat_options& options = {})
      : Heat_exponential_map(tm, options, get(CGAL::vertex_point, tm)) {}

  /// As above, with an explicit vertex point map.
  Heat_exponential_map(const TriangleMesh& tm, const Heat_options& options, Vertex_point_map vpm)
      : Front(tm, vpm), m_options(checked(options)) {
    // Queries work on vertices renumbered along a space-filling curve (see
    // internal::locality_order); sources, patches and results use the
    // user's indices.
    m_indexed.arrays = internal::renumbered_mesh_arrays(m_indexed.arrays,
                                                        internal::locality_order(m_indexed.arrays));
    build_operators();
    // One workspace ready for the first query: touching its O(n) memory for
    // the first time costs page faults that belong to the precomputation.
    // With a second thread per query, its solver workspace too (one query
    // at a time is what that option is for).
    m_workspaces.acquire([this] {
      auto ws = std::make_unique<Workspace>(*this);
      if (m_options.query_threads > 1)
        ws->region_star_solve = internal::Localized_cholesky_solver::Workspace(
            m_heat_local.size(), m_heat_local.number_of_supernodes(),
            is_linear_in_heat(m_angle_estimator)
                ? (m_separate_distance_heat ? 3 : 2)
                : internal::Localized_cholesky_solver::max_block_width);
      return ws;
    });
  }

  /// Geodesic polar coordinates around the vertex of index `source` in
  /// `vertices(tm)` for the vertices of `patch`; `compute()` takes a vertex
  /// descriptor, `compute_many()` and `compute_many_by_index()` many sources.
  /// \throws Invalid_input if the index is out of range, the source is
  ///         isolated or the patch names vertices out of range or outside
  ///         the source's component.
  /// \throws Computation_error if heat underflows inside the patch (choose a
  ///         larger time factor or a smaller patch).
  Result compute_by_index(std::size_t source, const Patch& patch,
                          const Query_options& query = {}) const;

  /// Diffusion time t = time_factor * h^2 of the heat the angles come from.
  double time_step() const { return m_time_step; }
  /// Diffusion time of the heat the distance comes from.
  double distance_time_step() const { return m_distance_time_step; }
  /// Mean edge length h of the input mesh.
  double mean_edge_length() const { return m_indexed.arrays.mean_edge_length; }
  /// The near-source blend a query from the vertex of index `source` uses,
  /// in mean edge lengths like `Heat_options::near_source_blend`: the
  /// option's, scaled so that the blend ends where the surface normal has
  /// turned by `blend_normal_turn` (by at most `max_near_source_widening`).
  /// Vertices nearer than `begin` h take geometric coordinates, those from
  /// `end` h on the heat's.
  /// \throws Invalid_input if the index is out of range or the source is
  ///         isolated.
  Near_source_blend near_source_blend_at(std::size_t source) const {
    const int s = internal::checked_source(m_indexed.arrays, source);
    const internal::Near_source_zone zone =
        near_source_zone(s, internal::vertex_normal(m_indexed.arrays, s));
    const double h = m_indexed.arrays.mean_edge_length;
    return {zone.begin / h, zone.end / h};
  }
  /// Elimination-tree height of the heat factor (columns on its longest path).
  int heat_tree_height() const { return m_heat_local.tree_height(); }
  /// Elimination-tree height of the Poisson factor.
  int poisson_tree_height() const { return m_poisson_local.tree_height(); }
  /// Supernodes of the Poisson factor whose rows below are kept in low-rank
  /// form (`Heat_options::poisson_compression_tolerance`).
  std::size_t poisson_compressed_supernodes() const {
    return m_poisson_local.number_of_compressed_supernodes();
  }
  /// Stored entries of all factors (heat, Poisson and, if separate, the
  /// distance heat), in the dense supernodal form the queries traverse.
  std::size_t factor_nonzeros() const {
    return m_heat_local.number_of_entries() + m_poisson_local.number_of_entries() +
           (m_separate_distance_heat ? m_distance_heat_local.number_of_entries() : 0);
  }
  /// Bytes held by the factors' entries, the bulk of the object's memory
  /// between queries: 8 per entry, 4 per entry kept in single precision
  /// (`Heat_options::factor_precision`).
  std::size_t factor_bytes() const {
    return m_heat_local.entry_bytes() + m_poisson_local.entry_bytes() +
           (m_separate_distance_heat ? m_distance_heat_local.entry_bytes() : 0);
  }
  using Front::number_of_vertices;
  /// The settings the object was built with.
  const Heat_options& options() const { return m_options; }
  /// The estimator the queries use: `options().angle_estimator`, except
  /// that `heat_quadratic_fit` at a time factor below
  /// `min_time_factor_of_two_ring_fit` becomes `log_heat_quadratic_fit`.
  Angle_estimator angle_estimator() const { return m_angle_estimator; }

  /// Below this time factor the heat falls by more than a factor e across
  /// the two-ring (its log-gradient is about 1 / sqrt(t), the two-ring's
  /// radius 2h), beyond what `heat_quadratic_fit`'s cubic correction models
  /// (measured at m = 1: mean angle errors of 0.02-0.5 rad on spheres).
  static constexpr double min_time_factor_of_two_ring_fit = 4.0;

  /// The near-source blend (`Heat_options::near_source_blend`) is stretched
  /// by up to this factor where the surface is flat at its scale. Measured
  /// on the accuracy study (doc/results.md, section 0): stretching 2h-6h to
  /// 3h-9h lowers the mean angle error on every surface, regular and
  /// jittered, and to 4h-12h lowers most but raises the regular saddle's at
  /// h = 0.05.
  static constexpr double max_near_source_widening = 1.5;
  /// The normal's turn (rad) across the blend's end at which the blend
  /// keeps its nominal width. A query scales the blend by this turn over the
  /// turn it measures: wider where the surface is flatter (up to
  /// max_near_source_widening), narrower where it bends more. Projected
  /// chords are good directions where the surface is nearly flat; on a
  /// coarse, curved one-ring its intrinsic angles disagree with the heat's
  /// directions of the next rings, and a blend between them shears the
  /// triangles in between over. Narrowing the blend where the normal turns
  /// by more than 1 rad took the patches with folds of doc/folds.md from
  /// 176 to 165 of 300 (dino 45 -> 38, bull 45 -> 42) and lowered the
  /// largest angle error against the exact map within 2h on all six meshes.
  static constexpr double blend_normal_turn = 1.0;

 private:
  // What a star solve writes: its right-hand side and the heat from the
  // star on the rows asked for, row-major.
  struct Star_solve {
    std::vector<internal::Rhs_entry> rhs;
    std::vector<double> heat;
  };

  struct Workspace {
    explicit Workspace(const Heat_exponential_map& owner)
        : heat_solve(owner.m_heat_local.size(), owner.m_heat_local.number_of_supernodes(),
                     is_linear_in_heat(owner.m_angle_estimator)
                         ? (owner.m_separate_distance_heat ? 3 : 2)
                         : internal::Localized_cholesky_solver::max_block_width),
          poisson_solve(owner.m_poisson_local.size(), owner.m_poisson_local.number_of_supernodes(),
                        1),
          tentative(owner.number_of_vertices()) {
      if (owner.m_separate_distance_heat)
        distance_heat_solve = internal::Localized_cholesky_solver::Workspace(
            owner.m_distance_heat_local.size(), owner.m_distance_heat_local.number_of_supernodes(),
            1);
      if (owner.has_boundary())
        boundary_heat_solve = internal::Localized_cholesky_solver::Workspace(
            owner.m_boundary_heat_local.size(), owner.m_boundary_heat_local.number_of_supernodes(),
            is_linear_in_heat(owner.m_angle_estimator)
                ? 3
                : internal::Localized_cholesky_solver::max_block_width);
      in_region.resize(owner.number_of_vertices());
      seen.resize(owner.number_of_vertices());
      wanted.resize(owner.number_of_vertices());
    }
    internal::Localized_cholesky_solver::Workspace heat_solve, distance_heat_solve, poisson_solve,
        boundary_heat_solve;
    // The second thread's (query_threads 2): sized by the first solve that
    // uses it (or, in the constructor's workspace, made at once), so a
    // workspace of a parallel batch, whose queries run on one thread each,
    // never holds it.
    internal::Localized_cholesky_solver::Workspace region_star_solve;
    internal::Vertex_marks in_region, seen, wanted;
    std::vector<double> tentative;
    std::vector<int> candidates;       // vertices the heat is solved for
    std::size_t breadth_first_head = 0;  // where their breadth-first search can go on
    std::vector<int> region;           // the hottest candidates: where distance is integrated
    std::vector<std::size_t> heat_row; // row of each region vertex in `heat`, ascending
    std::vector<std::size_t> rows;     // scratch for hottest_rows
    std::vector<double> heat_values;   // scratch for hottest_rows
    std::vector<int> region_by_index;  // the region in vertex order: walks per-vertex arrays in memory order
    std::vector<int> sort_scratch;
    std::vector<int> cut_short_at;     // hottest candidates on the candidates' edge
    std::vector<int> frontier, next_frontier;  // scratch for grow_rings_around
    std::vector<int> patch;            // the patch vertices, nearest first
    std::vector<internal::Rhs_entry> rhs;
    Star_solve star;                   // the star solve on the patch
    Star_solve boundary_star;          // its Dirichlet twin, where the region meets a boundary
    bool meets_boundary = false;       // whether boundary_star holds this query's solve
    Star_solve region_star;            // the star solve of a second thread, on the region
    std::vector<double> heat;          // heat from the source on the candidates
    bool prune = false;                // whether this query's heat solves are pruned
    double heat_drop_below = 0;        // the source heat's pruning threshold (0: not pruned)
    std::vector<double> region_heat;   // ws.heat at each region vertex
    std::vector<double> divergence, potential;
  };

  // The options, validated before anything is factored.
  static const Heat_options& checked(const Heat_options& options) {
    auto check_time = [](double m, const char* name) {
      if (!(m > 0) || !std::isfinite(m))
        throw Invalid_input(std::string("the ") + name + " must be positive and finite (got " +
                            std::to_string(m) + ")");
    };
    check_time(options.time_factor, "time factor");
    if (options.distance_time_factor)
      check_time(*options.distance_time_factor, "distance time factor");
    const Near_source_blend& blend = options.near_source_blend;
    if (!(blend.begin >= 0) || !(blend.end >= blend.begin) || !std::isfinite(blend.end))
      throw Invalid_input("near_source_blend must satisfy 0 <= begin <= end < infinity (got begin " +
                          std::to_string(blend.begin) + ", end " + std::to_string(blend.end) + ")");
    if (!(options.pruning_tolerance >= 0) || !(options.pruning_tolerance <= 1e-10))
      throw Invalid_input("pruning_tolerance must be in [0, 1e-10] (got " +
                          std::to_string(options.pruning_tolerance) + ")");
    if (!(options.poisson_compression_tolerance >= 0) ||
        !(options.poisson_compression_tolerance <= 1e-10))
      throw Invalid_input("poisson_compression_tolerance must be in [0, 1e-10] (got " +
                          std::to_string(options.poisson_compression_tolerance) + ")");
    if (options.query_threads != 1 && options.query_threads != 2)
      throw Invalid_input("query_threads must be 1 or 2 (got " +
                          std::to_string(options.query_threads) + ")");
    if (!(options.region_growth >= 1) || !std::isfinite(options.region_growth))
      throw Invalid_input("region_growth must be at least 1 (got " +
                          std::to_string(options.region_growth) + ")");
    return options;
  }

  void build_operators() {
    internal::Intrinsic_triangulation tri = m_indexed.arrays.intrinsic_triangulation();
    if (m_options.laplacian == Laplacian_mode::intrinsic_delaunay)
      internal::make_intrinsic_delaunay(tri);
    const std::vector<internal::Triangle_shape> shapes = internal::triangle_shapes(tri);
    m_faces = internal::Faces_by_smallest_corner(tri, shapes);
    m_heat_neighbors = internal::vertex_adjacency(tri);

    const double corner_regularization =
        m_options.regularization == Poisson_regularization::cgal_compatible ? 1e-8 : 0.0;
    internal::Sparse_matrix L = internal::cotan_laplacian(tri, shapes, corner_regularization);
    const Eigen::VectorXd mass = m_options.vertex_area == Vertex_area::mixed_voronoi
                                     ? internal::mixed_voronoi_mass(tri, shapes)
                                     : internal::lumped_mass(tri, shapes);
    m_mean_vertex_area = mass.sum() / static_cast<double>(std::max<Eigen::Index>(1, mass.size()));
    const double h2 = m_indexed.arrays.mean_edge_length * m_indexed.arrays.mean_edge_length;
    m_time_step = m_options.time_factor * h2;
    m_distance_time_step = m_options.distance_time_factor.value_or(m_options.time_factor) * h2;
    m_separate_distance_heat = m_distance_time_step != m_time_step;
    m_angle_estimator = m_options.angle_estimator;
    if (m_angle_estimator == Angle_estimator::heat_quadratic_fit &&
        m_options.time_factor < min_time_factor_of_two_ring_fit)
      m_angle_estimator = Angle_estimator::log_heat_quadratic_fit;

    std::vector<int> isolated;
    for (std::size_t v = 0; v < m_indexed.arrays.number_of_vertices(); ++v)
      if (m_indexed.arrays.is_isolated(static_cast<int>(v))) isolated.push_back(static_cast<int>(v));

    auto heat_matrix = [&](double t) {
      internal::Sparse_matrix heat = t * L;
      for (int v = 0; v < heat.rows(); ++v) heat.coeffRef(v, v) += mass[v];
      internal::make_identity_row(heat, isolated);
      return heat;
    };
    {
      const internal::Sparse_matrix heat = heat_matrix(m_time_step);
      m_heat_local = factor_locally(heat, "heat", nullptr, m_options.factor_precision);
      if (!m_separate_distance_heat) prepare_pruning(heat);
      factor_boundary_heat(heat, isolated);
    }
    if (m_separate_distance_heat) {
      const internal::Sparse_matrix distance_heat = heat_matrix(m_distance_time_step);
      m_distance_heat_local = factor_locally(distance_heat, "distance heat", &m_heat_local,
                                             m_options.factor_precision);
      prepare_pruning(distance_heat);
    }

    // Identity rows need a zero right-hand side: isolated vertices get no
    // divergence anyway, and a pinned vertex's potential must stay 0.
    std::vector<int> identity_rows = isolated;
    m_is_pinned.assign(m_indexed.arrays.number_of_vertices(), 0);
    if (m_options.regularization == Poisson_regularization::pinned_vertex) {
      std::vector<char> component_pinned(m_indexed.arrays.component_size.size(), 0);
      for (std::size_t v = 0; v < m_indexed.arrays.number_of_vertices(); ++v) {
        const int c = m_indexed.arrays.component[v];
        if (!component_pinned[c] && !m_indexed.arrays.is_isolated(static_cast<int>(v))) {
          component_pinned[c] = 1;
          m_is_pinned[v] = 1;
          identity_rows.push_back(static_cast<int>(v));
        }
      }
    }
    internal::make_identity_row(L, identity_rows);
    m_poisson_local =
        factor_locally(L, "Poisson", &m_heat_local, m_options.factor_precision);
    internal::Rows_below_compression compression;
    compression.tolerance = m_options.poisson_compression_tolerance;
    if (compression.tolerance > 0)
      compression.single_tolerance =
          std::max(compression.tolerance, single_precision_compression_tolerance);
    m_poisson_local.compress_rows_below(compression);
  }

  // The heat matrix with the boundary vertices' rows and columns made
  // identity: the heat with a zero (Dirichlet) boundary condition, beside
  // the natural (Neumann) one of `heat` (see solve_boundary_star_heat).
  // Loops shorter than the heat's length scale sqrt(t) are left out: such a
  // pinhole barely changes the Neumann heat, while zero heat on it is a
  // sink (ChineseDragon-10kv's two three-vertex holes, a fiftieth of an
  // edge across, took its mean angle errors from 0.16 to 0.47 rad). Not
  // built when no loop is that long.
  void factor_boundary_heat(internal::Sparse_matrix heat, std::vector<int> identity_rows) {
    m_is_boundary =
        internal::vertices_on_long_boundary_loops(m_indexed.arrays, std::sqrt(m_time_step));
    if (!has_boundary()) return;
    for (std::size_t v = 0; v < m_is_boundary.size(); ++v)
      if (m_is_boundary[v]) identity_rows.push_back(static_cast<int>(v));
    internal::make_identity_row(heat, identity_rows);
    m_boundary_heat_local =
        factor_locally(heat, "boundary heat", &m_heat_local, m_options.factor_precision);
  }
  bool has_boundary() const { return !m_is_boundary.empty(); }
  bool touches_boundary(const std::vector<int>& vertices) const {
    return has_boundary() && std::any_of(vertices.begin(), vertices.end(), [&](int v) {
             return m_is_boundary[static_cast<std::size_t>(v)] != 0;
           });
  }

  // Factors A with the solver model and keeps only the supernodal copy the
  // localized solves traverse (the model's own factor is released at once,
  // halving the memory held between queries).
  //
  // `like` is an earlier factor of a matrix with the same (or a larger)
  // sparsity pattern: the Poisson and distance-heat matrices have the heat
  // matrix's pattern, so a solver model that accepts an ordering reuses the
  // heat factor's instead of computing the same nested dissection again
  // (METIS is most of a factorization's time on large meshes,
  // doc/performance.md).
  template <class Model = Solver>
  static auto factor_with_ordering(Model& solver, const internal::Sparse_matrix& A,
                                   const std::vector<int>& ordering, int)
      -> decltype(solver.factor(A, ordering), void()) {
    solver.factor(A, ordering);
  }
  template <class Model = Solver>
  static void factor_with_ordering(Model& solver, const internal::Sparse_matrix& A,
                                   const std::vector<int>&, long) {
    solver.factor(A);
  }
  // A solver model reports failure in its own way (CHOLMOD's status, Eigen's
  // info); the user sees one Computation_error naming the system.
  static internal::Localized_cholesky_solver factor_locally(
      const internal::Sparse_matrix& A, const char* system,
      const internal::Localized_cholesky_solver* like, Factor_precision precision) {
    Solver solver;
    try {
      if (like)
        factor_with_ordering(solver, A, like->permutation(), 0);
      else
        solver.factor(A);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw Computation_error(std::string("the ") + system + " matrix could not be factored (" +
                              e.what() + "); nearly degenerate faces make it numerically "
                              "indefinite: repair the mesh (expmap --repair) or remesh it");
    }
    return internal::Localized_cholesky_solver(solver.factor_view(), precision);
  }

  // Pruned source-heat solves rely on the distance-heat matrix being an
  // M-matrix (no positive off-diagonal entry): its inverse factor is then
  // nonnegative, so pruning can only lower values and a too-bold threshold
  // shows in the smallest value returned. Its diagonal bounds the heat at
  // the source from below: (A^-1)_ss >= 1 / A_ss for any SPD matrix.
  // The same property lets the source-heat solve find the hottest vertices
  // largest first (Localized_cholesky_solver::solve_largest).
  void prepare_pruning(const internal::Sparse_matrix& A) {
    m_pruning_tolerance = 0;
    m_inverse_heat_diagonal.clear();
    const Eigen::VectorXd diagonal = A.diagonal();
    // Interior edges of an intrinsic Delaunay triangulation have
    // nonnegative cotan weights (up to its flip slack, 1e-12, and rounding);
    // a boundary edge opposite an obtuse angle has a negative one, and then
    // the heat solves are neither pruned nor largest first.
    m_distance_heat_is_m_matrix = false;
    for (int k = 0; k < A.outerSize(); ++k)
      for (internal::Sparse_matrix::InnerIterator it(A, k); it; ++it)
        if (it.row() != it.col() &&
            it.value() > 1e-12 * std::sqrt(diagonal[it.row()] * diagonal[k]))
          return;
    m_distance_heat_is_m_matrix = true;
    if (m_options.pruning_tolerance == 0) return;
    m_inverse_heat_diagonal.resize(static_cast<std::size_t>(A.rows()));
    for (int v = 0; v < A.rows(); ++v) m_inverse_heat_diagonal[v] = 1.0 / diagonal[v];
    m_pruning_tolerance = m_options.pruning_tolerance;
  }

  const internal::Localized_cholesky_solver& distance_heat() const {
    return m_separate_distance_heat ? m_distance_heat_local : m_heat_local;
  }

  // The truncation of a Poisson block kept in floats (`factor_precision`
  // single): its entries are rounded to about 6e-8 of themselves already.
  static constexpr double single_precision_compression_tolerance = 1e-7;

  // Candidates solved for heat per patch vertex wanted, beyond `region_growth`.
  static constexpr double candidate_excess = 1.3;

  // Candidates per region vertex when the first candidates cut the region
  // short (see `region_is_cut_short`).
  static constexpr double widened_candidate_excess = 2.5;
  static constexpr int targeted_widening_rounds = 3;
  // Rings added around the cut-short vertices per round: a fifth of the
  // patch's radius in edge hops (a disk of n vertices on a regular
  // triangulation has a radius of about sqrt(n / 3) hops).
  static int targeted_widening_rings(std::size_t target) {
    return std::max(2, static_cast<int>(std::ceil(0.2 * std::sqrt(static_cast<double>(target) / 3))));
  }

  // Breadth-first candidates for a patch of `target` vertices `growth` times
  // larger, `excess` times as many.
  static std::size_t breadth_first_budget(std::size_t target, double growth, double excess) {
    return static_cast<std::size_t>(std::ceil(growth * excess * static_cast<double>(target))) +
           16;
  }
  // Fills ws.candidates, nearest first by graph distance, `excess` times as
  // many as a patch `growth` times larger than asked.
  void grow_candidates(int s, const Patch& patch, std::size_t target,
                       const std::vector<int>& wanted, double growth, double excess,
                       Workspace& ws) const;
  // Step 1 (distance part): the heat from the source on the candidates
  // (fills ws.heat, one value per candidate).
  Solve_statistics solve_source_heat(int s, Workspace& ws) const;
  // The same, pruned below ws.heat_drop_below (not pruned if it is 0).
  Solve_statistics solve_source_heat_below(int s, Workspace& ws) const;
  // A guess of the smallest heat from s on `count` candidates: the scale of
  // the pruning threshold of the source-heat solve.
  double smallest_heat_guess(int s, std::size_t count) const;
  // Whether a query from s on `count` candidates prunes its heat solves.
  bool prunes(int s, std::size_t count) const;
  // Sets ws.prune and the source heat's threshold ws.heat_drop_below (0:
  // not pruned) for a query from s on `count` candidates, whose smallest
  // heat is `smallest_heat` (if positive) or smallest_heat_guess's.
  void choose_source_heat_pruning(int s, std::size_t count, Workspace& ws,
                                  double smallest_heat = 0) const;
  static constexpr std::size_t min_component_per_pruned_candidate = 10;
  static constexpr std::size_t min_pruned_component = 200000;
  // Checks a pruned source-heat solve's threshold against the heat of the
  // chosen region; solves again (and chooses the region again) if it was
  // above the tolerance times the region's smallest heat.
  // (`largest_first`: the solve was solve_hottest_source_heat's.)
  Solve_statistics confirm_pruned_source_heat(int s, bool largest_first, Workspace& ws) const;
  // The same heat on the candidates after they were widened.
  Solve_statistics extend_source_heat(Workspace& ws) const;
  // Step 1 (distance part) without breadth-first candidates: the heat from
  // the source solved largest first (Localized_cholesky_solver::
  // solve_largest) until the `kept` hottest vertices of the component are
  // known; the candidates are the vertices solved, the source first.
  // Pruned below ws.heat_drop_below (not pruned if it is 0).
  Solve_statistics solve_hottest_source_heat(int s, std::size_t kept, Workspace& ws) const;
  // The same solve continued until the `kept` hottest are known (a retry).
  Solve_statistics extend_hottest_source_heat(std::size_t kept, Workspace& ws) const;
  // Moves the source to the front of a largest-first solve's candidates
  // (and its heat with it), where choose_region wants it.
  static void put_source_first(int s, Workspace& ws) {
    const auto at = static_cast<std::size_t>(
        std::find(ws.candidates.begin(), ws.candidates.end(), s) - ws.candidates.begin());
    std::swap(ws.candidates[0], ws.candidates[at]);
    std::swap(ws.heat[0], ws.heat[at]);
  }
  // Whether a query finds its region largest first: for patches given by a
  // vertex count or a radius, if the matrix allows it. (A vertex-set patch
  // names no size its region could be cut to before the distance is known.)
  bool finds_region_largest_first(const Patch& patch) const {
    return patch.kind() != Patch::Kind::vertex_set && m_distance_heat_is_m_matrix;
  }
  // The heat from the source at distance d as one implicit step of time t
  // spreads it over a plane: the screened Poisson kernel K0(d / sqrt(t)) /
  // (2 pi t) (K0 the modified Bessel function), a positive normal number
  // (the smallest one where it underflows). A radius patch's region is the
  // vertices with at least the heat at `region_radius`: a level set of the
  // heat like a count patch's region, sized by distance instead of by a
  // count, which a radius patch does not know before its distances.
  // Measured against the heat at 5% patches' reach (armadillo,
  // refined_elephant): 0.64-1.07 times the kernel for most sources, up to 2.1
  // in the elephant's limbs, where heat spreads along a tube (a larger
  // region than asked); a factor 2 is about 0.7 sqrt(t) in distance.
  double heat_at_distance(double d) const;
  // The radius of a radius patch's region: as far beyond the patch as a
  // disk with `growth` times its vertices reaches (sqrt(growth) times the
  // radius), plus one diffusion length for the kernel's error above.
  double region_radius(double patch_radius, double growth) const {
    return std::sqrt(growth) * patch_radius + std::sqrt(m_distance_time_step);
  }
  // Step 1 (distance part) for a radius patch: the heat from the source
  // solved largest first until every vertex with at least `threshold` is
  // known (Localized_cholesky_solver::solve_at_least), or continued there
  // (`retry`); sets `kept` to the region's size, the vertices of at least
  // that heat. Pruned below ws.heat_drop_below (not pruned if it is 0).
  Solve_statistics solve_source_heat_at_least(int s, double threshold, bool retry,
                                              std::size_t& kept, Workspace& ws) const;
  // Step 1 (distance part) without candidates (finds_region_largest_first;
  // manual section 2, steps 3 and 4): the source heat solved, or its search
  // continued (`retry`), until the region for a patch `growth` times larger
  // is known; sets `kept` to its size.
  Solve_statistics solve_region_largest_first(int s, const Patch& patch, std::size_t target,
                                              std::size_t component, double growth, bool retry,
                                              std::size_t& kept, Workspace& ws) const;
  internal::Localized_cholesky_solver::Workspace& source_heat_workspace(Workspace& ws) const {
    return m_separate_distance_heat ? ws.distance_heat_solve : ws.heat_solve;
  }
  // Sets ws.heat_row to the `kept` hottest candidates (the source among
  // them), the region, in candidate order.
  void choose_region(std::size_t kept, Workspace& ws) const;
  // Whether one of the `hottest` candidates lies on the candidates' edge
  // (those that do are left in ws.cut_short_at):
  // the breadth-first candidates then cut the heat's level sets short on
  // that side, and a patch of `hottest` vertices would come too close to the
  // region's edge. Needs the candidates marked and `choose_region` done.
  bool region_is_cut_short(std::size_t hottest, Workspace& ws) const;
  // The candidates at `rows` with a neighbour outside the candidates, into
  // ws.cut_short_at.
  void edge_of_candidates(const std::vector<std::size_t>& rows, Workspace& ws) const;
  // Step 4 for a region cut short: grows the candidates where the region
  // touches their edge (at most targeted_widening_rounds rounds of
  // rings), else everywhere to widened_candidate_excess times the region;
  // extends the source heat and chooses the region (of `kept` vertices)
  // again each time.
  Solve_statistics widen_candidates(std::size_t target, double growth, std::size_t kept,
                                    std::size_t component, bool& whole_component,
                                    Workspace& ws) const;
  // Marks the chosen region and fills ws.region and ws.region_heat.
  void mark_region(Workspace& ws) const;
  // Steps 2 and 3: integrates the normalized heat gradient on the region
  // (fills ws.divergence and ws.potential, the distances).
  Solve_statistics integrate_distance(int s, Workspace& ws) const;
  // The `count` rows of `rows` (ascending) with the most heat from the
  // source, ties to the lower row, into `out` in ascending order. By the
  // count-th largest heat value (internal::kth_largest) and one pass: a
  // selection on the values themselves, not on rows compared through the
  // heat array.
  static void hottest_rows(const std::vector<std::size_t>& rows, std::size_t count,
                           std::vector<std::size_t>& out, Workspace& ws);
  // Solves the heat from the source and its neighbours for `rows` (region
  // vertices: the patch's, or the whole region's beside the distance) into
  // out.heat, in `solver`; reads only ws's region and its source heat, so
  // it may run beside integrate_distance.
  Solve_statistics solve_star_heat(const internal::Star_gradient& star,
                                   const std::vector<int>& rows, Star_solve& out,
                                   internal::Localized_cholesky_solver::Workspace& solver,
                                   const Workspace& ws) const;
  // The right-hand side of a star solve of `width` columns (see solve_star_heat).
  void star_right_hand_side(const internal::Star_gradient& star, std::size_t width,
                            std::vector<internal::Rhs_entry>& rhs) const;
  // Step 6 on a surface with a boundary: the heat solves carry the natural
  // (Neumann) boundary condition, under which the heat from v is the free
  // heat kernel plus its mirror image across the boundary (method of
  // images). At a source on the boundary the image doubles the gradient's
  // tangential part and cancels its normal part, so every direction read
  // there collapses onto the boundary's tangent; near it, the image pulls
  // the directions towards their mirror images. The heat with a zero
  // (Dirichlet) boundary is the kernel minus its image: the sum of the two
  // is twice the free kernel, image-free, wherever the boundary is locally
  // straight. This solve gives the Dirichlet half on the patch
  // (ws.boundary_star), which write_result adds to the Neumann star solve.
  Solve_statistics solve_boundary_star_heat(const internal::Star_gradient& star,
                                            Workspace& ws) const;
  // Columns of the Dirichlet star solve: a linear estimator's two and the
  // heat from s (the Neumann solve reads that from the distance step).
  std::size_t boundary_star_columns(const internal::Star_gradient& star) const {
    return is_linear_in_heat(m_angle_estimator) ? 3 : star.vertices.size();
  }
  // The star solve's pruning threshold (0: none), from the source heat on
  // `rows`, and the smallest magnitude it is checked against.
  double star_heat_drop_below(const std::vector<int>& rows, const Workspace& ws) const;
  double smallest_star_value(std::size_t width, const std::vector<double>& heat) const;
  // A second thread starts (16 microseconds, up to 60) only for regions of at
  // least this many vertices: a 1% patch of a 26k-vertex mesh (a region of
  // 522, a 0.24 ms query) took 1.12x the time with it.
  static constexpr std::size_t min_region_beside_distance = 1500;
  // The region's star solve read at the patch's rows (`order`, into the
  // region): fills ws.star.heat as the patch's own solve would.
  static void read_star_heat_on_patch(std::size_t width, const std::vector<std::size_t>& order,
                                      Workspace& ws) {
    ws.star.heat.resize(order.size() * width);
    for (std::size_t p = 0; p < order.size(); ++p)
      std::copy_n(ws.region_star.heat.data() + order[p] * width, width,
                  ws.star.heat.data() + p * width);
  }
  // The linear map from heat values on the star of s to their gradient at
  // s, for the chosen angle estimator.
  internal::Star_gradient source_star_gradient(int s, const internal::Tangent_frame& frame) const {
    if (m_angle_estimator == Angle_estimator::log_heat_quadratic_fit ||
        m_angle_estimator == Angle_estimator::heat_quadratic_fit) {
      // Fitted on the triangulation the heat lives on: after intrinsic
      // Delaunay flips the input one-ring may hold slivers whose far corners
      // the heat never diffused along. The linear fit costs two columns
      // whatever its stencil, so it takes the two-ring: twice the baseline
      // and about three times the samples average out the heat's
      // vertex-to-vertex discretization noise on irregular meshes (its mean
      // angle error on a jittered sphere is about a third of the one-ring's).
      internal::Star_gradient star;
      star.vertices = internal::ring_neighborhood(
          m_heat_neighbors, s,
          m_angle_estimator == Angle_estimator::heat_quadratic_fit ? 2 : 1);
      // Next to a boundary the stencil is one-sided, and the fitted
      // quadratic's gradient at its edge follows the coarse, long fans
      // boundaries often have (mirrored patches at boundary sources of
      // lion-head and mask_cone even with the Dirichlet half, see
      // solve_boundary_star_heat); the one-ring's area-weighted gradient
      // has no lever arm.
      if (touches_boundary(star.vertices)) return internal::star_gradient(m_indexed.arrays, s, frame);
      if (auto fitted = internal::quadratic_fit_star_gradient(m_indexed.arrays, std::move(star), frame))
        return *fitted;
    }
    return internal::star_gradient(m_indexed.arrays, s, frame);
  }
  // Columns of the star solve: 2 for a linear estimator, else one per star vertex.
  std::size_t star_columns(const internal::Star_gradient& star) const {
    if (!is_linear_in_heat(m_angle_estimator)) return star.vertices.size();
    return m_separate_distance_heat ? 3 : 2;
  }
  // The gradient at s of the heat from patch vertex v, from the star
  // solve's row `h` (see solve_star_heat): the direction of the geodesic
  // from s to v (the paper's step 3, by the heat's symmetry). For
  // `heat_quadratic_fit` it is divided by `at_source`, the heat from v at
  // s, and still carries the fit's cubic leak (see write_result).
  std::array<double, 2> heat_direction(double at_source, const internal::Star_gradient& star,
                                       const double* h, std::vector<double>& values) const;
  // Polar angle of v at heat distance r from its heat direction, blended
  // with the geometric direction next to the source (Near_source_blend, see
  // near_source_angle).
  double polar_angle(int s, int v, double r, const std::array<double, 2>& direction,
                     const internal::Tangent_frame& frame, const internal::Source_one_ring& ring,
                     const internal::Near_source_zone& zone) const;
  // The geometric direction of v next to the source: a neighbour's edge at
  // its intrinsic angle (the corner angles at s summed and rescaled to
  // 2 pi, as DGPC starts), any other vertex's chord projected onto the
  // tangent plane and carried into the same intrinsic angles by the wedge
  // of neighbours it projects into. A projection alone shrinks or widens
  // the corners of a curved one-ring unevenly and can take them out of
  // their cyclic order.
  double near_source_angle(int s, int v, const internal::Tangent_frame& frame,
                           const internal::Source_one_ring& ring) const;
  // The query's blend from geometric into heat coordinates: the options'
  // Near_source_blend in mean edge lengths, scaled by blend_normal_turn over
  // the normal's turn across the blend's end (at most
  // max_near_source_widening): the blend then ends where the normal has
  // turned by blend_normal_turn, or at 1.5 times its nominal end where the
  // surface is flatter.
  // `normal`: the vertex normal of s (the query's frame's).
  internal::Near_source_zone near_source_zone(int s, const internal::Vector3& normal) const {
    const double h_mean = m_indexed.arrays.mean_edge_length;
    internal::Near_source_zone zone{m_options.near_source_blend.begin * h_mean,
                                    m_options.near_source_blend.end * h_mean};
    if (zone.end > 0) {
      const double turn = internal::normal_turn_rate(m_indexed.arrays, s, normal) * zone.end;
      const double scale = turn > 0 ? std::min(blend_normal_turn / turn, max_near_source_widening)
                                    : max_near_source_widening;
      zone.begin *= scale;
      zone.end *= scale;
    }
    return zone;
  }
  // The distance of v at heat distance r. A neighbour of the source takes
  // its edge's length (the exact polyhedral distance, where DGPC starts),
  // blended into r like the angle: the heat distance is off by about 0.1 h
  // anywhere, a tenth of a neighbour's distance, and a patch's texture is
  // interpolated from these corners right next to the source. Farther
  // vertices keep r: chord lengths there cut through space on coarse curved
  // meshes and fold triangles over (doc/results.md, section 0).
  double blended_distance(int s, int v, double r, const internal::Source_one_ring& ring,
                          const internal::Near_source_zone& zone) const {
    const double w = zone.heat_weight(r);
    if (w == 1.0 || ring.position(v) < 0) return r;
    const double edge =
        internal::norm(internal::operator-(m_indexed.arrays.point[v], m_indexed.arrays.point[s]));
    return w * r + (1 - w) * edge;
  }
  // How far from the source the region ends (both infinity if it has no
  // boundary): `vertex`, the smallest distance at a region vertex with a
  // neighbour outside the region; `edge`, the smallest distance to the
  // middle of an edge leaving the region (such a vertex's distance plus
  // half its shortest edge out), where its vertices' cells end. Only
  // vertices at most `horizon` from the source are looked at (both ends are
  // infinity if no boundary vertex is that near): the margin check passes
  // its reach times the margin, and a boundary vertex beyond that passes
  // both of its tests.
  struct Region_end {
    double vertex, edge;
  };
  Region_end region_end(double horizon, const Workspace& ws) const;
  // Region positions of the patch vertices, nearest first.
  std::vector<std::size_t> select_patch(const Patch& patch, std::size_t target,
                                        const std::vector<int>& wanted,
                                        const Workspace& ws) const;
  void write_result(int s, const internal::Tangent_frame& frame,
                    const internal::Star_gradient& star, const std::vector<std::size_t>& order,
                    const Workspace& ws, Result& result) const;

  using Front::m_indexed;
  Heat_options m_options;
  internal::Faces_by_smallest_corner m_faces;  // of the triangulation the operators are built on
  internal::Vertex_adjacency m_heat_neighbors;  // its neighbours: the stars the angles are fitted on
  std::vector<char> m_is_pinned;  // one vertex per component in the Poisson system
  double m_time_step = 0, m_distance_time_step = 0;
  bool m_separate_distance_heat = false;
  double m_pruning_tolerance = 0;  // Heat_options::pruning_tolerance, 0 if the matrix forbids it
  bool m_distance_heat_is_m_matrix = false;  // see prepare_pruning
  std::vector<double> m_inverse_heat_diagonal;  // 1 / A_vv of the distance-heat matrix, if pruning
  double m_mean_vertex_area = 0;  // the lumped mass's mean: the mesh's area per vertex
  Angle_estimator m_angle_estimator = Angle_estimator::heat_quadratic_fit;  // see angle_estimator()
  internal::Localized_cholesky_solver m_heat_local, m_distance_heat_local, m_poisson_local;
  // The heat matrix with Dirichlet conditions on the mesh boundary (empty
  // for closed meshes): see solve_boundary_star_heat.
  internal::Localized_cholesky_solver m_boundary_heat_local;
  std::vector<char> m_is_boundary;  // per vertex: on a loop of the Dirichlet heat; empty if none
  mutable internal::Workspace_pool<Workspace> m_workspaces;
};

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_source_heat(int s, Workspace& ws) const {
  choose_source_heat_pruning(s, ws.candidates.size(), ws);
  return solve_source_heat_below(s, ws);
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::choose_source_heat_pruning(int s, std::size_t count,
                                                                  Workspace& ws,
                                                                  double smallest_heat) const {
  ws.prune = prunes(s, count);
  ws.heat_drop_below = 0;
  if (ws.prune)
    ws.heat_drop_below =
        m_pruning_tolerance * (smallest_heat > 0 ? smallest_heat : smallest_heat_guess(s, count));
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_source_heat_below(int s,
                                                                          Workspace& ws) const {
  ws.rhs.assign(1, internal::Rhs_entry{s, 0, 1.0});
  ws.heat.resize(ws.candidates.size());
  // Extendable: if the candidates are widened, only the back substitution
  // of the new candidates' supernodes is added.
  if (ws.heat_drop_below == 0)
    return distance_heat().solve_extendable(ws.rhs, 1, ws.candidates.data(),
                                            ws.candidates.size(), ws.heat.data(),
                                            source_heat_workspace(ws));
  return distance_heat().solve_extendable(ws.rhs, 1, ws.candidates.data(),
                                          ws.candidates.size(), ws.heat.data(),
                                          source_heat_workspace(ws), ws.heat_drop_below);
}

template <class TM, class VPM, class S>
bool Heat_exponential_map<TM, VPM, S>::prunes(int s, std::size_t count) const {
  // Pruning skips the far parts of the top separators, which a query's
  // solves walk whatever its size; it pays when they are most of the work,
  // on patches much smaller than a large mesh. Measured (doc/paper_scale.md):
  // 31% faster queries at 0.26% candidates of a 2.85M-vertex mesh, 9% at
  // 1.3%; 11-16% and 3-6% on a 711k-vertex one. With the tolerance 1e-12
  // and the Poisson factor compressed, 1-2% patches (2.6-5.2% candidates)
  // gain too: 0.88 / 0.96 of the unpruned time at 1 / 2% of the
  // 2.85M-vertex mesh, 0.97 at 1-3% of the 711k-vertex one; 5% patches (13%
  // candidates) gained nothing, 10% lost 1%. Hence candidates up to a tenth
  // of the component.
  // On meshes of 26k-45k vertices the far separators are too near for the
  // heat to fall below the threshold: nothing was pruned, and the checks
  // cost 7-11% of a 0.1% query.
  const auto component = static_cast<std::size_t>(
      m_indexed.arrays.component_size[m_indexed.arrays.component[s]]);
  return m_pruning_tolerance > 0 && component >= min_pruned_component &&
         count * min_component_per_pruned_candidate <= component;
}

template <class TM, class VPM, class S>
double Heat_exponential_map<TM, VPM, S>::smallest_heat_guess(int s, std::size_t count) const {
  // The heat at the source is at least 1 / A_ss. Away from it, the heat of
  // one implicit step decays about like exp(-d / sqrt(t)); the candidates
  // reach about the radius of a disk of `count` vertices of the mean edge
  // length. Decay and distance are overestimated generously: a guess too
  // small only prunes less, one too large costs a second solve.
  const double radius = m_indexed.arrays.mean_edge_length *
                        std::sqrt(static_cast<double>(count) * std::sqrt(3.0) / (2 * M_PI));
  return m_inverse_heat_diagonal[static_cast<std::size_t>(s)] * 1e-3 *
         std::exp(-2.0 * radius / std::sqrt(m_distance_time_step));
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::confirm_pruned_source_heat(
    int s, bool largest_first, Workspace& ws) const {
  Solve_statistics stats;
  for (int attempt = 0; ws.heat_drop_below > 0; ++attempt) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const std::size_t row : ws.heat_row) smallest = std::min(smallest, ws.heat[row]);
    // 2: room for the rounding of `smallest` itself.
    if (ws.heat_drop_below <= 2 * m_pruning_tolerance * smallest) break;
    // Pruning only lowers values here (see prepare_pruning), so the
    // smallest pruned value is below the true one: a threshold from it is
    // safe. Twice too bold (a region of barely positive heat): no pruning.
    ws.heat_drop_below = attempt == 0 ? m_pruning_tolerance * smallest : 0.0;
    const std::size_t kept = ws.heat_row.size();
    stats += largest_first ? solve_hottest_source_heat(s, kept, ws) : solve_source_heat_below(s, ws);
    choose_region(kept, ws);
  }
  return stats;
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::extend_source_heat(Workspace& ws) const {
  ws.heat.resize(ws.candidates.size());
  return distance_heat().extend(ws.candidates.data(), ws.candidates.size(), ws.heat.data(),
                                source_heat_workspace(ws));
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_hottest_source_heat(
    int s, std::size_t kept, Workspace& ws) const {
  ws.rhs.assign(1, internal::Rhs_entry{s, 0, 1.0});
  const Solve_statistics stats = distance_heat().solve_largest(
      ws.rhs, kept, ws.candidates, ws.heat, source_heat_workspace(ws), ws.heat_drop_below);
  put_source_first(s, ws);
  return stats;
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::extend_hottest_source_heat(
    std::size_t kept, Workspace& ws) const {
  return distance_heat().extend_largest(kept, ws.candidates, ws.heat, source_heat_workspace(ws));
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::hottest_rows(const std::vector<std::size_t>& rows,
                                                    std::size_t count,
                                                    std::vector<std::size_t>& out, Workspace& ws) {
  out.clear();
  if (count >= rows.size()) {
    out.assign(rows.begin(), rows.end());
    return;
  }
  if (count == 0) return;
  std::size_t hotter = 0;
  const double threshold = internal::kth_largest(
      rows.size(), count, [&](std::size_t i) { return ws.heat[rows[i]]; }, ws.heat_values, hotter);
  // Rows hotter than the threshold all belong; of those at it, the lowest.
  std::size_t at_threshold = count - hotter;
  for (const std::size_t row : rows) {
    const double h = ws.heat[row];
    if (h > threshold || (h == threshold && at_threshold > 0 && at_threshold--)) out.push_back(row);
  }
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::choose_region(std::size_t kept, Workspace& ws) const {
  // The region the distance is integrated on: the candidates with the most
  // heat from the source. Heat level sets are near-geodesic circles, so the
  // cut-off of the Poisson right-hand side is nearly rotationally symmetric
  // and shifts distances by a nearly constant amount, which the
  // normalization at the source removes. (A graph-distance region has
  // polygonal edges that bend the distance field instead.)
  ws.rows.resize(ws.candidates.size());
  std::iota(ws.rows.begin(), ws.rows.end(), std::size_t{0});
  hottest_rows(ws.rows, kept, ws.heat_row, ws);
  // The source leads the region (its heat is the largest, but a poor mesh
  // could break that tie; keep it regardless).
  if (!ws.heat_row.empty() && ws.heat_row.front() != 0) {
    ws.heat_row.pop_back();
    ws.heat_row.insert(ws.heat_row.begin(), 0);
  }
}

template <class TM, class VPM, class S>
bool Heat_exponential_map<TM, VPM, S>::region_is_cut_short(std::size_t hottest,
                                                           Workspace& ws) const {
  hottest_rows(ws.heat_row, hottest, ws.rows, ws);
  edge_of_candidates(ws.rows, ws);
  return !ws.cut_short_at.empty();
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::edge_of_candidates(const std::vector<std::size_t>& rows,
                                                          Workspace& ws) const {
  const auto& m = m_indexed.arrays;
  ws.cut_short_at.clear();
  for (const std::size_t row : rows) {
    const int v = ws.candidates[row];
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p)
      if (!ws.in_region.is_marked(m.neighbor[p])) {
        ws.cut_short_at.push_back(v);
        break;
      }
  }
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::widen_candidates(std::size_t target,
                                                                    double growth, std::size_t kept,
                                                                    std::size_t component,
                                                                    bool& whole_component,
                                                                    Workspace& ws) const {
  Solve_statistics stats;
  auto take_new_candidates = [&] {
    whole_component = ws.candidates.size() == component;
    stats += extend_source_heat(ws);
    choose_region(whole_component ? ws.candidates.size() : kept, ws);
  };
  // Rings around the region's vertices on the candidates' edge, on that
  // side only, until the region is clear of the edge.
  for (int round = 0;; ++round) {
    if (whole_component) return stats;
    edge_of_candidates(ws.heat_row, ws);
    if (ws.cut_short_at.empty()) return stats;
    if (round == targeted_widening_rounds) break;
    internal::grow_rings_around(m_indexed.arrays, ws.in_region, ws.cut_short_at,
                                targeted_widening_rings(target), ws.candidates, ws.frontier,
                                ws.next_frontier);
    take_new_candidates();
  }
  // Still on the edge (a mesh much finer one way than the other): the
  // breadth-first search continued everywhere.
  ws.breadth_first_head = internal::continue_region_by_hops(
      m_indexed.arrays, ws.in_region, breadth_first_budget(target, growth, widened_candidate_excess),
      ws.candidates, ws.breadth_first_head);
  take_new_candidates();
  return stats;
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::mark_region(Workspace& ws) const {
  // ws.heat_row is in candidate order, the source first.
  const std::size_t kept = ws.heat_row.size();
  ws.region.resize(kept);
  ws.region_heat.resize(kept);
  ws.in_region.next_query();
  for (std::size_t i = 0; i < kept; ++i) {
    ws.region[i] = ws.candidates[ws.heat_row[i]];
    ws.region_heat[i] = ws.heat[ws.heat_row[i]];
    ws.in_region.mark(ws.region[i], static_cast<int>(i));
  }
  // The loops over the region's faces and neighbours read per-vertex arrays;
  // in vertex order (which follows the surface, see locality_order) they
  // stream through memory instead of jumping between breadth-first rings.
  ws.region_by_index.assign(ws.region.begin(), ws.region.end());
  internal::radix_sort_indices(ws.region_by_index, ws.sort_scratch);
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::integrate_distance(int s, Workspace& ws) const {
  const std::size_t kept = ws.region.size();
  Solve_statistics stats;
  // Step 2: divergence of the normalized heat gradient, from the faces whose
  // three corners lie in the region (so the right-hand side sums to zero).
  ws.divergence.assign(kept, 0.0);
  for (const int v : ws.region_by_index) {
    for (auto f = m_faces.begin(v); f != m_faces.end(v); ++f) {
      const auto& c = f->corner;
      if (!ws.in_region.is_marked(c[0]) || !ws.in_region.is_marked(c[1]) ||
          !ws.in_region.is_marked(c[2]))
        continue;
      std::array<int, 3> at;
      std::array<double, 3> u;
      for (int k = 0; k < 3; ++k) {
        at[k] = ws.in_region.value(c[k]);
        u[k] = ws.region_heat[static_cast<std::size_t>(at[k])];
      }
      const auto div = internal::normalized_gradient_divergence(f->divergence, u);
      for (int k = 0; k < 3; ++k) ws.divergence[static_cast<std::size_t>(at[k])] += div[k];
    }
  }

  // Step 3: integrate, L phi = div X; phi is a distance up to a constant.
  // Filled in place: a pushed temporary is stored in pieces and reloaded
  // whole, a store-forwarding stall per entry.
  ws.rhs.resize(kept);
  std::size_t entries = 0;
  for (std::size_t i = 0; i < kept; ++i)
    if (ws.divergence[i] != 0.0 && !m_is_pinned[ws.region[i]]) {
      internal::Rhs_entry& e = ws.rhs[entries++];
      e.row = ws.region[i];
      e.column = 0;
      e.value = ws.divergence[i];
    }
  ws.rhs.resize(entries);
  ws.potential.resize(kept);
  stats += m_poisson_local.solve(ws.rhs, 1, ws.region.data(), kept, ws.potential.data(), ws.poisson_solve);
  // The distance must be smallest at the source. Slightly negative values
  // next to it are discretization error and are clamped to 0; a clearly
  // negative one means the heat was not positive (cotan weights of obtuse,
  // non-Delaunay triangles) and the whole field is unreliable.
  const double at_source = ws.potential[0];
  std::size_t lowest = 0;
  for (std::size_t i = 0; i < kept; ++i)
    if (ws.potential[i] < ws.potential[lowest]) lowest = i;
  if (ws.potential[lowest] - at_source < -0.5 * m_indexed.arrays.mean_edge_length) {
    // Intrinsic Delaunay flips cannot remove an obtuse angle opposite a
    // boundary edge. Where that breaks the heat (ALSTOM_TEST4's strips),
    // neither a larger time factor nor --repair helped: the geodesic
    // methods are the way out.
    const std::string cause =
        m_options.laplacian == Laplacian_mode::direct
            ? "on this mesh's non-Delaunay triangles; use Laplacian_mode::intrinsic_delaunay (the "
              "default) or a larger time factor"
            : "here, although the Laplacian is intrinsic Delaunay (obtuse angles opposite "
              "boundary edges, which edge flips cannot remove, can cause this); map this source "
              "with DGPC or the exact method";
    throw Computation_error(
        "the heat distance from source vertex " + std::to_string(m_indexed.arrays.to_original(s)) +
        " is smallest at vertex " + std::to_string(m_indexed.arrays.to_original(ws.region[lowest])) +
        ", not at the source: the heat diffusion is not positive " + cause);
  }
  for (double& phi : ws.potential) phi = std::max(0.0, phi - at_source);
  return stats;
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_star_heat(
    const internal::Star_gradient& star, const std::vector<int>& rows, Star_solve& out,
    internal::Localized_cholesky_solver::Workspace& solver, const Workspace& ws) const {
  // Step 1 (angle part), read on the patch (or, beside the distance, on
  // the region). A linear estimator needs two columns, the rows of the
  // gradient weights: by symmetry their solution at v is the estimated
  // gradient of the heat from v. A logarithmic one needs the heat from
  // every patch vertex on the star: one column per star vertex.
  const std::size_t width = star_columns(star);
  star_right_hand_side(star, width, out.rhs);
  out.heat.resize(rows.size() * width);
  const double drop_below = star_heat_drop_below(rows, ws);
  if (drop_below == 0)
    return m_heat_local.solve(out.rhs, static_cast<int>(width), rows.data(), rows.size(),
                              out.heat.data(), solver);
  Solve_statistics stats =
      m_heat_local.solve(out.rhs, static_cast<int>(width), rows.data(), rows.size(),
                         out.heat.data(), solver, drop_below);
  // The gradient columns change sign, so pruning need not lower them: the
  // check is that every value read stays far above the threshold.
  if (drop_below > m_pruning_tolerance * smallest_star_value(width, out.heat))
    stats += m_heat_local.solve(out.rhs, static_cast<int>(width), rows.data(), rows.size(),
                                out.heat.data(), solver);
  return stats;
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::star_right_hand_side(
    const internal::Star_gradient& star, std::size_t width,
    std::vector<internal::Rhs_entry>& rhs) const {
  rhs.clear();
  if (is_linear_in_heat(m_angle_estimator)) {
    for (std::size_t c = 0; c < star.vertices.size(); ++c) {
      rhs.push_back({star.vertices[c], 0, star.along_e1[c]});
      rhs.push_back({star.vertices[c], 1, star.along_e2[c]});
    }
    if (width == 3) rhs.push_back({star.vertices[0], 2, 1.0});  // the heat from s
  } else {
    for (std::size_t c = 0; c < width; ++c)
      rhs.push_back({star.vertices[c], static_cast<int>(c), 1.0});
  }
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_boundary_star_heat(
    const internal::Star_gradient& star, Workspace& ws) const {
  // The star solve's right-hand side on the Dirichlet heat, whose boundary
  // rows are identity: their entries would only copy themselves into the
  // boundary's heat, which is zero. A linear estimator also needs the heat
  // from s (column 2) for the heat at the source.
  const std::size_t width = boundary_star_columns(star);
  Star_solve& out = ws.boundary_star;
  star_right_hand_side(star, width, out.rhs);
  out.rhs.erase(std::remove_if(out.rhs.begin(), out.rhs.end(),
                               [&](const internal::Rhs_entry& e) {
                                 return m_is_boundary[static_cast<std::size_t>(e.row)] != 0;
                               }),
                out.rhs.end());
  out.heat.assign(ws.patch.size() * width, 0.0);
  if (out.rhs.empty()) return {};
  return m_boundary_heat_local.solve(out.rhs, static_cast<int>(width), ws.patch.data(),
                                     ws.patch.size(), out.heat.data(), ws.boundary_heat_solve);
}

template <class TM, class VPM, class S>
double Heat_exponential_map<TM, VPM, S>::star_heat_drop_below(const std::vector<int>& rows,
                                                              const Workspace& ws) const {
  // The source heat on the rows sets the scale (it is the star's heat,
  // only with the distance time step if that differs: then no pruning).
  if (!ws.prune || m_separate_distance_heat) return 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const int v : rows)
    smallest = std::min(smallest, ws.region_heat[static_cast<std::size_t>(ws.in_region.value(v))]);
  // A neighbour's heat at v is within a small factor of the source's; the
  // gradient of the heat from v at s is about that heat over sqrt(t) (it
  // decays like exp(-d / sqrt(t))).
  const double scale = is_linear_in_heat(m_angle_estimator) ? 1 / std::sqrt(m_time_step) : 1.0;
  return m_pruning_tolerance * 1e-3 * smallest * scale;
}

template <class TM, class VPM, class S>
double Heat_exponential_map<TM, VPM, S>::smallest_star_value(
    std::size_t width, const std::vector<double>& heat) const {
  double smallest = std::numeric_limits<double>::infinity();
  if (is_linear_in_heat(m_angle_estimator)) {  // the gradient, a vector: its squared length
    for (std::size_t i = 0; i + width <= heat.size(); i += width)
      smallest = std::min(smallest, heat[i] * heat[i] + heat[i + 1] * heat[i + 1]);
    return std::sqrt(smallest);
  }
  for (const double h : heat) smallest = std::min(smallest, h);
  return smallest;
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::grow_candidates(int s, const Patch& patch,
                                                       std::size_t target,
                                                       const std::vector<int>& wanted,
                                                       double growth, double excess,
                                                       Workspace& ws) const {
  // Graph distance along edges bounds the geodesic distance from above, so
  // the candidates are taken generously; the query checks the result.
  const double radius_scale = std::sqrt(growth * excess) * 1.1;
  auto grow = [&](auto keep) {
    internal::grow_region(m_indexed.arrays, s, ws.in_region, ws.seen, ws.tentative, ws.candidates, keep);
  };
  if (patch.kind() == Patch::Kind::geodesic_radius) {
    const double limit = patch.radius() * radius_scale;
    grow([&](int, double d, std::size_t) { return d <= limit; });
  } else if (patch.kind() == Patch::Kind::vertex_set) {
    // Reach every wanted vertex (distinct, source excluded), then keep going
    // to the same margin.
    ws.wanted.next_query();
    for (int v : wanted) ws.wanted.mark(v, 0);
    std::size_t reached = 0;
    double limit = wanted.empty() ? 0.0 : -1.0;
    grow([&](int v, double d, std::size_t) {
      if (limit >= 0) return d <= limit;
      if (ws.wanted.is_marked(v) && ++reached == wanted.size()) limit = d * radius_scale;
      return true;
    });
  } else {
    // Only the count matters here: the region is cut from the candidates by
    // heat, so a breadth-first search (no heap) is enough.
    ws.breadth_first_head = internal::grow_region_by_hops(
        m_indexed.arrays, s, ws.in_region, breadth_first_budget(target, growth, excess),
        ws.candidates);
  }
}

template <class TM, class VPM, class S>
typename Heat_exponential_map<TM, VPM, S>::Result
Heat_exponential_map<TM, VPM, S>::compute_by_index(std::size_t source_index, const Patch& patch,
                                                   const Query_options& query) const {
  const int s = internal::checked_source(m_indexed.arrays, source_index);
  std::optional<internal::Vector3> reference;
  if (query.reference_direction) reference = *query.reference_direction;
  const internal::Tangent_frame frame = internal::tangent_frame(m_indexed.arrays, s, reference);
  const internal::Star_gradient star = source_star_gradient(s, frame);
  const std::size_t component =
      static_cast<std::size_t>(m_indexed.arrays.component_size[m_indexed.arrays.component[s]]);
  const std::size_t target = internal::patch_target_count(m_indexed.arrays, patch, s);
  const std::vector<int> wanted = patch.kind() == Patch::Kind::vertex_set
                                      ? internal::checked_vertex_set(m_indexed.arrays, patch, s)
                                      : std::vector<int>{};

  auto ws = m_workspaces.acquire([this] { return std::make_unique<Workspace>(*this); });
  Result result;
  // The Poisson step is cut off at the region's edge; the patch must stay
  // clear of it by this factor in distance (a geodesic disk with
  // `region_growth` times the patch's vertices has sqrt(region_growth)).
  const double margin = std::max(1.0, 0.85 * std::sqrt(m_options.region_growth));
  // Breadth-first candidates (patches given by a vertex count) cut the
  // heat's level sets short on the side of the short edges. That is checked
  // on the heat, before the distance is integrated: the hottest candidates,
  // as many as a disk `margin` times the patch's radius holds, must not
  // touch the candidates' edge. Otherwise the candidates grow where the
  // region touches their edge (or, failing that, everywhere; the region
  // keeps its size), which costs the back substitution of the new
  // candidates only; a retry after the distance costs a whole query.
  const bool breadth_first = patch.kind() == Patch::Kind::fraction ||
                             patch.kind() == Patch::Kind::vertex_count;
  const std::size_t hottest_inside =
      static_cast<std::size_t>(std::ceil(margin * margin * static_cast<double>(target)));
  const bool largest_first = finds_region_largest_first(patch);
  for (double growth = m_options.region_growth;; growth *= 2) {
    const bool retry = growth > m_options.region_growth;
    if (retry) ++result.statistics.region_retries;
    bool whole_component = false;
    if (largest_first) {
      // The region is the hottest vertices of the component: no candidates
      // to cut it short. A retry continues the first attempt's solve.
      std::size_t kept = 0;
      result.statistics +=
          solve_region_largest_first(s, patch, target, component, growth, retry, kept, *ws);
      whole_component = kept == component;
      choose_region(kept, *ws);
    } else {
      grow_candidates(s, patch, target, wanted, growth, candidate_excess, *ws);
      whole_component = ws->candidates.size() == component;
      // A retry extends the first attempt's heat to its larger candidates.
      result.statistics += retry ? extend_source_heat(*ws) : solve_source_heat(s, *ws);
      const std::size_t kept =
          whole_component ? ws->candidates.size()
                          : static_cast<std::size_t>(std::ceil(
                                static_cast<double>(ws->candidates.size()) / candidate_excess));
      choose_region(kept, *ws);
      if (breadth_first && !whole_component && region_is_cut_short(hottest_inside, *ws))
        result.statistics += widen_candidates(target, growth, kept, component, whole_component, *ws);
    }
    result.statistics += confirm_pruned_source_heat(s, largest_first, *ws);
    mark_region(*ws);
    // Steps 2 and 3; with a second thread, the star solve beside them, on
    // the region (the patch is not known before the distance).
    bool star_beside = m_options.query_threads > 1 && !internal::in_parallel_loop() &&
                       ws->region.size() >= min_region_beside_distance;
    {
      std::future<Solve_statistics> region_star;
      if (star_beside) {
        try {
          region_star = std::async(std::launch::async, [this, &star, &w = *ws] {
            return solve_star_heat(star, w.region, w.region_star, w.region_star_solve, w);
          });
        } catch (const std::system_error&) {
          star_beside = false;  // no thread to be had: the star after the distance
        }
      }
      // (If this throws, the future's destructor waits for the star solve,
      // which uses the workspace, before the workspace goes back.)
      result.statistics += integrate_distance(s, *ws);
      if (star_beside) result.statistics += region_star.get();
    }
    const std::vector<std::size_t> order = select_patch(patch, target, wanted, *ws);
    const double reach = patch.kind() == Patch::Kind::geodesic_radius
                             ? patch.radius()
                             : (order.empty() ? 0.0 : ws->potential[order.back()]);
    const bool complete =
        patch.kind() == Patch::Kind::vertex_set ? order.size() == wanted.size() + 1
        : patch.kind() == Patch::Kind::geodesic_radius ? true
                                                        : order.size() == target;
    // The margin is measured to where the region ends, the middle of the
    // edges that leave it; the patch itself must lie inside its last
    // vertices (a radius patch then holds every vertex within its radius).
    // A boundary vertex farther than reach * margin (>= reach) passes both
    // tests, so region_end need not look beyond it.
    const Region_end end = region_end(reach * margin, *ws);
    if (whole_component || (complete && reach < end.vertex && reach * margin <= end.edge)) {
      ws->patch.clear();
      for (std::size_t i : order) ws->patch.push_back(ws->region[i]);
      if (star_beside)
        read_star_heat_on_patch(star_columns(star), order, *ws);
      else
        result.statistics += solve_star_heat(star, ws->patch, ws->star, ws->heat_solve, *ws);
      // Where the region has no boundary vertex, the boundary's image is
      // at least two patch radii away and its heat negligible.
      ws->meets_boundary = touches_boundary(ws->region);
      if (ws->meets_boundary) result.statistics += solve_boundary_star_heat(star, *ws);
      write_result(s, frame, star, order, *ws, result);
      return result;
    }
  }
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_region_largest_first(
    int s, const Patch& patch, std::size_t target, std::size_t component, double growth,
    bool retry, std::size_t& kept, Workspace& ws) const {
  Solve_statistics stats;
  if (patch.kind() == Patch::Kind::geodesic_radius) {
    // Down to the heat at the region's radius.
    const double reach = region_radius(patch.radius(), growth);
    const double threshold = heat_at_distance(reach);
    if (!retry) {
      // Pruned as a count patch of a flat disk of that radius would be.
      const double disk = M_PI * reach * reach / m_mean_vertex_area;
      const std::size_t count = disk < static_cast<double>(component)
                                    ? static_cast<std::size_t>(disk)
                                    : component;
      choose_source_heat_pruning(s, count, ws, threshold);
    }
    stats += solve_source_heat_at_least(s, threshold, retry, kept, ws);
    // Every vertex solved: a lower threshold would find no more (heat
    // that underflowed to zero), so the region is the whole component.
    if (ws.candidates.size() == component) kept = component;
  } else {
    // As many as breadth-first candidates would give (and pruned as
    // they would be).
    const std::size_t budget = breadth_first_budget(target, growth, candidate_excess);
    kept = std::min(component, static_cast<std::size_t>(std::ceil(
                                   static_cast<double>(budget) / candidate_excess)));
    if (retry) {
      stats += extend_hottest_source_heat(kept, ws);
    } else {
      choose_source_heat_pruning(s, budget, ws);
      stats += solve_hottest_source_heat(s, kept, ws);
    }
  }
  return stats;
}

template <class TM, class VPM, class S>
double Heat_exponential_map<TM, VPM, S>::heat_at_distance(double d) const {
  const double t = m_distance_time_step;
  const double kernel = internal::bessel_k0(d / std::sqrt(t)) / (2 * M_PI * t);
  return std::isnormal(kernel) ? kernel : std::numeric_limits<double>::min();
}

template <class TM, class VPM, class S>
Solve_statistics Heat_exponential_map<TM, VPM, S>::solve_source_heat_at_least(
    int s, double threshold, bool retry, std::size_t& kept, Workspace& ws) const {
  Solve_statistics stats;
  if (retry) {
    stats = distance_heat().extend_at_least(threshold, ws.candidates, ws.heat,
                                             source_heat_workspace(ws));
  } else {
    ws.rhs.assign(1, internal::Rhs_entry{s, 0, 1.0});
    stats = distance_heat().solve_at_least(ws.rhs, threshold, ws.candidates, ws.heat,
                                           source_heat_workspace(ws), ws.heat_drop_below);
    put_source_first(s, ws);
  }
  // The source always (a heat below the threshold at the source is a patch
  // radius far beyond what the time step resolves).
  kept = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::count_if(ws.heat.begin(), ws.heat.end(),
                                                 [&](double h) { return h >= threshold; })));
  return stats;
}

template <class TM, class VPM, class S>
typename Heat_exponential_map<TM, VPM, S>::Region_end Heat_exponential_map<TM, VPM, S>::region_end(
    double horizon, const Workspace& ws) const {
  const auto& m = m_indexed.arrays;
  Region_end end{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const int v : ws.region_by_index) {
    // end.vertex <= end.edge: a vertex at least as far as end.edge lowers
    // neither, and its neighbours need not be looked at.
    const double d = ws.potential[static_cast<std::size_t>(ws.in_region.value(v))];
    if (d >= end.edge || d > horizon) continue;
    double shortest_out = std::numeric_limits<double>::infinity();
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
      const int u = m.neighbor[p];
      if (!ws.in_region.is_marked(u))
        shortest_out =
            std::min(shortest_out, internal::norm(internal::operator-(m.point[u], m.point[v])));
    }
    if (shortest_out == std::numeric_limits<double>::infinity()) continue;
    end.vertex = std::min(end.vertex, d);
    end.edge = std::min(end.edge, d + 0.5 * shortest_out);
  }
  return end;
}

template <class TM, class VPM, class S>
std::vector<std::size_t> Heat_exponential_map<TM, VPM, S>::select_patch(
    const Patch& patch, std::size_t target, const std::vector<int>& wanted,
    const Workspace& ws) const {
  std::vector<std::size_t> order;  // region positions, nearest first
  if (patch.kind() == Patch::Kind::vertex_set) {
    order.push_back(0);  // the source
    for (int v : wanted)  // distinct, without the source
      if (ws.in_region.is_marked(v)) order.push_back(static_cast<std::size_t>(ws.in_region.value(v)));
  } else {
    order.resize(ws.region.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
  }
  if (patch.kind() == Patch::Kind::geodesic_radius)
    order.erase(std::remove_if(order.begin(), order.end(),
                               [&](std::size_t i) { return ws.potential[i] > patch.radius(); }),
                order.end());
  // Sorted by distance, ties by vertex, with both keys side by side (a
  // comparison through the region's arrays costs two cache misses).
  struct Key {
    double distance;
    int vertex;
    std::size_t position;
    bool operator<(const Key& other) const {
      return distance < other.distance || (distance == other.distance && vertex < other.vertex);
    }
  };
  std::vector<Key> keys(order.size()), scratch;
  std::vector<std::size_t> bucket_start;
  for (std::size_t k = 0; k < order.size(); ++k)
    keys[k] = {ws.potential[order[k]], ws.region[order[k]], order[k]};
  const bool by_count =
      patch.kind() != Patch::Kind::geodesic_radius && patch.kind() != Patch::Kind::vertex_set;
  internal::keep_nearest_sorted(keys, by_count ? target : keys.size(), scratch, bucket_start);
  order.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = keys[k].position;
  return order;
}

template <class TM, class VPM, class S>
void Heat_exponential_map<TM, VPM, S>::write_result(int s, const internal::Tangent_frame& frame,
                                                    const internal::Star_gradient& star,
                                                    const std::vector<std::size_t>& order,
                                                    const Workspace& ws, Result& result) const {
  const std::size_t width = star_columns(star);
  const bool remove_leak = m_angle_estimator == Angle_estimator::heat_quadratic_fit;
  const internal::Near_source_zone zone = near_source_zone(s, frame.normal);
  std::vector<double> values(star.vertices.size());
  const std::size_t boundary_width = boundary_star_columns(star);
  std::vector<double> both(width);  // the Neumann and Dirichlet heat, summed
  // Step 7: the heat directions of the patch vertices (where the blend
  // wants them), then, for the quadratic fit, their cubic leak removed for
  // all of them at once.
  std::vector<std::array<double, 2>> direction(order.size());
  std::vector<std::array<double, 2>> leaking;
  std::vector<double> leak_radius;
  std::vector<std::size_t> leaking_at;
  for (std::size_t p = 0; p < order.size(); ++p) {
    const std::size_t i = order[p];
    const int v = ws.region[i];
    const double* h = ws.star.heat.data() + p * width;
    // The heat from v at the source: its own column for a logarithmic
    // estimator, the source heat of the distance step (or, where that has
    // another time, the third column of the star solve) otherwise.
    double at_source = !is_linear_in_heat(m_angle_estimator) ? h[0]
                       : m_separate_distance_heat                     ? h[2]
                                                                      : ws.region_heat[i];
    if (ws.meets_boundary) {
      const double* dirichlet = ws.boundary_star.heat.data() + p * boundary_width;
      for (std::size_t c = 0; c < width; ++c) both[c] = h[c] + dirichlet[c];
      at_source = is_linear_in_heat(m_angle_estimator) ? at_source + dirichlet[2] : both[0];
      h = both.data();
    }
    if (!(std::abs(at_source) > std::numeric_limits<double>::min()))
      throw Computation_error("heat diffusion underflows at vertex " +
                              std::to_string(m_indexed.arrays.to_original(v)) +
                              " (distance " + std::to_string(ws.potential[i]) +
                              "); increase the time factor or request a smaller patch");
    if (v == s || zone.heat_weight(ws.potential[i]) == 0.0) continue;  // no heat direction needed
    direction[p] = heat_direction(at_source, star, h, values);
    if (remove_leak && at_source > 0) {
      leaking.push_back(direction[p]);
      leak_radius.push_back(std::max(ws.potential[i], m_indexed.arrays.mean_edge_length));
      leaking_at.push_back(p);
    }
  }
  internal::remove_cubic_leak(star, leaking.data(), leak_radius.data(), leaking.size(), m_time_step);
  for (std::size_t k = 0; k < leaking_at.size(); ++k) direction[leaking_at[k]] = leaking[k];

  std::vector<internal::Polar_entry> entries;
  entries.reserve(order.size());
  const internal::Source_one_ring ring = internal::source_one_ring(m_indexed.arrays, s, frame);
  for (std::size_t p = 0; p < order.size(); ++p) {
    const std::size_t i = order[p];
    const int v = ws.region[i];
    if (v == s) continue;
    entries.push_back({static_cast<int>(m_indexed.arrays.to_original(v)),
                       blended_distance(s, v, ws.potential[i], ring, zone),
                       polar_angle(s, v, ws.potential[i], direction[p], frame, ring, zone)});
  }
  Solve_statistics statistics = result.statistics;
  result = internal::assemble_local_map(static_cast<int>(m_indexed.arrays.to_original(s)), entries,
                                        m_indexed.descriptors, frame);
  result.statistics = statistics;
}

template <class TM, class VPM, class S>
std::array<double, 2> Heat_exponential_map<TM, VPM, S>::heat_direction(
    double at_source, const internal::Star_gradient& star, const double* h,
    std::vector<double>& values) const {
  if (is_linear_in_heat(m_angle_estimator)) {
    // The solve applied the gradient weights already.
    if (m_angle_estimator == Angle_estimator::heat_quadratic_fit && at_source > 0)
      return {{h[0] / at_source, h[1] / at_source}};
    return {{h[0], h[1]}};
  }
  const std::size_t width = star.vertices.size();
  const bool use_log = std::all_of(h, h + width, [](double x) { return x > 0; });
  for (std::size_t c = 0; c < width; ++c) values[c] = use_log ? std::log(h[c]) : h[c];
  return star.apply(values.data());
}

template <class TM, class VPM, class S>
double Heat_exponential_map<TM, VPM, S>::polar_angle(int s, int v, double r,
                                                     const std::array<double, 2>& direction,
                                                     const internal::Tangent_frame& frame,
                                                     const internal::Source_one_ring& ring,
                                                     const internal::Near_source_zone& zone) const {
  const double w = zone.heat_weight(r);
  if (w == 0.0) return near_source_angle(s, v, frame, ring);
  const double heat_angle = std::atan2(direction[1], direction[0]);
  if (w == 1.0) return heat_angle;
  const double geometric = near_source_angle(s, v, frame, ring);
  // Blend unit vectors, not angles, so that the wrap at +-pi does not matter.
  return std::atan2(w * std::sin(heat_angle) + (1 - w) * std::sin(geometric),
                    w * std::cos(heat_angle) + (1 - w) * std::cos(geometric));
}

template <class TM, class VPM, class S>
double Heat_exponential_map<TM, VPM, S>::near_source_angle(
    int s, int v, const internal::Tangent_frame& frame,
    const internal::Source_one_ring& ring) const {
  if (const int k = ring.position(v); k >= 0)
    return ring.angle[static_cast<std::size_t>(k)] - ring.reference_angle;
  const double projected =
      frame.angle_of(internal::operator-(m_indexed.arrays.point[v], m_indexed.arrays.point[s]));
  return ring.native_angle(projected) - ring.reference_angle;
}

/// \ingroup PkgExpmapRef
/// One-shot heat exponential map: precomputes for `tm` and answers a single
/// query. Same defaults as `Heat_exponential_map`. Build the class instead
/// when computing more than one map on a mesh.
template <class TriangleMesh>
Local_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> estimate_exponential_map(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    const Patch& patch, const Heat_options& options = {}, const Query_options& query = {}) {
  return Heat_exponential_map<TriangleMesh>(tm, options).compute(source, patch, query);
}

}  // namespace expmap

#endif  // EXPMAP_HEAT_EXPONENTIAL_MAP_H
