// The angle estimators: the quadratic fit on the star of the source is
// exact for quadratics where the area-weighted piecewise linear gradient is
// not, and on a sphere with irregular one-rings it gives smaller angle
// errors against the analytic map (doc/manual.md, section 2, step 7).
#include <expmap/Analytic_surfaces.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/internal/Indexed_mesh.h>
#include <expmap/internal/Star_gradient.h>
#include <expmap/internal/Tangent_frame.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace expmap_test;

namespace {

// Moves every vertex by a random vector of length up to `jitter` times the
// mean edge length, in the tangent plane of the surface (`normal(p)`),
// keeping the connectivity: irregular one-rings, valid triangles.
template <class Normal, class Project>
void jitter_vertices(expmap::Triangle_soup& soup, double jitter, unsigned seed, Normal normal,
                     Project project) {
  double total = 0;
  std::size_t edges = 0;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto& a = soup.points[t[k]];
      const auto& b = soup.points[t[(k + 1) % 3]];
      total += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      ++edges;
    }
  const double spacing = total / static_cast<double>(edges);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (auto& p : soup.points) {
    const std::array<double, 3> n = normal(p);
    const std::array<double, 3> a = std::abs(n[2]) < 0.9 ? std::array<double, 3>{{0, 0, 1}}
                                                         : std::array<double, 3>{{1, 0, 0}};
    std::array<double, 3> u{{a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2],
                             a[0] * n[1] - a[1] * n[0]}};
    const double length_u = std::hypot(u[0], u[1], u[2]);
    for (double& x : u) x /= length_u;
    const std::array<double, 3> v{{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2],
                                   n[0] * u[1] - n[1] * u[0]}};
    const double angle = 2 * M_PI * uniform(rng);
    const double length = jitter * spacing * std::sqrt(uniform(rng));
    for (int d = 0; d < 3; ++d)
      p[d] += length * (std::cos(angle) * u[d] + std::sin(angle) * v[d]);
    project(p);
  }
}

// Mean angle error (up to a rotation) of heat maps of radius 0.5 on the unit
// sphere, averaged over a few sources.
double sphere_angle_error(const expmap::Triangle_soup& soup, expmap::Angle_estimator estimator) {
  Surface_mesh mesh;
  expmap::soup_to_mesh(soup, mesh);
  expmap::Heat_options options;
  options.angle_estimator = estimator;
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options);
  std::vector<double> errors;
  for (std::size_t s : {17u, 4000u, 9001u}) {
    const auto map = heat.compute_by_index(s, expmap::Patch::geodesic_radius(0.5));
    std::vector<double> computed, exact;
    for (std::size_t i = 1; i < map.size(); ++i) {
      computed.push_back(map.angle[i]);
      exact.push_back(expmap::sphere_exponential_map(soup.points[s], soup.points[map.indices[i]],
                                                     1.0, map.axis_u)
                          .theta_unrotated);
    }
    errors.push_back(mean_angle_error_up_to_rotation(computed, exact));
  }
  return mean(errors);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(angle_estimators)

BOOST_AUTO_TEST_CASE(quadratic_fit_is_exact_for_quadratics_on_an_irregular_star) {
  expmap::Triangle_soup soup = expmap::make_equilateral_grid(4, 0.1);
  jitter_vertices(
      soup, 0.3, 5, [](const auto&) { return std::array<double, 3>{{0, 0, 1}}; },
      [](auto&) {});
  Surface_mesh mesh;
  expmap::soup_to_mesh(soup, mesh);
  const expmap::internal::Indexed_mesh<Surface_mesh, CGAL::Default> indexed(
      mesh, get(CGAL::vertex_point, mesh));
  const int s = 0;  // the centre of the hexagonal grid: an interior vertex
  BOOST_TEST_REQUIRE(indexed.arrays.degree(s) == 6);
  const auto frame = expmap::internal::tangent_frame(indexed.arrays, s, std::nullopt);
  const auto fitted = expmap::internal::quadratic_fit_star_gradient(indexed.arrays, s, frame);
  BOOST_TEST_REQUIRE(fitted.has_value());
  const auto linear = expmap::internal::star_gradient(indexed.arrays, s, frame);

  // f = 3 + 2x - y + 5x^2 - 4xy + 7y^2 in the frame's coordinates about s:
  // grad f(s) = (2, -1).
  std::vector<double> values;
  for (int v : fitted->vertices) {
    const auto& pv = indexed.arrays.point[v];
    const auto& ps = indexed.arrays.point[s];
    const expmap::internal::Vector3 d{{pv[0] - ps[0], pv[1] - ps[1], pv[2] - ps[2]}};
    const double x = expmap::internal::dot(d, frame.e1), y = expmap::internal::dot(d, frame.e2);
    values.push_back(3 + 2 * x - y + 5 * x * x - 4 * x * y + 7 * y * y);
  }
  const auto g = fitted->apply(values.data());
  BOOST_TEST(std::abs(g[0] - 2) < 1e-10);
  BOOST_TEST(std::abs(g[1] + 1) < 1e-10);
  // The area-weighted gradient (unnormalized: only its direction is used)
  // is turned by the quadratic part here (same star, same vertex order).
  BOOST_TEST_REQUIRE(linear.vertices == fitted->vertices);
  const auto p = linear.apply(values.data());
  const double turn = std::abs(std::remainder(std::atan2(p[1], p[0]) - std::atan2(-1.0, 2.0),
                                              2 * M_PI));
  BOOST_TEST_MESSAGE("area-weighted gradient turned by " << turn << " rad");
  BOOST_TEST(turn > 1e-2);
}

BOOST_AUTO_TEST_CASE(quadratic_fit_reduces_angle_error_on_irregular_one_rings) {
  expmap::Triangle_soup regular = expmap::make_icosphere(5, 1.0);  // 10,242 vertices
  expmap::Triangle_soup irregular = regular;
  jitter_vertices(
      irregular, 0.35, 1, [](const auto& p) { return p; },
      [](auto& p) {
        const double r = std::hypot(p[0], p[1], p[2]);
        for (double& x : p) x /= r;
      });
  using E = expmap::Angle_estimator;
  const double regular_linear = sphere_angle_error(regular, E::log_heat_gradient);
  const double regular_fit = sphere_angle_error(regular, E::log_heat_quadratic_fit);
  const double irregular_linear = sphere_angle_error(irregular, E::log_heat_gradient);
  const double irregular_fit = sphere_angle_error(irregular, E::log_heat_quadratic_fit);
  BOOST_TEST_MESSAGE("mean angle error, regular sphere: area-weighted " << regular_linear
                     << ", quadratic fit " << regular_fit << "; jittered: area-weighted "
                     << irregular_linear << ", quadratic fit " << irregular_fit);
  BOOST_TEST(irregular_fit < 0.6 * irregular_linear);
  BOOST_TEST(regular_fit < 1.05 * regular_linear);
}

BOOST_AUTO_TEST_SUITE_END()
