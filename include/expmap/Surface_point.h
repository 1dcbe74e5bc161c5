// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_SURFACE_POINT_H
#define EXPMAP_SURFACE_POINT_H

/// \file Surface_point.h
/// A point of the surface as a source: a face and barycentric coordinates.

#include <array>

namespace expmap {

/// \ingroup PkgExpmapRef
/// A point of a triangle face given by barycentric coordinates: the point
/// `w[0] p0 + w[1] p1 + w[2] p2` with, as in CGAL's
/// `Polygon_mesh_processing::Face_location`,
/// p0 = `source(halfedge(face, tm), tm)`, p1 = `target(halfedge(face, tm), tm)`
/// and p2 = `target(next(halfedge(face, tm), tm), tm)`, so a location from
/// `CGAL::Polygon_mesh_processing::locate()` converts member by member
/// (`locate_surface_point()` in `Locate_surface_point.h` does it).
///
/// The coordinates must be finite, at least -1e-12 each and of positive sum;
/// they are clamped to zero and rescaled to sum to 1. A point with one
/// coordinate 1 (after that) is that corner vertex, and a query from it is
/// the query from the vertex, bit for bit; a point with one coordinate 0
/// lies on an edge.
///
/// \tparam FaceDescriptor `boost::graph_traits<TriangleMesh>::face_descriptor`.
template <class FaceDescriptor>
struct Surface_point {
  FaceDescriptor face{};                        ///< the face the point lies in
  std::array<double, 3> barycentric{{1, 0, 0}};  ///< its barycentric coordinates
};

}  // namespace expmap

#endif  // EXPMAP_SURFACE_POINT_H
