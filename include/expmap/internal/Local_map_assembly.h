// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_LOCAL_MAP_ASSEMBLY_H
#define EXPMAP_INTERNAL_LOCAL_MAP_ASSEMBLY_H

#include <expmap/Local_map.h>
#include <expmap/internal/Nearest_first.h>
#include <expmap/internal/Tangent_frame.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace expmap {
namespace internal {

/// Polar coordinates of one patch vertex, before sorting.
struct Polar_entry {
  int vertex;
  double distance;
  double angle;
};

/// Angle wrapped to (-pi, pi], the range of `Local_map::angle`.
inline double wrap_angle(double a) {
  // Most angles come from atan2 and are in range already; std::remainder
  // would return them unchanged, at the cost of a library call.
  if (a > -M_PI && a <= M_PI) return a;
  const double two_pi = 2 * M_PI;
  a = std::remainder(a, two_pi);  // [-pi, pi]
  if (a <= -M_PI) a += two_pi;
  return a;
}

/// Fills a `Local_map` the way every method reports it: the source first
/// (r = 0, theta = 0), then the entries nearest first (ties by vertex
/// index, so results do not depend on traversal order). Entries for the
/// source itself are dropped. `entries` is sorted in place.
template <class VertexDescriptor>
Local_map<VertexDescriptor> assemble_local_map(int source, std::vector<Polar_entry>& entries,
                                               const std::vector<VertexDescriptor>& descriptors,
                                               const Tangent_frame& frame) {
  auto nearer = [](const Polar_entry& a, const Polar_entry& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.vertex < b.vertex);
  };
  // Methods that select their patch by distance pass it sorted already, or
  // nearly: the heat method's distances next to the source are adjusted
  // after the selection.
  sort_nearly_sorted(entries.begin(), entries.end(), nearer);
  Local_map<VertexDescriptor> map;
  map.source = descriptors[source];
  map.normal = frame.normal;
  map.axis_u = frame.e1;
  map.axis_v = frame.e2;
  const std::size_t size = entries.size() + 1;
  map.vertices.reserve(size);
  map.indices.reserve(size);
  map.distance.reserve(size);
  map.angle.reserve(size);
  auto add = [&](int v, double r, double theta) {
    map.vertices.push_back(descriptors[v]);
    map.indices.push_back(static_cast<std::size_t>(v));
    map.distance.push_back(r);
    map.angle.push_back(theta);
  };
  add(source, 0.0, 0.0);
  for (const Polar_entry& e : entries)
    if (e.vertex != source) add(e.vertex, e.distance, wrap_angle(e.angle));
  return map;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_LOCAL_MAP_ASSEMBLY_H
