// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test geometry, shared by the test suites and the evaluation programs
// (benchmark/evaluation); not part of the library. Generators of analytic
// meshes: sphere, planar grids, height fields, cylinder, cone. Their exact
// exponential maps, where known in closed form, are in
// Analytic_exponential_maps.h.
//
// Every generator returns a `Triangle_soup` whose triangles are oriented
// counter-clockwise seen from the outside (for planar meshes and height
// fields: seen from +z). All generators are deterministic; the only random
// operation, `flip_random_edges()`, takes a seed and uses `std::mt19937`
// with its own (portable) shuffling, so it gives the same mesh on every
// platform and standard library. `soup_to_mesh()` turns a soup into any
// CGAL `MutableFaceGraph` (Surface_mesh, Polyhedron_3, ...) keeping the
// vertex order.
#ifndef EXPMAP_TEST_ANALYTIC_SURFACES_H
#define EXPMAP_TEST_ANALYTIC_SURFACES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <expmap/internal/Vector3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace expmap_analytic {

/// A triangle mesh as a polygon soup: an array of points and an array of
/// triangles given by indices into `points`.
///
/// Triangles are oriented counter-clockwise seen from the outside of the
/// surface (the right-hand normal points outward).
struct Triangle_soup {
  std::vector<std::array<double, 3>> points;  ///< vertex positions
  std::vector<std::array<int, 3>> triangles;  ///< corner indices into `points`

  std::size_t number_of_vertices() const { return points.size(); }  ///< `points.size()`
  std::size_t number_of_faces() const { return triangles.size(); }  ///< `triangles.size()`
};

namespace detail {

// The library's double 3-vectors (std::array<double, 3>, the type of the
// soup's points) and their algebra. The generators below and the exact maps
// (Analytic_exponential_maps.h) bring them into scope with
// `using namespace detail`.
using expmap::internal::Vector3;
using expmap::internal::operator+;
using expmap::internal::operator-;
using expmap::internal::operator*;
using expmap::internal::cross;
using expmap::internal::dot;
using expmap::internal::norm;
using expmap::internal::squared_norm;

inline bool is_finite(const Vector3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

inline void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("expmap: " + message);
}

inline void require_positive(double value, const char* function, const char* name) {
  require(std::isfinite(value) && value > 0,
          std::string(function) + ": " + name + " must be positive and finite (got " +
              std::to_string(value) + ")");
}

inline void require_finite(double value, const char* function, const char* name) {
  require(std::isfinite(value), std::string(function) + ": " + name + " must be finite");
}

inline void require_vertex_budget(double count, const char* function) {
  require(count <= static_cast<double>(std::numeric_limits<int>::max()),
          std::string(function) + ": too many vertices or triangles for int indices");
}

/// Unit vector along `v`; throws if `v` is (numerically) zero or not finite.
inline Vector3 normalized(const Vector3& v, const std::string& what) {
  const double length = norm(v);
  require(std::isfinite(length) && length > 0, what + " must be a non-zero finite vector");
  return (1.0 / length) * v;
}

/// Unbiased integer in [0, n) from the raw 32-bit output of a Mersenne
/// twister (whose sequence is fixed by the standard, unlike the
/// distributions and std::shuffle, which differ between libraries).
inline std::uint32_t uniform_below(std::mt19937& generator, std::uint32_t n) {
  const std::uint32_t threshold = (0u - n) % n;  // 2^32 mod n
  for (;;) {
    const std::uint32_t x = static_cast<std::uint32_t>(generator());
    if (x >= threshold) return x % n;
  }
}

inline std::uint64_t directed_key(int u, int v) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) |
         static_cast<std::uint64_t>(static_cast<std::uint32_t>(v));
}

