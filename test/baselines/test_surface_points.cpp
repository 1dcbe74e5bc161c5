// Sources at points of faces (expmap::Surface_point): a corner gives the
// vertex's map, a point on an edge the same map from both faces, the plane
// exactly, the sphere about as well as from a vertex.
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Locate_surface_point.h>
#include <expmap/Surface_point.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "surface_point_fixtures.h"

using namespace expmap_test;

namespace {
template <class Mesh>
using Dgpc = expmap::Geodesic_polar_coordinates<Mesh>;
}  // namespace

BOOST_AUTO_TEST_SUITE(surface_points)

BOOST_AUTO_TEST_CASE(locator_finds_the_face_and_coordinates) {
  const auto mesh = to_mesh<Surface_mesh>(icosphere(3));
  const expmap::Surface_point_locator<Surface_mesh> locator(mesh);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 5, 3)) {
    const Point_source p{Face(static_cast<Surface_mesh::size_type>(f)), {{0.2, 0.3, 0.5}}};
    const Point_source found = locator.locate(surface_point_position(mesh, p));
    BOOST_TEST(found.face == p.face);
    for (int k = 0; k < 3; ++k) BOOST_TEST(std::abs(found.barycentric[k] - p.barycentric[k]) < 1e-12);
  }
  const Point_source once = expmap::locate_surface_point(mesh, {{0, 0, 2}});
  const auto x = surface_point_position(mesh, once);
  BOOST_TEST(x[2] > 0.99);  // nearest the north pole
}

// The library's position of a surface point is CGAL's construct_point of
// the same face location (the corner order both use).
BOOST_AUTO_TEST_CASE(position_is_cgals_construct_point) {
  const auto mesh = to_mesh<Surface_mesh>(icosphere(2));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> weight(0.0, 1.0);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 20, 5)) {
    const double a = weight(random), b = weight(random) * (1 - a);
    const Point_source p{Face(static_cast<Surface_mesh::size_type>(f)), {{a, b, 1 - a - b}}};
    const CGAL::Polygon_mesh_processing::Face_location<Surface_mesh, double> location{
        p.face, {{a, b, 1 - a - b}}};
    const auto expected = CGAL::Polygon_mesh_processing::construct_point(location, mesh);
    const auto x = surface_point_position(mesh, p);
    for (int d = 0; d < 3; ++d) BOOST_TEST(std::abs(x[d] - expected[d]) < 1e-15);
  }
}

// Points with a coordinate that is not finite, or so far away that the
// nearest-point search would overflow (CGAL's search traps on elephant's
// {-1e308, 0, 1e308}), are refused with a message; points far out but
// within the bound are still located.
BOOST_AUTO_TEST_CASE(locator_refuses_points_it_cannot_locate) {
  const auto mesh = load_mesh<Surface_mesh>("elephant.off");
  const expmap::Surface_point_locator<Surface_mesh> locator(mesh);
  const auto refused = [&](const std::array<double, 3>& xyz, const std::string& text) {
    try {
      locator.locate(xyz);
    } catch (const expmap::Invalid_input& e) {
      BOOST_TEST_MESSAGE(e.what());
      return std::string(e.what()).find(text) != std::string::npos;
    }
    return false;
  };
  const double inf = std::numeric_limits<double>::infinity();
  BOOST_TEST(refused({{-1e308, 0, 1e308}}, "the point (-1e+308, 0, 1e+308) is too far from the mesh"));
  BOOST_TEST(refused({{1e200, 0, 0}}, "too far from the mesh"));
  BOOST_TEST(refused({{0, 0, std::nan("")}}, "has a coordinate that is not finite"));
  BOOST_TEST(refused({{-inf, 0, 0}}, "has a coordinate that is not finite"));
  BOOST_TEST(refused({{0, 0, -std::numeric_limits<double>::max()}}, "too far from the mesh"));
  BOOST_CHECK_THROW(expmap::locate_surface_point(mesh, {{1e308, 1e308, 1e308}}), expmap::Invalid_input);

  // The bound: 1e8 times the bounding box's largest side, from the box.
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  double size = 0;
  for (int k = 0; k < 3; ++k) size = std::max(size, box.max(k) - box.min(k));
  const double bound = expmap::Surface_point_locator<Surface_mesh>::max_relative_distance * size;
  BOOST_TEST(refused({{box.xmax() + 1.01 * bound, 0, 0}}, "too far from the mesh"));
  // Within it, the nearest point far out along +x is a point of largest x.
  const Point_source near = locator.locate({{box.xmax() + 0.99 * bound, 0, 0}});
  BOOST_TEST(surface_point_position(mesh, near)[0] > box.xmax() - 1e-6 * size);
}

// A mesh without faces has no point to locate.
BOOST_AUTO_TEST_CASE(locator_refuses_a_mesh_without_faces_or_with_nan) {
  Surface_mesh empty;
  empty.add_vertex(Surface_mesh::Point(0, 0, 0));
  BOOST_CHECK_THROW(expmap::Surface_point_locator<Surface_mesh>{empty}, expmap::Invalid_input);
  // A vertex whose coordinate is not a number (a bounding box skips it).
  Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(5));
  mesh.point(*mesh.vertices().begin()) = Surface_mesh::Point(NAN, 0, 0);
  BOOST_CHECK_THROW(expmap::Surface_point_locator<Surface_mesh>{mesh}, expmap::Invalid_input);
}

BOOST_AUTO_TEST_CASE(dgpc_corner_is_the_vertex) {
  check_corner_is_the_vertex<Dgpc>(icosphere(6), 0.4, 1e-12);
}

BOOST_AUTO_TEST_CASE(dgpc_edge_point_from_both_faces) {
  check_edge_point_from_both_faces<Dgpc>(icosphere(6), 0.4, 1e-9, 1.5);
}

// DGPC is exact on a plane from a vertex, and from a point: the front
// starts with the face's unfolding, exact on a plane.
BOOST_AUTO_TEST_CASE(dgpc_exact_on_a_planar_grid) {
  check_exact_on_a_plane_from_boundary_faces<Dgpc>(1e-12, 1e-9);
}

// A point inside a face against the exact map of the unit sphere from that
// point, and the face's corners as sources for comparison.
BOOST_AUTO_TEST_CASE(dgpc_sphere_point_as_accurate_as_a_vertex) {
  check_sphere_point_as_accurate_as_a_vertex<Dgpc>("DGPC", icosphere(5), 0.5, 1.5);
}

// The sphere's exact map itself moves by up to 1.11 times the distance
// moved; DGPC measured 1.02 .. 1.16 inside a face, up to 1.46 across an edge.
BOOST_AUTO_TEST_CASE(dgpc_no_jump_when_the_point_moves) {
  check_no_jump<Dgpc>("DGPC", icosphere(5), 0.4, 0.02, 2);
  check_no_jump<Dgpc>("DGPC, jittered", jittered_icosphere(), 0.4, 0.02, 2);
}

BOOST_AUTO_TEST_CASE(dgpc_bad_points) { check_bad_points<Dgpc>(); }

BOOST_AUTO_TEST_SUITE_END()
