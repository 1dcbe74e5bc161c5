// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of make_intrinsic_delaunay on hand-built Intrinsic_triangulations.
// The checks are independent of the flip code: planar meshes are compared
// with Euclidean distances and the empty-circumcircle property, curved ones
// with invariants of intrinsic flips (cone angle at every vertex, total
// area, Euler characteristic).

#include <expmap/internal/operators/Intrinsic_delaunay.h>

#include <boost/test/unit_test.hpp>

#include "Triangulation_from_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using expmap::internal::Intrinsic_triangulation;
using expmap::internal::make_intrinsic_delaunay;
using expmap::internal::triangle_shape;
using expmap_test::make_triangulation;

using Point2 = std::array<double, 2>;
using Point3 = std::array<double, 3>;
using Face = std::array<int, 3>;

const double pi = std::acos(-1.0);

/// splitmix64: reproducible on every platform, unlike std:: distributions.
class Random {
 public:
  explicit Random(std::uint64_t seed) : m_state(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(next() % n); }

 private:
  std::uint64_t m_state;
};

double distance(const Point3& p, const Point3& q) {
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                   (p[2] - q[2]) * (p[2] - q[2]));
}

/// Unordered edge key (std::minmax would return references to temporaries).
std::pair<int, int> sorted_pair(int u, int v) { return {std::min(u, v), std::max(u, v)}; }

Point3 lift(const Point2& p) { return {{p[0], p[1], 0.0}}; }

double orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double total_area(const Intrinsic_triangulation& tri) {
  double sum = 0;
  for (const auto& l : tri.length) sum += triangle_shape(l).area;
  return sum;
}

/// Interior angle at every corner, from the law of cosines (independent of
/// triangle_shape's cotangents).
std::vector<double> cone_angles(const Intrinsic_triangulation& tri) {
  std::vector<double> angle(tri.number_of_vertices, 0.0);
  for (std::size_t f = 0; f < tri.face.size(); ++f) {
    const auto& l = tri.length[f];
    for (int k = 0; k < 3; ++k) {
      const double a = l[k], b = l[(k + 2) % 3], opposite = l[(k + 1) % 3];
      const double c = std::max(-1.0, std::min(1.0, (a * a + b * b - opposite * opposite) /
                                                        (2 * a * b)));
      angle[tri.face[f][k]] += std::acos(c);
    }
  }
  return angle;
}

/// Twins matched by vertex pair, written independently of the library; only
/// valid for meshes without repeated edges, which the tests check.
std::vector<int> twins_by_vertex_pair(const Intrinsic_triangulation& tri) {
  std::map<std::pair<int, int>, int> directed;
  for (std::size_t f = 0; f < tri.face.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto key = std::make_pair(tri.face[f][k], tri.face[f][(k + 1) % 3]);
      BOOST_REQUIRE_MESSAGE(directed.count(key) == 0, "directed edge used twice");
      directed[key] = static_cast<int>(3 * f + k);
    }
  }
  std::vector<int> twin(3 * tri.face.size(), -1);
  for (const auto& entry : directed) {
    const auto it = directed.find(std::make_pair(entry.first.second, entry.first.first));
    if (it != directed.end()) twin[entry.second] = it->second;
  }
  return twin;
}

/// Halfedge h = 3 f + k of tri.
int source(const Intrinsic_triangulation& tri, int h) { return tri.face[h / 3][h % 3]; }
int target(const Intrinsic_triangulation& tri, int h) { return tri.face[h / 3][(h + 1) % 3]; }
double length(const Intrinsic_triangulation& tri, int h) { return tri.length[h / 3][h % 3]; }

