// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_FACTOR_PRECISION_H
#define EXPMAP_FACTOR_PRECISION_H

/// \file Factor_precision.h
/// The precision of the factors kept between queries.

namespace expmap {

/// \ingroup PkgExpmapRef
/// The precision a Cholesky factor is kept in between queries
/// (`Heat_options::poisson_factor_precision`). The localized solves
/// accumulate in double precision either way; only the factor's entries are
/// rounded.
enum class Factor_precision {
  /// The solver model's factor as it is.
  double_precision,
  /// Entries rounded to single precision: half the memory, and the
  /// triangular solves, which stream the factor, faster. Only for factors
  /// whose entries stay within float's range: a Laplacian's fill decays
  /// slowly with distance, a heat system's exponentially (on a 711k-vertex
  /// mesh below 1e-38, where floats lose their digits).
  single_precision
};

}  // namespace expmap

#endif  // EXPMAP_FACTOR_PRECISION_H
