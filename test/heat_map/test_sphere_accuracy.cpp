// Accuracy of the heat exponential map against the analytic map of the unit
// sphere, and on a planar grid; the measurements behind the default time
// factor (doc/time_factor.md).
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>

#include <boost/test/unit_test.hpp>

#include <random>

#include "Analytic_exponential_maps.h"
#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;

namespace {

struct Errors {
  std::vector<double> angle;     // per source: mean |theta - exact| up to rotation
  std::vector<double> distance;  // per source: mean |r - exact|
};

std::vector<std::size_t> random_sources(std::size_t n, std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  std::vector<std::size_t> sources;
  for (std::size_t i = 0; i < count; ++i) sources.push_back(pick(rng));
  return sources;
}

const expmap_analytic::Triangle_soup& unit_icosphere_40962() {
  static const expmap_analytic::Triangle_soup soup = expmap_analytic::make_icosphere(6, 1.0);
  return soup;
}

Errors sphere_errors(double time_factor, const std::vector<std::size_t>& sources) {
  const expmap_analytic::Triangle_soup& soup = unit_icosphere_40962();
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  expmap::Heat_options options;
  options.time_factor = time_factor;
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options);
  Errors errors;
  for (std::size_t s : sources) {
    const auto map = heat.compute_by_index(s, expmap::Patch::geodesic_radius(0.5));
    std::vector<double> computed, exact, distance_errors;
    for (std::size_t i = 1; i < map.size(); ++i) {
      const auto polar = expmap_analytic::sphere_exponential_map(
          soup.points[s], soup.points[map.indices[i]], 1.0, map.axis_u);
      computed.push_back(map.angle[i]);
      exact.push_back(polar.theta_unrotated);
      distance_errors.push_back(std::abs(map.distance[i] - polar.r));
    }
    errors.angle.push_back(mean_angle_error_up_to_rotation(computed, exact));
    errors.distance.push_back(mean(distance_errors));
  }
  return errors;
}

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

}  // namespace

BOOST_AUTO_TEST_SUITE(sphere_accuracy)

BOOST_AUTO_TEST_CASE(angles_at_time_factor_50) {
  const auto sources = random_sources(unit_icosphere_40962().number_of_vertices(), 10, 2018);
  const Errors e = sphere_errors(50, sources);
  BOOST_TEST_MESSAGE("m = 50: angle median " << median(e.angle) << " max " << max_of(e.angle)
                                             << ", distance median " << median(e.distance));
  BOOST_TEST(median(e.angle) < 1e-3);
  BOOST_TEST(max_of(e.angle) < 5e-3);
}

BOOST_AUTO_TEST_CASE(distances_at_time_factor_1_no_worse_than_cgal) {
  const auto sources = random_sources(unit_icosphere_40962().number_of_vertices(), 10, 2018);
  const Errors ours = sphere_errors(1, sources);

  // CGAL's heat method (t = h^2) on the same mesh, same vertices (r <= 0.5).
  const expmap_analytic::Triangle_soup& soup = unit_icosphere_40962();
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Surface_mesh> cgal(mesh);
  auto d = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:d", 0.0).first;
  std::vector<double> cgal_errors;
  for (std::size_t s : sources) {
    const Surface_mesh::Vertex_index source(static_cast<Surface_mesh::size_type>(s));
    cgal.clear_sources();
    cgal.add_source(source);
    cgal.estimate_geodesic_distances(d);
    std::vector<double> errors;
    for (auto v : vertices(mesh)) {
      const double exact =
          expmap_analytic::sphere_exponential_map(soup.points[s], soup.points[v], 1.0, {{1, 0, 0}})
              .r;
      if (exact <= 0.5 && v != source) errors.push_back(std::abs(get(d, v) - exact));
    }
    cgal_errors.push_back(mean(errors));
  }
  BOOST_TEST_MESSAGE("m = 1: distance mean error median " << median(ours.distance) << " (CGAL "
                                                          << median(cgal_errors) << ")");
  // The localized query integrates distance on a region a few times the
  // patch, CGAL on the whole mesh: the median over sources must be no worse,
  // and no single source more than 2% worse.
  BOOST_TEST(median(ours.distance) <= median(cgal_errors));
  for (std::size_t i = 0; i < sources.size(); ++i)
    BOOST_TEST(ours.distance[i] <= cgal_errors[i] * 1.02);
}

BOOST_AUTO_TEST_CASE(time_factor_table) {
  // The table of doc/time_factor.md; also guards against regressions.
  const auto sources = random_sources(unit_icosphere_40962().number_of_vertices(), 10, 2018);
  double previous_angle = 1;
  for (double m : {1.0, 10.0, 50.0, 100.0}) {
    const Errors e = sphere_errors(m, sources);
    BOOST_TEST_MESSAGE("m = " << m << ": angle median " << median(e.angle) << " max "
                              << max_of(e.angle) << ", distance median " << median(e.distance)
                              << " max " << max_of(e.distance));
    BOOST_TEST(median(e.angle) <= previous_angle);  // smoothing helps angles on a sphere
    BOOST_TEST(median(e.distance) < 4e-3);
    previous_angle = median(e.angle);
  }
}

void check_planar(const expmap_analytic::Triangle_soup& soup, std::size_t s, const char* name,
                  double angle_bound, double distance_bound_in_h) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  const auto map = heat.compute_by_index(s, expmap::Patch::geodesic_radius(0.5));
  std::vector<double> computed, exact, distance_errors;
  for (std::size_t i = 1; i < map.size(); ++i) {
    const auto polar = expmap_analytic::plane_exponential_map(
        soup.points[s], soup.points[map.indices[i]], map.axis_u);
    computed.push_back(map.angle[i]);
    exact.push_back(polar.theta_unrotated);
    distance_errors.push_back(std::abs(map.distance[i] - polar.r));
  }
  const double angle_error = mean_angle_error_up_to_rotation(computed, exact);
  BOOST_TEST_MESSAGE(name << ", default time factor: mean angle error " << angle_error
                          << ", mean distance error " << mean(distance_errors)
                          << " (h = " << heat.mean_edge_length() << ")");
  BOOST_TEST(angle_error < angle_bound);
  BOOST_TEST(mean(distance_errors) < distance_bound_in_h * heat.mean_edge_length());
}

BOOST_AUTO_TEST_CASE(planar_grids_are_nearly_exact) {
  // Sources at the centre, radius 0.5, far from the boundary. Bounds are the
  // measured errors (see the test log) rounded up.
  check_planar(expmap_analytic::make_equilateral_grid(50, 0.02), 0, "equilateral grid", 2e-4, 0.15);
  check_planar(expmap_analytic::make_grid(100, 100, 2.0, 2.0),
               expmap_analytic::grid_origin_vertex(100, 100), "union-jack grid", 7e-3, 0.1);
}

BOOST_AUTO_TEST_SUITE_END()