void check_twins(const Intrinsic_triangulation& tri, const std::vector<int>& twin) {
  BOOST_REQUIRE_EQUAL(twin.size(), 3 * tri.face.size());
  for (int h = 0; h < static_cast<int>(twin.size()); ++h) {
    const int t = twin[h];
    if (t < 0) continue;
    BOOST_REQUIRE_EQUAL(twin[t], h);
    BOOST_REQUIRE_NE(t / 3, h / 3);
    BOOST_REQUIRE_EQUAL(source(tri, t), target(tri, h));
    BOOST_REQUIRE_EQUAL(target(tri, t), source(tri, h));
    BOOST_REQUIRE_EQUAL(length(tri, t), length(tri, h));
  }
}

/// Smallest cot(alpha) + cot(beta) over interior edges.
double min_cotan_sum(const Intrinsic_triangulation& tri, const std::vector<int>& twin) {
  double worst = std::numeric_limits<double>::infinity();
  for (int h = 0; h < static_cast<int>(twin.size()); ++h) {
    const int t = twin[h];
    if (t < h) continue;  // boundary, or seen from the other side
    // The corner opposite halfedge 3 f + k is corner (k + 2) % 3.
    const double cot_h = triangle_shape(tri.length[h / 3]).cotangent[(h % 3 + 2) % 3];
    const double cot_t = triangle_shape(tri.length[t / 3]).cotangent[(t % 3 + 2) % 3];
    worst = std::min(worst, cot_h + cot_t);
  }
  return worst;
}

int euler_characteristic(const Intrinsic_triangulation& tri, const std::vector<int>& twin) {
  int edges = 0;
  for (int h = 0; h < static_cast<int>(twin.size()); ++h) {
    if (twin[h] < 0 || twin[h] > h) ++edges;
  }
  return static_cast<int>(tri.number_of_vertices) - edges + static_cast<int>(tri.face.size());
}

void check_every_vertex_has_a_face(const Intrinsic_triangulation& tri) {
  std::vector<char> used(tri.number_of_vertices, 0);
  for (const Face& f : tri.face) {
    for (int v : f) used[v] = 1;
  }
  BOOST_CHECK(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
}

std::set<std::pair<int, int>> edge_set(const Intrinsic_triangulation& tri) {
  std::set<std::pair<int, int>> edges;
  for (const Face& f : tri.face) {
    for (int k = 0; k < 3; ++k) {
      edges.insert(sorted_pair(f[k], f[(k + 1) % 3]));
    }
  }
  return edges;
}

// ---------------------------------------------------------------------------
// Planar jittered grid, triangulated badly.

/// n x n points in [0, n-1]^2. Interior points are jittered in 2D; boundary
/// points only along the boundary and corners not at all, so the domain is
/// the convex square and its Delaunay triangulation covers exactly the mesh.
std::vector<Point2> jittered_grid(int n, double jitter, Random& random) {
  std::vector<Point2> points;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const bool x_border = (i == 0 || i == n - 1), y_border = (j == 0 || j == n - 1);
      const double dx = x_border ? 0.0 : random.uniform(-jitter, jitter);
      const double dy = y_border ? 0.0 : random.uniform(-jitter, jitter);
      points.push_back({{i + dx, j + dy}});
    }
  }
  return points;
}

/// Planar edge flip on a plain face list, used to spoil a triangulation.
/// Flips the edge of face f, corner k when its quad is strictly convex.
bool planar_flip(std::vector<Face>& faces, const std::vector<Point2>& p, std::size_t f, int k) {
  const int a = faces[f][k], b = faces[f][(k + 1) % 3], c = faces[f][(k + 2) % 3];
  for (std::size_t g = 0; g < faces.size(); ++g) {
    for (int j = 0; j < 3; ++j) {
      if (faces[g][j] != b || faces[g][(j + 1) % 3] != a) continue;
      const int d = faces[g][(j + 2) % 3];
      // Strict convexity with a margin keeps the spoiled mesh free of
      // near-degenerate triangles whose 2D orientation would be ambiguous.
      const double scale = 1e-3;
      if (orient(p[a], p[d], p[c]) <= scale || orient(p[d], p[b], p[c]) <= scale) return false;
      faces[f] = {{a, d, c}};
      faces[g] = {{d, b, c}};
      return true;
    }
  }
  return false;  // boundary edge
}

