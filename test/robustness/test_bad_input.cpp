// Bad input gets a clear exception or a documented correct result: never a
// crash, a hang or a NaN in the output.
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>

#include <boost/test/unit_test.hpp>

#include <limits>

#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;
using Vertex = Surface_mesh::Vertex_index;

namespace {

// Checks that `f` throws an exception of type E whose message contains `needle`.
template <class E, class F>
void check_message(F f, const std::string& needle) {
  try {
    f();
    BOOST_ERROR("no exception; expected one mentioning '" << needle << "'");
  } catch (const E& e) {
    BOOST_TEST_MESSAGE("message: " << e.what());
    BOOST_TEST(std::string(e.what()).find(needle) != std::string::npos);
  }
}

Surface_mesh small_grid() {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(10, 10, 1.0, 1.0), mesh);
  return mesh;
}

template <class Map>
void check_finite(const Map& map) {
  for (std::size_t i = 0; i < map.size(); ++i) {
    BOOST_TEST(std::isfinite(map.distance[i]));
    BOOST_TEST(std::isfinite(map.angle[i]));
    BOOST_TEST(map.distance[i] >= 0.0);
    BOOST_TEST(map.angle[i] > -M_PI);
    BOOST_TEST(map.angle[i] <= M_PI);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bad_input)

BOOST_AUTO_TEST_CASE(empty_mesh) {
  Surface_mesh mesh;
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh); }, "empty");
}

BOOST_AUTO_TEST_CASE(non_triangle_face) {
  Surface_mesh mesh;
  const Vertex a = mesh.add_vertex(Point(0, 0, 0)), b = mesh.add_vertex(Point(1, 0, 0)),
               c = mesh.add_vertex(Point(1, 1, 0)), d = mesh.add_vertex(Point(0, 1, 0));
  mesh.add_face(a, b, c, d);
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh); }, "triangulate");
}

BOOST_AUTO_TEST_CASE(non_finite_coordinates) {
  Surface_mesh mesh = small_grid();
  mesh.point(Vertex(7)) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh); }, "vertex 7");
  mesh.point(Vertex(7)) = Point(std::numeric_limits<double>::infinity(), 0, 0);
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh); }, "non-finite");
}

BOOST_AUTO_TEST_CASE(zero_area_triangle) {
  Surface_mesh mesh = small_grid();
  // Collapse a vertex onto its neighbour's position: its faces lose their area.
  mesh.point(Vertex(12)) = mesh.point(Vertex(13));
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh); }, "degenerate");
}

BOOST_AUTO_TEST_CASE(bad_parameters) {
  check_message<expmap::Invalid_input>([] { expmap::Patch::geodesic_radius(0); }, "radius");
  check_message<expmap::Invalid_input>([] { expmap::Patch::geodesic_radius(-1); }, "radius");
  check_message<expmap::Invalid_input>(
      [] { expmap::Patch::geodesic_radius(std::numeric_limits<double>::quiet_NaN()); }, "radius");
  check_message<expmap::Invalid_input>([] { expmap::Patch::fraction(0); }, "fraction");
  check_message<expmap::Invalid_input>([] { expmap::Patch::fraction(1.5); }, "fraction");
  check_message<expmap::Invalid_input>([] { expmap::Patch::vertex_count(0); }, "at least one");
  check_message<expmap::Invalid_input>([] { expmap::Patch::vertex_set({}); }, "empty");
  const Surface_mesh mesh = small_grid();
  expmap::Heat_options options;
  options.time_factor = 0;
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options); },
      "time_factor must be positive");
  options.time_factor = -3;
  check_message<expmap::Invalid_input>(
      [&] { expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options); },
      "time_factor must be positive");
}

BOOST_AUTO_TEST_CASE(source_and_patch_vertices_out_of_range) {
  const Surface_mesh mesh = small_grid();
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  check_message<expmap::Invalid_input>(
      [&] { heat.compute_by_index(121, expmap::Patch::fraction(0.5)); }, "source vertex 121");
  check_message<expmap::Invalid_input>(
      [&] { heat.compute_by_index(3, expmap::Patch::vertex_set({5, 999})); }, "999");
}

BOOST_AUTO_TEST_CASE(reference_parallel_to_normal) {
  const Surface_mesh mesh = small_grid();
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  expmap::Query_options query;
  query.reference_direction = std::array<double, 3>{{0, 0, 2}};
  check_message<expmap::Invalid_input>(
      [&] { heat.compute_by_index(60, expmap::Patch::fraction(0.5), query); }, "reference");
  // The heat method renumbers its copy of the mesh; the message names the
  // user's vertex, for every source.
  for (std::size_t source : {0u, 17u, 60u, 120u})
    check_message<expmap::Invalid_input>(
        [&] { heat.compute_by_index(source, expmap::Patch::fraction(0.5), query); },
        "at source vertex " + std::to_string(source));
}

BOOST_AUTO_TEST_CASE(isolated_vertex_is_ignored_but_cannot_be_a_source) {
  Surface_mesh mesh = small_grid();
  const Vertex lonely = mesh.add_vertex(Point(5, 5, 5));
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  check_message<expmap::Invalid_input>(
      [&] { heat.compute(lonely, expmap::Patch::fraction(0.5)); }, "isolated");
  const auto map = heat.compute_by_index(60, expmap::Patch::fraction(1.0));
  BOOST_TEST(map.size() == 121u);  // the whole component, not the isolated vertex
  check_finite(map);
}

