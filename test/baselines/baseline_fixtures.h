// Meshes, reference maps and error measures shared by the baseline tests
// (DEM, DGPC, exact).
#ifndef EXPMAP_TEST_BASELINE_FIXTURES_H
#define EXPMAP_TEST_BASELINE_FIXTURES_H

#include <expmap/Local_map.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "Analytic_exponential_maps.h"
#include "Analytic_surfaces.h"
#include "test_support.h"

namespace expmap_test {

/// |a - b| as angles, in [0, pi].
inline double angle_difference(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * M_PI));
}

/// A planar grid of 2 x 2 with n x n cells; `flipped`: half of its
/// flippable edges flipped (the paper's irregular mesh of figure 13).
inline expmap_analytic::Triangle_soup planar_grid(int n, bool flipped) {
  expmap_analytic::Triangle_soup soup = expmap_analytic::make_grid(n, n, 2.0, 2.0);
  if (flipped) expmap_analytic::flip_random_edges(soup, 0.5, 7);
  return soup;
}

template <class Mesh>
Mesh to_mesh(const expmap_analytic::Triangle_soup& soup) {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  return mesh;
}

/// Worst relative distance error and worst angle error of a map against
/// the exact map of the plane z = 0 (the same e1: no rotation removed).
struct Planar_errors {
  double distance = 0, angle = 0;
};

template <class Map>
Planar_errors planar_errors(const Map& map, const expmap_analytic::Triangle_soup& soup) {
  Planar_errors e;
  const auto& source = soup.points[map.indices[0]];
  for (std::size_t i = 1; i < map.size(); ++i) {
    const expmap_analytic::Polar exact =
        expmap_analytic::plane_exponential_map(source, soup.points[map.indices[i]], map.axis_u);
    e.distance = std::max(e.distance, std::abs(map.distance[i] - exact.r) / exact.r);
    e.angle = std::max(e.angle, angle_difference(map.angle[i], exact.theta_unrotated));
  }
  return e;
}

/// Vertices with both coordinates in [-limit, limit], picked at random.
inline std::vector<std::size_t> random_vertices_inside(const expmap_analytic::Triangle_soup& soup,
                                                       double limit, std::size_t count,
                                                       unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, soup.number_of_vertices() - 1);
  std::vector<std::size_t> chosen;
  while (chosen.size() < count) {
    const std::size_t v = pick(rng);
    if (std::abs(soup.points[v][0]) <= limit && std::abs(soup.points[v][1]) <= limit)
      chosen.push_back(v);
  }
  return chosen;
}

/// Mean errors of a map on the unit sphere against the analytic map, with
/// the angle measured in the same frame (axis_u of the map), and the same
/// after removing the best constant rotation (circular mean of the
/// differences), which must not matter since all methods share the frame.
struct Sphere_errors {
  double distance = 0, angle = 0, angle_rotation_removed = 0;
  std::size_t vertices = 0;
};

template <class Map>
Sphere_errors sphere_errors(const Map& map, const expmap_analytic::Triangle_soup& soup) {
  Sphere_errors e;
  const auto& source = soup.points[map.indices[0]];
  std::vector<double> differences;
  double c = 0, s = 0;
  for (std::size_t i = 1; i < map.size(); ++i) {
    const expmap_analytic::Polar exact = expmap_analytic::sphere_exponential_map(
        source, soup.points[map.indices[i]], 1.0, map.axis_u);
    e.distance += std::abs(map.distance[i] - exact.r);
    const double d = std::remainder(map.angle[i] - exact.theta_unrotated, 2 * M_PI);
    differences.push_back(d);
    e.angle += std::abs(d);
    c += std::cos(d);
    s += std::sin(d);
  }
  const double rotation = std::atan2(s, c);
  for (double d : differences) e.angle_rotation_removed += angle_difference(d, rotation);
  e.vertices = differences.size();
  const double count = static_cast<double>(std::max<std::size_t>(1, e.vertices));
  e.distance /= count;
  e.angle /= count;
  e.angle_rotation_removed /= count;
  return e;
}

