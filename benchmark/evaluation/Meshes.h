// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_MESHES_H
#define EXPMAP_BENCHMARK_EVALUATION_MESHES_H

/// \file Meshes.h
/// Triangle soups and Surface_meshes: conversion both ways (vertex and face
/// order kept), and the measures the studies report of a mesh (mean edge
/// length h, fraction of non-Delaunay edges).

#include "Analytic_surfaces.h"
#include "Common.h"

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>

namespace expmap_evaluation {

inline Mesh to_mesh(const expmap_analytic::Triangle_soup& soup) {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(soup, mesh);
  return mesh;
}

/// The soup of a Surface_mesh (vertex and face order kept).
inline expmap_analytic::Triangle_soup to_soup(const Mesh& mesh) {
  expmap_analytic::Triangle_soup soup;
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    soup.points.push_back({{p.x(), p.y(), p.z()}});
  }
  for (auto f : faces(mesh)) {
    std::array<int, 3> t{};
    int c = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[c++] = int(std::size_t(v));
    soup.triangles.push_back(t);
  }
  return soup;
}

inline double mean_edge_length(const expmap_analytic::Triangle_soup& soup) {
  // Over triangle sides: each interior edge counts twice, boundary edges
  // once, as in the library's h (Mesh_arrays) up to that weighting.
  double sum = 0;
  std::size_t count = 0;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto& a = soup.points[std::size_t(t[k])];
      const auto& b = soup.points[std::size_t(t[(k + 1) % 3])];
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                       (a[2] - b[2]) * (a[2] - b[2]));
      ++count;
    }
  return sum / static_cast<double>(count);
}

inline double mean_edge_length(const Mesh& mesh) {
  double sum = 0;
  std::size_t count = 0;
  for (auto e : mesh.edges()) {
    sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)),
                                            mesh.point(mesh.vertex(e, 1))));
    ++count;
  }
  return sum / static_cast<double>(count);
}

/// Fraction of the interior edges of a soup whose two opposite angles sum
/// to more than pi (by more than 1e-9): the edges that make the cotan
/// Laplacian lose its positive weights.
inline double non_delaunay_fraction(const expmap_analytic::Triangle_soup& soup) {
  std::map<std::pair<int, int>, double> opposite;  // edge -> sum of opposite angles
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const auto& pa = soup.points[std::size_t(a)];
      const auto& pb = soup.points[std::size_t(b)];
      const auto& pc = soup.points[std::size_t(c)];
      const Vec3 u{{pa[0] - pc[0], pa[1] - pc[1], pa[2] - pc[2]}};
      const Vec3 v{{pb[0] - pc[0], pb[1] - pc[1], pb[2] - pc[2]}};
      const double cosine = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) /
                            std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) *
                                      (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      opposite[key] += std::acos(std::clamp(cosine, -1.0, 1.0));
      ++count[key];
    }
  std::size_t interior = 0, bad = 0;
  for (const auto& [key, sum] : opposite)
    if (count[key] == 2) {
      ++interior;
      bad += sum > pi + 1e-9;
    }
  return interior ? double(bad) / double(interior) : 0.0;
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_MESHES_H