/// Splits every cell of a (columns x rows) quad lattice into two triangles.
/// `index(i, j)` gives the vertex at lattice corner (i, j), `i` modulo the
/// caller's convention. The diagonal of cell (i, j) goes through its corner
/// (i, j) when `(i + j + parity) % 2 == 0` ("/"), otherwise through the
/// corners (i + 1, j) and (i, j + 1) ("\"). Triangles are counter-clockwise
/// when i runs along the first and j along the second tangent direction of
/// a right-handed frame (u, v, outward normal).
template <class Index>
void triangulate_lattice(int columns, int rows, int parity, Index index,
                         std::vector<std::array<int, 3>>& triangles) {
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const int v00 = index(i, j), v10 = index(i + 1, j);
      const int v11 = index(i + 1, j + 1), v01 = index(i, j + 1);
      if ((i + j + parity) % 2 == 0) {
        triangles.push_back({{v00, v10, v11}});
        triangles.push_back({{v00, v11, v01}});
      } else {
        triangles.push_back({{v00, v10, v01}});
        triangles.push_back({{v10, v11, v01}});
      }
    }
  }
}

}  // namespace detail

// ---------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------

/// Geodesic icosphere: the regular icosahedron subdivided `subdivisions`
/// times, each time splitting every edge at its midpoint (four triangles per
/// triangle) and projecting the new vertices radially onto the sphere.
///
/// The sphere is centred at the origin. It has `10 * 4^s + 2` vertices and
/// `20 * 4^s` triangles (s = 5: 10,242 vertices; s = 6: 40,962 vertices and
/// 81,920 triangles). Vertex ordering: vertices 0..11 are the icosahedron's,
/// vertex 0 being at `radius * (-1, phi, 0) / sqrt(1 + phi^2)` (phi the golden
/// ratio); then, level by level, the edge midpoints in the order they are
/// first met while visiting the triangles of the previous level. Shared
/// midpoints are created once (edge-midpoint cache), so the soup is a closed,
/// consistently outward-oriented 2-manifold of genus 0.
///
/// \param subdivisions number of subdivision steps, in [0, 9]
/// \param radius sphere radius, positive
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_icosphere(int subdivisions, double radius = 1.0) {
  using namespace detail;
  require(
      subdivisions >= 0 && subdivisions <= 9,
      "make_icosphere: subdivisions must be in [0, 9] (got " + std::to_string(subdivisions) + ")");
  require_positive(radius, "make_icosphere", "radius");

  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Triangle_soup soup;
  const std::size_t final_vertices = 10 * (std::size_t(1) << (2 * subdivisions)) + 2;
  soup.points.reserve(final_vertices);
  const Vector3 ico[12] = {{{-1, t, 0}}, {{1, t, 0}},  {{-1, -t, 0}}, {{1, -t, 0}},
                           {{0, -1, t}}, {{0, 1, t}},  {{0, -1, -t}}, {{0, 1, -t}},
                           {{t, 0, -1}}, {{t, 0, 1}},  {{-t, 0, -1}}, {{-t, 0, 1}}};
  for (const Vector3& p : ico) soup.points.push_back(normalized(p, "icosahedron vertex"));
  soup.triangles = {{{0, 11, 5}}, {{0, 5, 1}},  {{0, 1, 7}},   {{0, 7, 10}}, {{0, 10, 11}},
                    {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}},
                    {{3, 9, 4}},  {{3, 4, 2}},  {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},
                    {{4, 9, 5}},  {{2, 4, 11}}, {{6, 2, 10}},  {{8, 6, 7}},  {{9, 8, 1}}};

  for (int level = 0; level < subdivisions; ++level) {
    std::unordered_map<std::uint64_t, int> midpoint;
    midpoint.reserve(soup.triangles.size() * 3 / 2);
    auto middle = [&](int a, int b) {
      const std::uint64_t key = a < b ? directed_key(a, b) : directed_key(b, a);
      const auto found = midpoint.find(key);
      if (found != midpoint.end()) return found->second;
      const Vector3 m = soup.points[std::size_t(a)] + soup.points[std::size_t(b)];
      const int index = static_cast<int>(soup.points.size());
      soup.points.push_back(normalized(m, "edge midpoint"));
      midpoint.emplace(key, index);
      return index;
    };
    std::vector<std::array<int, 3>> finer;
    finer.reserve(4 * soup.triangles.size());
    for (const auto& f : soup.triangles) {
      const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      finer.push_back({{f[0], ab, ca}});
      finer.push_back({{f[1], bc, ab}});
      finer.push_back({{f[2], ca, bc}});
      finer.push_back({{ab, bc, ca}});
    }
    soup.triangles.swap(finer);
  }
  if (radius != 1.0)
    for (auto& p : soup.points) p = radius * p;
  return soup;
}