struct Planar_mesh {
  std::vector<Point2> points;
  std::vector<Face> faces;
};

/// Jittered n x n grid, random quad diagonals, then `spoil_flips` random
/// planar flips that move it far from Delaunay.
Planar_mesh bad_planar_mesh(int n, std::uint64_t point_seed, std::uint64_t mesh_seed,
                            int spoil_flips) {
  Random point_random(point_seed);
  Planar_mesh mesh;
  mesh.points = jittered_grid(n, 0.3, point_random);
  Random random(mesh_seed);
  const auto& p = mesh.points;
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const int v00 = j * n + i, v10 = v00 + 1, v01 = v00 + n, v11 = v01 + 1;
      std::array<Face, 2> diag_a{{{{v00, v10, v11}}, {{v00, v11, v01}}}};
      std::array<Face, 2> diag_b{{{{v00, v10, v01}}, {{v10, v11, v01}}}};
      const auto positive = [&](const std::array<Face, 2>& q) {
        return orient(p[q[0][0]], p[q[0][1]], p[q[0][2]]) > 0 &&
               orient(p[q[1][0]], p[q[1][1]], p[q[1][2]]) > 0;
      };
      const std::array<Face, 2>& chosen =
          (random.next() & 1) ? (positive(diag_a) ? diag_a : diag_b)
                              : (positive(diag_b) ? diag_b : diag_a);
      BOOST_REQUIRE(positive(chosen));
      mesh.faces.push_back(chosen[0]);
      mesh.faces.push_back(chosen[1]);
    }
  }
  for (int attempt = 0; attempt < spoil_flips; ++attempt) {
    planar_flip(mesh.faces, p, random.index(mesh.faces.size()), static_cast<int>(random.index(3)));
  }
  return mesh;
}

Intrinsic_triangulation planar_triangulation(const Planar_mesh& mesh) {
  std::vector<Point3> points;
  for (const Point2& q : mesh.points) points.push_back(lift(q));
  return make_triangulation(points, mesh.faces);
}

/// Largest in-circle determinant of any point against any face, relative to
/// the face's scale; > 0 means a point strictly inside a circumcircle.
double worst_incircle(const Intrinsic_triangulation& tri, const std::vector<Point2>& p) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const Face& f : tri.face) {
    const Point2 &a = p[f[0]], &b = p[f[1]], &c = p[f[2]];
    BOOST_REQUIRE_GT(orient(a, b, c), 0.0);
    for (std::size_t v = 0; v < p.size(); ++v) {
      if (static_cast<int>(v) == f[0] || static_cast<int>(v) == f[1] ||
          static_cast<int>(v) == f[2]) {
        continue;
      }
      const double ax = a[0] - p[v][0], ay = a[1] - p[v][1];
      const double bx = b[0] - p[v][0], by = b[1] - p[v][1];
      const double cx = c[0] - p[v][0], cy = c[1] - p[v][1];
      const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
      const double det = ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) +
                         a2 * (bx * cy - by * cx);
      const double scale = std::max({a2, b2, c2});
      worst = std::max(worst, det / (scale * scale));
    }
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(intrinsic_delaunay)

BOOST_AUTO_TEST_CASE(regular_grid_is_left_unchanged) {
  // Rectangles split along one diagonal: every diagonal is co-circular
  // (cot alpha + cot beta = 0 up to rounding) and must not be flipped.
  const int nx = 12, ny = 9;
  const double hx = 1.0, hy = 0.6;
  std::vector<Point3> points;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) points.push_back({{0.1 + i * hx, 0.3 + j * hy, 0.0}});
  }
  std::vector<Face> faces;
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const int v00 = j * nx + i, v10 = v00 + 1, v01 = v00 + nx, v11 = v01 + 1;
      faces.push_back({{v00, v10, v11}});
      faces.push_back({{v00, v11, v01}});
    }
  }
  Intrinsic_triangulation tri = make_triangulation(points, faces);
  const Intrinsic_triangulation original = tri;
  std::vector<int> twin;
  BOOST_CHECK_EQUAL(make_intrinsic_delaunay(tri, twin), 0u);
  BOOST_CHECK(tri.face == original.face);
  BOOST_CHECK(tri.length == original.length);
  BOOST_CHECK(twin == twins_by_vertex_pair(tri));
  BOOST_CHECK_EQUAL(euler_characteristic(tri, twin), 1);
}