/// Seeded random vertex indices in [0, n).
inline std::vector<std::size_t> random_sources(std::size_t n, std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  std::vector<std::size_t> sources;
  for (std::size_t i = 0; i < count; ++i) sources.push_back(pick(rng));
  return sources;
}

inline const expmap_analytic::Triangle_soup& icosphere(int subdivisions) {
  static const expmap_analytic::Triangle_soup level5 = expmap_analytic::make_icosphere(5, 1.0);
  static const expmap_analytic::Triangle_soup level6 = expmap_analytic::make_icosphere(6, 1.0);
  return subdivisions == 5 ? level5 : level6;
}

/// Two maps of the same vertices agree vertex by vertex (matched by
/// index: near-ties in distance may order them differently).
template <class MapA, class MapB>
void check_same_map(const MapA& a, const MapB& b, double tolerance) {
  BOOST_TEST_REQUIRE(a.size() == b.size());
  BOOST_TEST(a.indices[0] == b.indices[0]);
  std::vector<std::size_t> position(*std::max_element(a.indices.begin(), a.indices.end()) + 1,
                                    a.size());
  for (std::size_t i = 0; i < a.size(); ++i) position[a.indices[i]] = i;
  double distance = 0, angle = 0;
  for (std::size_t j = 0; j < b.size(); ++j) {
    BOOST_TEST_REQUIRE(b.indices[j] < position.size());
    const std::size_t i = position[b.indices[j]];
    BOOST_TEST_REQUIRE(i < a.size());
    distance = std::max(distance, std::abs(a.distance[i] - b.distance[j]));
    angle = std::max(angle, angle_difference(a.angle[i], b.angle[j]));
  }
  BOOST_TEST(distance <= tolerance);
  BOOST_TEST(angle <= tolerance);
}

// ---------------------------------------------------------------------------
// Checks every method must pass; each test file runs them on its method
// with the bounds measured for it.
// ---------------------------------------------------------------------------

/// On planar meshes the method is exact: every vertex within the radius,
/// with its analytic distance and angle (the shared frame: no rotation
/// removed), from interior sources, boundary sources, and with a reference
/// direction; on the regular grid and with half its edges flipped.
template <template <class> class Method>
void check_exact_on_planar_grids(double distance_tolerance, double angle_tolerance) {
  const double radius = 0.61;  // no grid distance ties with it
  for (bool flipped : {false, true}) {
    expmap_analytic::Triangle_soup soup = expmap_analytic::make_grid(40, 40, 2.0, 2.0);
    if (flipped) BOOST_TEST_REQUIRE(expmap_analytic::flip_random_edges(soup, 0.5, 7) > 500u);
    const auto mesh = to_mesh<Surface_mesh>(soup);
    const Method<Surface_mesh> method(mesh);
    std::vector<std::size_t> sources = random_vertices_inside(soup, 0.35, 4, 11);
    sources.push_back(expmap_analytic::grid_vertex_index(40, 20, 0));  // boundary, straight angle
    sources.push_back(expmap_analytic::grid_vertex_index(40, 0, 40));  // corner, right angle
    for (std::size_t s : sources) {
      for (bool turned : {false, true}) {
        expmap::Query_options query;
        if (turned) query.reference_direction = std::array<double, 3>{{0.3, -1.0, 0.2}};
        const auto map = method.compute_by_index(s, expmap::Patch::geodesic_radius(radius), query);
        const Planar_errors e = planar_errors(map, soup);
        std::size_t inside = 0;
        for (const auto& p : soup.points)
          inside += std::hypot(p[0] - soup.points[s][0], p[1] - soup.points[s][1]) <= radius;
        BOOST_TEST_MESSAGE((flipped ? "flipped" : "regular")
                           << " grid, source " << s << (turned ? " (turned e1)" : "") << ": "
                           << map.size() << " vertices, max relative r error " << e.distance
                           << ", max theta error " << e.angle);
        BOOST_TEST(map.size() == inside);
        BOOST_TEST(e.distance <= distance_tolerance);
        BOOST_TEST(e.angle <= angle_tolerance);
      }
    }
  }
}

