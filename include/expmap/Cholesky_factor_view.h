// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_CHOLESKY_FACTOR_VIEW_H
#define EXPMAP_CHOLESKY_FACTOR_VIEW_H

/// \file Cholesky_factor_view.h
/// The read-only view of a sparse Cholesky factor that every model of the
/// `SparseCholeskySolver` concept hands to the localized solver.

namespace expmap {

/// \ingroup PkgExpmapConcepts
/// A sparse Cholesky factor of a symmetric positive definite matrix A,
/// seen as plain compressed-column arrays owned by the solver model.
///
/// With P the permutation (`permutation[k]` is the row of A that became
/// pivot k) the factor satisfies `A(P, P) = L D L^T`:
///
/// - `unit_diagonal == false`: an LL^T factor (D = I). Column j stores its
///   diagonal entry L(j, j) first, then the strictly lower entries.
/// - `unit_diagonal == true`: an LDL^T factor with unit L. Column j stores
///   only the strictly lower entries and `diagonal[j]` holds D(j, j).
///
/// Within a column the strictly lower entries may come in any order. The
/// elimination tree is implied: the parent of column j is the smallest row
/// index among its strictly lower entries.
///
/// The view stays valid as long as the solver object that produced it is
/// alive and not re-factored.
struct Cholesky_factor_view {
  int size = 0;                       ///< the order n of A
  const int* permutation = nullptr;   ///< n entries, pivot -> row of A
  const int* column_start = nullptr;  ///< n + 1 entries
  const int* row_index = nullptr;     ///< column_start[n] entries
  const double* value = nullptr;      ///< column_start[n] entries
  bool unit_diagonal = false;         ///< true for LDL^T, false for LL^T
  const double* diagonal = nullptr;   ///< D for LDL^T, nullptr for LL^T
};

}  // namespace expmap

#endif  // EXPMAP_CHOLESKY_FACTOR_VIEW_H
