// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_FOLD_FREE_RADIUS_H
#define EXPMAP_FOLD_FREE_RADIUS_H

/// \file Fold_free_radius.h
/// Where a local map is one-to-one: the disk around the source inside which
/// no patch triangle folds over, and the map cut to it.
///
/// Maps fold far from the source (past the injectivity radius, or where a
/// method's angles are noisy), rarely near it. The disk up to the nearest
/// fold is the part of a map that can be used as a parameterization as is.

#include <expmap/Fold_overs.h>
#include <expmap/Local_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {

/// The fold-free disk of a map: its radius (`Local_map::fold_free_radius`)
/// and whether any patch triangle folds (then only the vertices strictly
/// inside the disk are free of folds; otherwise all are).
struct Fold_free_disk {
  double radius = 0;
  bool folds = false;
  std::size_t flipped = 0;    ///< patch triangles flipped or collapsed
  std::size_t triangles = 0;  ///< all patch triangles
};

/// The disk of `map`, whose patch triangles `for_each_triangle(visit)`
/// passes to `visit` as the positions of their corners in the map, in the
/// face's order, each once.
template <class VertexDescriptor, class ForEachTriangle>
Fold_free_disk fold_free_disk(const Local_map<VertexDescriptor>& map,
                              ForEachTriangle for_each_triangle) {
  Fold_free_disk disk;
  if (map.size() > 0) disk.radius = *std::max_element(map.distance.begin(), map.distance.end());
  // Each vertex's (u, v) once, not once per triangle: the cosines and sines
  // would cost more than the rest.
  std::vector<std::array<double, 2>> uv(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) uv[i] = map.uv(i);
  const auto uv_of = [&](std::size_t i) { return uv[i]; };
  for_each_triangle([&](const std::array<std::size_t, 3>& corner) {
    ++disk.triangles;
    if (signed_uv_area2(uv_of, corner) > 0) return;
    disk.folds = true;
    ++disk.flipped;
    disk.radius = std::min(disk.radius, std::max({map.distance[corner[0]], map.distance[corner[1]],
                                                  map.distance[corner[2]]}));
  });
  return disk;
}

/// Cuts `map` to `disk`: if it folds, keeps the source and the vertices
/// nearer than the radius, in their order. No kept triangle then has a
/// corner at or beyond the radius, so none is flipped, and the cut map's own
/// fold-free radius is its largest distance.
template <class VertexDescriptor>
void trim_to_disk(Local_map<VertexDescriptor>& map, const Fold_free_disk& disk) {
  map.fold_free_radius = disk.radius;
  if (!disk.folds) return;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (!(map.distance[i] < disk.radius) && map.vertices[i] != map.source) continue;
    map.vertices[kept] = map.vertices[i];
    map.indices[kept] = map.indices[i];
    map.distance[kept] = map.distance[i];
    map.angle[kept] = map.angle[i];
    ++kept;
  }
  map.vertices.resize(kept);
  map.indices.resize(kept);
  map.distance.resize(kept);
  map.angle.resize(kept);
  map.fold_free_radius = kept > 0 ? *std::max_element(map.distance.begin(), map.distance.end()) : 0;
}

/// The patch triangles of `map` for `fold_free_disk()`, from the user's mesh.
template <class TriangleMesh, class VertexDescriptor>
Fold_free_disk fold_free_disk(const TriangleMesh& tm, const Local_map<VertexDescriptor>& map) {
  const auto triangles = patch_triangles(tm, map);
  return fold_free_disk(map, [&](auto visit) {
    for (const auto& t : triangles) visit(t.corner);
  });
}

}  // namespace internal

/// \ingroup PkgExpmapRef
/// The fold-free radius of `map` on `tm`, as `Local_map::fold_free_radius`:
/// the smallest, over the patch triangles that `map` flips or collapses
/// (`is_flipped()`), of the largest distance among their corners; the
/// largest distance in `map` if it flips none. Every triangle whose corners
/// are all nearer than it is mapped one-to-one. The methods fill the field
/// when a query asks (`Query_options::find_fold_free_radius`); this finds
/// it for any map, e.g. one computed without it or changed by hand.
/// Cost: proportional to the patch.
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \pre as `count_flipped_triangles()`.
template <class TriangleMesh, class VertexDescriptor>
double fold_free_radius(const TriangleMesh& tm, const Local_map<VertexDescriptor>& map) {
  return internal::fold_free_disk(tm, map).radius;
}

/// \ingroup PkgExpmapRef
/// `map` cut to its fold-free disk, as `Query_options::trim_folds` does: if
/// it flips a patch triangle, only the source and the vertices nearer than
/// `fold_free_radius(tm, map)` stay (in their order), so the result flips
/// none; otherwise `map` is returned whole. A map that folds right at the
/// source (a flipped triangle whose corners are all at distance 0, as in a
/// collapsed distance field) keeps its source alone. The result's
/// `fold_free_radius` is its own: its largest distance.
///
/// \code
/// const auto disk = expmap::trim_to_fold_free_disk(mesh, map);
/// assert(expmap::count_flipped_triangles(mesh, disk).flipped == 0);
/// \endcode
template <class TriangleMesh, class VertexDescriptor>
Local_map<VertexDescriptor> trim_to_fold_free_disk(const TriangleMesh& tm,
                                                   Local_map<VertexDescriptor> map) {
  const internal::Fold_free_disk disk = internal::fold_free_disk(tm, map);
  internal::trim_to_disk(map, disk);
  return map;
}

}  // namespace expmap

#endif  // EXPMAP_FOLD_FREE_RADIUS_H