/// Index of the vertex at lattice position (i, j) of `make_grid(nx, ny, ...)`
/// (and of the height fields built on it): `j * (nx + 1) + i`, with i along x
/// and j along y, both starting at the corner (-width/2, -height/2).
inline std::size_t grid_vertex_index(int nx, int i, int j) {
  return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx + 1) +
         static_cast<std::size_t>(i);
}

/// Index of the vertex at the origin of `make_grid(nx, ny, ...)`, i.e.
/// `grid_vertex_index(nx, nx / 2, ny / 2)`. This vertex has valence 8 (all
/// four diagonals meet there).
/// \throws std::invalid_argument unless nx and ny are even and positive
inline std::size_t grid_origin_vertex(int nx, int ny) {
  detail::require(nx > 0 && ny > 0 && nx % 2 == 0 && ny % 2 == 0,
                  "grid_origin_vertex: nx and ny must be even and positive");
  return grid_vertex_index(nx, nx / 2, ny / 2);
}

/// Regular planar triangulation of the rectangle
/// [-width/2, width/2] x [-height/2, height/2] in the plane z = 0.
///
/// The rectangle is cut into nx x ny cells, each split into two right
/// triangles. Diagonals alternate in a checkerboard ("union jack") pattern:
/// the four diagonals meet at every vertex (i, j) with i - nx/2 + j - ny/2
/// even (valence 8), the others have valence 4. The mesh is therefore
/// symmetric under x -> -x and y -> -y when nx and ny are even, and it is
/// Delaunay (every cell is inscribed in a circle, so opposite angles sum to
/// at most pi, exactly pi across the diagonals). Coordinates are computed so
/// that symmetric vertices have exactly opposite coordinates.
///
/// Vertex ordering: row by row, `grid_vertex_index(nx, i, j) = j*(nx+1) + i`,
/// (nx+1)(ny+1) vertices, 2 nx ny triangles (counter-clockwise seen from +z).
/// When nx and ny are even, vertex `grid_origin_vertex(nx, ny)` is exactly
/// at the origin.
///
/// \param nx number of cells along x, at least 1
/// \param ny number of cells along y, at least 1
/// \param width extent along x, positive
/// \param height extent along y, positive
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_grid(int nx, int ny, double width, double height) {
  using namespace detail;
  require(nx >= 1 && ny >= 1, "make_grid: nx and ny must be at least 1 (got " + std::to_string(nx) +
                                  ", " + std::to_string(ny) + ")");
  require_positive(width, "make_grid", "width");
  require_positive(height, "make_grid", "height");
  require_vertex_budget(2.0 * (double(nx) + 1) * (double(ny) + 1), "make_grid");

  Triangle_soup soup;
  soup.points.reserve(std::size_t(nx + 1) * std::size_t(ny + 1));
  for (int j = 0; j <= ny; ++j) {
    const double y = height * double(2 * j - ny) / double(2 * ny);
    for (int i = 0; i <= nx; ++i) {
      const double x = width * double(2 * i - nx) / double(2 * nx);
      soup.points.push_back({{x, y, 0.0}});
    }
  }
  soup.triangles.reserve(2 * std::size_t(nx) * std::size_t(ny));
  triangulate_lattice(
      nx, ny, nx / 2 + ny / 2,
      [nx](int i, int j) { return static_cast<int>(grid_vertex_index(nx, i, j)); }, soup.triangles);
  return soup;
}

