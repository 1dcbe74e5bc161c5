// The exact polyhedral exponential map: analytic distances on developable
// meshes (plane, unrolled cylinder), close to the sphere's, the same on
// every mesh representation.
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>

#include <CGAL/squared_distance_3.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <iterator>

#include "baseline_fixtures.h"

using namespace expmap_test;

namespace {
template <class Mesh>
using Exact = expmap::Exact_exponential_map<Mesh>;
}

BOOST_AUTO_TEST_SUITE(exact)

// Distances are exact to rounding; angles too, including the paths that
// CGAL reports corrupted when they run along grid lines (see
// Exact_exponential_map::first_direction).
BOOST_AUTO_TEST_CASE(exact_on_planar_grids) { check_exact_on_planar_grids<Exact>(1e-9, 1e-9); }

// The polyhedral cylinder (a prism: each quad is a flat rectangle) unrolls
// onto a strip of width around * chord: a geodesic that neither wraps nor
// meets the boundary has the length of the straight line in the strip.
BOOST_AUTO_TEST_CASE(unrolled_cylinder_distances) {
  const int around = 48, along = 40;
  const double length = 4.0, radius = 1.0;
  const expmap_analytic::Triangle_soup soup =
      expmap_analytic::make_cylinder(around, along, radius, length);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Exact<Surface_mesh> exact(mesh);
  const double chord = 2 * radius * std::sin(M_PI / around);
  // The source ring (z = 0) and one ring a quarter of the way up.
  for (int ring : {along / 2, along / 4 + 3}) {
    const std::size_t s = static_cast<std::size_t>(ring * around + 5);
    const double max_r = 1.5;  // well below half the circumference and the ends
    const auto map = exact.compute_by_index(s, expmap::Patch::geodesic_radius(max_r));
    double worst = 0;
    std::size_t inside = 0;
    for (std::size_t v = 0; v < soup.number_of_vertices(); ++v) {
      int di = static_cast<int>(v % around) - static_cast<int>(s % around);
      if (di > around / 2) di -= around;
      if (di < -around / 2) di += around;
      const double dz = soup.points[v][2] - soup.points[s][2];
      inside += std::hypot(di * chord, dz) <= max_r;
    }
    for (std::size_t i = 1; i < map.size(); ++i) {
      const std::size_t v = map.indices[i];
      int di = static_cast<int>(v % around) - static_cast<int>(s % around);
      if (di > around / 2) di -= around;
      if (di < -around / 2) di += around;
      const double unrolled = std::hypot(di * chord, soup.points[v][2] - soup.points[s][2]);
      worst = std::max(worst, std::abs(map.distance[i] - unrolled) / unrolled);
    }
    BOOST_TEST_MESSAGE("cylinder, source " << s << ": " << map.size()
                                           << " vertices, max relative r error " << worst);
    BOOST_TEST(map.size() == inside);
    BOOST_TEST(worst <= 1e-9);
  }
}

// The apex's angle sum is rescaled to 2 pi; the boundary ring is never reached.
BOOST_AUTO_TEST_CASE(cone_from_its_apex) { check_cone_from_apex<Exact>(1e-10, 1e-9); }

// Only the mesh's own error is left: the polyhedral geodesics of the
// inscribed icosphere are a little shorter than great circles. Measured
// (5 sources): mean |r error| 4.4e-5 .. 4.9e-5, mean |theta error|
// 4.6e-4 .. 5.3e-4; both shrink on finer spheres (1.2e-5 and 1.8e-4 on
// 40,962 vertices).
BOOST_AUTO_TEST_CASE(close_to_the_analytic_sphere) {
  check_sphere_accuracy<Exact>("exact", 1e-4, 1e-3);
}

BOOST_AUTO_TEST_CASE(same_on_surface_mesh_and_polyhedron) {
  check_same_on_all_representations<Exact>();
}

BOOST_AUTO_TEST_CASE(patch_kinds) { check_patch_kinds<Exact>(true); }

BOOST_AUTO_TEST_CASE(bad_input) { check_bad_input<Exact>(); }

