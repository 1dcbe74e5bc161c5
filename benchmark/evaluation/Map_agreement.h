// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_MAP_AGREEMENT_H
#define EXPMAP_BENCHMARK_EVALUATION_MAP_AGREEMENT_H

/// \file Map_agreement.h
/// How well a local map agrees with a reference map of the same source
/// (the exact polyhedral one), vertex by vertex: its fold-overs, its angle
/// error after the best rotation, its distance error (absolute and
/// relative).
///
/// Only a rotation is removed, never a reflection: the methods share one
/// tangent frame and sense of angle, so a mirrored map is wrong, and its
/// differences theta - theta_exact = c - 2 theta_exact spread around the
/// circle, leaving an error near pi/2 whatever rotation is removed.

#include "Statistics.h"

#include <expmap/Fold_overs.h>
#include <expmap/Local_map.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

namespace expmap_evaluation {

/// Agreement of one map with a reference map.
struct Map_agreement {
  std::size_t flipped = 0;    ///< patch triangles the map turns over or collapses
  std::size_t triangles = 0;  ///< all patch triangles (`expmap::count_flipped_triangles`)
  /// Patch vertices both maps hold, the source excluded.
  std::size_t common_vertices = 0;
  /// Mean |theta - theta_ref - rotation| over the common vertices, with the
  /// rotation the circular mean of the differences (NaN without a reference
  /// or common vertices).
  double angle_error = std::numeric_limits<double>::quiet_NaN();
  double rotation = 0;  ///< the rotation removed
  /// Mean |r - r_ref| / r_ref over the common vertices (NaN as above).
  double relative_distance_error = std::numeric_limits<double>::quiet_NaN();
  /// Mean |r - r_ref| over the common vertices (NaN as above), in the
  /// mesh's units: divided by the patch radius it weighs every vertex alike,
  /// where the relative error above is largest next to the source.
  double distance_error = std::numeric_limits<double>::quiet_NaN();

  /// flipped / triangles (0 for a patch without triangles).
  double flipped_fraction() const {
    return triangles ? static_cast<double>(flipped) / static_cast<double>(triangles) : 0.0;
  }
};

/// Fills the angle and distance errors of `agreement` for `map` against
/// `reference` (maps of the same mesh and source; compared at the vertices
/// both patches hold, by vertex index).
template <class VertexDescriptor>
void compare_with_reference(const expmap::Local_map<VertexDescriptor>& map,
                            const expmap::Local_map<VertexDescriptor>& reference,
                            Map_agreement& agreement) {
  std::unordered_map<std::size_t, std::size_t> in_reference;
  in_reference.reserve(reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) in_reference.emplace(reference.indices[i], i);
  std::vector<double> computed, exact, dr, relative_dr;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto it = in_reference.find(map.indices[i]);
    if (it == in_reference.end()) continue;
    const double r_ref = reference.distance[it->second];
    if (!(r_ref > 0)) continue;  // the source: its angle is undefined
    computed.push_back(map.angle[i]);
    exact.push_back(reference.angle[it->second]);
    dr.push_back(std::abs(map.distance[i] - r_ref));
    relative_dr.push_back(dr.back() / r_ref);
  }
  agreement.common_vertices = computed.size();
  if (computed.empty()) return;
  agreement.angle_error = mean(angle_errors_up_to_rotation(computed, exact, agreement.rotation));
  agreement.relative_distance_error = mean(relative_dr);
  agreement.distance_error = mean(dr);
}

/// The fold-overs of `map`, a map of `tm` (no reference to compare with).
template <class TriangleMesh, class VertexDescriptor>
Map_agreement map_agreement(const TriangleMesh& tm,
                            const expmap::Local_map<VertexDescriptor>& map) {
  Map_agreement agreement;
  const expmap::Fold_over_count folds = expmap::count_flipped_triangles(tm, map);
  agreement.flipped = folds.flipped;
  agreement.triangles = folds.total;
  return agreement;
}

/// The agreement of `map`, a map of `tm`, with `reference`: its fold-overs
/// and its errors at the common vertices.
template <class TriangleMesh, class VertexDescriptor>
Map_agreement map_agreement(const TriangleMesh& tm, const expmap::Local_map<VertexDescriptor>& map,
                            const expmap::Local_map<VertexDescriptor>& reference) {
  Map_agreement agreement = map_agreement(tm, map);
  compare_with_reference(map, reference, agreement);
  return agreement;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_MAP_AGREEMENT_H