/// Perfectly regular planar mesh: a hexagonal patch of equilateral triangles
/// of side `edge` in the plane z = 0, centred at the origin.
///
/// Vertex ordering: vertex 0 is the centre (at the origin, the source vertex);
/// then ring k = 1..rings holds 6k vertices, listed counter-clockwise (seen
/// from +z) starting with the vertex at (k * edge, 0, 0). Ring k starts at
/// index 1 + 3k(k-1). There are 3 rings (rings + 1) + 1 vertices and
/// 6 rings^2 triangles (counter-clockwise seen from +z); every interior
/// vertex has valence 6.
///
/// \param rings number of rings around the central vertex, at least 1
/// \param edge edge length, positive
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_equilateral_grid(int rings, double edge) {
  using namespace detail;
  require(rings >= 1,
          "make_equilateral_grid: rings must be at least 1 (got " + std::to_string(rings) + ")");
  require_positive(edge, "make_equilateral_grid", "edge");
  require_vertex_budget(6.0 * double(rings) * double(rings) + 3.0 * rings + 1,
                        "make_equilateral_grid");

  // Axial lattice coordinates (a, b): position a * (1, 0) + b * (1/2, sqrt(3)/2).
  const int d[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  const int side = 2 * rings + 1;
  std::vector<int> index(std::size_t(side) * std::size_t(side), -1);
  auto slot = [&](int a, int b) -> int& {
    return index[std::size_t(a + rings) * std::size_t(side) + std::size_t(b + rings)];
  };
  auto inside = [&](int a, int b) {
    return std::abs(a) <= rings && std::abs(b) <= rings && std::abs(a + b) <= rings;
  };
  const double half_sqrt3 = std::sqrt(3.0) / 2.0;

  Triangle_soup soup;
  std::vector<std::array<int, 2>> axial;
  auto add_vertex = [&](int a, int b) {
    slot(a, b) = static_cast<int>(soup.points.size());
    axial.push_back({{a, b}});
    soup.points.push_back({{edge * double(2 * a + b) / 2.0, edge * double(b) * half_sqrt3, 0.0}});
  };
  add_vertex(0, 0);
  for (int k = 1; k <= rings; ++k)
    for (int s = 0; s < 6; ++s)
      for (int step = 0; step < k; ++step)
        add_vertex(k * d[s][0] + step * d[(s + 2) % 6][0], k * d[s][1] + step * d[(s + 2) % 6][1]);

  soup.triangles.reserve(6 * std::size_t(rings) * std::size_t(rings));
  // Each triangle is listed once, from its vertex (a, b) of smallest b then
  // largest a: "up" triangles (a, b), (a + 1, b), (a, b + 1) and "down"
  // triangles (a, b), (a, b + 1), (a - 1, b + 1).
  for (const auto& ab : axial) {
    const int a = ab[0], b = ab[1];
    if (inside(a + 1, b) && inside(a, b + 1))
      soup.triangles.push_back({{slot(a, b), slot(a + 1, b), slot(a, b + 1)}});
    if (inside(a, b + 1) && inside(a - 1, b + 1))
      soup.triangles.push_back({{slot(a, b), slot(a, b + 1), slot(a - 1, b + 1)}});
  }
  return soup;
}

/// Randomly flips edges of a triangle soup (the paper's "50% of the edges
/// randomly flipped" meshes).
///
/// An interior edge {a, b} shared by the triangles (a, b, c) and (b, a, d) is
/// flippable when c != d, the edge {c, d} does not already exist, and the
/// quadrilateral a d b c is strictly convex (seen along the sum of the two
/// triangle normals; tolerance 1e-10 on the sine of the new corner angles),
/// so the flip keeps the surface embedded and, for planar meshes, keeps the
/// total area. The flip replaces the two triangles by (a, d, c) and
/// (d, b, c), reusing their slots in `soup.triangles`; points are not
/// touched.
///
/// `round(fraction * E)` edges are flipped, where E is the number of interior
/// edges that are flippable in the input. Candidates are visited in a random
/// order (Fisher-Yates shuffle driven by `std::mt19937(seed)` raw output, so
/// the result is identical on every platform); an edge is flipped if it is
/// still flippable when visited, at most once, and edges created by flips
/// are never flipped. If a pass ends short of the target, further passes
/// over the still-unflipped candidates are made while they make progress
/// (at most 100 passes), so fewer edges than requested may be flipped when
/// too few remain flippable. Each flip makes the quadrilaterals of some
/// neighbouring edges non-convex, so the process saturates: on
/// `make_equilateral_grid()` (where every interior edge is initially
/// flippable) it stops at about 46-47% of the interior edges, so fraction
/// 0.5 yields ~0.47 there; check the returned count.
///
/// \param soup consistently oriented manifold triangle soup, modified in place
/// \param fraction fraction of the initially flippable edges to flip, in [0, 1]
/// \param seed seed of the `std::mt19937` generator
/// \return the number of edges flipped
/// \throws std::invalid_argument if fraction is outside [0, 1], an index is
///         out of range, or a directed edge is used by two triangles
inline std::size_t flip_random_edges(Triangle_soup& soup, double fraction, unsigned seed) {
  using namespace detail;
  require(fraction >= 0.0 && fraction <= 1.0,
          "flip_random_edges: fraction must be in [0, 1] (got " + std::to_string(fraction) + ")");
  const int n = static_cast<int>(soup.points.size());
  std::unordered_map<std::uint64_t, int> face_of;  // directed edge (u, v) -> face
  face_of.reserve(3 * soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const auto& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      require(t[k] >= 0 && t[k] < n, "flip_random_edges: vertex index out of range");
      require(t[k] != t[(k + 1) % 3], "flip_random_edges: degenerate triangle");
      const bool inserted = face_of.emplace(directed_key(t[k], t[(k + 1) % 3]), int(f)).second;
      require(inserted,
              "flip_random_edges: a directed edge is used twice (non-manifold or "
              "inconsistently oriented soup)");
    }
  }
  auto face_at = [&](int u, int v) {
    const auto it = face_of.find(directed_key(u, v));
    return it == face_of.end() ? -1 : it->second;
  };
  auto opposite = [&](int f, int u, int v) {
    const auto& t = soup.triangles[std::size_t(f)];
    for (int k = 0; k < 3; ++k)
      if (t[k] == u && t[(k + 1) % 3] == v) return t[(k + 2) % 3];
    return -1;
  };
  // Returns true (and flips when `apply`) if edge {a, b} exists and is flippable.
  auto try_flip = [&](int a, int b, bool apply) {
    const int f1 = face_at(a, b), f2 = face_at(b, a);
    if (f1 < 0 || f2 < 0) return false;
    const int c = opposite(f1, a, b), d = opposite(f2, b, a);
    if (c == d || face_at(c, d) >= 0 || face_at(d, c) >= 0) return false;
    const auto& pa = soup.points[std::size_t(a)];
    const auto& pb = soup.points[std::size_t(b)];
    const auto& pc = soup.points[std::size_t(c)];
    const auto& pd = soup.points[std::size_t(d)];
    const Vector3 n1 = cross(pb - pa, pc - pa);
    const Vector3 n2 = cross(pa - pb, pd - pb);
    const double l1 = norm(n1), l2 = norm(n2);
    if (!(l1 > 0) || !(l2 > 0)) return false;
    const Vector3 normal = (1.0 / l1) * n1 + (1.0 / l2) * n2;
    const double ln = norm(normal);
    if (!(ln > 1e-12)) return false;  // the two triangles fold onto each other
    auto positive = [&](const Vector3& p, const Vector3& q, const Vector3& r) {
      const Vector3 u = q - p, v = r - p;
      return dot(cross(u, v), normal) > 1e-10 * ln * norm(u) * norm(v);
    };
    if (!positive(pa, pd, pc) || !positive(pd, pb, pc)) return false;
    if (!apply) return true;
    soup.triangles[std::size_t(f1)] = {{a, d, c}};
    soup.triangles[std::size_t(f2)] = {{d, b, c}};
    face_of.erase(directed_key(a, b));
    face_of.erase(directed_key(b, a));
    face_of[directed_key(a, d)] = f1;
    face_of[directed_key(d, c)] = f1;
    face_of[directed_key(c, a)] = f1;
    face_of[directed_key(d, b)] = f2;
    face_of[directed_key(b, c)] = f2;
    face_of[directed_key(c, d)] = f2;
    return true;
  };

  // Candidates in a deterministic order: faces in order, edges (a < b) in
  // corner order, each interior edge once.
  std::vector<std::array<int, 2>> candidates;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < b && try_flip(a, b, false)) candidates.push_back({{a, b}});
    }
  const std::size_t target = static_cast<std::size_t>(
      std::llround(fraction * static_cast<double>(candidates.size())));
  if (target == 0) return 0;

  std::mt19937 generator(seed);
  for (std::size_t i = candidates.size() - 1; i > 0; --i) {
    const std::size_t j = uniform_below(generator, static_cast<std::uint32_t>(i + 1));
    std::swap(candidates[i], candidates[j]);
  }
  std::vector<char> done(candidates.size(), 0);
  std::size_t flipped = 0;
  for (int pass = 0; pass < 100 && flipped < target; ++pass) {
    const std::size_t before = flipped;
    for (std::size_t k = 0; k < candidates.size() && flipped < target; ++k) {
      if (done[k]) continue;
      if (try_flip(candidates[k][0], candidates[k][1], true)) {
        done[k] = 1;
        ++flipped;
      }
    }
    if (flipped == before) break;
  }
  return flipped;
}