/// From the apex of a cone (a vertex whose angle sum is 2 pi sin(alpha),
/// here pi) the geodesics are the generators: r is the slant distance and
/// theta the azimuth of the generator, which is also the angle of its
/// projection onto the tangent plane. Rescaling the apex's angle sum to
/// 2 pi (DGPC) gives exactly these angles; the exact map reads them off the
/// first path segment.
template <template <class> class Method>
void check_cone_from_apex(double distance_tolerance, double angle_tolerance) {
  const expmap_analytic::Triangle_soup soup = expmap_analytic::make_cone(32, 20, M_PI / 3, 1.0);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto map = method.compute_by_index(0, expmap::Patch::geodesic_radius(0.93));
  BOOST_TEST_REQUIRE(map.size() == 1u + 18u * 32u);
  double worst_r = 0, worst_theta = 0;
  for (std::size_t i = 1; i < map.size(); ++i) {
    const auto& p = soup.points[map.indices[i]];
    const double slant = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    double u = 0, v = 0;
    for (int k = 0; k < 3; ++k) {
      u += p[k] * map.axis_u[k];
      v += p[k] * map.axis_v[k];
    }
    worst_r = std::max(worst_r, std::abs(map.distance[i] - slant) / slant);
    worst_theta = std::max(worst_theta, angle_difference(map.angle[i], std::atan2(v, u)));
  }
  BOOST_TEST_MESSAGE("cone apex: max relative r error " << worst_r << ", max theta error "
                                                        << worst_theta);
  BOOST_TEST(worst_r <= distance_tolerance);
  BOOST_TEST(worst_theta <= angle_tolerance);
}

/// Mean errors against the analytic map of the unit sphere (10,242
/// vertices, radius 0.5, seeded random sources) stay below the bounds.
template <template <class> class Method>
void check_sphere_accuracy(const char* name, double distance_bound, double angle_bound) {
  const expmap_analytic::Triangle_soup& soup = icosphere(5);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  for (std::size_t s : random_sources(soup.number_of_vertices(), 5, 2018)) {
    const auto map = method.compute_by_index(s, expmap::Patch::geodesic_radius(0.5));
    const Sphere_errors e = sphere_errors(map, soup);
    BOOST_TEST_MESSAGE(name << " on the 10,242-vertex sphere, source " << s << ", " << e.vertices
                            << " vertices: mean |r error| " << e.distance << ", mean |theta error| "
                            << e.angle << " (" << e.angle_rotation_removed
                            << " with the best rotation removed)");
    BOOST_TEST(e.vertices > 500u);
    BOOST_TEST(e.distance <= distance_bound);
    BOOST_TEST(e.angle <= angle_bound);
    // The frame is shared: removing a rotation gains (almost) nothing.
    BOOST_TEST(e.angle - e.angle_rotation_removed <= 0.1 * e.angle);
  }
}

