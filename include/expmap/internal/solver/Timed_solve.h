// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_TIMED_SOLVE_H
#define EXPMAP_INTERNAL_SOLVER_TIMED_SOLVE_H

#include <expmap/Solve_statistics.h>

#include <chrono>

namespace expmap {
namespace internal {

/// Runs `solve` (a callable returning `Solve_statistics`) and returns its
/// statistics with `solve_seconds` set to the wall time it took. Every
/// public solve of `Localized_cholesky_solver` goes through it, so a query
/// can report how its time splits between the solves and the rest.
template <class Solve>
Solve_statistics timed_solve(Solve solve) {
  const auto start = std::chrono::steady_clock::now();
  Solve_statistics stats = solve();
  stats.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_TIMED_SOLVE_H