/// Scales every point: (x, y, z) -> (sx x, sy y, sz z). Triangles are kept;
/// positive factors keep the orientation.
///
/// \param soup soup modified in place
/// \param sx,sy,sz scale factors, positive and finite
/// \throws std::invalid_argument if a factor is not positive
inline void scale_anisotropically(Triangle_soup& soup, double sx, double sy, double sz) {
  using namespace detail;
  require_positive(sx, "scale_anisotropically", "sx");
  require_positive(sy, "scale_anisotropically", "sy");
  require_positive(sz, "scale_anisotropically", "sz");
  for (auto& p : soup.points) {
    p[0] *= sx;
    p[1] *= sy;
    p[2] *= sz;
  }
}

// Height field z = f(x, y) on make_grid(n, n, 2 half_width, 2 half_width).
namespace detail {

template <class Height>
Triangle_soup make_height_field(int n, double half_width, Height f, const char* function) {
  require(n >= 2 && n % 2 == 0,
          std::string(function) + ": n must be even and at least 2 (got " + std::to_string(n) + ")");
  require_positive(half_width, function, "half_width");
  Triangle_soup soup = make_grid(n, n, 2.0 * half_width, 2.0 * half_width);
  for (auto& p : soup.points) p[2] = f(p[0], p[1]);
  return soup;
}

}  // namespace detail

