// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_SUPERNODAL_FACTOR_H
#define EXPMAP_INTERNAL_SOLVER_SUPERNODAL_FACTOR_H

#include <expmap/Cholesky_factor_view.h>
#include <expmap/Factor_precision.h>
#include <expmap/internal/solver/Huge_page_allocator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace expmap {
namespace internal {

/// A Cholesky factor L (A(P,P) = L L^T) regrouped into fundamental
/// supernodes: runs of consecutive columns j, j+1, ... where each column's
/// parent in the elimination tree is the next one and their row patterns
/// below the run coincide. Each supernode is stored densely:
///
/// - the diagonal block (its lower triangle, packed row-major: row r holds
///   columns 0..r and starts at offset r (r + 1) / 2), and
/// - the rows below it (nbelow x ncol, row-major) with their row indices.
///
/// Triangular solves then work on small dense blocks instead of scattering
/// one entry at a time: the rows below a supernode are updated with a short
/// dot product per row, and the separators at the top of a nested
/// dissection ordering — which every localized solve passes through — are
/// single large supernodes.
///
/// Built from any `Cholesky_factor_view` (an LDL^T factor is scaled to
/// LL^T), so every solver model gets the same kernel.
///
/// The entries are kept in double precision or, to halve the memory a
/// solve streams, rounded to single precision (`Factor_precision`) in every
/// supernode whose nonzero entries a float holds to its full 24 bits (none
/// below the smallest normal float); the others stay in double precision.
/// The solves accumulate in double either way.
struct Supernodal_factor {
  struct Supernode {
    int first_column = 0;     // columns first_column .. first_column + ncol - 1
    int ncol = 0;
    int nbelow = 0;           // rows below the diagonal block
    std::size_t diagonal = 0; // offset of the diagonal block in its entries' array
    std::size_t below = 0;    // offset of the below block in its entries' array
    bool single = false;      // its entries in `single_value`, else in `value`
    std::size_t below_rows = 0;  // offset of the below rows in `row_index`
    int parent = -1;          // parent supernode, -1 for a root
    // -1: the rows below are dense; else they are kept as U V^T of this
    // rank in the block's place (compress_rows_below, Low_rank_rows_below.h).
    int rank = -1;
  };

  int size = 0;
  std::vector<Supernode> supernode;
  std::vector<int> supernode_of_column;
  // The arrays a solve reads in scattered pieces (see Huge_page_allocator).
  std::vector<int, Huge_page_allocator<int>> row_index;
  // The entries, of each supernode in one of the two arrays.
  std::vector<double, Huge_page_allocator<double>> value;
  std::vector<float, Huge_page_allocator<float>> single_value;
  std::vector<int> permutation;          // pivot -> row of A
  std::vector<int> inverse_permutation;  // row of A -> pivot
  Factor_precision precision = Factor_precision::double_precision;  // as asked for

  std::size_t number_of_entries() const { return value.size() + single_value.size(); }
  /// Bytes held by the entries.
  std::size_t value_bytes() const {
    return value.size() * sizeof(double) + single_value.size() * sizeof(float);
  }

  /// Calls f with the entries array of supernode `sn` (float or double, the
  /// precision its entries are kept in; one branch per supernode, and the
  /// callers' kernels are compiled for both). f returns the same type for
  /// both. (The return types are deduced, not declared: a declared one would
  /// instantiate f with the const arrays for a non-const factor too.)
  template <class F>
  decltype(auto) with_entries(const Supernode& sn, F&& f) const {
    if (sn.single) return f(single_value.data());
    return f(value.data());
  }
  template <class F>
  decltype(auto) with_entries(const Supernode& sn, F&& f) {
    if (sn.single) return f(single_value.data());
    return f(value.data());
  }

  /// Offset of row r of a packed lower-triangular diagonal block.
  static std::size_t triangle_row(int r) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(r + 1) / 2;
  }
};

