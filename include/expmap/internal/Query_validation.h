// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_QUERY_VALIDATION_H
#define EXPMAP_INTERNAL_QUERY_VALIDATION_H

#include <expmap/Errors.h>
#include <expmap/Patch.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Vector3.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace expmap {
namespace internal {

/// The checks every method makes on a query before touching the mesh, with
/// the same messages for all of them.
/// Sources and patch vertices are given, and named in messages, by their
/// index in the user's mesh; the functions return the index `m` stores them
/// at (the same unless `m` was renumbered).
/// \throws Invalid_input if `source` is out of range or isolated.
inline int checked_source(const Mesh_arrays& m, std::size_t source) {
  const std::size_t n = m.number_of_vertices();
  if (source >= n)
    throw Invalid_input("source vertex " + std::to_string(source) +
                        " is out of range (the mesh has " + std::to_string(n) + " vertices)");
  const int s = m.from_original(source);
  if (m.is_isolated(s))
    throw Invalid_input("source vertex " + std::to_string(source) +
                        " is isolated (no incident face)");
  return s;
}

/// The distinct vertices of a vertex-set patch, the source `s` (as stored)
/// excluded unless `keep_source` (a point source near `s` maps it too).
/// \throws Invalid_input if one is out of range or not connected to `s`.
inline std::vector<int> checked_vertex_set(const Mesh_arrays& m, const Patch& patch, int s,
                                           bool keep_source = false) {
  const std::size_t n = m.number_of_vertices();
  std::vector<int> wanted;
  for (std::size_t original : patch.vertices()) {
    if (original >= n)
      throw Invalid_input("patch vertex " + std::to_string(original) +
                          " is out of range (the mesh has " + std::to_string(n) + " vertices)");
    const int v = m.from_original(original);
    if (m.component[v] != m.component[s])
      throw Invalid_input("patch vertex " + std::to_string(original) +
                          " is not connected to source vertex " + std::to_string(m.to_original(s)));
    if (v != s || keep_source) wanted.push_back(v);
  }
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  return wanted;
}

/// The number of vertices (source included) a count or fraction patch asks
/// for, capped by the size of the source's component (0 for other kinds).
inline std::size_t patch_target_count(const Mesh_arrays& m, const Patch& patch, int s) {
  const std::size_t component = static_cast<std::size_t>(m.component_size[m.component[s]]);
  return std::min(component, patch.target_count(m.number_of_vertices()));
}

/// A query's source, frame and patch after the checks above, in the order
/// every method makes them (so the first error is the same for all).
struct Checked_query {
  int source;                // as stored in the mesh arrays
  Tangent_frame frame;       // the frame all methods measure angles in
  Patch::Kind kind;
  bool by_count;             // a count or fraction patch
  std::size_t target;        // its vertex count, as `patch_target_count()`
  std::vector<int> wanted;   // a vertex-set patch's vertices, as `checked_vertex_set()`
};

/// \throws Invalid_input as the checks above, and if the reference
///         direction is parallel to the source's normal.
inline Checked_query checked_query(const Mesh_arrays& m, std::size_t source, const Patch& patch,
                                   const Query_options& query) {
  const int s = checked_source(m, source);
  std::optional<Vector3> reference;
  if (query.reference_direction) reference = *query.reference_direction;
  Checked_query q{s, tangent_frame(m, s, reference), patch.kind(), false, 0, {}};
  q.by_count = q.kind == Patch::Kind::vertex_count || q.kind == Patch::Kind::fraction;
  q.target = patch_target_count(m, patch, s);
  if (q.kind == Patch::Kind::vertex_set) q.wanted = checked_vertex_set(m, patch, s);
  return q;
}

/// The checks of `checked_query()` for a point source that is no vertex:
/// `source` is then the point's nearest corner (the patch must lie in its
/// component), `frame` the frame at the point, `target` counts patch
/// vertices only (the point is no vertex) and `wanted` may hold any corner.
inline Checked_query checked_point_query(const Mesh_arrays& m, const Point_source& p,
                                         const Patch& patch, const Query_options& query) {
  const int s = p.nearest_corner();
  std::optional<Vector3> reference;
  if (query.reference_direction) reference = *query.reference_direction;
  Checked_query q{s, point_tangent_frame(m, p, reference), patch.kind(), false, 0, {}};
  q.by_count = q.kind == Patch::Kind::vertex_count || q.kind == Patch::Kind::fraction;
  q.target = patch_target_count(m, patch, s);
  if (q.kind == Patch::Kind::vertex_set) q.wanted = checked_vertex_set(m, patch, s, true);
  return q;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_QUERY_VALIDATION_H