// The submesh a query builds its tree on, counted without building it: for
// a radius patch on a plane, every face within the radius of the source
// (point to triangle), counted one by one; from a vertex as from a point at
// that vertex; stopped just past a limit; none for a patch of the source
// alone, all faces for the whole mesh.
BOOST_AUTO_TEST_CASE(region_faces_count_the_submesh) {
  const auto mesh = to_mesh<Surface_mesh>(expmap_analytic::make_grid(40, 40, 2.0, 2.0));
  const Exact<Surface_mesh> exact(mesh);
  const auto source = *std::next(mesh.vertices().begin(), 20 * 41 + 17);
  const Point& s = mesh.point(source);
  // The point of a face around the source at that vertex: coordinate 1
  // at its corner (in the order of Surface_point).
  expmap::Surface_point<Surface_mesh::Face_index> at_vertex{mesh.face(mesh.halfedge(source)), {}};
  const auto first = mesh.halfedge(at_vertex.face);
  const Surface_mesh::Vertex_index corners[3] = {mesh.source(first), mesh.target(first),
                                                 mesh.target(mesh.next(first))};
  for (int k = 0; k < 3; ++k) at_vertex.barycentric[k] = corners[k] == source ? 1.0 : 0.0;
  // Radii off the grid's spacing (0.05): no face is at the radius itself.
  for (const double radius : {0.07, 0.31, 0.83}) {
    std::size_t within = 0;
    for (const auto f : mesh.faces()) {
      const auto h = mesh.halfedge(f);
      const Kernel::Triangle_3 t(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                 mesh.point(mesh.target(mesh.next(h))));
      within += CGAL::squared_distance(s, t) <= radius * radius;
    }
    BOOST_TEST_CONTEXT("radius " << radius) {
      const auto patch = expmap::Patch::geodesic_radius(radius);
      BOOST_TEST(exact.region_faces(source, patch) == within);
      BOOST_TEST(exact.region_faces(at_vertex, patch) == within);
      BOOST_TEST(exact.region_faces(source, patch, 10) == std::min<std::size_t>(within, 11));
    }
  }
  BOOST_TEST(exact.region_faces(source, expmap::Patch::vertex_count(1)) == 0u);
  BOOST_TEST(exact.region_faces(source, expmap::Patch::fraction(1.0)) == mesh.number_of_faces());
}

BOOST_AUTO_TEST_CASE(concurrent_queries) { check_concurrent_queries<Exact>(); }

// One interface for all methods: on a real mesh, DEM and DGPC are queried
// for the vertices of the exact map's patch (1% of the armadillo), and the
// three maps compare vertex by vertex in the shared frame.
BOOST_AUTO_TEST_CASE(baselines_agree_with_the_exact_map_on_a_real_mesh) {
  const auto mesh = load_mesh<Surface_mesh>("armadillo.off");
  const Exact<Surface_mesh> exact(mesh);
  const expmap::Discrete_exponential_map<Surface_mesh> dem(mesh);
  const expmap::Geodesic_polar_coordinates<Surface_mesh> dgpc(mesh);
  for (std::size_t s : random_sources(num_vertices(mesh), 3, 7)) {
    const auto reference = exact.compute_by_index(s, expmap::Patch::fraction(0.01));
    const expmap::Patch same_vertices = expmap::Patch::vertex_set(reference.indices);
    auto compare = [&](const char* name, const auto& map, double r_bound, double theta_bound) {
      BOOST_TEST_REQUIRE(map.size() == reference.size());
      std::vector<std::size_t> position(num_vertices(mesh));
      for (std::size_t i = 0; i < map.size(); ++i) position[map.indices[i]] = i;
      double r_error = 0, theta_error = 0, r_sum = 0;
      for (std::size_t j = 1; j < reference.size(); ++j) {
        const std::size_t i = position[reference.indices[j]];
        r_error += std::abs(map.distance[i] - reference.distance[j]);
        r_sum += reference.distance[j];
        theta_error += angle_difference(map.angle[i], reference.angle[j]);
      }
      const double count = static_cast<double>(reference.size() - 1);
      BOOST_TEST_MESSAGE(name << " vs exact on the armadillo, source " << s << ": relative mean |r| "
                              << r_error / r_sum << ", mean |theta| " << theta_error / count);
      BOOST_TEST(r_error / r_sum <= r_bound);
      BOOST_TEST(theta_error / count <= theta_bound);
    };
    // Measured: DEM 0.4% .. 3% and 0.02 .. 0.11 rad, DGPC 0.1% .. 0.4% and
    // 0.017 .. 0.044 rad.
    compare("DEM", dem.compute_by_index(s, same_vertices), 0.06, 0.25);
    compare("DGPC", dgpc.compute_by_index(s, same_vertices), 0.01, 0.08);
  }
}

BOOST_AUTO_TEST_SUITE_END()