/// Gaussian bump: the height field z = amplitude * exp(-(x^2 + y^2) / (2 sigma^2))
/// over the square [-half_width, half_width]^2, sampled on the grid of
/// `make_grid(n, n, 2 half_width, 2 half_width)` (same vertex ordering and
/// union-jack diagonals, triangles counter-clockwise seen from +z).
///
/// The apex (0, 0, amplitude) is vertex `grid_origin_vertex(n, n)`
/// = (n/2)(n+2), which has valence 8; use it as the source for
/// `gaussian_bump_exponential_map()`.
///
/// \param n number of cells per side, even and at least 2
/// \param half_width half side of the square domain, positive
/// \param amplitude height of the apex, finite (negative gives a dent)
/// \param sigma standard deviation of the Gaussian, positive
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_gaussian_bump(int n, double half_width, double amplitude,
                                        double sigma) {
  using namespace detail;
  require_finite(amplitude, "make_gaussian_bump", "amplitude");
  require_positive(sigma, "make_gaussian_bump", "sigma");
  const double inv = 1.0 / (2.0 * sigma * sigma);
  return detail::make_height_field(
      n, half_width,
      [=](double x, double y) { return amplitude * std::exp(-(x * x + y * y) * inv); },
      "make_gaussian_bump");
}

/// Saddle: the height field z = amplitude * sin(x) * sin(y) over the square
/// [-half_width, half_width]^2, sampled on the grid of
/// `make_grid(n, n, 2 half_width, 2 half_width)` (same vertex ordering,
/// triangles counter-clockwise seen from +z).
///
/// The saddle point (0, 0, 0) is vertex `grid_origin_vertex(n, n)`
/// = (n/2)(n+2). There is no closed-form exponential map for this surface.
///
/// \param n number of cells per side, even and at least 2
/// \param half_width half side of the square domain, positive
/// \param amplitude amplitude of the sine product, finite
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_saddle(int n, double half_width, double amplitude) {
  detail::require_finite(amplitude, "make_saddle", "amplitude");
  return detail::make_height_field(
      n, half_width, [=](double x, double y) { return amplitude * std::sin(x) * std::sin(y); },
      "make_saddle");
}