/// Regroups the factor of `view` into fundamental supernodes, its entries
/// kept in `precision`.
/// \throws std::runtime_error if an LDL^T factor has a non-positive pivot.
inline Supernodal_factor make_supernodal_factor(
    const Cholesky_factor_view& view,
    Factor_precision precision = Factor_precision::double_precision) {
  const int n = view.size;
  Supernodal_factor f;
  f.size = n;
  f.permutation.assign(view.permutation, view.permutation + n);
  f.inverse_permutation.assign(static_cast<std::size_t>(n), -1);
  for (int k = 0; k < n; ++k) f.inverse_permutation[f.permutation[k]] = k;

  // Strictly lower entries of column j start at `first[j]`; its parent is
  // its smallest such row.
  std::vector<int> first(static_cast<std::size_t>(n)), count(static_cast<std::size_t>(n)),
      parent(static_cast<std::size_t>(n), -1);
  for (int j = 0; j < n; ++j) {
    first[j] = view.column_start[j] + (view.unit_diagonal ? 0 : 1);
    count[j] = view.column_start[j + 1] - first[j];
    int p = n;
    for (int q = first[j]; q < view.column_start[j + 1]; ++q) p = std::min(p, view.row_index[q]);
    parent[j] = p == n ? -1 : p;
  }
  auto diagonal_of = [&](int j) {
    if (!view.unit_diagonal) return view.value[view.column_start[j]];
    if (!(view.diagonal[j] > 0))
      throw std::runtime_error("LDL^T factor with a non-positive pivot: the matrix is not "
                               "positive definite");
    return std::sqrt(view.diagonal[j]);
  };

  // A supernode goes to floats if a float holds every nonzero entry of its
  // columns to 24 bits: a heat system's factor decays exponentially away
  // from the diagonal, and its top separators reach below the float range.
  auto fits_a_float = [&](int begin, int end) {
    constexpr double smallest = std::numeric_limits<float>::min();
    for (int col = begin; col < end; ++col) {
      const double d = diagonal_of(col);
      const double scale = view.unit_diagonal ? d : 1.0;
      if (d < smallest || d > std::numeric_limits<float>::max()) return false;
      for (int q = first[col]; q < view.column_start[col + 1]; ++q) {
        const double v = std::abs(view.value[q] * scale);
        if (v != 0 && (v < smallest || v > std::numeric_limits<float>::max())) return false;
      }
    }
    return true;
  };

  // The supernodes' column ranges and the exact sizes of the arrays first:
  // growing `value` by doubling would hold up to three times the factor
  // (old and new buffer) at once, the peak of the whole precomputation on
  // large meshes.
  std::vector<int> supernode_end;
  std::vector<char> supernode_single;
  std::size_t doubles = 0, singles = 0, rows_below = 0;
  for (int j = 0; j < n;) {
    int end = j + 1;
    while (end < n && parent[end - 1] == end && count[end - 1] == count[end] + 1) ++end;
    const std::size_t ncol = static_cast<std::size_t>(end - j), nbelow = count[end - 1];
    const bool single = precision == Factor_precision::single_precision && fits_a_float(j, end);
    (single ? singles : doubles) += Supernodal_factor::triangle_row(end - j) + nbelow * ncol;
    rows_below += nbelow;
    supernode_end.push_back(end);
    supernode_single.push_back(single ? 1 : 0);
    j = end;
  }
  f.precision = precision;
  f.value.assign(doubles, 0.0);
  f.single_value.assign(singles, 0.0f);
  f.row_index.reserve(rows_below);
  f.supernode.reserve(supernode_end.size());

  f.supernode_of_column.assign(static_cast<std::size_t>(n), -1);
  std::size_t next_double = 0, next_single = 0;
  for (int j = 0, k = 0; j < n; ++k) {
    const int end = supernode_end[static_cast<std::size_t>(k)];
    Supernodal_factor::Supernode s;
    s.first_column = j;
    s.ncol = end - j;
    s.nbelow = count[end - 1];
    s.single = supernode_single[static_cast<std::size_t>(k)] != 0;
    std::size_t& next_value = s.single ? next_single : next_double;
    s.diagonal = next_value;
    s.below = s.diagonal + Supernodal_factor::triangle_row(s.ncol);
    s.below_rows = f.row_index.size();
    next_value = s.below + static_cast<std::size_t>(s.nbelow) * s.ncol;
    auto store = [&f, &s](std::size_t offset, double v) {
      if (s.single)
        f.single_value[offset] = static_cast<float>(v);
      else
        f.value[offset] = v;
    };
    // Rows below the run: the pattern of its last column.
    {
      const int last = end - 1;
      for (int q = first[last]; q < view.column_start[last + 1]; ++q)
        f.row_index.push_back(view.row_index[q]);
      std::sort(f.row_index.begin() + static_cast<std::ptrdiff_t>(s.below_rows), f.row_index.end());
    }
    const int* below_rows = f.row_index.data() + s.below_rows;
    for (int c = 0; c < s.ncol; ++c) {
      const int col = j + c;
      const double d = diagonal_of(col);
      const double scale = view.unit_diagonal ? d : 1.0;  // LDL^T -> LL^T
      store(s.diagonal + Supernodal_factor::triangle_row(c) + c, d);
      for (int q = first[col]; q < view.column_start[col + 1]; ++q) {
        const int row = view.row_index[q];
        const double v = view.value[q] * scale;
        if (row < end) {
          store(s.diagonal + Supernodal_factor::triangle_row(row - j) + c, v);
        } else {
          const int t = static_cast<int>(std::lower_bound(below_rows, below_rows + s.nbelow, row) -
                                         below_rows);
          store(s.below + static_cast<std::size_t>(t) * s.ncol + c, v);
        }
      }
      f.supernode_of_column[col] = static_cast<int>(f.supernode.size());
    }
    f.supernode.push_back(s);
    j = end;
  }
  for (auto& s : f.supernode)
    s.parent = s.nbelow == 0 ? -1 : f.supernode_of_column[f.row_index[s.below_rows]];
  return f;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_SUPERNODAL_FACTOR_H
