// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_LOCATE_SURFACE_POINT_H
#define EXPMAP_LOCATE_SURFACE_POINT_H

/// \file Locate_surface_point.h
/// The surface point nearest to a point of space, by CGAL's AABB tree.

#include <expmap/Errors.h>
#include <expmap/Surface_point.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

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
  /// The mesh's face type, which located points name.
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  /// The point type of the mesh's `vertex_point` map.
  using Point_3 = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  /// The kernel of `Point_3`, whose AABB traits the tree uses.
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;

  /// How far from the mesh's bounding box, in multiples of its largest
  /// side, a point may be and still be located.
  static constexpr double max_relative_distance = 1e8;

  /// Builds the tree of the faces of `tm` and its search tree for nearest
  /// points.
  /// \throws Invalid_input if `tm` has no face or a vertex with a
  ///         coordinate that is not finite.
  explicit Surface_point_locator(const TriangleMesh& tm) : m_tm(tm) {
    if (faces(tm).empty()) throw Invalid_input("cannot locate points on a mesh without faces");
    for (const auto v : vertices(tm)) {
      const Point_3& p = get(CGAL::vertex_point, tm, v);
      if (!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
          !std::isfinite(CGAL::to_double(p.z())))
        throw Invalid_input("cannot locate points on a mesh with coordinates that are not finite");
    }
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
    for (int k = 0; k < 3; ++k) {
      m_low[k] = box.min(k);
      m_high[k] = box.max(k);
      m_size = std::max(m_size, m_high[k] - m_low[k]);
    }
    CGAL::Polygon_mesh_processing::build_AABB_tree(tm, m_tree);
    // CGAL builds the hierarchy and its search tree on the first query
    // otherwise: seconds on millions of faces, which belong here, not to
    // whichever query comes first.
    m_tree.build();
    m_tree.accelerate_distance_queries();
  }

  /// The point of the surface nearest to `xyz` (any nearest one where
  /// several are equally near), with barycentric coordinates in the order
  /// of `Surface_point`. Coordinates below 1e-12 are round-off of the
  /// location (a point at a vertex comes back as 1, 0, 1e-16, say): they
  /// are set to 0 and the others rescaled, so that a point at a vertex's
  /// position is that vertex, and one on an edge is on the edge, exactly.
  /// \throws Invalid_input if a coordinate of `xyz` is not finite or `xyz`
  ///         is farther from the mesh than the class's bound.
  Surface_point<face_descriptor> locate(const std::array<double, 3>& xyz) const {
    check_near_enough(xyz);
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
    if (!(sum > 0) || !std::isfinite(sum))
      throw Computation_error(
          "the nearest surface point's barycentric coordinates came out not finite (a degenerate "
          "face near the point?)");
    for (double& w : point.barycentric) w /= sum;
    return point;
  }

 private:
  void check_near_enough(const std::array<double, 3>& xyz) const {
    std::ostringstream point;
    point << "the point (" << xyz[0] << ", " << xyz[1] << ", " << xyz[2] << ")";
    double outside = 0;  // the largest distance from the box along an axis
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(xyz[k]))
        throw Invalid_input(point.str() + " has a coordinate that is not finite");
      // Differences of finite numbers may overflow to infinity: that is
      // too far, as it should be.
      outside = std::max({outside, m_low[k] - xyz[k], xyz[k] - m_high[k]});
    }
    if (outside > max_relative_distance * m_size) {
      std::ostringstream message;
      message << point.str() << " is too far from the mesh to locate its nearest surface point: "
              << "at least " << outside << " from the mesh's bounding box, more than "
              << max_relative_distance << " times the mesh's size " << m_size;
      throw Invalid_input(message.str());
    }
  }

  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  const TriangleMesh& m_tm;
  std::array<double, 3> m_low{}, m_high{};  // the bounding box
  double m_size = 0;                        // its largest side
  Tree m_tree;
};

/// \ingroup PkgExpmapRef
/// The surface point of `tm` nearest to `xyz`. Builds an AABB tree on every
/// call: for many points use one `Surface_point_locator`.
/// \throws Invalid_input as the locator's constructor and `locate()` do.
template <class TriangleMesh>
Surface_point<typename boost::graph_traits<TriangleMesh>::face_descriptor> locate_surface_point(
    const TriangleMesh& tm, const std::array<double, 3>& xyz) {
  return Surface_point_locator<TriangleMesh>(tm).locate(xyz);
}

/// \ingroup PkgExpmapRef
/// The position of `point` on `tm`: its corners' points weighted by its
/// barycentric coordinates, in the corner order of `Surface_point` (CGAL's
/// `Polygon_mesh_processing::construct_point()` of the same face location).
template <class TriangleMesh>
std::array<double, 3> surface_point_position(
    const TriangleMesh& tm,
    const Surface_point<typename boost::graph_traits<TriangleMesh>::face_descriptor>& point) {
  const auto h = halfedge(point.face, tm);
  const auto points = get(CGAL::vertex_point, tm);
  const decltype(source(h, tm)) corners[3] = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
  std::array<double, 3> x{{0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    const auto& p = get(points, corners[k]);
    x[0] += point.barycentric[k] * CGAL::to_double(p.x());
    x[1] += point.barycentric[k] * CGAL::to_double(p.y());
    x[2] += point.barycentric[k] * CGAL::to_double(p.z());
  }
  return x;
}

}  // namespace expmap

#endif  // EXPMAP_LOCATE_SURFACE_POINT_H
