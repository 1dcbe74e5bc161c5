// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_SOURCE_HEAT_H
#define EXPMAP_INTERNAL_HEAT_SOURCE_HEAT_H

// Step 2 (manual, section 2): the heat from the source, A h = e_s, solved
// on the candidates or, with an M-matrix, largest first until the region is
// known; pruned on small patches of large meshes. Where the boundary reaches
// the patch, also the Dirichlet heat, for the distance.

#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>
#include <expmap/internal/Bessel_k0.h>
#include <expmap/internal/Kth_largest.h>
#include <expmap/internal/heat/Query_workspace.h>
#include <expmap/internal/heat/Region.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace expmap {
namespace internal {
namespace heat {

// Pruning skips the far parts of the top separators, which a query's solves
// walk whatever its size: it pays on patches much smaller than a large mesh
// (doc/performance.md). On meshes below this size the far separators are
// too near for the heat to fall below the threshold.
constexpr std::size_t min_pruned_component = 200000;
// ... and for solves on at most a tenth of the component.
constexpr std::size_t min_component_per_pruned_candidate = 10;

// Whether a query from s on `count` candidates prunes its heat solves.
inline bool prunes(const Context& c, int s, std::size_t count) {
  const auto component =
      static_cast<std::size_t>(c.mesh.component_size[c.mesh.component[s]]);
  return c.pruning_tolerance > 0 && component >= min_pruned_component &&
         count * min_component_per_pruned_candidate <= component;
}

// A guess of the smallest heat from s on `count` candidates, the scale of
// the pruning threshold. The heat at the source is at least 1 / A_ss; away
// from it, one implicit step decays about like exp(-d / sqrt(t)) and the
// candidates reach about the radius of a disk of `count` vertices. Decay
// and distance are overestimated and the guess scaled down: a guess too
// small only prunes less, one too large costs a second solve. On
// elephant_loop2 at 0.1-2% (30 sources) a decay factor of 1 reads
// 0.94-0.97x the factor entries, but 1.16-1.20x for 4 sources at 2%; no
// scale-down 0.96-1.00x, its time within the noise (0.72-1.54x in 4 runs).
constexpr double heat_decay_overestimate = 2.0;
constexpr double smallest_heat_safety = 1e-3;

inline double smallest_heat_guess(const Context& c, int s, std::size_t count) {
  const double radius = c.mesh.mean_edge_length *
                        std::sqrt(static_cast<double>(count) * std::sqrt(3.0) / (2 * M_PI));
  return c.factors.inverse_heat_diagonal[static_cast<std::size_t>(s)] * smallest_heat_safety *
         std::exp(-heat_decay_overestimate * radius / std::sqrt(c.factors.time_step));
}

// Sets ws.prune and the source heat's threshold ws.heat_drop_below (0: not
// pruned) for a query from s on `count` candidates, whose smallest heat is
// `smallest_heat` (if positive) or smallest_heat_guess's.
inline void choose_source_heat_pruning(const Context& c, int s, std::size_t count, Workspace& ws,
                                       double smallest_heat = 0) {
  ws.prune = prunes(c, s, count);
  ws.heat_drop_below = 0;
  if (ws.prune)
    ws.heat_drop_below = c.pruning_tolerance *
                         (smallest_heat > 0 ? smallest_heat : smallest_heat_guess(c, s, count));
}

// The heat from s on the candidates (ws.heat), pruned below
// ws.heat_drop_below. Extendable: if the candidates grow, only the back
// substitution of the new ones' supernodes is added.
inline Solve_statistics solve_source_heat_below(const Context& c, Workspace& ws) {
  ws.rhs.clear();
  c.source.add_heat(ws.rhs, 0);
  ws.heat.resize(ws.candidates.size());
  return c.factors.heat.solve_extendable(ws.rhs, 1, ws.candidates.data(), ws.candidates.size(),
                                         ws.heat.data(), ws.heat_solve, ws.heat_drop_below);
}

inline Solve_statistics solve_source_heat(const Context& c, int s, Workspace& ws) {
  choose_source_heat_pruning(c, s, ws.candidates.size(), ws);
  return solve_source_heat_below(c, ws);
}

// The same heat on the candidates after they grew.
inline Solve_statistics extend_source_heat(const Context& c, Workspace& ws) {
  ws.heat.resize(ws.candidates.size());
  return c.factors.heat.extend(ws.candidates.data(), ws.candidates.size(), ws.heat.data(),
                               ws.heat_solve);
}

// Moves the source to the front of a largest-first solve's candidates (and
// its heat with it), where choose_region wants it.
inline void put_source_first(int s, Workspace& ws) {
  const auto at = static_cast<std::size_t>(
      std::find(ws.candidates.begin(), ws.candidates.end(), s) - ws.candidates.begin());
  std::swap(ws.candidates[0], ws.candidates[at]);
  std::swap(ws.heat[0], ws.heat[at]);
}

// Without candidates: the heat solved largest first until the `kept`
// hottest vertices of the component are known; the candidates are the
// vertices solved, the source first.
inline Solve_statistics solve_hottest_source_heat(const Context& c, int s, std::size_t kept,
                                                  Workspace& ws) {
  ws.rhs.clear();
  c.source.add_heat(ws.rhs, 0);
  const Solve_statistics stats = c.factors.heat.solve_largest(ws.rhs, kept, ws.candidates, ws.heat,
                                                              ws.heat_solve, ws.heat_drop_below);
  put_source_first(s, ws);
  return stats;
}

// The same solve continued until the `kept` hottest are known (a retry).
inline Solve_statistics extend_hottest_source_heat(const Context& c, std::size_t kept,
                                                   Workspace& ws) {
  return c.factors.heat.extend_largest(kept, ws.candidates, ws.heat, ws.heat_solve);
}

// The heat from the source at distance d as one implicit step of time t
// spreads it over a plane: K0(d / sqrt(t)) / (2 pi t), a positive normal
// number (the smallest one where it underflows). Against the heat at 5%
// patches' reach it is 0.64-1.07 times the kernel for most sources, up to
// 2.1 in limbs, where heat spreads along a tube; a factor 2 is about
// 0.7 sqrt(t) in distance.
inline double heat_at_distance(const Context& c, double d) {
  const double t = c.factors.time_step;
  const double kernel = bessel_k0(d / std::sqrt(t)) / (2 * M_PI * t);
  return std::isnormal(kernel) ? kernel : std::numeric_limits<double>::min();
}

// The radius of a radius patch's region: as far beyond the patch as a disk
// with `growth` times its vertices reaches, plus one diffusion length for
// the kernel's error above.
inline double region_radius(const Context& c, double patch_radius, double growth) {
  return std::sqrt(growth) * patch_radius + std::sqrt(c.factors.time_step);
}

// For a radius patch: the heat solved largest first until every vertex
// with at least `threshold` is known, or continued there (`retry`); sets
// `kept` to the region's size, the vertices of at least that heat.
inline Solve_statistics solve_source_heat_at_least(const Context& c, int s, double threshold,
                                                   bool retry, std::size_t& kept, Workspace& ws) {
  Solve_statistics stats;
  if (retry) {
    stats = c.factors.heat.extend_at_least(threshold, ws.candidates, ws.heat, ws.heat_solve);
  } else {
    ws.rhs.clear();
    c.source.add_heat(ws.rhs, 0);
    stats = c.factors.heat.solve_at_least(ws.rhs, threshold, ws.candidates, ws.heat, ws.heat_solve,
                                          ws.heat_drop_below);
    put_source_first(s, ws);
  }
  // The source always (a heat below the threshold at the source is a patch
  // radius far beyond what the time step resolves).
  kept = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::count_if(ws.heat.begin(), ws.heat.end(),
                                                 [&](double h) { return h >= threshold; })));
  return stats;
}