BOOST_AUTO_TEST_CASE(planar_point_set_reaches_its_delaunay_triangulation) {
  const int n = 20;
  const Planar_mesh mesh = bad_planar_mesh(n, 12345, 777, 4000);
  const std::vector<Point2>& p = mesh.points;
  Intrinsic_triangulation tri = planar_triangulation(mesh);
  const std::size_t face_count = tri.face.size();
  const double area_before = total_area(tri);
  BOOST_REQUIRE_LT(min_cotan_sum(tri, twins_by_vertex_pair(tri)), -1.0);  // really bad input
  BOOST_REQUIRE_GT(worst_incircle(tri, p), 1e-3);

  std::vector<int> twin;
  const std::size_t flips = make_intrinsic_delaunay(tri, twin);
  BOOST_TEST_MESSAGE("planar: " << flips << " flips");
  BOOST_CHECK_GT(flips, 100u);
  BOOST_CHECK_EQUAL(tri.number_of_vertices, p.size());
  BOOST_CHECK_EQUAL(tri.face.size(), face_count);
  BOOST_CHECK_EQUAL(tri.length.size(), face_count);
  check_twins(tri, twin);
  // A planar triangulation has no repeated edges, so vertex pairs identify
  // edges and the library's adjacency must match an independent one.
  BOOST_CHECK(twin == twins_by_vertex_pair(tri));
  BOOST_CHECK_EQUAL(euler_characteristic(tri, twin), 1);
  check_every_vertex_has_a_face(tri);

  BOOST_CHECK_GE(min_cotan_sum(tri, twin), -1e-10);
  BOOST_CHECK_CLOSE_FRACTION(total_area(tri), area_before, 1e-12);
  BOOST_CHECK_CLOSE_FRACTION(total_area(tri), (n - 1.0) * (n - 1.0), 1e-12);

  // Flipped lengths come from an unfolding; in the plane they must be the
  // Euclidean distances, and each intrinsic triangle must be the 2D one.
  double worst_length_error = 0;
  for (std::size_t f = 0; f < tri.face.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const double expected = distance(lift(p[tri.face[f][k]]), lift(p[tri.face[f][(k + 1) % 3]]));
      worst_length_error = std::max(worst_length_error, std::abs(tri.length[f][k] - expected));
    }
    const auto& v = tri.face[f];
    BOOST_CHECK_CLOSE_FRACTION(triangle_shape(tri.length[f]).area,
                               0.5 * orient(p[v[0]], p[v[1]], p[v[2]]), 1e-9);
  }
  BOOST_CHECK_LT(worst_length_error, 1e-10);

  // Empty circumcircles: together with the above this makes the result the
  // Delaunay triangulation of the points (unique, points are generic).
  BOOST_CHECK_LT(worst_incircle(tri, p), 1e-10);

  // Uniqueness, checked directly: another bad triangulation of the same
  // points must end with the same edges.
  Intrinsic_triangulation other = planar_triangulation(bad_planar_mesh(n, 12345, 4242, 6000));
  BOOST_REQUIRE(edge_set(other) != edge_set(tri));
  make_intrinsic_delaunay(other);
  BOOST_CHECK(edge_set(other) == edge_set(tri));

  // Already Delaunay now: nothing left to flip.
  BOOST_CHECK_EQUAL(make_intrinsic_delaunay(tri), 0u);
}