/// A Surface_mesh and a Polyhedron_3 of the same soup give the same maps,
/// for every kind of patch, on a closed mesh and on one with boundary.
template <template <class> class Method>
void check_same_on_all_representations() {
  expmap_analytic::Triangle_soup grid = expmap_analytic::make_grid(24, 24, 2.0, 2.0);
  expmap_analytic::flip_random_edges(grid, 0.5, 3);
  const expmap_analytic::Triangle_soup* meshes[] = {&icosphere(5), &grid};
  for (const expmap_analytic::Triangle_soup* soup : meshes) {
    const auto surface_mesh = to_mesh<Surface_mesh>(*soup);
    const auto polyhedron = to_mesh<Polyhedron>(*soup);
    const Method<Surface_mesh> a(surface_mesh);
    const Method<Polyhedron> b(polyhedron);
    const auto n = soup->number_of_vertices();
    for (std::size_t s : random_sources(n, 2, 99)) {
      for (const expmap::Patch& patch :
           {expmap::Patch::geodesic_radius(0.4), expmap::Patch::vertex_count(150),
            expmap::Patch::vertex_set({(s + 7) % n, (s + 100) % n, s})}) {
        check_same_map(a.compute_by_index(s, patch), b.compute_by_index(s, patch), 1e-10);
      }
    }
    // Queries by descriptor are queries by index.
    const auto v = *std::next(vertices(polyhedron).first, 5);
    check_same_map(b.compute(v, expmap::Patch::vertex_count(40)),
                   a.compute_by_index(5, expmap::Patch::vertex_count(40)), 0.0);
  }
}

/// What every patch kind returns: the source first (r = 0, theta = 0),
/// then nearest first; k vertices for counts; the set for vertex sets;
/// the whole component for fraction 1; angles in (-pi, pi].
template <template <class> class Method>
void check_patch_kinds(bool nearest_by_reported_distance) {
  const expmap_analytic::Triangle_soup& soup = icosphere(5);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const std::size_t s = 1234, n = soup.number_of_vertices();
  auto check_shape = [&](const auto& map) {
    BOOST_TEST_REQUIRE(map.size() >= 1u);
    BOOST_TEST(map.indices[0] == s);
    BOOST_TEST(map.distance[0] == 0.0);
    BOOST_TEST(map.angle[0] == 0.0);
    for (std::size_t i = 1; i < map.size(); ++i) {
      BOOST_TEST(map.distance[i - 1] <= map.distance[i]);
      BOOST_TEST((map.angle[i] > -M_PI && map.angle[i] <= M_PI));
      BOOST_TEST(map.indices[i] != s);
    }
  };
  const auto by_count = method.compute_by_index(s, expmap::Patch::vertex_count(300));
  check_shape(by_count);
  BOOST_TEST(by_count.size() == 300u);
  const auto by_fraction = method.compute_by_index(s, expmap::Patch::fraction(0.05));
  check_shape(by_fraction);
  BOOST_TEST(by_fraction.size() == static_cast<std::size_t>(std::ceil(0.05 * n)));
  const auto single = method.compute_by_index(s, expmap::Patch::vertex_count(1));
  BOOST_TEST(single.size() == 1u);

  // The k vertices of a count patch are the nearest ones of a larger
  // patch: by reported distance, or for DEM, in Dijkstra's order (which
  // decides the vertices DEM freezes first).
  const auto larger = method.compute_by_index(s, expmap::Patch::vertex_count(600));
  if (nearest_by_reported_distance) {
    BOOST_TEST(by_count.distance.back() <= larger.distance[300] * (1 + 1e-9));
  } else {
    std::vector<std::size_t> small(by_count.indices), large(larger.indices);
    std::sort(small.begin(), small.end());
    std::sort(large.begin(), large.end());
    BOOST_TEST(std::includes(large.begin(), large.end(), small.begin(), small.end()));
  }

  const std::vector<std::size_t> set{100, 4000, 1234, 100, 9000};
  const auto by_set = method.compute_by_index(s, expmap::Patch::vertex_set(set));
  check_shape(by_set);
  std::vector<std::size_t> got(by_set.indices.begin(), by_set.indices.end());
  std::sort(got.begin(), got.end());
  BOOST_TEST((got == std::vector<std::size_t>{100, 1234, 4000, 9000}));

  const auto by_radius = method.compute_by_index(s, expmap::Patch::geodesic_radius(0.3));
  check_shape(by_radius);
  BOOST_TEST(by_radius.distance.back() <= 0.3);
  BOOST_TEST(by_radius.size() > 100u);
  // The map frame is the shared one: orthonormal, right-handed.
  const auto& m = by_radius;
  const double cross_z = m.axis_u[0] * m.axis_v[1] - m.axis_u[1] * m.axis_v[0];
  const double cross_x = m.axis_u[1] * m.axis_v[2] - m.axis_u[2] * m.axis_v[1];
  const double cross_y = m.axis_u[2] * m.axis_v[0] - m.axis_u[0] * m.axis_v[2];
  BOOST_TEST(std::abs(cross_x - m.normal[0]) + std::abs(cross_y - m.normal[1]) +
                 std::abs(cross_z - m.normal[2]) <
             1e-12);

  expmap_analytic::Triangle_soup small = expmap_analytic::make_icosphere(2, 1.0);
  const auto small_mesh = to_mesh<Surface_mesh>(small);
  const Method<Surface_mesh> whole(small_mesh);
  BOOST_TEST(whole.compute_by_index(3, expmap::Patch::fraction(1.0)).size() ==
             small.number_of_vertices());
}

