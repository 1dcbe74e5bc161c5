// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_FACTOR_INSPECTION_H
#define EXPMAP_INTERNAL_HEAT_FACTOR_INSPECTION_H

// The shape of a Heat_exponential_map's factors, for the benchmarks and the
// tests that check the factorization; no part of the library's interface.

#include <cstddef>

namespace expmap {
namespace internal {
namespace heat {

struct Factor_inspection {
  /// Elimination-tree height of the heat factor (columns on its longest path).
  template <class Heat_map>
  static int heat_tree_height(const Heat_map& map) {
    return map.whole_factors().heat.tree_height();
  }
  /// Elimination-tree height of the Poisson factor.
  template <class Heat_map>
  static int poisson_tree_height(const Heat_map& map) {
    return map.whole_factors().poisson.tree_height();
  }
  /// Supernodes of the Poisson factor whose rows below are kept in low-rank
  /// form (`Heat_options::poisson_compression_tolerance`).
  template <class Heat_map>
  static std::size_t poisson_compressed_supernodes(const Heat_map& map) {
    return map.whole_factors().poisson.number_of_compressed_supernodes();
  }
  /// Stored entries of all factors, in the dense supernodal form the
  /// queries traverse.
  template <class Heat_map>
  static std::size_t factor_entries(const Heat_map& map) {
    const auto& f = map.whole_factors();
    return f.heat.number_of_entries() + f.poisson.number_of_entries() +
           f.boundary_heat.number_of_entries();
  }
};

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_FACTOR_INSPECTION_H
