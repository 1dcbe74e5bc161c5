// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the analytic test-mesh generators and their exact exponential
// maps (test/support/Analytic_surfaces.h, Analytic_exponential_maps.h).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "Analytic_exponential_maps.h"
#include "Analytic_surfaces.h"

namespace {

using Vec3 = std::array<double, 3>;
const double pi = std::acos(-1.0);

Vec3 sub(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 normalize(const Vec3& a) {
  const double l = norm(a);
  return {{a[0] / l, a[1] / l, a[2] / l}};
}

/// Wraps an angle to (-pi, pi].
double wrap(double a) {
  while (a > pi) a -= 2 * pi;
  while (a <= -pi) a += 2 * pi;
  return a;
}

/// Twice the area vector of triangle f.
Vec3 area_vector(const expmap_analytic::Triangle_soup& s, std::size_t f) {
  const auto& t = s.triangles[f];
  const Vec3& a = s.points[std::size_t(t[0])];
  const Vec3& b = s.points[std::size_t(t[1])];
  const Vec3& c = s.points[std::size_t(t[2])];
  return cross(sub(b, a), sub(c, a));
}

/// Directed edge -> number of uses.
std::map<std::pair<int, int>, int> directed_edges(const expmap_analytic::Triangle_soup& s) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  return edges;
}

std::set<std::pair<int, int>> undirected_edges(const expmap_analytic::Triangle_soup& s) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k)
      edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  return edges;
}

/// Every directed edge used at most once; returns the number of boundary
/// (twinless) directed edges.
std::size_t check_oriented_manifold_edges(const expmap_analytic::Triangle_soup& s) {
  const auto edges = directed_edges(s);
  std::size_t boundary = 0, reused = 0;
  for (const auto& e : edges) {
    if (e.second != 1) ++reused;
    if (edges.find({e.first.second, e.first.first}) == edges.end()) ++boundary;
  }
  BOOST_TEST(reused == 0u);
  return boundary;
}

long euler_characteristic(const expmap_analytic::Triangle_soup& s) {
  return long(s.points.size()) - long(undirected_edges(s).size()) + long(s.triangles.size());
}

double signed_volume(const expmap_analytic::Triangle_soup& s) {
  double v = 0;
  for (const auto& t : s.triangles)
    v += dot(s.points[std::size_t(t[0])],
             cross(s.points[std::size_t(t[1])], s.points[std::size_t(t[2])])) / 6.0;
  return v;
}

/// Sum of the signed (seen from +z) areas of a planar soup, and the minimum
/// signed area.
std::pair<double, double> planar_areas(const expmap_analytic::Triangle_soup& s) {
  double total = 0, smallest = 1e300;
  for (std::size_t f = 0; f < s.triangles.size(); ++f) {
    const double a = 0.5 * area_vector(s, f)[2];
    total += a;
    smallest = std::min(smallest, a);
  }
  return {total, smallest};
}