/// Bad queries throw Invalid_input naming the vertex.
template <template <class> class Method>
void check_bad_input() {
  expmap_analytic::Triangle_soup soup = expmap_analytic::make_grid(4, 4, 1.0, 1.0);
  auto mesh = to_mesh<Surface_mesh>(soup);
  const auto isolated = mesh.add_vertex(Point(5, 5, 5));
  const Method<Surface_mesh> method(mesh);
  auto message_of = [&](auto&& query) -> std::string {
    try {
      query();
    } catch (const expmap::Invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const auto patch = expmap::Patch::vertex_count(5);
  const std::string out_of_range = message_of([&] { method.compute_by_index(1000, patch); });
  BOOST_TEST(out_of_range.find("source vertex 1000 is out of range") != std::string::npos,
             out_of_range);
  const std::string lonely = message_of([&] { method.compute(isolated, patch); });
  BOOST_TEST(lonely.find("source vertex 25 is isolated") != std::string::npos, lonely);
  const std::string set = message_of(
      [&] { method.compute_by_index(0, expmap::Patch::vertex_set({1, 77})); });
  BOOST_TEST(set.find("patch vertex 77 is out of range") != std::string::npos, set);
  const std::string unreachable = message_of(
      [&] { method.compute_by_index(0, expmap::Patch::vertex_set({1, 25})); });
  BOOST_TEST(unreachable.find("patch vertex 25 is not connected to source vertex 0") !=
                 std::string::npos,
             unreachable);
  expmap::Query_options vertical;
  vertical.reference_direction = std::array<double, 3>{{0, 0, 1}};
  const std::string reference = message_of([&] { method.compute_by_index(12, patch, vertical); });
  BOOST_TEST(reference.find("source vertex 12") != std::string::npos, reference);
  // A patch larger than the component stops at the component.
  BOOST_TEST(method.compute_by_index(0, expmap::Patch::fraction(1.0)).size() == 25u);
}

/// Concurrent queries on one object give the results of sequential ones.
template <template <class> class Method>
void check_concurrent_queries() {
  const expmap_analytic::Triangle_soup& soup = icosphere(5);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto sources = random_sources(soup.number_of_vertices(), 8, 5);
  using Map = decltype(method.compute_by_index(0, expmap::Patch::vertex_count(1)));
  std::vector<Map> sequential, parallel(sources.size());
  for (std::size_t s : sources)
    sequential.push_back(method.compute_by_index(s, expmap::Patch::vertex_count(400)));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < sources.size(); i += 2)
        parallel[i] = method.compute_by_index(sources[i], expmap::Patch::vertex_count(400));
    });
  for (auto& thread : threads) thread.join();
  for (std::size_t i = 0; i < sources.size(); ++i) check_same_map(sequential[i], parallel[i], 0.0);
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_BASELINE_FIXTURES_H
