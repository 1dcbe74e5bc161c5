// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_LOCAL_MAP_ASSEMBLY_H
#define EXPMAP_INTERNAL_LOCAL_MAP_ASSEMBLY_H

#include <expmap/Fold_free_radius.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Nearest_first.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Tangent_frame.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
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

/// Visits the faces in `faces` whose three corners are all among the `count`
/// vertices of a patch, `vertex(i)` the (renumbered) mesh vertex at patch
/// position i: each face once, from the faces its smallest corner owns
/// (stored with that vertex), as the positions of its corners in the face's
/// order. Stops at the first face for which `visit` returns true, and
/// returns whether it did. `position`, sized to the mesh, is scratch (a hash
/// map would cost a good part of a small query).
template <class VertexOf, class Visit>
bool visit_patch_faces(const Owned_faces& faces, std::size_t count, VertexOf vertex,
                       Vertex_marks& position, Visit visit) {
  position.next_query();
  for (std::size_t i = 0; i < count; ++i) position.mark(vertex(i), static_cast<int>(i));
  for (std::size_t i = 0; i < count; ++i) {
    const int v = vertex(i);
    for (int p = faces.start[v]; p < faces.start[v + 1]; ++p) {
      const std::array<int, 3>& face = faces.face[p];
      if (!position.is_marked(face[1]) || !position.is_marked(face[2])) continue;
      const std::array<std::size_t, 3> corner{{i, static_cast<std::size_t>(position.value(face[1])),
                                               static_cast<std::size_t>(position.value(face[2]))}};
      if (visit(corner)) return true;
    }
  }
  return false;
}

/// The fold-free disk of `map`, which must be nearest first, from the faces
/// of `mesh`: the same triangles `patch_triangles()` finds in the user's
/// mesh, and the same disk as `fold_free_radius()`. `map.indices` are the
/// user's indices; `mesh` may be renumbered. `position` is scratch for
/// `visit_patch_faces()`, whose pass is one of the query's cheapest.
template <class VertexDescriptor>
Fold_free_disk fold_free_disk(const Mesh_arrays& mesh, const Local_map<VertexDescriptor>& map,
                              Vertex_marks& position) {
  Fold_free_disk disk;
  if (map.size() == 0) return disk;
  disk.radius = map.distance.back();
  std::vector<std::array<double, 2>> uv;  // each vertex's once: sines and cosines are the cost
  uv.reserve(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) uv.push_back(map.uv(i));
  const auto uv_of = [&](std::size_t i) { return uv[i]; };
  const auto vertex = [&](std::size_t i) { return mesh.from_original(map.indices[i]); };
  const auto visit = [&](const std::array<std::size_t, 3>& corner) {
    ++disk.triangles;
    if (signed_uv_area2(uv_of, corner) > 0) return false;
    disk.folds = true;
    ++disk.flipped;
    disk.radius = std::min(disk.radius, std::max({map.distance[corner[0]], map.distance[corner[1]],
                                                  map.distance[corner[2]]}));
    return false;
  };
  visit_patch_faces(mesh.owned_faces, map.size(), vertex, position, visit);
  return disk;
}

/// A `Local_map` the way every method reports it: the source first (r = 0,
/// theta = 0), then the entries nearest first (ties by vertex index, so
/// results do not depend on traversal order), with no fold-free radius.
/// Entries for the source itself are dropped. `entries` is sorted in place;
/// their vertices and `source` are indices of the user's mesh. Without
/// `source_row` (a point source that is no vertex) the map has no row at
/// r = 0, keeps entries for `source`, and `source` only names the map's
/// `source`.
template <class VertexDescriptor>
Local_map<VertexDescriptor> sorted_local_map(int source, std::vector<Polar_entry>& entries,
                                             const std::vector<VertexDescriptor>& descriptors,
                                             const Tangent_frame& frame, bool source_row = true) {
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
  if (source_row) add(source, 0.0, 0.0);
  for (const Polar_entry& e : entries)
    if (e.vertex != source || !source_row) add(e.vertex, e.distance, wrap_angle(e.angle));
  return map;
}

/// What `query` asks of a map's fold-free disk: its radius in the map
/// (`find_fold_free_radius`), or the map cut to it (`trim_folds`).
template <class VertexDescriptor>
void apply_fold_options(Local_map<VertexDescriptor>& map, const Fold_free_disk& disk,
                        const Query_options& query) {
  if (query.trim_folds)
    trim_to_disk(map, disk);
  else if (query.find_fold_free_radius)
    map.fold_free_radius = disk.radius;
}

/// `sorted_local_map()` with the fold-free radius if `query` asks for it,
/// cut to that disk if `query.trim_folds`. `mesh` stores the user's mesh
/// (maybe renumbered); `position` is scratch for `fold_free_disk()`.
template <class VertexDescriptor>
Local_map<VertexDescriptor> assemble_local_map(const Mesh_arrays& mesh, int source,
                                               std::vector<Polar_entry>& entries,
                                               const std::vector<VertexDescriptor>& descriptors,
                                               const Tangent_frame& frame,
                                               const Query_options& query,
                                               Vertex_marks& position, bool source_row = true) {
  Local_map<VertexDescriptor> map = sorted_local_map(source, entries, descriptors, frame, source_row);
  if (query.trim_folds || query.find_fold_free_radius)
    apply_fold_options(map, fold_free_disk(mesh, map, position), query);
  return map;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_LOCAL_MAP_ASSEMBLY_H
