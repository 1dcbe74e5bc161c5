// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_HEAT_FACTORS_H
#define EXPMAP_INTERNAL_HEAT_HEAT_FACTORS_H

// The heat method's precomputation (manual, section 2): the intrinsic
// triangulation, the cotan operators and the factorizations every query
// solves on.

#include <expmap/Angle_estimator.h>
#include <expmap/Errors.h>
#include <expmap/Heat_options.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/operators/Boundary_loops.h>
#include <expmap/internal/operators/Cotan_operators.h>
#include <expmap/internal/operators/Faces_by_smallest_corner.h>
#include <expmap/internal/operators/Intrinsic_delaunay.h>
#include <expmap/internal/operators/Triangulation_adjacency.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

/// Below this time factor the heat falls by more than a factor e across the
/// two-ring (its log-gradient is about 1 / sqrt(t), the two-ring's radius
/// 2h), beyond what `heat_quadratic_fit`'s cubic correction models.
constexpr double min_time_factor_of_two_ring_fit = 4.0;

/// The estimator a query asking for `requested` uses at `time_factor`:
/// `heat_quadratic_fit` below `min_time_factor_of_two_ring_fit` becomes
/// `log_heat_quadratic_fit`.
inline Angle_estimator angle_estimator_at(Angle_estimator requested, double time_factor) {
  if (requested == Angle_estimator::heat_quadratic_fit &&
      time_factor < min_time_factor_of_two_ring_fit)
    return Angle_estimator::log_heat_quadratic_fit;
  return requested;
}

/// The steps of the precomputation, in the order they run, for
/// `Heat_options::progress`.
enum class Precomputation_step {
  locality_order,
  intrinsic_delaunay,
  operators,
  heat_factorization,
  boundary_heat_factorization,
  poisson_factorization,
  poisson_compression,
  query_workspace,
  done
};

/// Reports the start of `step` to `options.progress`, if set: its name and
/// the share of the precomputation's time before it: about the mean of
/// three runs, two on elephant_loop2 (711,420 vertices) and one on
/// elephant_loop1 (177,852), large meshes being where a progress report
/// matters. The runs differ by up to 0.2 in the factorizations' shares
/// (doc/viewer.md), so these are estimates. The copy of the mesh the constructor makes before
/// the first step is the first 3%. These meshes are closed; a boundary's
/// factorization takes its share from the heat's and the Poisson's.
inline void report(const Heat_options& options, Precomputation_step step) {
  struct Row {
    const char* name;
    double before;
  };
  static constexpr Row rows[] = {{"locality order", 0.03},
                                 {"intrinsic Delaunay triangulation", 0.07},
                                 {"cotan operators", 0.08},
                                 {"heat factorization", 0.20},
                                 {"boundary heat factorization", 0.45},
                                 {"Poisson factorization", 0.58},
                                 {"Poisson compression", 0.90},
                                 {"query workspace", 0.99},
                                 {"done", 1.0}};
  if (options.progress) {
    const Row& row = rows[static_cast<int>(step)];
    options.progress(row.name, row.before);
  }
}

/// Everything a query reads besides the mesh: operators and factors of the
/// triangulation the Laplacian is built on. Immutable once built.
struct Heat_factors {
  Faces_by_smallest_corner faces;  // the divergence's faces, by smallest corner
  Vertex_adjacency neighbors;      // the stars the angles are fitted on
  std::vector<char> is_pinned;     // one vertex per component in the Poisson system
  double time_step = 0;            // t = time_factor h^2
  double mean_vertex_area = 0;     // the mass matrix's mean: the area per vertex
  // The heat matrix A = M + tL is an M-matrix (no positive off-diagonal
  // entry): its inverse factor is then nonnegative, so the source heat can
  // be solved largest first and pruning only lowers values.
  bool heat_is_m_matrix = false;
  std::vector<double> inverse_heat_diagonal;  // 1 / A_vv, a lower bound of the heat at v
                                              // (only for an M-matrix)
  Localized_cholesky_solver heat, poisson;
  // The heat with a zero (Dirichlet) condition on the mesh's boundary loops
  // at least sqrt(t) long (see Star_solve.h), and those loops' vertices;
  // both empty where there is none.
  Localized_cholesky_solver boundary_heat;
  std::vector<char> is_boundary;

