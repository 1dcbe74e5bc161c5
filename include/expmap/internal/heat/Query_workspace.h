// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_QUERY_WORKSPACE_H
#define EXPMAP_INTERNAL_HEAT_QUERY_WORKSPACE_H

// What the phases of a heat query read (the context) and write (the
// workspace). A workspace is O(n) memory reused query after query, one per
// thread (see Workspace_pool).

#include <expmap/Heat_options.h>
#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/front/Geodesic_front.h>
#include <expmap/internal/heat/Heat_factors.h>
#include <expmap/internal/heat/Heat_source.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

/// The read-only inputs of every phase.
struct Context {
  Context(const Mesh_arrays& mesh, const Heat_factors& factors, const Heat_options& options,
          const Heat_query_options& query, const Source& source)
      : mesh(mesh),
        factors(factors),
        options(options),
        query(query),
        source(source),
        estimator(angle_estimator_at(query.angle_estimator, options.time_factor)),
        pruning_tolerance(factors.heat_is_m_matrix ? query.pruning_tolerance : 0.0) {}

  const Mesh_arrays& mesh;  // renumbered along locality_order
  const Heat_factors& factors;
  const Heat_options& options;     // the precomputation's
  const Heat_query_options& query;  // this query's
  const Source& source;            // this query's
  Angle_estimator estimator;       // the query's, as the time factor allows
  double pruning_tolerance;        // the query's, 0 where the heat matrix forbids pruning
};

/// A star solve's right-hand side and the heat from the star on the rows
/// asked for, row-major.
struct Star_solve {
  std::vector<Rhs_entry> rhs;
  std::vector<double> heat;
};

/// The widest block a star solve (step 6) needs: two columns for the
/// estimators linear in the heat (three with the boundary's Dirichlet
/// column), else one per star vertex, which the solver splits into blocks
/// of its widest kernel. The solver workspace's block is sized by it.
inline int star_solve_width(Angle_estimator estimator, bool boundary) {
  return is_linear_in_heat(estimator) ? (boundary ? 3 : 2)
                                      : Localized_cholesky_solver::max_block_width;
}

/// The state of one query, phase by phase.
struct Workspace {
  /// A workspace for the default estimator's star solves.
  Workspace(const Heat_factors& factors, std::size_t n)
      : poisson_solve(factors.poisson.size(), factors.poisson.number_of_supernodes(), 1) {
    reserve_on_huge_pages(tentative, n);
    tentative.resize(n);
    fit_star_solves(factors, Heat_query_options().angle_estimator);
    in_region.resize(n);
    seen.resize(n);
    wanted.resize(n);
    map_position.resize(n);
  }

  /// Widens the star solves' workspaces for `estimator` if they are
  /// narrower: a workspace keeps the widest block any of its queries asked
  /// for.
  void fit_star_solves(const Heat_factors& factors, Angle_estimator estimator) {
    const int width = star_solve_width(estimator, false);
    if (width <= star_width) return;
    star_width = width;
    heat_solve = Localized_cholesky_solver::Workspace(
        factors.heat.size(), factors.heat.number_of_supernodes(), width);
    if (factors.has_boundary())
      boundary_heat_solve = Localized_cholesky_solver::Workspace(
          factors.boundary_heat.size(), factors.boundary_heat.number_of_supernodes(),
          star_solve_width(estimator, true));
    region_star_solve = Localized_cholesky_solver::Workspace(0, 0, width);
  }

  int star_width = 0;  // the widest star solve the workspaces below serve
  Localized_cholesky_solver::Workspace heat_solve, poisson_solve, boundary_heat_solve;
  // The second thread's (query_threads 2): sized by the first solve that
  // uses it, so a workspace of a parallel batch, whose queries run on one
  // thread each, never holds it.
  Localized_cholesky_solver::Workspace region_star_solve;
  Vertex_marks in_region, seen, wanted;
  Vertex_marks map_position;  // assemble_local_map's scratch
  std::vector<double> tentative;

  // Steps 1 and 2: candidates, source heat, region.
  std::vector<int> candidates;         // vertices the heat is solved for
  std::size_t breadth_first_head = 0;  // where their breadth-first search can go on
  std::vector<double> heat;            // heat from the source on the candidates
  bool prune = false;                  // whether this query's heat solves are pruned
  double heat_drop_below = 0;          // the source heat's pruning threshold (0: not pruned)
  std::vector<int> region;             // the hottest candidates: where distance is integrated
  std::vector<std::size_t> heat_row;   // row of each region vertex in `heat`, ascending
  std::vector<double> region_heat;     // `heat` at each region vertex
  std::vector<double> distance_heat;   // the heat the distance is read from, if not region_heat
  std::vector<int> region_by_index;    // the region in vertex order (memory order)
  std::vector<int> cut_short_at;       // hottest candidates on the candidates' edge
  // Scratch of those steps.
  std::vector<std::size_t> rows;
  std::vector<double> heat_values;
  std::vector<int> sort_scratch, frontier, next_frontier;
  std::vector<Rhs_entry> rhs;

  // Steps 3 and 4: divergence and distance on the region.
  std::vector<double> divergence, potential;

  // Steps 5 and 6: the patch and its star solves.
  std::vector<int> patch;     // the patch vertices, nearest first
  Star_solve star;            // the star solve on the patch
  Star_solve boundary_star;   // its Dirichlet twin, where the region meets a boundary
  bool meets_boundary = false;
  Star_solve region_star;     // the star solve of a second thread, on the region

  // Step 7: each patch vertex (as stored, a vertex source first) and its
  // (u, v), for step 8's fold check.
  struct Patch_uv {
    int vertex;
    std::array<double, 2> uv;
  };
  std::vector<Patch_uv> patch_uv;

  // Step 8: the geodesic front's map, made on the first query that needs
  // it (most workspaces never do).
  std::unique_ptr<Geodesic_front> front;
  std::vector<Polar_entry> front_entries;
  Front_anchor anchor;  // the heat's map the front is held to
};

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_QUERY_WORKSPACE_H