// With an M-matrix, for count, fraction and radius patches: the source heat
// solved, or its search continued (`retry`), until the region for a patch
// `growth` times larger is known; sets `kept` to its size.
inline Solve_statistics solve_region_largest_first(const Context& c, int s, const Patch& patch,
                                                   std::size_t target, std::size_t component,
                                                   double growth, bool retry, std::size_t& kept,
                                                   Workspace& ws) {
  Solve_statistics stats;
  if (patch.kind() == Patch::Kind::geodesic_radius) {
    // Down to the heat at the region's radius.
    const double reach = region_radius(c, patch.radius(), growth);
    const double threshold = heat_at_distance(c, reach);
    if (!retry) {
      // Pruned as a count patch of a flat disk of that radius would be.
      const double disk = M_PI * reach * reach / c.factors.mean_vertex_area;
      const std::size_t count =
          disk < static_cast<double>(component) ? static_cast<std::size_t>(disk) : component;
      choose_source_heat_pruning(c, s, count, ws, threshold);
    }
    stats += solve_source_heat_at_least(c, s, threshold, retry, kept, ws);
    // Every vertex solved: a lower threshold would find no more (heat that
    // underflowed to zero), so the region is the whole component.
    if (ws.candidates.size() == component) kept = component;
  } else {
    // As many as breadth-first candidates would give (and pruned as they
    // would be).
    const std::size_t budget = breadth_first_budget(target, growth, candidate_excess);
    kept = std::min(component, static_cast<std::size_t>(std::ceil(
                                   static_cast<double>(budget) / candidate_excess)));
    if (retry) {
      stats += extend_hottest_source_heat(c, kept, ws);
    } else {
      choose_source_heat_pruning(c, s, budget, ws);
      stats += solve_hottest_source_heat(c, s, kept, ws);
    }
  }
  return stats;
}

