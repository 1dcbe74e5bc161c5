// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_LOCATE_SURFACE_POINT_H
#define EXPMAP_LOCATE_SURFACE_POINT_H

/// \file Locate_surface_point.h
/// The surface point nearest to a point of space, by CGAL's AABB tree.

#include <expmap/Surface_point.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>

#include <array>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Finds the surface points nearest to points of space. It builds CGAL's
/// AABB tree of the faces once (O(F log F)), so that each `locate()` costs
/// about O(log F); the mesh must outlive the locator and stay unchanged.
///
/// \tparam TriangleMesh a `FaceListGraph` of triangles whose vertex points
///         are points of a CGAL kernel.
///
/// \code
/// expmap::Surface_point_locator<Mesh> locator(mesh);
/// auto map = dgpc.compute(locator.locate({0.1, 0.2, 0.3}), expmap::Patch::geodesic_radius(0.1));
/// \endcode
template <class TriangleMesh>
class Surface_point_locator {
 public:
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Point_3 = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;

  /// Builds the tree of the faces of `tm`.
  explicit Surface_point_locator(const TriangleMesh& tm) : m_tm(tm) {
    CGAL::Polygon_mesh_processing::build_AABB_tree(tm, m_tree);
  }

  /// The point of the surface nearest to `xyz` (any nearest one where
  /// several are equally near), with barycentric coordinates in the order
  /// of `Surface_point`. Coordinates below 1e-12 are round-off of the
  /// location (a point at a vertex comes back as 1, 0, 1e-16, say): they
  /// are set to 0 and the others rescaled, so that a point at a vertex's
  /// position is that vertex, and one on an edge is on the edge, exactly.
  Surface_point<face_descriptor> locate(const std::array<double, 3>& xyz) const {
    const auto location = CGAL::Polygon_mesh_processing::locate_with_AABB_tree(
        Point_3(xyz[0], xyz[1], xyz[2]), m_tree, m_tm);
    Surface_point<face_descriptor> point;
    point.face = location.first;
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      const double w = CGAL::to_double(location.second[k]);
      point.barycentric[k] = w < 1e-12 ? 0.0 : w;
      sum += point.barycentric[k];
    }
    for (double& w : point.barycentric) w /= sum;
    return point;
  }

 private:
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  const TriangleMesh& m_tm;
  Tree m_tree;
};

/// \ingroup PkgExpmapRef
/// The surface point of `tm` nearest to `xyz`. Builds an AABB tree on every
/// call: for many points use one `Surface_point_locator`.
template <class TriangleMesh>
Surface_point<typename boost::graph_traits<TriangleMesh>::face_descriptor> locate_surface_point(
    const TriangleMesh& tm, const std::array<double, 3>& xyz) {
  return Surface_point_locator<TriangleMesh>(tm).locate(xyz);
}

}  // namespace expmap

#endif  // EXPMAP_LOCATE_SURFACE_POINT_H
