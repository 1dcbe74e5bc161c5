// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_RHS_ENTRY_H
#define EXPMAP_INTERNAL_SOLVER_RHS_ENTRY_H

namespace expmap {
namespace internal {

/// One entry of a sparse right-hand side: `value` at `row` of column `column`.
struct Rhs_entry {
  int row;
  int column;
  double value;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_RHS_ENTRY_H
