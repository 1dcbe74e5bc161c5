// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_SURFACES_H
#define EXPMAP_BENCHMARK_EVALUATION_SURFACES_H

/// \file Surfaces.h
/// The meshes of the accuracy study (Table 1): geodesic and jittered
/// spheres, jittered Delaunay height fields, and the choice of the family
/// member whose mean edge length is closest to a target.

#include "Analytic_surfaces.h"
#include "Common.h"
#include "Meshes.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace expmap_evaluation {

/// Geodesic (class I) sphere of frequency k: every face of the icosahedron
/// split into k^2 triangles on a barycentric lattice, points projected onto
/// the unit sphere. 10 k^2 + 2 vertices; unlike the icosphere (k = 2^s) any
/// resolution can be hit.
inline expmap_analytic::Triangle_soup geodesic_sphere(int k) {
  const expmap_analytic::Triangle_soup ico = expmap_analytic::make_icosphere(0, 1.0);
  expmap_analytic::Triangle_soup soup;
  // Key: the icosahedron vertices with non-zero lattice weight, sorted.
  std::map<std::array<int, 6>, int> index;
  auto vertex = [&](const std::array<int, 3>& corners, const std::array<int, 3>& weights) {
    std::array<std::pair<int, int>, 3> entries{};
    int m = 0;
    for (int c = 0; c < 3; ++c)
      if (weights[c] > 0) entries[m++] = {corners[c], weights[c]};
    for (int a = 1; a < m; ++a)  // insertion sort of at most three entries
      for (int b = a; b > 0 && entries[b] < entries[b - 1]; --b) std::swap(entries[b], entries[b - 1]);
    std::array<int, 6> key;
    key.fill(-1);
    for (int c = 0; c < m; ++c) {
      key[2 * c] = entries[c].first;
      key[2 * c + 1] = entries[c].second;
    }
    const auto found = index.find(key);
    if (found != index.end()) return found->second;
    Vec3 p{0, 0, 0};
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) p[d] += weights[c] * ico.points[std::size_t(corners[c])][d];
    const double norm = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double& x : p) x /= norm;
    const int i = static_cast<int>(soup.points.size());
    soup.points.push_back(p);
    index.emplace(key, i);
    return i;
  };
  for (const auto& f : ico.triangles) {
    auto at = [&](int i, int j) { return vertex(f, {{k - i - j, i, j}}); };
    for (int j = 0; j < k; ++j)
      for (int i = 0; i + j < k; ++i) {
        soup.triangles.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}});
        if (i + j + 2 <= k) soup.triangles.push_back({{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
      }
  }
  return soup;
}

