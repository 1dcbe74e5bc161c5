// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_FACTOR_PRECISION_H
#define EXPMAP_FACTOR_PRECISION_H

/// \file Factor_precision.h
/// The precision of the factors kept between queries.

namespace expmap {

/// \ingroup PkgExpmapRef
/// The precision the Cholesky factors are kept in between queries. The
/// localized solves accumulate in double precision either way; only the
/// factor's entries are rounded.
enum class Factor_precision {
  /// The solver model's factor as it is.
  double_precision,
  /// Entries rounded to single precision: half the memory, and the
  /// triangular solves, which stream the factor, about 1.2-1.35x faster on
  /// meshes of a million vertices and more. The maps move by a few 1e-7 of
  /// the patch radius in distance and radians in angle on the meshes of
  /// doc/performance.md: far below the method's own error, but not zero.
  single_precision
};

}  // namespace expmap

#endif  // EXPMAP_FACTOR_PRECISION_H