BOOST_AUTO_TEST_CASE(flat_bipyramid_gets_repeated_edges) {
  // Triangular bipyramid of height 2h over a unit-circumradius triangle:
  // each equator edge faces two angles of ~120 degrees, so all three are
  // flipped into three distinct edges from the top to the bottom apex.
  const double h = 0.1;
  std::vector<Point3> points;
  for (int i = 0; i < 3; ++i) {
    points.push_back({{std::cos(2 * pi * i / 3), std::sin(2 * pi * i / 3), 0.0}});
  }
  points.push_back({{0.0, 0.0, h}});   // 3: top
  points.push_back({{0.0, 0.0, -h}});  // 4: bottom
  std::vector<Face> faces;
  for (int i = 0; i < 3; ++i) {
    faces.push_back({{i, (i + 1) % 3, 3}});
    faces.push_back({{(i + 1) % 3, i, 4}});
  }
  Intrinsic_triangulation tri = make_triangulation(points, faces);
  const double area_before = total_area(tri);
  const std::vector<double> angles_before = cone_angles(tri);

  std::vector<int> twin;
  BOOST_CHECK_EQUAL(make_intrinsic_delaunay(tri, twin), 3u);
  check_twins(tri, twin);
  BOOST_CHECK_GE(min_cotan_sum(tri, twin), -1e-10);
  BOOST_CHECK_CLOSE_FRACTION(total_area(tri), area_before, 1e-12);
  BOOST_CHECK_EQUAL(euler_characteristic(tri, twin), 2);
  check_every_vertex_has_a_face(tri);
  const std::vector<double> angles_after = cone_angles(tri);
  for (std::size_t v = 0; v < angles_before.size(); ++v) {
    BOOST_CHECK_SMALL(angles_after[v] - angles_before[v], 1e-12);
  }

  // Each new edge is the geodesic over the midpoint of an equator edge,
  // at radius 1/2: length 2 sqrt(1/4 + h^2).
  int apex_edges = 0;
  for (int hh = 0; hh < static_cast<int>(twin.size()); ++hh) {
    if (twin[hh] < hh) continue;
    if (sorted_pair(source(tri, hh), target(tri, hh)) == std::make_pair(3, 4)) {
      ++apex_edges;
      BOOST_CHECK_CLOSE_FRACTION(length(tri, hh), 2 * std::sqrt(0.25 + h * h), 1e-14);
    }
  }
  BOOST_CHECK_EQUAL(apex_edges, 3);
  // Repeated edges make the output ambiguous for twin matching by vertex
  // pair: feeding it back is rejected rather than silently mis-glued.
  BOOST_CHECK_THROW(make_intrinsic_delaunay(tri), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(bent_strip_keeps_intrinsic_invariants) {
  // A badly triangulated planar patch rolled onto a cylinder: lengths are
  // 3D chords, so the metric is genuinely not the planar one.
  const int n = 14;
  const Planar_mesh mesh = bad_planar_mesh(n, 99, 5, 2000);
  const double radius = 3.0;
  std::vector<Point3> points;
  for (const Point2& q : mesh.points) {
    const double theta = q[0] / radius;
    points.push_back({{radius * std::sin(theta), q[1], radius * (1 - std::cos(theta))}});
  }
  Intrinsic_triangulation tri = make_triangulation(points, mesh.faces);
  const double area_before = total_area(tri);
  const std::vector<double> angles_before = cone_angles(tri);

  std::vector<int> twin;
  const std::size_t flips = make_intrinsic_delaunay(tri, twin);
  BOOST_CHECK_GT(flips, 10u);
  check_twins(tri, twin);
  BOOST_CHECK_GE(min_cotan_sum(tri, twin), -1e-10);
  BOOST_CHECK_CLOSE_FRACTION(total_area(tri), area_before, 1e-12);
  BOOST_CHECK_EQUAL(euler_characteristic(tri, twin), 1);
  check_every_vertex_has_a_face(tri);
  const std::vector<double> angles_after = cone_angles(tri);
  double worst_angle_change = 0;
  for (std::size_t v = 0; v < angles_before.size(); ++v) {
    worst_angle_change = std::max(worst_angle_change, std::abs(angles_after[v] - angles_before[v]));
  }
  BOOST_CHECK_LT(worst_angle_change, 1e-9);
}

BOOST_AUTO_TEST_CASE(noisy_sphere_keeps_intrinsic_invariants) {
  // Octahedron subdivided three times, pushed to the unit sphere, then
  // vertices moved tangentially and radially: a closed curved surface full
  // of obtuse triangles.
  std::vector<Point3> points{{{1, 0, 0}}, {{-1, 0, 0}}, {{0, 1, 0}},
                             {{0, -1, 0}}, {{0, 0, 1}}, {{0, 0, -1}}};
  std::vector<Face> faces{{{0, 2, 4}}, {{2, 1, 4}}, {{1, 3, 4}}, {{3, 0, 4}},
                          {{2, 0, 5}}, {{1, 2, 5}}, {{3, 1, 5}}, {{0, 3, 5}}};
  for (int level = 0; level < 3; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto mid = [&](int u, int v) {
      const auto key = sorted_pair(u, v);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const int id = static_cast<int>(points.size());
      points.push_back({{0.5 * (points[u][0] + points[v][0]), 0.5 * (points[u][1] + points[v][1]),
                         0.5 * (points[u][2] + points[v][2])}});
      midpoint[key] = id;
      return id;
    };
    std::vector<Face> finer;
    for (const Face& f : faces) {
      const int m01 = mid(f[0], f[1]), m12 = mid(f[1], f[2]), m20 = mid(f[2], f[0]);
      finer.push_back({{f[0], m01, m20}});
      finer.push_back({{m01, f[1], m12}});
      finer.push_back({{m20, m12, f[2]}});
      finer.push_back({{m01, m12, m20}});
    }
    faces = finer;
  }
  Random random(2026);
  for (Point3& q : points) {
    const double norm = distance(q, {{0, 0, 0}});
    for (double& x : q) x = x / norm + random.uniform(-0.12, 0.12);
  }
  Intrinsic_triangulation tri = make_triangulation(points, faces);
  const double area_before = total_area(tri);
  const std::vector<double> angles_before = cone_angles(tri);

  std::vector<int> twin;
  const std::size_t flips = make_intrinsic_delaunay(tri, twin);
  BOOST_TEST_MESSAGE("sphere: " << flips << " flips on " << tri.face.size() << " faces");
  BOOST_CHECK_GT(flips, 10u);
  check_twins(tri, twin);
  BOOST_CHECK_GE(min_cotan_sum(tri, twin), -1e-10);
  BOOST_CHECK_CLOSE_FRACTION(total_area(tri), area_before, 1e-12);
  BOOST_CHECK_EQUAL(euler_characteristic(tri, twin), 2);
  check_every_vertex_has_a_face(tri);
  const std::vector<double> angles_after = cone_angles(tri);
  double angle_defect = 0, worst_angle_change = 0;
  for (std::size_t v = 0; v < angles_before.size(); ++v) {
    worst_angle_change = std::max(worst_angle_change, std::abs(angles_after[v] - angles_before[v]));
    angle_defect += 2 * pi - angles_after[v];
  }
  BOOST_CHECK_LT(worst_angle_change, 1e-9);
  BOOST_CHECK_SMALL(angle_defect - 4 * pi, 1e-8);  // Gauss-Bonnet, chi = 2
}

BOOST_AUTO_TEST_CASE(single_triangle_has_only_boundary_edges) {
  // An obtuse triangle: its long edge is "non-Delaunay" on one side only,
  // and boundary edges are never flipped.
  Intrinsic_triangulation tri =
      make_triangulation({{{0, 0, 0}}, {{4, 0, 0}}, {{2, 0.1, 0}}}, {{{0, 1, 2}}});
  const Intrinsic_triangulation original = tri;
  BOOST_CHECK_EQUAL(make_intrinsic_delaunay(tri), 0u);
  BOOST_CHECK(tri.face == original.face);
  BOOST_CHECK(tri.length == original.length);
}

BOOST_AUTO_TEST_CASE(doubled_obtuse_triangle_is_not_flipped_into_a_loop) {
  // Two copies of an obtuse triangle glued along all three edges (a closed
  // surface, each vertex of degree 2). The long edge faces two obtuse
  // angles, but flipping it would join vertex 2 to itself: it must be left.
  Intrinsic_triangulation tri = make_triangulation(
      {{{0, 0, 0}}, {{4, 0, 0}}, {{2, 0.5, 0}}}, {{{0, 1, 2}}, {{1, 0, 2}}});
  const Intrinsic_triangulation original = tri;
  std::vector<int> twin;
  BOOST_CHECK_EQUAL(make_intrinsic_delaunay(tri, twin), 0u);
  BOOST_CHECK(tri.face == original.face);
  BOOST_CHECK(tri.length == original.length);
  check_twins(tri, twin);
  BOOST_CHECK_EQUAL(euler_characteristic(tri, twin), 2);
  BOOST_CHECK_LT(min_cotan_sum(tri, twin), 0.0);  // documented leftover
}

BOOST_AUTO_TEST_CASE(non_manifold_edge_is_rejected) {
  // Three faces around edge (3, 7).
  std::vector<Point3> points(8, Point3{{0, 0, 0}});
  for (int i = 0; i < 8; ++i) points[i] = {{std::cos(i * 1.0), std::sin(i * 1.0), 0.1 * i}};
  Intrinsic_triangulation tri = make_triangulation(points, {{{3, 7, 0}}, {{7, 3, 1}}, {{3, 7, 2}}});
  try {
    make_intrinsic_delaunay(tri);
    BOOST_ERROR("non-manifold input accepted");
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    BOOST_TEST_MESSAGE(what);
    BOOST_CHECK(what.find("(3, 7)") != std::string::npos);
    BOOST_CHECK(what.find("non-manifold") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(inconsistent_orientation_is_rejected) {
  std::vector<Point3> points(8, Point3{{0, 0, 0}});
  for (int i = 0; i < 8; ++i) points[i] = {{std::cos(i * 1.0), std::sin(i * 1.0), 0.1 * i}};
  Intrinsic_triangulation tri = make_triangulation(points, {{{7, 3, 0}}, {{7, 3, 1}}});
  try {
    make_intrinsic_delaunay(tri);
    BOOST_ERROR("inconsistently oriented input accepted");
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    BOOST_TEST_MESSAGE(what);
    BOOST_CHECK(what.find("(7, 3)") != std::string::npos);
    BOOST_CHECK(what.find("orientation") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(malformed_input_is_rejected) {
  const std::vector<Point3> points{{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}};
  {
    Intrinsic_triangulation tri = make_triangulation(points, {{{0, 1, 2}}});
    tri.face[0][2] = 3;  // out of range
    BOOST_CHECK_THROW(make_intrinsic_delaunay(tri), std::invalid_argument);
  }
  {
    Intrinsic_triangulation tri = make_triangulation(points, {{{0, 1, 2}}});
    tri.length.clear();
    BOOST_CHECK_THROW(make_intrinsic_delaunay(tri), std::invalid_argument);
  }
  {
    Intrinsic_triangulation tri = make_triangulation(points, {{{0, 1, 2}}});
    tri.length[0][1] = std::nan("");
    BOOST_CHECK_THROW(make_intrinsic_delaunay(tri), std::invalid_argument);
  }
  {
    Intrinsic_triangulation tri = make_triangulation(points, {{{0, 1, 1}}});
    BOOST_CHECK_THROW(make_intrinsic_delaunay(tri), std::invalid_argument);
  }
}

BOOST_AUTO_TEST_SUITE_END()