// Checks a pruned source-heat solve's threshold against the heat of the
// chosen region; solves again (and chooses the region again) if it was
// above the tolerance times the region's smallest heat. Pruning only lowers
// values here (the inverse of an M-matrix's factor is nonnegative), so a
// threshold from the smallest pruned value is safe; twice too bold (a
// region of barely positive heat): no pruning.
inline Solve_statistics confirm_pruned_source_heat(const Context& c, int s, bool largest_first,
                                                   Workspace& ws) {
  Solve_statistics stats;
  const double tolerance = c.pruning_tolerance;
  for (int attempt = 0; ws.heat_drop_below > 0; ++attempt) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const std::size_t row : ws.heat_row) smallest = std::min(smallest, ws.heat[row]);
    // 2: room for the rounding of `smallest` itself.
    if (ws.heat_drop_below <= 2 * tolerance * smallest) break;
    ws.heat_drop_below = attempt == 0 ? tolerance * smallest : 0.0;
    const std::size_t kept = ws.heat_row.size();
    stats += largest_first ? solve_hottest_source_heat(c, s, kept, ws)
                           : solve_source_heat_below(c, ws);
    choose_region(kept, ws);
  }
  return stats;
}

// Near a boundary, the distance is read from the mean of the Neumann and
// the Dirichlet heat from s (Crane et al. 2013, section 3.3) on the region.
// A source on the boundary has no Dirichlet heat: its distance keeps the
// Neumann heat. Only where the boundary reaches the patch (its `target`
// hottest vertices; a radius patch: the region): farther off, a hole's zero
// heat would only bend the distance towards it.
inline Solve_statistics average_boundary_heat(const Context& c, std::size_t target,
                                              Workspace& ws) {
  ws.distance_heat.clear();
  if (!c.factors.has_boundary()) return {};
  // A point's corners on the boundary add nothing to the Dirichlet heat
  // (their rows are identity, their heat zero); the normalized gradient
  // does not see the factor 1/2 the mean then takes off the Neumann heat
  // where all of them are: a point comes to the mean continuously.
  const auto on_boundary = [&](int v) {
    return c.factors.is_boundary[static_cast<std::size_t>(v)] != 0;
  };
  ws.rhs.clear();
  c.source.add_heat(ws.rhs, 0, on_boundary);
  if (ws.rhs.empty()) return {};
  double hottest_kept = 0;
  if (target > 0 && target < ws.region.size()) {
    std::size_t larger = 0;
    hottest_kept = kth_largest(
        ws.region.size(), target, [&](std::size_t i) { return ws.region_heat[i]; },
        ws.heat_values, larger);
  }
  bool reaches_patch = false;
  for (std::size_t i = 0; i < ws.region.size() && !reaches_patch; ++i)
    reaches_patch = c.factors.is_boundary[static_cast<std::size_t>(ws.region[i])] &&
                    ws.region_heat[i] >= hottest_kept;
  if (!reaches_patch) return {};
  ws.distance_heat.resize(ws.region.size());
  const Solve_statistics stats =
      c.factors.boundary_heat.solve(ws.rhs, 1, ws.region.data(), ws.region.size(),
                                    ws.distance_heat.data(), ws.boundary_heat_solve);
  for (std::size_t i = 0; i < ws.region.size(); ++i)
    ws.distance_heat[i] = 0.5 * (ws.region_heat[i] + ws.distance_heat[i]);
  return stats;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_SOURCE_HEAT_H