BOOST_AUTO_TEST_CASE(patches_stay_in_the_source_component) {
  expmap_analytic::Triangle_soup soup = expmap_analytic::make_grid(6, 6, 1.0, 1.0);
  const expmap_analytic::Triangle_soup other = expmap_analytic::make_grid(6, 6, 1.0, 1.0);
  const int offset = static_cast<int>(soup.points.size());
  for (auto p : other.points) soup.points.push_back({{p[0] + 3, p[1], p[2]}});
  for (auto t : other.triangles) soup.triangles.push_back({{t[0] + offset, t[1] + offset, t[2] + offset}});
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  const auto map = heat.compute_by_index(24, expmap::Patch::fraction(1.0));
  BOOST_TEST(map.size() == 49u);
  check_finite(map);
  check_message<expmap::Invalid_input>(
      [&] { heat.compute_by_index(24, expmap::Patch::vertex_set({60})); }, "not connected");
}

BOOST_AUTO_TEST_CASE(source_on_the_boundary_works) {
  // Neumann boundary: a corner source still gets finite distances close to
  // the Euclidean ones on a flat grid. The heat method smooths most near a
  // boundary (Crane et al. 2013, section 3.2.3); the bound is measured.
  const expmap_analytic::Triangle_soup soup = expmap_analytic::make_grid(40, 40, 1.0, 1.0);
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  for (std::size_t source : {0u, 20u}) {  // a corner and a boundary edge midpoint
    const auto map = heat.compute_by_index(source, expmap::Patch::geodesic_radius(0.4));
    check_finite(map);
    BOOST_TEST(map.size() > 20u);
    double worst = 0;
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto& p = soup.points[map.indices[i]];
      const auto& s = soup.points[source];
      worst = std::max(worst, std::abs(map.distance[i] - std::hypot(p[0] - s[0], p[1] - s[1])));
    }
    BOOST_TEST_MESSAGE("boundary source " << source << ": largest distance error " << worst);
    BOOST_TEST(worst < 0.1 * 0.4);
  }
}

BOOST_AUTO_TEST_CASE(heat_underflow_is_reported_not_returned_as_nan) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  expmap::Heat_options options;
  options.time_factor = 1e-3;  // heat decays like exp(-d / sqrt(t)): far too fast here
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options);
  expmap::Heat_query_options heat_only;
  heat_only.fallback = expmap::Heat_fallback::none;
  check_message<expmap::Computation_error>(
      [&] { heat.compute_by_index(0, expmap::Patch::fraction(1.0), heat_only); }, "underflow");
  // By default the geodesic front maps the source instead.
  const auto map = heat.compute_by_index(0, expmap::Patch::fraction(1.0));
  BOOST_TEST(map.statistics.front_maps == 1u);
  BOOST_TEST(map.size() == heat.number_of_vertices());
  check_finite(map);
}

BOOST_AUTO_TEST_CASE(distance_not_minimal_at_the_source_is_reported) {
  // dino has obtuse non-Delaunay triangles; with the input mesh's cotan
  // Laplacian and t = h^2 the heat turns negative and the distance field's
  // minimum leaves the source (found by the evaluation: 196 vertices at r = 0
  // before this check). The intrinsic Delaunay default is fine there.
  const Surface_mesh mesh = load_mesh<Surface_mesh>("dino.off");
  expmap::Heat_options options;
  options.time_factor = 1;
  options.laplacian = expmap::Laplacian_mode::direct;
  expmap::Heat_exponential_map<Surface_mesh> direct(mesh, options);
  expmap::Heat_query_options heat_only;  // the heat's own map; by default the front's
  heat_only.fallback = expmap::Heat_fallback::none;
  check_message<expmap::Computation_error>(
      [&] { direct.compute_by_index(896, expmap::Patch::fraction(0.05), heat_only); },
      "intrinsic_delaunay");
  check_finite(direct.compute_by_index(896, expmap::Patch::fraction(0.05)));
  options.laplacian = expmap::Laplacian_mode::intrinsic_delaunay;
  expmap::Heat_exponential_map<Surface_mesh> intrinsic(mesh, options);
  const auto map = intrinsic.compute_by_index(896, expmap::Patch::fraction(0.05));
  check_finite(map);
  // With the intrinsic Delaunay default the same failure has another cause
  // (ALSTOM_TEST4's strips: obtuse angles opposite boundary edges), and
  // its message must not send the user to the mode already in use.
  Surface_mesh strips;
  expmap::IO::read_triangle_mesh(data_mesh("ALSTOM_TEST4.off"), strips);  // as the CLI reads it
  const expmap::Heat_exponential_map<Surface_mesh> by_default(strips);
  check_message<expmap::Computation_error>(
      [&] { by_default.compute_by_index(675, expmap::Patch::fraction(0.05), heat_only); },
      "boundary edges");
  std::size_t zeros = 0;
  for (double r : map.distance) zeros += r == 0.0;
  BOOST_TEST(zeros == 1u);  // only the source
}

BOOST_AUTO_TEST_SUITE_END()