/// Open cylinder of axis z (two boundary loops), radius `radius`, spanning
/// z in [-length/2, length/2].
///
/// Vertex ordering: ring j = 0..along (at z = length (j/along - 1/2)) holds
/// `around` vertices; vertex `j * around + i` is at angle 2 pi i / around
/// (counter-clockwise about +z, i = 0 on the +x axis). When `along` is even,
/// vertex `(along / 2) * around` is exactly at (radius, 0, 0): the natural
/// source. Each quad is split by a diagonal alternating in a checkerboard
/// pattern (perfectly alternating when `around` is even), arranged so that
/// the four diagonals meet at that source vertex (valence 8). There are
/// (along + 1) around vertices and 2 around along triangles, oriented
/// counter-clockwise seen from outside (away from the axis).
///
/// \param around number of vertices per ring, at least 3
/// \param along number of quad rows along the axis, at least 1
/// \param radius cylinder radius, positive
/// \param length cylinder length, positive
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_cylinder(int around, int along, double radius, double length) {
  using namespace detail;
  require(around >= 3,
          "make_cylinder: around must be at least 3 (got " + std::to_string(around) + ")");
  require(along >= 1,
          "make_cylinder: along must be at least 1 (got " + std::to_string(along) + ")");
  require_positive(radius, "make_cylinder", "radius");
  require_positive(length, "make_cylinder", "length");
  require_vertex_budget(2.0 * double(around) * (double(along) + 1), "make_cylinder");

  const double two_pi = 2.0 * std::acos(-1.0);
  Triangle_soup soup;
  soup.points.reserve(std::size_t(along + 1) * std::size_t(around));
  for (int j = 0; j <= along; ++j) {
    const double z = length * double(2 * j - along) / double(2 * along);
    for (int i = 0; i < around; ++i) {
      const double phi = two_pi * double(i) / double(around);
      soup.points.push_back({{radius * std::cos(phi), radius * std::sin(phi), z}});
    }
  }
  soup.triangles.reserve(2 * std::size_t(around) * std::size_t(along));
  // Parity along/2: the source vertex (along/2) * around has valence 8.
  triangulate_lattice(
      around, along, along / 2, [around](int i, int j) { return j * around + i % around; },
      soup.triangles);
  return soup;
}

