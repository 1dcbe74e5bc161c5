// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lumped mass matrices of the heat step. Checked against planar
// geometry, independently of how the areas are summed: on a planar mesh the
// cotan Laplacian of |x|^2 at an interior vertex is -4 times its Voronoi
// area (the cotan formula), so the mixed Voronoi mass must give M^-1 L
// |x|^2 = -4 exactly where the triangles are non-obtuse, which the
// barycentric mass does not on irregular triangles; and both share out
// every triangle's area.

#include <expmap/internal/operators/Cotan_operators.h>

#include <boost/test/unit_test.hpp>

#include "Analytic_surfaces.h"
#include "Triangulation_from_points.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace {

using expmap::internal::Intrinsic_triangulation;

// A hexagonal patch of equilateral triangles (edge 1) with its inner
// vertices moved by up to `jitter` (reproducibly): irregular, still
// non-obtuse for small jitter.
expmap_analytic::Triangle_soup jittered_planar_grid(double jitter) {
  const int rings = 8;
  expmap_analytic::Triangle_soup soup = expmap_analytic::make_equilateral_grid(rings, 1.0);
  const std::size_t outer_ring_start = std::size_t(1 + 3 * rings * (rings - 1));
  std::uint64_t state = 12345;
  auto unit = [&state]() {  // splitmix64, in [-1, 1)
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) / double(std::uint64_t(1) << 52) - 1.0;
  };
  for (std::size_t v = 0; v < outer_ring_start; ++v) {
    soup.points[v][0] += jitter * unit();
    soup.points[v][1] += jitter * unit();
  }
  return soup;
}

// Whether each vertex lies on the boundary (an edge with one triangle).
std::vector<bool> boundary_vertices(const expmap_analytic::Triangle_soup& soup) {
  std::map<std::pair<std::size_t, std::size_t>, int> edge_faces;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      ++edge_faces[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<bool> boundary(soup.points.size(), false);
  for (const auto& [edge, count] : edge_faces)
    if (count == 1) boundary[edge.first] = boundary[edge.second] = true;
  return boundary;
}

// The largest |(L |x|^2)_v / M_v + 4| over interior vertices.
double largest_quadratic_defect(const expmap_analytic::Triangle_soup& soup,
                                const Eigen::VectorXd& mass,
                                const expmap::internal::Sparse_matrix& L) {
  Eigen::VectorXd square(static_cast<Eigen::Index>(soup.points.size()));
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    square[Eigen::Index(v)] = soup.points[v][0] * soup.points[v][0] + soup.points[v][1] * soup.points[v][1];
  const Eigen::VectorXd image = L * square;
  const std::vector<bool> boundary = boundary_vertices(soup);
  double largest = 0;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (!boundary[v])
      largest = std::max(largest, std::abs(image[Eigen::Index(v)] / mass[Eigen::Index(v)] + 4));
  return largest;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(vertex_area)

BOOST_AUTO_TEST_CASE(mixed_voronoi_mass_inverts_the_laplacian_of_a_quadratic) {
  const expmap_analytic::Triangle_soup soup = jittered_planar_grid(0.12);
  const Intrinsic_triangulation tri = expmap_test::make_triangulation(soup.points, soup.triangles);
  const auto shapes = expmap::internal::triangle_shapes(tri);
  for (const auto& shape : shapes)
    for (double cot : shape.cotangent) BOOST_TEST_REQUIRE(cot > 0);  // the premise: no obtuse angle
  const auto L = expmap::internal::cotan_laplacian(tri, shapes);
  const Eigen::VectorXd mixed = expmap::internal::mixed_voronoi_mass(tri, shapes);
  const Eigen::VectorXd barycentric = expmap::internal::lumped_mass(tri, shapes);
  const double mixed_defect = largest_quadratic_defect(soup, mixed, L);
  const double barycentric_defect = largest_quadratic_defect(soup, barycentric, L);
  BOOST_TEST_MESSAGE("largest |M^-1 L |x|^2 + 4|: mixed Voronoi " << mixed_defect << ", barycentric "
                     << barycentric_defect);
  BOOST_TEST(mixed_defect < 1e-10);
  BOOST_TEST(barycentric_defect > 0.05);  // the irregularity the mixed area corrects

  // On the regular grid both are the same.
  const expmap_analytic::Triangle_soup regular = jittered_planar_grid(0.0);
  const Intrinsic_triangulation regular_tri =
      expmap_test::make_triangulation(regular.points, regular.triangles);
  const auto regular_shapes = expmap::internal::triangle_shapes(regular_tri);
  const Eigen::VectorXd a = expmap::internal::mixed_voronoi_mass(regular_tri, regular_shapes);
  const Eigen::VectorXd b = expmap::internal::lumped_mass(regular_tri, regular_shapes);
  BOOST_TEST((a - b).cwiseAbs().maxCoeff() < 1e-12);
}

BOOST_AUTO_TEST_CASE(both_masses_share_out_every_triangle) {
  // Strongly jittered: obtuse triangles take the half / quarter split.
  const expmap_analytic::Triangle_soup soup = jittered_planar_grid(0.45);
  const Intrinsic_triangulation tri = expmap_test::make_triangulation(soup.points, soup.triangles);
  const auto shapes = expmap::internal::triangle_shapes(tri);
  std::size_t obtuse = 0;
  double area = 0;
  for (const auto& shape : shapes) {
    area += shape.area;
    if (shape.cotangent[0] < 0 || shape.cotangent[1] < 0 || shape.cotangent[2] < 0) ++obtuse;
  }
  BOOST_TEST_REQUIRE(obtuse > 10u);
  const Eigen::VectorXd mixed = expmap::internal::mixed_voronoi_mass(tri, shapes);
  BOOST_TEST(std::abs(mixed.sum() - area) < 1e-12 * area);
  BOOST_TEST(std::abs(expmap::internal::lumped_mass(tri, shapes).sum() - area) < 1e-12 * area);
  BOOST_TEST(mixed.minCoeff() > 0);

  // One obtuse triangle alone: half to the obtuse corner, a quarter to each
  // other one.
  Intrinsic_triangulation one;
  one.number_of_vertices = 3;
  one.face = {{{0, 1, 2}}};
  // Corners (0, 0), (2, 0), (1, 0.3): obtuse at corner 2.
  const double side = std::hypot(1.0, 0.3);
  one.length = {{{2.0, side, side}}};
  const auto one_shape = expmap::internal::triangle_shapes(one);
  const Eigen::VectorXd m = expmap::internal::mixed_voronoi_mass(one, one_shape);
  BOOST_TEST(std::abs(m[2] - 0.15) < 1e-14);
  BOOST_TEST(std::abs(m[0] - 0.075) < 1e-14);
  BOOST_TEST(std::abs(m[1] - 0.075) < 1e-14);
}

BOOST_AUTO_TEST_SUITE_END()
