// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_FACTOR_PRECISION_H
#define EXPMAP_FACTOR_PRECISION_H

/// \file Factor_precision.h
/// The precision of the factors kept between queries.

namespace expmap {

/// \ingroup PkgExpmapRef
/// The precision the Cholesky factors are kept in between queries
/// (`Heat_options::factor_precision`). The localized solves accumulate in
/// double precision either way; only the factors' entries are rounded.
enum class Factor_precision {
  /// The solver model's factors as they are.
  double_precision,
  /// Entries rounded to single precision wherever a float holds them to
  /// its full 24 bits: every supernode of the factor whose nonzero entries
  /// all lie in the normal float range. The others stay in double
  /// precision: a heat system's factor decays exponentially away from the
  /// diagonal, and on large meshes its top separators hold entries below
  /// 1e-38, where a float keeps few or no digits.
  single_precision
};

}  // namespace expmap

#endif  // EXPMAP_FACTOR_PRECISION_H