/// Irregular Delaunay version of `geodesic_sphere(k)`: every vertex moved
/// in its tangent plane by a uniformly random vector of length up to
/// `jitter` times the lattice spacing, projected back onto the sphere, and
/// triangulated as the convex hull of the points (the spherical Delaunay
/// triangulation). Seeded std::mt19937, so deterministic.
inline expmap_analytic::Triangle_soup jittered_sphere(int k, double jitter, unsigned seed) {
  const expmap_analytic::Triangle_soup lattice = geodesic_sphere(k);
  const double spacing = mean_edge_length(lattice);
  std::mt19937 rng(seed);
  auto uniform = [&rng]() { return double(rng()) / 4294967296.0; };
  std::vector<Point> points;
  for (const auto& p : lattice.points) {
    // Tangent basis at p.
    const Vec3 a = std::abs(p[2]) < 0.9 ? Vec3{{0, 0, 1}} : Vec3{{1, 0, 0}};
    Vec3 u{{a[1] * p[2] - a[2] * p[1], a[2] * p[0] - a[0] * p[2], a[0] * p[1] - a[1] * p[0]}};
    const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (double& x : u) x /= nu;
    const Vec3 v{{p[1] * u[2] - p[2] * u[1], p[2] * u[0] - p[0] * u[2], p[0] * u[1] - p[1] * u[0]}};
    const double angle = 2 * pi * uniform(), length = jitter * spacing * std::sqrt(uniform());
    Vec3 q;
    for (int d = 0; d < 3; ++d) q[d] = p[d] + length * (std::cos(angle) * u[d] + std::sin(angle) * v[d]);
    const double nq = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    points.emplace_back(q[0] / nq, q[1] / nq, q[2] / nq);
  }
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  // The hull numbers its vertices in an order that depends on the memory
  // layout of the run (seen: other sources picked, other errors, after other
  // studies ran first). Renumber them in the order of the jittered points and
  // sort the faces, so vertex indices -- and the sources picked by index --
  // are the same in every run.
  const expmap_analytic::Triangle_soup unordered = to_soup(hull);
  std::map<std::array<double, 3>, int> input_index;
  for (std::size_t i = 0; i < points.size(); ++i)
    input_index[{{points[i].x(), points[i].y(), points[i].z()}}] = static_cast<int>(i);
  std::vector<int> order(unordered.points.size());
  for (std::size_t v = 0; v < order.size(); ++v) order[v] = static_cast<int>(v);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return input_index.at(unordered.points[a]) < input_index.at(unordered.points[b]);
  });
  std::vector<int> new_index(order.size());
  expmap_analytic::Triangle_soup soup;
  for (std::size_t k = 0; k < order.size(); ++k) {
    new_index[order[k]] = static_cast<int>(k);
    soup.points.push_back(unordered.points[order[k]]);
  }
  for (auto t : unordered.triangles) {
    for (int& v : t) v = new_index[v];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());  // orientation kept
    soup.triangles.push_back(t);
  }
  std::sort(soup.triangles.begin(), soup.triangles.end());
  return soup;
}

/// Irregular Delaunay height field: the points of a hexagonal lattice of
/// spacing `edge` covering the disk of radius `extent`, each interior point
/// (not the origin, not the outer ring) moved by a uniformly random vector
/// of length up to `jitter * edge`, Delaunay-triangulated in the plane and
/// lifted by `height`. Vertex 0 is the origin.
template <class Height>
expmap_analytic::Triangle_soup jittered_height_field(double edge, double extent, double jitter,
                                                     unsigned seed, Height height) {
  const int rings = static_cast<int>(std::ceil(extent / (edge * std::sqrt(3.0) / 2)));
  const expmap_analytic::Triangle_soup lattice =
      expmap_analytic::make_equilateral_grid(rings, edge);
  const std::size_t outer_ring_start = std::size_t(1 + 3 * rings * (rings - 1));
  std::mt19937 rng(seed);
  auto uniform = [&rng]() { return double(rng()) / 4294967296.0; };
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
  Delaunay dt;
  expmap_analytic::Triangle_soup soup;
  for (std::size_t i = 0; i < lattice.points.size(); ++i) {
    double x = lattice.points[i][0], y = lattice.points[i][1];
    if (i > 0 && i < outer_ring_start) {
      const double angle = 2 * pi * uniform(), length = jitter * edge * std::sqrt(uniform());
      x += length * std::cos(angle);
      y += length * std::sin(angle);
    }
    soup.points.push_back({{x, y, height(x, y)}});
    dt.insert(Kernel::Point_2(x, y))->info() = int(i);
  }
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    soup.triangles.push_back({{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}});
  return soup;
}

/// The smallest/largest parameter of a mesh family whose mean edge length
/// is closest to `target` (h decreasing in the parameter).
template <class Make>
int closest_resolution(double target, int first, int step, Make make) {
  int best = first;
  double best_gap = std::numeric_limits<double>::infinity();
  for (int k = first;; k += step) {
    const double h = mean_edge_length(make(k));
    const double gap = std::abs(std::log(h / target));
    if (gap < best_gap) {
      best_gap = gap;
      best = k;
    }
    if (h < target) break;
  }
  return best;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_SURFACES_H
