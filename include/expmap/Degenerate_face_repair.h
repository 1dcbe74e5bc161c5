// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_DEGENERATE_FACE_REPAIR_H
#define EXPMAP_DEGENERATE_FACE_REPAIR_H

/// \file Degenerate_face_repair.h
/// Removing the faces every method refuses (zero area) and the needles and
/// caps next to them, with CGAL's repair functions.

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>

namespace expmap {

/// \ingroup PkgExpmapRef
/// What `repair_degenerate_faces()` did.
struct Degenerate_face_repair {
  std::size_t faces_before = 0;     ///< faces of the mesh before the repair
  std::size_t faces_after = 0;      ///< faces after it
  std::size_t vertices_before = 0;  ///< vertices before the repair
  std::size_t vertices_after = 0;   ///< vertices after it (collapsed ones are gone)
  bool complete = true;  ///< false if CGAL could not remove every degenerate face
};

/// \ingroup PkgExpmapRef
/// Removes degenerate faces (collinear or coincident corners), then needles
/// (longest edge over 1000 times the shortest) and caps (an angle above
/// 179 degrees), by collapsing edges and flipping them
/// (`CGAL::Polygon_mesh_processing::remove_degenerate_faces` and
/// `experimental::remove_almost_degenerate_faces` of CGAL 5.5). The thresholds
/// are loose on purpose: they remove what makes cotangent weights unbounded
/// and keep every usable triangle. Vertices on collapsed edges disappear;
/// the mesh's garbage is collected, so its vertex indices are contiguous
/// again (a `CGAL::Surface_mesh` property map follows the vertices).
///
/// \code
/// CGAL::Surface_mesh<Point> mesh = ...;
/// const auto repair = expmap::repair_degenerate_faces(mesh);
/// std::cout << repair.faces_before - repair.faces_after << " faces removed\n";
/// \endcode
/// \pre `mesh` is a triangle mesh.
template <class Point>
Degenerate_face_repair repair_degenerate_faces(CGAL::Surface_mesh<Point>& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Degenerate_face_repair r;
  r.faces_before = mesh.number_of_faces();
  r.vertices_before = mesh.number_of_vertices();
  r.complete = PMP::remove_degenerate_faces(mesh);
  const double cap_cosine = -0.99985;  // cos(179 degrees)
  const double needle_ratio = 1000;
  PMP::experimental::remove_almost_degenerate_faces(mesh, cap_cosine, needle_ratio, 0.0);
  mesh.collect_garbage();
  r.faces_after = mesh.number_of_faces();
  r.vertices_after = mesh.number_of_vertices();
  return r;
}

}  // namespace expmap

#endif  // EXPMAP_DEGENERATE_FACE_REPAIR_H
