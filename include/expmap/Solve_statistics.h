// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_SOLVE_STATISTICS_H
#define EXPMAP_SOLVE_STATISTICS_H

/// \file Solve_statistics.h
/// What a localized solve touched, for the performance studies.

#include <cstddef>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Work done by localized triangular solves: nodes of the elimination tree
/// visited by forward and back substitution and the factor entries streamed.
/// A query's cost is proportional to `factor_entries`; a query that had to
/// grow its region (`region_retries`) pays for every attempt.
struct Solve_statistics {
  std::size_t forward_nodes = 0;   ///< columns of L visited by L y = b
  std::size_t backward_nodes = 0;  ///< columns of L visited by L^T x = y
  std::size_t factor_entries = 0;  ///< stored entries of L read, both passes
  /// Wall-clock time spent in the solves (not in the rest of the query).
  double solve_seconds = 0;
  /// Times a heat query doubled its region because the patch came closer
  /// than the safety margin to the region's edge (manual, section 2,
  /// step 5); each retry repeats the distance step on the larger region.
  std::size_t region_retries = 0;
  /// Times a heat query grew its breadth-first candidates where the region
  /// touched their edge (manual, section 2, step 2; only where the heat
  /// matrix is not an M-matrix).
  std::size_t candidate_widenings = 0;
  /// Heat queries that also computed the geodesic front's map of their
  /// patch, because the heat's folded a triangle over, came near a
  /// boundary or failed (`Heat_query_options::fallback`).
  std::size_t front_checks = 0;
  /// Heat queries that returned the geodesic front's map: it folds fewer
  /// triangles over than the heat's (next to a boundary: not clearly
  /// more), or the heat failed.
  std::size_t front_maps = 0;

  /// Adds the work of another solve (all fields).
  Solve_statistics& operator+=(const Solve_statistics& other) {
    forward_nodes += other.forward_nodes;
    backward_nodes += other.backward_nodes;
    factor_entries += other.factor_entries;
    solve_seconds += other.solve_seconds;
    region_retries += other.region_retries;
    candidate_widenings += other.candidate_widenings;
    front_checks += other.front_checks;
    front_maps += other.front_maps;
    return *this;
  }
};

}  // namespace expmap

#endif  // EXPMAP_SOLVE_STATISTICS_H