/// Angle at corner `k` of triangle f.
double corner_angle(const expmap_analytic::Triangle_soup& s, std::size_t f, int k) {
  const auto& t = s.triangles[f];
  const Vec3& p = s.points[std::size_t(t[k])];
  const Vec3 u = sub(s.points[std::size_t(t[(k + 1) % 3])], p);
  const Vec3 v = sub(s.points[std::size_t(t[(k + 2) % 3])], p);
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

/// Largest (alpha + beta - pi) over interior edges, alpha and beta the
/// angles opposite the edge: <= 0 for a Delaunay triangulation.
double delaunay_excess(const expmap_analytic::Triangle_soup& s) {
  std::map<std::pair<int, int>, double> opposite_angle;  // directed edge -> angle
  for (std::size_t f = 0; f < s.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto& t = s.triangles[f];
      opposite_angle[{t[(k + 1) % 3], t[(k + 2) % 3]}] = corner_angle(s, f, k);
    }
  double worst = -pi;
  for (const auto& e : opposite_angle) {
    const auto twin = opposite_angle.find({e.first.second, e.first.first});
    if (twin != opposite_angle.end()) worst = std::max(worst, e.second + twin->second - pi);
  }
  return worst;
}

std::vector<std::size_t> valences(const expmap_analytic::Triangle_soup& s) {
  std::vector<std::size_t> v(s.points.size(), 0);
  for (const auto& e : undirected_edges(s)) {
    ++v[std::size_t(e.first)];
    ++v[std::size_t(e.second)];
  }
  return v;
}

double max_abs_difference(const Vec3& a, const Vec3& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

/// Length of the polyline (t, z(t)) with `n` segments on [0, rho].
double bump_polyline_length(double rho, double amplitude, double sigma, int n) {
  auto z = [&](double t) { return amplitude * std::exp(-t * t / (2 * sigma * sigma)); };
  double length = 0;
  for (int i = 0; i < n; ++i) {
    const double t0 = rho * i / n, t1 = rho * (i + 1) / n;
    length += std::hypot(t1 - t0, z(t1) - z(t0));
  }
  return length;
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;

template <class Mesh>
void check_mesh_from_soup(const expmap_analytic::Triangle_soup& soup, bool closed) {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  BOOST_TEST(CGAL::is_valid_polygon_mesh(mesh));
  BOOST_TEST(CGAL::is_triangle_mesh(mesh));
  BOOST_TEST(CGAL::is_closed(mesh) == closed);
  BOOST_TEST(num_vertices(mesh) == soup.points.size());
  BOOST_TEST(num_faces(mesh) == soup.triangles.size());
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::size_t i = 0, mismatches = 0;
  for (auto v : vertices(mesh)) {
    const Point_3& p = get(vpm, v);
    const Vec3& q = soup.points[i++];
    if (p.x() != q[0] || p.y() != q[1] || p.z() != q[2]) ++mismatches;
  }
  BOOST_TEST(mismatches == 0u);
  // Faces keep their orientation: the first face's halfedge cycle visits the
  // soup's first triangle in the same cyclic order.
  const auto f0 = *faces(mesh).begin();
  std::vector<Vec3> corners;
  for (auto h : CGAL::halfedges_around_face(halfedge(f0, mesh), mesh)) {
    const Point_3& p = get(vpm, target(h, mesh));
    corners.push_back({{p.x(), p.y(), p.z()}});
  }
  BOOST_TEST_REQUIRE(corners.size() == 3u);
  const auto& t = soup.triangles.front();
  bool same_cycle = false;
  for (int shift = 0; shift < 3; ++shift) {
    bool all = true;
    for (int k = 0; k < 3; ++k)
      all = all && corners[std::size_t(k)] == soup.points[std::size_t(t[(k + shift) % 3])];
    same_cycle = same_cycle || all;
  }
  BOOST_TEST(same_cycle);
  // A second call on a non-empty mesh is refused.
  BOOST_CHECK_THROW(expmap_analytic::soup_to_mesh(soup, mesh), std::invalid_argument);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(analytic_surfaces)

BOOST_AUTO_TEST_CASE(icosphere_counts_and_euler_characteristic) {
  for (int s = 0; s <= 6; ++s) {
    const auto soup = expmap_analytic::make_icosphere(s);
    const std::size_t power = std::size_t(1) << (2 * s);
    BOOST_TEST(soup.points.size() == 10 * power + 2);
    BOOST_TEST(soup.triangles.size() == 20 * power);
    BOOST_TEST(euler_characteristic(soup) == 2);
  }
  const auto s5 = expmap_analytic::make_icosphere(5);
  BOOST_TEST(s5.points.size() == 10242u);
  const auto s6 = expmap_analytic::make_icosphere(6);
  BOOST_TEST(s6.points.size() == 40962u);
  BOOST_TEST(s6.triangles.size() == 81920u);
}

BOOST_AUTO_TEST_CASE(icosphere_points_on_sphere_and_icosahedron_first) {
  const auto soup = expmap_analytic::make_icosphere(6);
  double worst = 0;
  for (const auto& p : soup.points) worst = std::max(worst, std::abs(norm(p) - 1.0));
  BOOST_TEST(worst <= 1e-14);

  const double t = (1 + std::sqrt(5.0)) / 2;
  const auto ico = expmap_analytic::make_icosphere(0);
  for (std::size_t i = 0; i < 12; ++i)
    BOOST_TEST(max_abs_difference(soup.points[i], ico.points[i]) == 0.0);
  BOOST_TEST(max_abs_difference(soup.points[0], normalize({{-1, t, 0}})) <= 1e-16);
  // All icosahedron edges have the same length.
  for (const auto& e : undirected_edges(ico))
    BOOST_TEST(std::abs(norm(sub(ico.points[std::size_t(e.first)],
                                 ico.points[std::size_t(e.second)])) -
                        2 / std::sqrt(1 + t * t)) <= 1e-15);

  const auto big = expmap_analytic::make_icosphere(3, 2.5);
  for (const auto& p : big.points) BOOST_TEST(std::abs(norm(p) - 2.5) <= 1e-14);
}

BOOST_AUTO_TEST_CASE(icosphere_closed_manifold_outward) {
  const auto soup = expmap_analytic::make_icosphere(4);
  BOOST_TEST(check_oriented_manifold_edges(soup) == 0u);  // every directed edge has its twin
  // No duplicated points (midpoint cache).
  std::set<Vec3> unique_points(soup.points.begin(), soup.points.end());
  BOOST_TEST(unique_points.size() == soup.points.size());
  // Outward orientation: positive volume close to the ball's, and every face
  // normal points away from the centre.
  const double volume = signed_volume(soup);
  BOOST_TEST(volume > 0);
  BOOST_TEST(std::abs(volume - 4.0 / 3.0 * pi) < 0.01);
  std::size_t inward = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (dot(area_vector(soup, f), soup.points[std::size_t(soup.triangles[f][0])]) <= 0) ++inward;
  BOOST_TEST(inward == 0u);
}

BOOST_AUTO_TEST_CASE(grid_planar_symmetric_delaunay) {
  const int nx = 8, ny = 6;
  const double w = 2.0, h = 1.5;
  const auto soup = expmap_analytic::make_grid(nx, ny, w, h);
  BOOST_TEST(soup.points.size() == std::size_t((nx + 1) * (ny + 1)));
  BOOST_TEST(soup.triangles.size() == std::size_t(2 * nx * ny));
  for (const auto& p : soup.points) BOOST_TEST(p[2] == 0.0);
  const std::size_t o = expmap_analytic::grid_origin_vertex(nx, ny);
  BOOST_TEST(o == expmap_analytic::grid_vertex_index(nx, nx / 2, ny / 2));
  BOOST_TEST(soup.points[o][0] == 0.0);
  BOOST_TEST(soup.points[o][1] == 0.0);
  BOOST_TEST(expmap_analytic::closest_vertex(soup, {{0.01, -0.02, 0.3}}) == o);
  // Corners and exact symmetry.
  BOOST_TEST(soup.points[0][0] == -w / 2);
  BOOST_TEST(soup.points[0][1] == -h / 2);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const auto& p = soup.points[expmap_analytic::grid_vertex_index(nx, i, j)];
      const auto& q = soup.points[expmap_analytic::grid_vertex_index(nx, nx - i, ny - j)];
      BOOST_TEST(p[0] == -q[0]);
      BOOST_TEST(p[1] == -q[1]);
    }
  // Triangles counter-clockwise seen from +z, covering the rectangle.
  const auto areas = planar_areas(soup);
  BOOST_TEST(areas.second > 0);
  BOOST_TEST(std::abs(areas.first - w * h) <= 1e-13);
  BOOST_TEST(check_oriented_manifold_edges(soup) == std::size_t(2 * (nx + ny)));
  BOOST_TEST(euler_characteristic(soup) == 1);
  // Delaunay (cocircular cells: opposite angles sum to at most pi).
  BOOST_TEST(delaunay_excess(soup) <= 1e-12);
  // Union jack: the origin has valence 8 and its one-ring is symmetric.
  const auto valence = valences(soup);
  BOOST_TEST(valence[o] == 8u);
  BOOST_TEST(valence[o + 1] == 4u);

  BOOST_TEST(delaunay_excess(expmap_analytic::make_grid(7, 5, 1.0, 3.0)) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(equilateral_grid_is_regular) {
  const int rings = 6;
  const double edge = 0.25;
  const auto soup = expmap_analytic::make_equilateral_grid(rings, edge);
  BOOST_TEST(soup.points.size() == std::size_t(3 * rings * (rings + 1) + 1));
  BOOST_TEST(soup.triangles.size() == std::size_t(6 * rings * rings));
  BOOST_TEST(max_abs_difference(soup.points[0], {{0, 0, 0}}) == 0.0);
  for (int k = 1; k <= rings; ++k) {
    const auto& p = soup.points[std::size_t(1 + 3 * k * (k - 1))];
    BOOST_TEST(std::abs(p[0] - k * edge) <= 1e-15);
    BOOST_TEST(p[1] == 0.0);
  }
  for (const auto& e : undirected_edges(soup))
    BOOST_TEST(std::abs(norm(sub(soup.points[std::size_t(e.first)],
                                 soup.points[std::size_t(e.second)])) -
                        edge) <= 1e-15);
  const auto areas = planar_areas(soup);
  BOOST_TEST(areas.second > 0);
  BOOST_TEST(std::abs(areas.first - 6 * rings * rings * std::sqrt(3.0) / 4 * edge * edge) <= 1e-13);
  BOOST_TEST(check_oriented_manifold_edges(soup) == std::size_t(6 * rings));
  BOOST_TEST(euler_characteristic(soup) == 1);
  // Vertices of rings < `rings` are interior, all of valence 6; ring k is
  // listed counter-clockwise.
  const auto valence = valences(soup);
  const std::size_t interior = std::size_t(3 * (rings - 1) * rings + 1);
  for (std::size_t v = 0; v < interior; ++v) BOOST_TEST(valence[v] == 6u);
  for (int k = 1; k <= rings; ++k) {
    const std::size_t first = std::size_t(1 + 3 * k * (k - 1));
    double previous = -1;
    for (std::size_t v = first; v < first + std::size_t(6 * k); ++v) {
      double a = std::atan2(soup.points[v][1], soup.points[v][0]);
      if (a < 0) a += 2 * pi;
      if (v > first) BOOST_TEST(a > previous);
      previous = a;
    }
  }
  BOOST_TEST(delaunay_excess(soup) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(flipped_equilateral_grid) {
  const auto regular = expmap_analytic::make_equilateral_grid(20, 0.1);
  const auto original_edges = undirected_edges(regular);
  // In the regular patch every interior edge is flippable.
  const std::size_t interior_edges = original_edges.size() - 6 * 20;

  // Below saturation the requested number of flips is met exactly.
  auto some = regular;
  BOOST_TEST(expmap_analytic::flip_random_edges(some, 0.3, 5u) ==
             std::size_t(std::llround(0.3 * double(interior_edges))));
  BOOST_TEST(planar_areas(some).second > 0);

  // Half of the edges: flips saturate a little below (each flip makes the
  // quads of its four neighbouring edges degenerate).
  auto flipped = regular;
  const std::size_t count = expmap_analytic::flip_random_edges(flipped, 0.5, 42u);
  BOOST_TEST(count <= std::size_t(std::llround(0.5 * double(interior_edges))));
  BOOST_TEST(double(count) >= 0.45 * double(interior_edges));
  BOOST_TEST(flipped.points == regular.points);
  BOOST_TEST(flipped.triangles.size() == regular.triangles.size());
  // Still an embedded, consistently oriented triangulation of the hexagon.
  const auto areas = planar_areas(flipped);
  BOOST_TEST(areas.second > 0);
  BOOST_TEST(std::abs(areas.first - planar_areas(regular).first) <= 1e-12);
  BOOST_TEST(check_oriented_manifold_edges(flipped) == 6 * 20u);
  BOOST_TEST(undirected_edges(flipped).size() == original_edges.size());
  // About half of the edges differ from the regular mesh's.
  std::size_t kept = 0;
  for (const auto& e : undirected_edges(flipped)) kept += original_edges.count(e);
  const std::size_t changed = original_edges.size() - kept;
  BOOST_TEST(changed <= count);
  BOOST_TEST(double(changed) >= 0.45 * double(interior_edges));
  BOOST_TEST_MESSAGE("equilateral grid, 20 rings: " << count << " flips of " << interior_edges
                                                    << " interior edges, " << changed
                                                    << " edges differ");
  // The result is no longer Delaunay.
  BOOST_TEST(delaunay_excess(flipped) > 0.1);

  // Deterministic for a seed, different for another seed.
  auto again = regular;
  expmap_analytic::flip_random_edges(again, 0.5, 42u);
  BOOST_TEST((again.triangles == flipped.triangles));
  auto other = regular;
  expmap_analytic::flip_random_edges(other, 0.5, 7u);
  BOOST_TEST((other.triangles != flipped.triangles));

  // Fraction 0 changes nothing.
  auto untouched = regular;
  BOOST_TEST(expmap_analytic::flip_random_edges(untouched, 0.0, 1u) == 0u);
  BOOST_TEST((untouched.triangles == regular.triangles));
}

BOOST_AUTO_TEST_CASE(flipped_square_grid_and_sphere) {
  // In the union-jack grid only the cell diagonals are flippable (the quads
  // around axis-parallel edges are degenerate): fraction 1 flips them all.
  const int n = 10;
  const auto grid = expmap_analytic::make_grid(n, n, 1.0, 1.0);
  auto flipped = grid;
  BOOST_TEST(expmap_analytic::flip_random_edges(flipped, 1.0, 3u) == std::size_t(n * n));
  const auto areas = planar_areas(flipped);
  BOOST_TEST(areas.second > 0);
  BOOST_TEST(std::abs(areas.first - 1.0) <= 1e-13);
  BOOST_TEST(flipped.points == grid.points);
  BOOST_TEST(delaunay_excess(flipped) <= 1e-12);  // still a square grid

  // On a closed mesh the flips keep a closed oriented manifold.
  const auto sphere = expmap_analytic::make_icosphere(3);
  auto flipped_sphere = sphere;
  const std::size_t count = expmap_analytic::flip_random_edges(flipped_sphere, 0.3, 11u);
  BOOST_TEST(count > 0u);
  BOOST_TEST(check_oriented_manifold_edges(flipped_sphere) == 0u);
  BOOST_TEST(euler_characteristic(flipped_sphere) == 2);
  BOOST_TEST(signed_volume(flipped_sphere) > 0);
  check_mesh_from_soup<CGAL::Surface_mesh<Point_3>>(flipped_sphere, true);
}

BOOST_AUTO_TEST_CASE(anisotropic_scaling) {
  auto soup = expmap_analytic::make_icosphere(2);
  const auto sphere = soup;
  expmap_analytic::scale_anisotropically(soup, 2.0, 1.0, 0.5);
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    BOOST_TEST(soup.points[i][0] == 2.0 * sphere.points[i][0]);
    BOOST_TEST(soup.points[i][1] == sphere.points[i][1]);
    BOOST_TEST(soup.points[i][2] == 0.5 * sphere.points[i][2]);
  }
  BOOST_TEST(std::abs(signed_volume(soup) - signed_volume(sphere)) <= 1e-12);
  BOOST_CHECK_THROW(expmap_analytic::scale_anisotropically(soup, 0.0, 1.0, 1.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::scale_anisotropically(soup, 1.0, -1.0, 1.0),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(gaussian_bump_mesh_and_reference) {
  const int n = 40;
  const double half_width = 2.0, amplitude = 0.8, sigma = 0.5;
  const auto soup = expmap_analytic::make_gaussian_bump(n, half_width, amplitude, sigma);
  BOOST_TEST(soup.points.size() == std::size_t((n + 1) * (n + 1)));
  BOOST_TEST(soup.triangles.size() == std::size_t(2 * n * n));
  const std::size_t apex = expmap_analytic::grid_origin_vertex(n, n);
  BOOST_TEST(apex == std::size_t((n / 2) * (n + 2)));
  BOOST_TEST(max_abs_difference(soup.points[apex], {{0, 0, amplitude}}) == 0.0);
  for (const auto& p : soup.points)
    BOOST_TEST(std::abs(p[2] - amplitude * std::exp(-(p[0] * p[0] + p[1] * p[1]) /
                                                    (2 * sigma * sigma))) <= 1e-15);
  // Counter-clockwise seen from +z.
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) BOOST_TEST(area_vector(soup, f)[2] > 0);

  // Meridian length against a fine polyline (error O(h^2), ~1e-11 here) and
  // its Richardson extrapolation.
  for (double rho : {0.1, 0.5, 1.0, 1.7, 3.0}) {
    const double reference = expmap_analytic::gaussian_bump_meridian_length(rho, amplitude, sigma);
    const double coarse = bump_polyline_length(rho, amplitude, sigma, 100000);
    const double fine = bump_polyline_length(rho, amplitude, sigma, 200000);
    BOOST_TEST(std::abs(reference - fine) <= 1e-9 * rho);
    BOOST_TEST(std::abs(reference - (4 * fine - coarse) / 3) <= 1e-11);
    BOOST_TEST(reference >= rho);
  }
  // Flat bump: the length is the radius; steep bump: longer than the drop.
  BOOST_TEST(std::abs(expmap_analytic::gaussian_bump_meridian_length(1.3, 0.0, sigma) - 1.3) <=
             1e-15);
  BOOST_TEST(expmap_analytic::gaussian_bump_meridian_length(3.0, 5.0, 0.3) > 5.0);
  BOOST_TEST(expmap_analytic::gaussian_bump_meridian_length(0.0, amplitude, sigma) == 0.0);

  // Exponential map: distance and azimuth, including through the mesh points.
  const Vec3 e1 = {{1, 0, 0}};
  const auto at_apex =
      expmap_analytic::gaussian_bump_exponential_map(soup.points[apex], amplitude, sigma, e1);
  BOOST_TEST(at_apex.r == 0.0);
  const auto q =
      expmap_analytic::gaussian_bump_exponential_map({{0.0, 0.7, 0.1}}, amplitude, sigma, e1);
  BOOST_TEST(std::abs(q.theta_unrotated - pi / 2) <= 1e-15);
  BOOST_TEST(q.r == expmap_analytic::gaussian_bump_meridian_length(0.7, amplitude, sigma));
  const auto diagonal = expmap_analytic::gaussian_bump_exponential_map(
      {{-0.5, -0.5, 0.0}}, amplitude, sigma, {{0, 1, 0}});
  // Measured from e1 = +y towards e2 = z x e1 = -x.
  BOOST_TEST(std::abs(diagonal.theta_unrotated - 3 * pi / 4) <= 1e-15);
  BOOST_CHECK_THROW(
      expmap_analytic::gaussian_bump_exponential_map({{1, 0, 0}}, amplitude, sigma, {{0, 0, 1}}),
      std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(saddle_mesh) {
  const int n = 16;
  const double half_width = 1.2, amplitude = 0.3;
  const auto soup = expmap_analytic::make_saddle(n, half_width, amplitude);
  BOOST_TEST(soup.points.size() == std::size_t((n + 1) * (n + 1)));
  const std::size_t o = expmap_analytic::grid_origin_vertex(n, n);
  BOOST_TEST(max_abs_difference(soup.points[o], {{0, 0, 0}}) == 0.0);
  for (const auto& p : soup.points)
    BOOST_TEST(std::abs(p[2] - amplitude * std::sin(p[0]) * std::sin(p[1])) <= 1e-16);
  BOOST_TEST(soup.points[0][0] == -half_width);
  BOOST_TEST(soup.points.back()[1] == half_width);
  BOOST_TEST(check_oriented_manifold_edges(soup) == std::size_t(4 * n));
  check_mesh_from_soup<CGAL::Surface_mesh<Point_3>>(soup, false);
}

BOOST_AUTO_TEST_CASE(cylinder_mesh_and_reference) {
  const int around = 32, along = 10;
  const double radius = 0.7, length = 3.0;
  const auto soup = expmap_analytic::make_cylinder(around, along, radius, length);
  BOOST_TEST(soup.points.size() == std::size_t(around * (along + 1)));
  BOOST_TEST(soup.triangles.size() == std::size_t(2 * around * along));
  for (const auto& p : soup.points) {
    BOOST_TEST(std::abs(std::hypot(p[0], p[1]) - radius) <= 1e-15);
    BOOST_TEST(std::abs(p[2]) <= length / 2);
  }
  const std::size_t source = std::size_t((along / 2) * around);
  BOOST_TEST(max_abs_difference(soup.points[source], {{radius, 0, 0}}) == 0.0);
  BOOST_TEST(valences(soup)[source] == 8u);
  BOOST_TEST(check_oriented_manifold_edges(soup) == std::size_t(2 * around));
  BOOST_TEST(euler_characteristic(soup) == 0);
  std::size_t inward = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    Vec3 c = {{0, 0, 0}};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 2; ++d) c[std::size_t(d)] += soup.points[std::size_t(soup.triangles[f][k])][std::size_t(d)];
    if (dot(area_vector(soup, f), c) <= 0) ++inward;
  }
  BOOST_TEST(inward == 0u);
  check_mesh_from_soup<CGAL::Surface_mesh<Point_3>>(soup, false);

  // Reference map: unrolled distances; n = +x at the source, e1 = +z,
  // e2 = n x e1 = -y.
  const Vec3 s = soup.points[source], e1 = {{0, 0, 1}};
  const auto up = expmap_analytic::cylinder_exponential_map(s, {{radius, 0, 1.1}}, radius, e1);
  BOOST_TEST(std::abs(up.r - 1.1) <= 1e-15);
  BOOST_TEST(std::abs(up.theta_unrotated) <= 1e-15);
  const double phi = 0.9;
  const Vec3 side = {{radius * std::cos(phi), radius * std::sin(phi), 0.0}};
  const auto around_map = expmap_analytic::cylinder_exponential_map(s, side, radius, e1);
  BOOST_TEST(std::abs(around_map.r - radius * phi) <= 1e-15);
  BOOST_TEST(std::abs(around_map.theta_unrotated + pi / 2) <= 1e-15);
  const Vec3 oblique = {{radius * std::cos(-phi), radius * std::sin(-phi), -0.4}};
  const auto o = expmap_analytic::cylinder_exponential_map(s, oblique, radius, e1);
  BOOST_TEST(std::abs(o.r - std::hypot(radius * phi, 0.4)) <= 1e-15);
  BOOST_TEST(std::abs(o.theta_unrotated - (pi - std::atan2(radius * phi, 0.4))) <= 1e-14);
  // Across the seam at phi = pi the shortest way is taken.
  const Vec3 s2 = {{-radius, 1e-9, 0.0}};
  const Vec3 p2 = {{radius * std::cos(pi + 0.2), radius * std::sin(pi + 0.2), 0.0}};
  BOOST_TEST(std::abs(expmap_analytic::cylinder_exponential_map(s2, p2, radius, e1).r -
                      radius * 0.2) <= 1e-8);
}

BOOST_AUTO_TEST_CASE(cone_mesh) {
  const int around = 64, along = 8;
  const double apex_angle = pi / 3, length = 2.0;
  const auto soup = expmap_analytic::make_cone(around, along, apex_angle, length);
  BOOST_TEST(soup.points.size() == std::size_t(1 + around * along));
  BOOST_TEST(soup.triangles.size() == std::size_t(around * (2 * along - 1)));
  BOOST_TEST(max_abs_difference(soup.points[0], {{0, 0, 0}}) == 0.0);
  BOOST_TEST(check_oriented_manifold_edges(soup) == std::size_t(around));
  BOOST_TEST(euler_characteristic(soup) == 1);
  for (int j = 1; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const auto& p = soup.points[std::size_t(1 + (j - 1) * around + i)];
      BOOST_TEST(std::abs(norm(p) - length * j / along) <= 1e-15);
      BOOST_TEST(std::abs(std::atan2(std::hypot(p[0], p[1]), p[2]) - apex_angle / 2) <= 1e-14);
    }
  // Outward (away from the axis, downwards) orientation.
  std::size_t inward = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Vec3 nrm = area_vector(soup, f);
    const Vec3& p = soup.points[std::size_t(soup.triangles[f][1])];
    if (nrm[0] * p[0] + nrm[1] * p[1] <= 0 || nrm[2] >= 0) ++inward;
  }
  BOOST_TEST(inward == 0u);
  // Angle sum at the apex close to 2 pi sin(alpha).
  double apex_sum = 0;
  for (std::size_t f = 0; f < std::size_t(around); ++f) apex_sum += corner_angle(soup, f, 0);
  BOOST_TEST(std::abs(apex_sum - 2 * pi * std::sin(apex_angle / 2)) <= 1e-3);
  check_mesh_from_soup<CGAL::Surface_mesh<Point_3>>(soup, false);
}

BOOST_AUTO_TEST_CASE(sphere_reference_map) {
  const double R = 1.5;
  const Vec3 s = {{0, 0, R}}, e1 = {{1, 0, 0}}, e2 = {{0, 1, 0}};  // e2 = n x e1
  const auto self = expmap_analytic::sphere_exponential_map(s, s, R, e1);
  BOOST_TEST(self.r == 0.0);
  BOOST_TEST(self.theta_unrotated == 0.0);
  // Antipode and points near it.
  BOOST_TEST(std::abs(expmap_analytic::sphere_exponential_map(s, {{0, 0, -R}}, R, e1).r - pi * R) <=
             1e-14);
  for (double eps : {1e-3, 1e-6, 1e-9}) {
    const Vec3 p = {{R * std::sin(eps), 0, -R * std::cos(eps)}};
    const auto m = expmap_analytic::sphere_exponential_map(s, p, R, e1);
    BOOST_TEST(std::abs(m.r - R * (pi - eps)) <= 1e-14);
    BOOST_TEST(std::abs(m.theta_unrotated) <= 1e-15);
  }
  // Direction e2 is at +pi/2 (counter-clockwise about the outward normal).
  const auto east = expmap_analytic::sphere_exponential_map(s, {{0, R, 0}}, R, e1);
  BOOST_TEST(std::abs(east.r - R * pi / 2) <= 1e-14);
  BOOST_TEST(std::abs(east.theta_unrotated - pi / 2) <= 1e-15);
  // Replacing e1 by e2 rotates the reference by +pi/2, so every angle
  // decreases by pi/2; the distance is unchanged. The map inverts exactly.
  const auto soup = expmap_analytic::make_icosphere(3, R);
  const Vec3 source = soup.points[5];
  const Vec3 n = normalize(source);
  const Vec3 u = normalize(cross({{0.3, -0.2, 1.0}}, n));  // a tangent direction
  const Vec3 v = cross(n, u);
  double worst_rotation = 0, worst_inverse = 0;
  for (const auto& p : soup.points) {
    const auto a = expmap_analytic::sphere_exponential_map(source, p, R, u);
    const auto b = expmap_analytic::sphere_exponential_map(source, p, R, v);
    BOOST_TEST(a.r == b.r);
    if (a.r > 1e-12 && a.r < R * pi - 1e-6)
      worst_rotation = std::max(worst_rotation, std::abs(wrap(b.theta_unrotated - a.theta_unrotated + pi / 2)));
    // exp_source(r, theta) = cos(r/R) source + R sin(r/R) (cos theta u + sin theta v)
    const double c = std::cos(a.r / R), sn = std::sin(a.r / R);
    Vec3 back;
    for (std::size_t k = 0; k < 3; ++k)
      back[k] = c * source[k] +
                R * sn * (std::cos(a.theta_unrotated) * u[k] + std::sin(a.theta_unrotated) * v[k]);
    worst_inverse = std::max(worst_inverse, max_abs_difference(back, p));
  }
  BOOST_TEST(worst_rotation <= 1e-12);
  BOOST_TEST(worst_inverse <= 1e-12);
  // The mesh orientation matches the angle orientation: around a source
  // vertex, each outward triangle (s, b, c) has theta(c) - theta(b) in (0, pi).
  std::size_t misordered = 0, around_source = 0;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] == 5) {
        ++around_source;
        const auto b = expmap_analytic::sphere_exponential_map(
            source, soup.points[std::size_t(t[(k + 1) % 3])], R, u);
        const auto c = expmap_analytic::sphere_exponential_map(
            source, soup.points[std::size_t(t[(k + 2) % 3])], R, u);
        const double turn = wrap(c.theta_unrotated - b.theta_unrotated);
        if (!(turn > 0 && turn < pi)) ++misordered;
      }
  BOOST_TEST(around_source == 5u);  // icosahedron vertex: valence 5
  BOOST_TEST(misordered == 0u);
  BOOST_CHECK_THROW(expmap_analytic::sphere_exponential_map(s, s, R, {{0, 0, 2}}),
                    std::invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::sphere_exponential_map(s, s, 0.0, e1), std::invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::sphere_exponential_map({{0, 0, 0}}, s, R, e1),
                    std::invalid_argument);
  (void)e2;
}

BOOST_AUTO_TEST_CASE(plane_reference_map) {
  const Vec3 s = {{0.5, -0.25, 0.0}};
  const auto m = expmap_analytic::plane_exponential_map(s, {{0.5, 0.75, 0.0}}, {{1, 0, 0}});
  BOOST_TEST(std::abs(m.r - 1.0) <= 1e-15);
  BOOST_TEST(std::abs(m.theta_unrotated - pi / 2) <= 1e-15);
  const auto rotated = expmap_analytic::plane_exponential_map(s, {{0.5, 0.75, 0.0}}, {{0, 2, 0}});
  BOOST_TEST(std::abs(rotated.theta_unrotated) <= 1e-15);
  const auto diag = expmap_analytic::plane_exponential_map(s, {{-0.5, -1.25, 0.0}}, {{1, 0, 0}});
  BOOST_TEST(std::abs(diag.r - std::sqrt(2.0)) <= 1e-15);
  BOOST_TEST(std::abs(diag.theta_unrotated + 3 * pi / 4) <= 1e-15);
  BOOST_CHECK_THROW(expmap_analytic::plane_exponential_map(s, s, {{0, 0, 1}}),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(soup_to_surface_mesh_and_polyhedron) {
  const auto sphere = expmap_analytic::make_icosphere(3);
  check_mesh_from_soup<CGAL::Surface_mesh<Point_3>>(sphere, true);
  check_mesh_from_soup<CGAL::Polyhedron_3<Kernel>>(sphere, true);
  check_mesh_from_soup<CGAL::Polyhedron_3<Kernel>>(expmap_analytic::make_grid(4, 6, 1.0, 2.0),
                                                   false);
  check_mesh_from_soup<CGAL::Surface_mesh<Point_3>>(expmap_analytic::make_equilateral_grid(3, 1.0),
                                                    false);

  // Surface_mesh indices are the soup indices.
  CGAL::Surface_mesh<Point_3> mesh;
  expmap_analytic::soup_to_mesh(sphere, mesh);
  for (std::size_t i : {std::size_t(0), std::size_t(11), std::size_t(12), sphere.points.size() - 1}) {
    const Point_3& p = mesh.point(CGAL::Surface_mesh<Point_3>::Vertex_index(static_cast<unsigned>(i)));
    BOOST_TEST(p.x() == sphere.points[i][0]);
    BOOST_TEST(p.y() == sphere.points[i][1]);
    BOOST_TEST(p.z() == sphere.points[i][2]);
  }

  // A soup that is not a manifold mesh is refused.
  expmap_analytic::Triangle_soup bad = expmap_analytic::make_grid(1, 1, 1.0, 1.0);
  bad.triangles.push_back(bad.triangles.front());
  CGAL::Surface_mesh<Point_3> out;
  BOOST_CHECK_THROW(expmap_analytic::soup_to_mesh(bad, out), std::invalid_argument);
  bad.triangles = {{{0, 1, 7}}};
  BOOST_CHECK_THROW(expmap_analytic::soup_to_mesh(bad, out), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(closest_vertex_lookup) {
  const auto sphere = expmap_analytic::make_icosphere(2);
  for (std::size_t i : {std::size_t(0), std::size_t(7), std::size_t(100)}) {
    Vec3 p = sphere.points[i];
    p[0] *= 1.01;
    BOOST_TEST(expmap_analytic::closest_vertex(sphere, p) == i);
  }
  BOOST_CHECK_THROW(expmap_analytic::closest_vertex(expmap_analytic::Triangle_soup{}, {{0, 0, 0}}),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(invalid_parameters_throw) {
  using std::invalid_argument;
  BOOST_CHECK_THROW(expmap_analytic::make_icosphere(-1), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_icosphere(10), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_icosphere(2, 0.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_icosphere(2, -1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_icosphere(2, std::nan("")), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_grid(0, 4, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_grid(4, 4, 0.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::grid_origin_vertex(3, 4), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_equilateral_grid(0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_equilateral_grid(2, -1.0), invalid_argument);
  auto soup = expmap_analytic::make_grid(2, 2, 1.0, 1.0);
  BOOST_CHECK_THROW(expmap_analytic::flip_random_edges(soup, -0.1, 1u), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::flip_random_edges(soup, 1.5, 1u), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_gaussian_bump(1, 1.0, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_gaussian_bump(3, 1.0, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_gaussian_bump(4, 1.0, 1.0, 0.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_gaussian_bump(4, -1.0, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_saddle(0, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_saddle(4, 1.0, std::nan("")), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_cylinder(2, 4, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_cylinder(8, 0, 1.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_cylinder(8, 4, 0.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_cone(8, 4, 0.0, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_cone(8, 4, pi, 1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::make_cone(8, 4, 1.0, -1.0), invalid_argument);
  BOOST_CHECK_THROW(expmap_analytic::gaussian_bump_meridian_length(-1.0, 1.0, 1.0),
                    invalid_argument);
  BOOST_CHECK_THROW(
      expmap_analytic::cylinder_exponential_map({{0, 0, 0}}, {{1, 0, 0}}, 1.0, {{0, 0, 1}}),
      invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
