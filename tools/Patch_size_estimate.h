// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_PATCH_SIZE_ESTIMATE_H
#define EXPMAP_TOOLS_PATCH_SIZE_ESTIMATE_H

/// \file Patch_size_estimate.h
/// How many vertices a patch will have, known before any map is computed:
/// what the viewer's patch limits are checked against.

#include <expmap/Patch.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace expmap_cli {

/// The vertices within Euclidean distance `radius` of `center` that the
/// mesh connects to the corners of `face` through edges between such
/// vertices (`face`'s corners count only if within `radius` themselves),
/// counted up to `cap` + 1: a count above `cap` only says "more than cap".
///
/// A vertex within geodesic distance R of a point is within Euclidean
/// distance R of it, so this is at least the size of the geodesic patch of
/// radius R around a point of `face`, up to the rare vertex whose only
/// edges towards the point leave the ball; more on surfaces that fold back
/// within R (the exact method's submesh is this ball). Touches only the
/// vertices it counts and their neighbours.
template <class Point>
std::size_t vertices_within(const CGAL::Surface_mesh<Point>& mesh,
                            typename CGAL::Surface_mesh<Point>::Face_index face,
                            const std::array<double, 3>& center, double radius, std::size_t cap) {
  using Mesh = CGAL::Surface_mesh<Point>;
  const auto inside = [&](typename Mesh::Vertex_index v) {
    const Point& p = mesh.point(v);
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = CGAL::to_double(p[k]) - center[k];
      d2 += d * d;
    }
    return d2 <= radius * radius;
  };
  std::vector<bool> seen(mesh.number_of_vertices(), false);
  std::vector<typename Mesh::Vertex_index> stack;
  for (const auto v : CGAL::vertices_around_face(mesh.halfedge(face), mesh))
    if (inside(v) && !seen[v]) {
      seen[v] = true;
      stack.push_back(v);
    }
  std::size_t count = stack.size();
  while (!stack.empty() && count <= cap) {
    const auto v = stack.back();
    stack.pop_back();
    for (const auto w : CGAL::vertices_around_target(mesh.halfedge(v), mesh)) {
      if (seen[w] || !inside(w)) continue;
      seen[w] = true;
      stack.push_back(w);
      if (++count > cap) break;
    }
  }
  return std::min(count, cap + 1);
}

/// The number of vertices `patch` asks for on `mesh`: a count or fraction
/// patch's count (at most the mesh's), a vertex set's size, or for a
/// radius patch `vertices_within()` the radius of `center` from `face`,
/// counted up to `cap` + 1.
template <class Point>
std::size_t estimated_patch_vertices(const CGAL::Surface_mesh<Point>& mesh, const expmap::Patch& patch,
                                     typename CGAL::Surface_mesh<Point>::Face_index face,
                                     const std::array<double, 3>& center, std::size_t cap) {
  if (patch.kind() == expmap::Patch::Kind::geodesic_radius)
    return vertices_within(mesh, face, center, patch.radius(), cap);
  if (patch.kind() == expmap::Patch::Kind::vertex_set) return patch.vertices().size();
  return std::min<std::size_t>(patch.target_count(mesh.number_of_vertices()), mesh.number_of_vertices());
}

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_PATCH_SIZE_ESTIMATE_H
