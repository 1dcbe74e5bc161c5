// The polar patch operator against what it samples: linear functions on a
// plane reproduced exactly, a smooth function on the unit sphere at the
// grid points of the exact exponential map, whole-ray shifts when the
// reference direction turns by a multiple of 2 pi / rays, and masks, never
// NaN, at boundaries.
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/Polar_patch_operator.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;

namespace {

using Mesh = Surface_mesh;
constexpr double pi = 3.14159265358979323846;

Mesh to_mesh(const expmap_analytic::Triangle_soup& soup) {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  return mesh;
}

// A 2 x 2 square of the plane z = 0 with 40 x 40 cells, half its flippable
// edges flipped so the triangles are irregular.
const expmap_analytic::Triangle_soup& plane_soup() {
  static const expmap_analytic::Triangle_soup soup = [] {
    expmap_analytic::Triangle_soup s = expmap_analytic::make_grid(40, 40, 2.0, 2.0);
    expmap_analytic::flip_random_edges(s, 0.5, 7);
    return s;
  }();
  return soup;
}

std::vector<double> resample(const expmap::Polar_patch_operator& op, const std::vector<double>& f) {
  const Eigen::Map<const Eigen::VectorXd> x(f.data(), static_cast<Eigen::Index>(f.size()));
  const Eigen::VectorXd y = op.weights * x;
  return std::vector<double>(y.data(), y.data() + y.size());
}

// Every row holds weights in [0, 1] summing to 1 where it is sampled, none
// where it is not.
void check_rows_are_barycentric(const expmap::Polar_patch_operator& op) {
  BOOST_TEST(static_cast<std::size_t>(op.weights.rows()) == op.sampled.size());
  for (Eigen::Index r = 0; r < op.weights.outerSize(); ++r) {
    double sum = 0;
    std::size_t entries = 0;
    for (decltype(op.weights)::InnerIterator it(op.weights, r); it; ++it) {
      BOOST_TEST((std::isfinite(it.value()) && it.value() >= 0 && it.value() <= 1));
      sum += it.value();
      ++entries;
    }
    BOOST_TEST(entries == (op.sampled[r] ? 3u : 0u));
    if (op.sampled[r]) BOOST_TEST(std::abs(sum - 1) < 1e-12);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(linear_functions_on_a_plane_are_reproduced_at_every_grid_point) {
  const auto& soup = plane_soup();
  const Mesh mesh = to_mesh(soup);
  std::vector<double> f;
  for (const auto& p : soup.points) f.push_back(0.7 * p[0] - 1.3 * p[1] + 0.2);
  // Sources at least R + 2 edges from the square's border.
  std::vector<std::size_t> sources;
  for (std::size_t v = 0; v < soup.points.size(); v += 37)
    if (std::abs(soup.points[v][0]) < 0.55 && std::abs(soup.points[v][1]) < 0.55)
      sources.push_back(v);
  BOOST_REQUIRE(sources.size() >= 10);
  const expmap::Polar_grid grid{0.3, 5, 16};
  expmap::Query_options query;
  query.reference_direction = {{1.0, 0.0, 0.0}};  // u along x, v along y

  auto check = [&](const expmap::Polar_patch_operator& op) {
    check_rows_are_barycentric(op);
    const std::vector<double> patches = resample(op, f);
    for (std::size_t s = 0; s < sources.size(); ++s) {
      BOOST_TEST(op.errors[s].empty());
      const auto& c = soup.points[sources[s]];
      for (std::size_t i = 0; i < grid.rings; ++i)
        for (std::size_t j = 0; j < grid.rays; ++j) {
          const std::size_t row = op.row(s, i, j);
          BOOST_TEST_REQUIRE(op.sampled[row] == 1);  // a flat disk: no fold, no edge
          const auto uv = grid.point(i, j);
          const double expected = 0.7 * (c[0] + uv[0]) - 1.3 * (c[1] + uv[1]) + 0.2;
          BOOST_TEST(std::abs(patches[row] - expected) < 1e-9);
        }
    }
  };
  check(expmap::polar_patch_operator(mesh, expmap::Exact_exponential_map<Mesh>(mesh), sources,
                                     grid, {}, query));
  check(expmap::polar_patch_operator(mesh, expmap::Geodesic_polar_coordinates<Mesh>(mesh),
                                     sources, grid, {}, query));
}

BOOST_AUTO_TEST_CASE(a_smooth_function_on_the_sphere_matches_its_values_at_the_grid_points) {
  const expmap_analytic::Triangle_soup soup = expmap_analytic::make_icosphere(5);  // 10,242
  const Mesh mesh = to_mesh(soup);
  auto f = [](const std::array<double, 3>& p) { return p[0] + 0.5 * p[1] * p[2]; };
  std::vector<double> values;
  for (const auto& p : soup.points) values.push_back(f(p));
  std::mt19937 random(5);
  std::vector<std::size_t> sources;
  for (int k = 0; k < 20; ++k) sources.push_back(random() % soup.points.size());
  const expmap::Polar_grid grid{0.4, 5, 16};  // about 130 vertices

  // Each grid point where the exact exponential map of the unit sphere puts
  // it: cos(rho) s + sin(rho) (cos(theta) e_u + sin(theta) e_v), in the
  // frame of the method's own map.
  auto worst_error = [&](const auto& method) {
    const expmap::Polar_patch_operator op =
        expmap::polar_patch_operator(mesh, method, sources, grid);
    check_rows_are_barycentric(op);
    const std::vector<double> patches = resample(op, values);
    double worst = 0;
    for (std::size_t s = 0; s < sources.size(); ++s) {
      const auto map = method.compute_by_index(sources[s], expmap::Patch::vertex_count(1));
      const auto& c = soup.points[sources[s]];
      const double norm = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      for (std::size_t i = 0; i < grid.rings; ++i)
        for (std::size_t j = 0; j < grid.rays; ++j) {
          BOOST_TEST_REQUIRE(op.sampled[op.row(s, i, j)] == 1);  // a sphere: no edge
          const double rho = grid.ring_radius(i), theta = grid.ray_angle(j);
          std::array<double, 3> q{};
          for (int k = 0; k < 3; ++k)
            q[k] = std::cos(rho) * c[k] / norm +
                   std::sin(rho) * (std::cos(theta) * map.axis_u[k] +
                                    std::sin(theta) * map.axis_v[k]);
          worst = std::max(worst, std::abs(patches[op.row(s, i, j)] - f(q)));
        }
    }
    return worst;
  };
  // |grad f| <= 1.2 on the sphere: the errors are the maps' own (exact: a
  // few 1e-4 of the radius on this mesh; DGPC's and the smoothed heat's
  // distances and angles more) plus linear interpolation's (h^2 / 8 |f''|,
  // h about 0.04).
  const double exact = worst_error(expmap::Exact_exponential_map<Mesh>(mesh));
  const double dgpc = worst_error(expmap::Geodesic_polar_coordinates<Mesh>(mesh));
  const double heat = worst_error(expmap::Heat_exponential_map<Mesh>(mesh));
  BOOST_TEST_MESSAGE("worst |patch - f| at the grid points: exact " << exact << ", DGPC " << dgpc
                                                                    << ", heat " << heat);
  BOOST_TEST(exact < 2e-3);
  BOOST_TEST(dgpc < 2e-3);
  BOOST_TEST(heat < 1e-2);
}

// Where the angles around the source sum to 2 pi (here: any vertex of the
// plane), turning the reference direction by phi turns every angle by
// -phi. At a curved vertex a tangent-plane angle phi is a different angle
// of the map (its angles are the surface's, scaled to 2 pi around the source).
BOOST_AUTO_TEST_CASE(turning_the_reference_by_whole_rays_shifts_the_rays) {
  const auto& soup = plane_soup();
  const Mesh mesh = to_mesh(soup);
  const expmap::Polar_grid grid{0.3, 4, 12};
  const std::size_t k = 5;  // rays
  const double phi = 2 * pi * double(k) / double(grid.rays);
  expmap::Heat_query_options straight, turned;
  straight.reference_direction = {{1.0, 0.0, 0.0}};
  turned.reference_direction = {{std::cos(phi), std::sin(phi), 0.0}};
  std::vector<std::size_t> sources;
  for (std::size_t v = 0; v < soup.points.size(); v += 101)
    if (std::abs(soup.points[v][0]) < 0.6 && std::abs(soup.points[v][1]) < 0.6)
      sources.push_back(v);
  auto check = [&](const auto& method) {
    const auto a = expmap::polar_patch_operator(mesh, method, sources, grid, {}, straight);
    const auto b = expmap::polar_patch_operator(mesh, method, sources, grid, {}, turned);
    const Eigen::MatrixXd dense_a(a.weights), dense_b(b.weights);
    for (std::size_t s = 0; s < sources.size(); ++s)
      for (std::size_t i = 0; i < grid.rings; ++i)
        for (std::size_t j = 0; j < grid.rays; ++j) {
          // theta' = theta - phi: ray j of the turned map is ray j + k of the other.
          const std::size_t rb = b.row(s, i, j), ra = a.row(s, i, (j + k) % grid.rays);
          BOOST_TEST_REQUIRE(a.sampled[ra] == 1);
          BOOST_TEST_REQUIRE(b.sampled[rb] == 1);
          BOOST_TEST((dense_a.row(ra) - dense_b.row(rb)).cwiseAbs().maxCoeff() < 1e-9);
        }
  };
  check(expmap::Geodesic_polar_coordinates<Mesh>(mesh));
  check(expmap::Heat_exponential_map<Mesh>(mesh));
}

BOOST_AUTO_TEST_CASE(boundaries_give_masks_never_nan) {
  const auto& soup = plane_soup();
  const Mesh mesh = to_mesh(soup);
  // Sources next to the square's border and in its corners: most of their
  // grid lies outside the mesh.
  std::vector<std::size_t> sources;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (std::max(std::abs(soup.points[v][0]), std::abs(soup.points[v][1])) > 0.93)
      sources.push_back(v);
  const expmap::Polar_grid grid{0.4, 5, 16};
  expmap::Query_options query;
  query.reference_direction = {{1.0, 0.0, 0.0}};
  const expmap::Exact_exponential_map<Mesh> exact(mesh);
  const auto op = expmap::polar_patch_operator(mesh, exact, sources, grid, {}, query);
  check_rows_are_barycentric(op);
  std::size_t inside = 0, outside = 0;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const auto& c = soup.points[sources[s]];
    for (std::size_t i = 0; i < grid.rings; ++i)
      for (std::size_t j = 0; j < grid.rays; ++j) {
        const auto uv = grid.point(i, j);
        const double x = c[0] + uv[0], y = c[1] + uv[1];
        const double from_center = std::max(std::abs(x), std::abs(y));
        if (std::abs(from_center - 1) < 1e-9) continue;  // on the border: either
        const bool in_square = from_center < 1;
        // Sampled exactly where the grid point is on the mesh (the square is
        // convex: the geodesics are straight).
        BOOST_TEST(op.sampled[op.row(s, i, j)] == (in_square ? 1 : 0));
        (in_square ? inside : outside) += 1;
      }
  }
  BOOST_TEST(inside > 0);
  BOOST_TEST(outside > 0);
}

BOOST_AUTO_TEST_CASE(the_same_operator_on_any_number_of_threads_and_clear_errors) {
  const Mesh mesh = load_mesh<Mesh>("elephant.off");
  const expmap::Heat_exponential_map<Mesh> heat(mesh);
  std::vector<std::size_t> sources;
  for (std::size_t v = 0; v < num_vertices(mesh); v += 97) sources.push_back(v);
  const expmap::Polar_grid grid{0.05, 5, 16};
  expmap::Batch_options one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = expmap::polar_patch_operator(mesh, heat, sources, grid, one);
  const auto b = expmap::polar_patch_operator(mesh, heat, sources, grid, two);
  BOOST_TEST(a.sampled == b.sampled);
  BOOST_TEST(a.weights.nonZeros() == b.weights.nonZeros());
  BOOST_TEST(std::equal(a.weights.valuePtr(), a.weights.valuePtr() + a.weights.nonZeros(),
                        b.weights.valuePtr()));
  BOOST_TEST(std::equal(a.weights.innerIndexPtr(),
                        a.weights.innerIndexPtr() + a.weights.nonZeros(),
                        b.weights.innerIndexPtr()));
  BOOST_CHECK_THROW(expmap::polar_patch_operator(mesh, heat, sources, {0.0, 5, 16}),
                    expmap::Invalid_input);
  BOOST_CHECK_THROW(expmap::polar_patch_operator(mesh, heat, sources, {0.05, 0, 16}),
                    expmap::Invalid_input);
  BOOST_CHECK_THROW(expmap::polar_patch_operator(mesh, heat, {num_vertices(mesh)}, grid),
                    expmap::Invalid_input);
  // A method of another mesh: its maps would index other vertices.
  const Mesh other = load_mesh<Mesh>("cactus.off");
  BOOST_CHECK_THROW(expmap::polar_patch_operator(other, heat, {0}, grid), expmap::Invalid_input);
}
