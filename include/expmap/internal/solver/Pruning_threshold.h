// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_PRUNING_THRESHOLD_H
#define EXPMAP_INTERNAL_SOLVER_PRUNING_THRESHOLD_H

/// \file Pruning_threshold.h
/// The threshold of a pruned localized solve (`drop_below`): what it means,
/// why it pays, how to choose it, and the two checks around it.
///
/// Every solve of `Localized_cholesky_solver` takes a `drop_below` >= 0.
/// With 0 the solve is exact: the same numbers as a full solve. With
/// `drop_below` > 0 it is pruned: an entry of the forward solution y
/// (L y = P b) or of the back solution x whose magnitude is at most
/// `drop_below` in every column of the block is not propagated: the entries
/// it would update are computed as if it were zero (its own value is still
/// computed and returned if requested). The kernels that skip the entries
/// are `Supernode_kernels::forward` and `backward`.
///
/// Why it pays: the dense separators at the top of the elimination tree
/// span the whole mesh, and every solve walks them; but the solution of a
/// well-conditioned system such as the heat system M + tL (and the forward
/// solution y with it) decays exponentially with the distance from the
/// right-hand side, so on most of a separator's columns it is far below
/// anything the caller reads, and the work of those columns (a column of L
/// each) is skipped.
///
/// Choosing `drop_below`: an entry below the threshold changes the returned
/// values by about itself times the entries of L^-1 (at most about 1
/// relative for the heat system, whose inverse factor is nonnegative and
/// diagonally dominated). To keep every returned value accurate to a
/// relative tolerance tau, pass tau times the smallest magnitude among the
/// requested rows (or a lower bound of it, e.g. from a previous solve);
/// `smallest_magnitude()` then checks the choice: the pruning was
/// consistent if drop_below <= tau * smallest_magnitude(out) up to rounding
/// (the pruned values are within tau of the full ones). Systems whose
/// solution does not decay (the Poisson system of the distance step) gain
/// nothing.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace expmap {
namespace internal {

/// Refuses a pruning threshold that is negative, NaN or infinite.
/// \throws std::invalid_argument
inline void check_drop_below(double drop_below) {
  if (!(drop_below >= 0) || !std::isfinite(drop_below))
    throw std::invalid_argument("Localized_cholesky_solver: drop_below must be >= 0 and finite");
}

/// Smallest |value| among `count` values (infinity if there are none): the
/// scale a pruned solve's `drop_below` is checked against.
inline double smallest_magnitude(const double* values, std::size_t count) {
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i) smallest = std::min(smallest, std::abs(values[i]));
  return smallest;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_PRUNING_THRESHOLD_H