/// Open cone with its apex as a vertex (not truncated).
///
/// The apex is vertex 0, at the origin; the axis is +z and the cone opens
/// upwards: a point at slant distance s from the apex and azimuth phi is
/// (s sin(alpha) cos(phi), s sin(alpha) sin(phi), s cos(alpha)) with
/// alpha = apex_angle / 2. Vertex ordering: ring j = 1..along (at slant
/// distance s = length j / along, so `length` is the length of the
/// generators) holds `around` vertices, vertex `1 + (j - 1) * around + i`
/// being at azimuth 2 pi i / around. The apex is joined to ring 1 by a fan;
/// quads between rings are split with alternating diagonals. There are
/// 1 + along around vertices and around (2 along - 1) triangles, oriented
/// counter-clockwise seen from outside (away from the axis). The surface is
/// intrinsically flat except at the apex, whose total angle is
/// 2 pi sin(alpha).
///
/// \param around number of vertices per ring, at least 3
/// \param along number of rings, at least 1
/// \param apex_angle full opening angle (between opposite generators), in (0, pi)
/// \param length slant length of the generators, positive
/// \throws std::invalid_argument if a parameter is out of range
inline Triangle_soup make_cone(int around, int along, double apex_angle, double length) {
  using namespace detail;
  const double pi = std::acos(-1.0);
  require(around >= 3, "make_cone: around must be at least 3 (got " + std::to_string(around) + ")");
  require(along >= 1, "make_cone: along must be at least 1 (got " + std::to_string(along) + ")");
  require(std::isfinite(apex_angle) && apex_angle > 0 && apex_angle < pi,
          "make_cone: apex_angle must be in (0, pi) (got " + std::to_string(apex_angle) + ")");
  require_positive(length, "make_cone", "length");
  require_vertex_budget(2.0 * double(around) * double(along) + 1, "make_cone");

  const double alpha = 0.5 * apex_angle;
  Triangle_soup soup;
  soup.points.reserve(1 + std::size_t(along) * std::size_t(around));
  soup.points.push_back({{0.0, 0.0, 0.0}});
  for (int j = 1; j <= along; ++j) {
    const double s = length * double(j) / double(along);
    for (int i = 0; i < around; ++i) {
      const double phi = 2.0 * pi * double(i) / double(around);
      soup.points.push_back({{s * std::sin(alpha) * std::cos(phi),
                              s * std::sin(alpha) * std::sin(phi), s * std::cos(alpha)}});
    }
  }
  soup.triangles.reserve(std::size_t(around) * std::size_t(2 * along - 1));
  auto ring = [around](int i, int j) { return 1 + (j - 1) * around + i % around; };
  for (int i = 0; i < around; ++i) soup.triangles.push_back({{0, ring(i + 1, 1), ring(i, 1)}});
  triangulate_lattice(
      around, along - 1, 0, [&](int i, int j) { return ring(i, j + 1); }, soup.triangles);
  return soup;
}

/// Index of the vertex closest (Euclidean distance) to `p`; ties go to the
/// smallest index.
/// \throws std::invalid_argument if the soup has no points
inline std::size_t closest_vertex(const Triangle_soup& soup, const std::array<double, 3>& p) {
  using namespace detail;
  require(!soup.points.empty(), "closest_vertex: the soup has no points");
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const double squared = squared_norm(soup.points[i] - p);
    if (squared < best_distance) {
      best_distance = squared;
      best = i;
    }
  }
  return best;
}

/// Builds a CGAL polygon mesh from a triangle soup with
/// `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh()`.
///
/// Vertex i of the soup becomes the i-th vertex of `mesh` (in the order of
/// `vertices(mesh)`; for a `CGAL::Surface_mesh` it has index i), and the
/// faces are added in the order of `soup.triangles` with the same
/// orientation.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with an internal
///         `CGAL::vertex_point_t` property map whose point type is
///         constructible from three doubles
/// \param soup the triangles, which must form a consistently oriented
///        manifold surface (`is_polygon_soup_a_polygon_mesh()`)
/// \param mesh output; must be empty (a freshly constructed mesh, or one
///        cleared with its `clear()` member, so that no garbage shifts the
///        vertex indices)
/// \throws std::invalid_argument if `mesh` is not empty, an index is out of
///         range, or the soup is not a polygon mesh
template <class PolygonMesh>
void soup_to_mesh(const Triangle_soup& soup, PolygonMesh& mesh) {
  using namespace detail;
  require(CGAL::is_empty(mesh), "soup_to_mesh: the output mesh must be empty");
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(soup.triangles.size());
  const int n = static_cast<int>(soup.points.size());
  for (const auto& t : soup.triangles) {
    for (int k = 0; k < 3; ++k)
      require(t[k] >= 0 && t[k] < n, "soup_to_mesh: vertex index out of range");
    polygons.push_back({{std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])}});
  }
  require(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons),
          "soup_to_mesh: the soup is not a consistently oriented manifold polygon mesh");
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, polygons, mesh);
}

}  // namespace expmap_analytic

#endif  // EXPMAP_TEST_ANALYTIC_SURFACES_H