  bool has_boundary() const { return !is_boundary.empty(); }
  bool touches_boundary(const std::vector<int>& vertices) const {
    return has_boundary() && std::any_of(vertices.begin(), vertices.end(), [&](int v) {
             return is_boundary[static_cast<std::size_t>(v)] != 0;
           });
  }
};

// The truncation of a Poisson block kept in floats: its entries are rounded
// to about 6e-8 of themselves already.
constexpr double single_precision_compression_tolerance = 1e-7;

// Lets a solver model that accepts an ordering reuse an earlier factor's:
// the Poisson and boundary-heat matrices have the heat matrix's pattern, and
// METIS is most of a factorization's time on large meshes.
template <class Solver>
auto factor_with_ordering(Solver& solver, const Sparse_matrix& A, const std::vector<int>& ordering,
                          int) -> decltype(solver.factor(A, ordering), void()) {
  solver.factor(A, ordering);
}
template <class Solver>
void factor_with_ordering(Solver& solver, const Sparse_matrix& A, const std::vector<int>&, long) {
  solver.factor(A);
}

// Factors A with the solver model and keeps only the supernodal copy the
// localized solves traverse (the model's own factor is released at once).
// A model reports failure in its own way (CHOLMOD's status, Eigen's info);
// the user sees one Computation_error naming the system.
template <class Solver>
Localized_cholesky_solver factor_locally(const Sparse_matrix& A, const char* system,
                                         const Localized_cholesky_solver* like,
                                         Factor_precision precision) {
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
  return Localized_cholesky_solver(solver.factor_view(), precision);
}

// Whether A has no positive off-diagonal entry, leaving out those between
// two vertices `skip` marks (if not empty). Interior edges of an intrinsic
// Delaunay triangulation have nonnegative cotan weights (up to its flip
// slack, 1e-12, and rounding); a boundary edge opposite an obtuse angle
// has a negative one.
inline bool is_m_matrix(const Sparse_matrix& A, const std::vector<char>& skip = {}) {
  const Eigen::VectorXd diagonal = A.diagonal();
  for (int k = 0; k < A.outerSize(); ++k)
    for (Sparse_matrix::InnerIterator it(A, k); it; ++it)
      if (it.row() != it.col() && it.value() > 1e-12 * std::sqrt(diagonal[it.row()] * diagonal[k]) &&
          (skip.empty() || !skip[static_cast<std::size_t>(k)] ||
           !skip[static_cast<std::size_t>(it.row())]))
        return false;
  return true;
}

/// What a subdomain's factorization takes from the whole mesh rather than
/// from its own topology: the vertices on the whole mesh's long boundary
/// loops (empty if none), and the cut, which is no boundary of the surface
/// (its obtuse corners do not keep the heat matrix from being an M-matrix
/// where queries read it: their regions stay clear of the cut).
struct Subdomain_topology {
  std::vector<char> long_boundary, is_cut;
};

// One vertex per connected component, pinned to potential 0 in the Poisson
// system (it is singular by a constant per component).
inline std::vector<char> pinned_vertices(const Mesh_arrays& mesh) {
  std::vector<char> pinned(mesh.number_of_vertices(), 0);
  std::vector<char> component_pinned(mesh.component_size.size(), 0);
  for (std::size_t v = 0; v < mesh.number_of_vertices(); ++v) {
    const int c = mesh.component[v];
    if (!component_pinned[c] && !mesh.is_isolated(static_cast<int>(v))) {
      component_pinned[c] = 1;
      pinned[v] = 1;
    }
  }
  return pinned;
}

