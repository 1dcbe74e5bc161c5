// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LOW_RANK_ROWS_BELOW_H
#define EXPMAP_INTERNAL_SOLVER_LOW_RANK_ROWS_BELOW_H

#include <expmap/internal/Parallel_loop.h>
#include <expmap/internal/solver/Lapack.h>
#include <expmap/internal/solver/Supernodal_factor.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace expmap {
namespace internal {

/// The singular value decomposition B = U S V^T of the row-major `rows` x
/// `columns` block B, thin (k = min(rows, columns) singular vectors), by
/// LAPACK's dgesdd: the block's entries, read as column-major, are B^T = V S
/// U^T, so dgesdd's left vectors are V and its right ones U^T.
struct Thin_svd {
  std::vector<double> sigma;  // k, descending
  std::vector<double> v;      // V column-major: V(q, j) at v[q + j * columns]
  std::vector<double> ut;     // U^T column-major: U(t, j) at ut[j + t * k]
  /// \returns false if LAPACK did not converge.
  template <class T>
  bool compute(const T* block, int rows, int columns) {
    const int k = std::min(rows, columns);
    std::vector<double> a(block, block + static_cast<std::size_t>(rows) * columns);
    sigma.resize(static_cast<std::size_t>(k));
    v.resize(static_cast<std::size_t>(columns) * k);
    ut.resize(static_cast<std::size_t>(k) * rows);
    std::vector<int> iwork(8 * static_cast<std::size_t>(k));
    const char jobz = 'S';
    int info = 0, lwork = -1;
    double optimal_lwork = 0;
    dgesdd_(&jobz, &columns, &rows, a.data(), &columns, sigma.data(), v.data(), &columns,
            ut.data(), &k, &optimal_lwork, &lwork, iwork.data(), &info, 1);
    if (info != 0) return false;
    lwork = static_cast<int>(optimal_lwork);
    std::vector<double> work(static_cast<std::size_t>(lwork));
    dgesdd_(&jobz, &columns, &rows, a.data(), &columns, sigma.data(), v.data(), &columns,
            ut.data(), &k, work.data(), &lwork, iwork.data(), &info, 1);
    return info == 0;
  }
};

/// Which supernodes' rows below are kept as a truncated singular value
/// decomposition, and how closely.
struct Rows_below_compression {
  /// Singular values at or below this times the block's largest are
  /// dropped from double-precision blocks; 0 leaves them dense.
  double tolerance = 0;
  /// The same for blocks kept in floats, whose entries are rounded to about
  /// 6e-8 of themselves already; 0 leaves them dense.
  double single_tolerance = 0;
  /// Only blocks with at least this many columns and rows below: smaller
  /// ones are a small share of any solve's reads.
  int min_side = 128;
  /// A block is compressed only if its two factors take at most this
  /// fraction of its entries (else the dense block reads faster).
  double max_fraction = 0.7;
};

/// Replaces the rows below of the large supernodes of `f` by U V^T, U (rows
/// below x r) = the left singular vectors scaled by their singular values
/// and V (columns x r) the right ones, r the singular values above
/// `c.tolerance` (`c.single_tolerance` for a block kept in floats) times the
/// largest; U and V are kept in the block's precision.
///
/// Why: the rows below a separator couple it to the separators above it,
/// far away on the mesh; that coupling is smooth and of low numerical rank
/// (elephant_loop3's Poisson factor: ranks of 82-118 for blocks of 698-1,128
/// rows at 1e-12, doc/paper_scale.md), while every solve through the
/// separator reads the whole block. The two factors are stored in the
/// block's own place (U's rows, then V's, row-major), so no memory is added;
/// `Supernode::rank` tells the kernels which form a block is in.
///
/// The change to a solve is about the tolerance times the norms of the
/// blocks on its path times its values there: at 1e-14, solutions of a
/// Poisson system moved by about 1e-13 of their spread
/// (test/solvers/test_low_rank_rows_below.cpp).
///
/// The decompositions run on `threads` threads (0: the hardware's count).
/// \returns the number of supernodes compressed.
/// \pre 0 <= c.tolerance < 1, 0 < c.max_fraction <= 1.
inline std::size_t compress_rows_below(Supernodal_factor& f, const Rows_below_compression& c,
                                       unsigned threads = 0) {
  auto valid = [](double tolerance) { return tolerance >= 0 && tolerance < 1; };
  if (!valid(c.tolerance) || !valid(c.single_tolerance) ||
      !(c.max_fraction > 0 && c.max_fraction <= 1))
    throw std::invalid_argument("compress_rows_below: tolerances must lie in [0, 1) and "
                                "max_fraction in (0, 1]");
  auto tolerance_of = [&c](const Supernodal_factor::Supernode& sn) {
    return sn.single ? c.single_tolerance : c.tolerance;
  };
  std::vector<std::size_t> candidates;
  for (std::size_t k = 0; k < f.supernode.size(); ++k) {
    const auto& sn = f.supernode[k];
    if (tolerance_of(sn) > 0 && sn.rank < 0 && sn.ncol >= c.min_side && sn.nbelow >= c.min_side)
      candidates.push_back(k);
  }
  // Largest first: the last ones to start are the quick ones.
  std::sort(candidates.begin(), candidates.end(), [&f](std::size_t a, std::size_t b) {
    const auto& x = f.supernode[a];
    const auto& y = f.supernode[b];
    return static_cast<double>(x.ncol) * x.nbelow > static_cast<double>(y.ncol) * y.nbelow;
  });
  // One block, its entries of type T at `below`: true if it was compressed.
  auto compress = [&c](Supernodal_factor::Supernode& sn, auto* below, double tolerance) {
    using T = std::remove_pointer_t<decltype(below)>;
    Thin_svd svd;
    // Not converged: the block stays dense, exact as it is.
    if (!svd.compute(below, sn.nbelow, sn.ncol)) return false;
    const std::vector<double>& sigma = svd.sigma;
    const int k = static_cast<int>(sigma.size());
    if (k == 0 || !(sigma[0] > 0)) return false;
    int r = 0;
    while (r < k && sigma[r] > tolerance * sigma[0]) ++r;
    const double entries = static_cast<double>(sn.nbelow) * sn.ncol;
    if (static_cast<double>(r) * (sn.nbelow + sn.ncol) > c.max_fraction * entries) return false;
    // The block has been copied into the decomposition: its place is free.
    T* U = below;
    T* V = below + static_cast<std::size_t>(sn.nbelow) * r;
    for (int t = 0; t < sn.nbelow; ++t)
      for (int j = 0; j < r; ++j)
        U[static_cast<std::size_t>(t) * r + j] =
            static_cast<T>(svd.ut[static_cast<std::size_t>(t) * k + j] * sigma[j]);
    for (int q = 0; q < sn.ncol; ++q)
      for (int j = 0; j < r; ++j)
        V[static_cast<std::size_t>(q) * r + j] =
            static_cast<T>(svd.v[static_cast<std::size_t>(j) * sn.ncol + q]);
    sn.rank = r;
    return true;
  };
  std::vector<char> compressed(candidates.size(), 0);
  parallel_loop(candidates.size(), batch_thread_count(threads, candidates.size()),
                [&](std::size_t i) {
    auto& sn = f.supernode[candidates[i]];
    compressed[i] = f.with_entries(
        sn, [&](auto* entries) { return compress(sn, entries + sn.below, tolerance_of(sn)); });
  });
  return static_cast<std::size_t>(std::count(compressed.begin(), compressed.end(), 1));
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_LOW_RANK_ROWS_BELOW_H