/// The precomputation: operators of the (intrinsic Delaunay) triangulation
/// of `mesh` and the factors of the heat matrix A = M + tL, of the Poisson
/// matrix L and, on meshes with a boundary, of A with Dirichlet boundary
/// rows. `options` must be `checked()`; `subdomain` is given for a
/// subdomain. (The Poisson system's pinned vertex may be anywhere, as on a
/// subdomain: a divergence sums to zero, so it moves no distance.)
template <class Solver>
Heat_factors factor_heat_operators(const Mesh_arrays& mesh, const Heat_options& options,
                                   const Subdomain_topology* subdomain = nullptr) {
  Heat_factors f;
  report(options, Precomputation_step::intrinsic_delaunay);
  Intrinsic_triangulation tri = mesh.intrinsic_triangulation();
  if (options.laplacian == Laplacian_mode::intrinsic_delaunay) make_intrinsic_delaunay(tri);
  report(options, Precomputation_step::operators);
  const std::vector<Triangle_shape> shapes = triangle_shapes(tri);
  f.faces = Faces_by_smallest_corner(tri, shapes);
  f.neighbors = vertex_adjacency(tri);

  const double corner_regularization =
      options.regularization == Poisson_regularization::cgal_compatible ? 1e-8 : 0.0;
  Sparse_matrix L = cotan_laplacian(tri, shapes, corner_regularization);
  const Eigen::VectorXd mass = options.vertex_area == Vertex_area::mixed_voronoi
                                   ? mixed_voronoi_mass(tri, shapes)
                                   : lumped_mass(tri, shapes);
  f.mean_vertex_area = mass.sum() / static_cast<double>(std::max<Eigen::Index>(1, mass.size()));
  const double h2 = mesh.mean_edge_length * mesh.mean_edge_length;
  f.time_step = options.time_factor * h2;

  // Identity rows need a zero right-hand side: isolated vertices get none,
  // and a pinned vertex's potential must stay 0.
  std::vector<int> identity_rows;
  for (std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
    if (mesh.is_isolated(static_cast<int>(v))) identity_rows.push_back(static_cast<int>(v));

  // The heat matrix A lives in this scope only: it is freed before the
  // Poisson factorization, where the precomputation's memory peaks.
  {
    Sparse_matrix A = f.time_step * L;
    for (int v = 0; v < A.rows(); ++v) A.coeffRef(v, v) += mass[v];
    make_identity_row(A, identity_rows);
    report(options, Precomputation_step::heat_factorization);
    f.heat = factor_locally<Solver>(A, "heat", nullptr, options.factor_precision);
    static const std::vector<char> no_cut;  // both branches lvalues: is_cut is not copied
    f.heat_is_m_matrix = is_m_matrix(A, subdomain ? subdomain->is_cut : no_cut);
    if (f.heat_is_m_matrix) {
      const Eigen::VectorXd diagonal = A.diagonal();
      f.inverse_heat_diagonal.resize(static_cast<std::size_t>(A.rows()));
      for (int v = 0; v < A.rows(); ++v) f.inverse_heat_diagonal[v] = 1.0 / diagonal[v];
    }

    // Loops shorter than the heat's length scale sqrt(t) are left out: such
    // a pinhole barely changes the Neumann heat, while zero heat on it is a
    // sink (ChineseDragon-10kv's three-vertex holes).
    f.is_boundary =
        subdomain ? subdomain->long_boundary
                  : vertices_on_long_boundary_loops(mesh, std::sqrt(f.time_step));
    if (f.has_boundary()) {
      std::vector<int> dirichlet_rows = identity_rows;
      for (std::size_t v = 0; v < f.is_boundary.size(); ++v)
        if (f.is_boundary[v]) dirichlet_rows.push_back(static_cast<int>(v));
      make_identity_row(A, dirichlet_rows);
      report(options, Precomputation_step::boundary_heat_factorization);
      f.boundary_heat =
          factor_locally<Solver>(A, "boundary heat", &f.heat, options.factor_precision);
    }
  }

  f.is_pinned.assign(mesh.number_of_vertices(), 0);
  if (options.regularization == Poisson_regularization::pinned_vertex) {
    f.is_pinned = pinned_vertices(mesh);
    for (std::size_t v = 0; v < f.is_pinned.size(); ++v)
      if (f.is_pinned[v]) identity_rows.push_back(static_cast<int>(v));
  }
  make_identity_row(L, identity_rows);
  report(options, Precomputation_step::poisson_factorization);
  f.poisson = factor_locally<Solver>(L, "Poisson", &f.heat, options.factor_precision);
  report(options, Precomputation_step::poisson_compression);
  Rows_below_compression compression;
  compression.tolerance = options.poisson_compression_tolerance;
  if (compression.tolerance > 0)
    compression.single_tolerance =
        std::max(compression.tolerance, single_precision_compression_tolerance);
  f.poisson.compress_rows_below(compression);
  return f;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_HEAT_FACTORS_H
