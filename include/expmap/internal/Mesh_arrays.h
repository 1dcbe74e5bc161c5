// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_MESH_ARRAYS_H
#define EXPMAP_INTERNAL_MESH_ARRAYS_H

#include <expmap/Errors.h>
#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/operators/Intrinsic_triangulation.h>
#include <expmap/internal/operators/Triangulation_adjacency.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace expmap {
namespace internal {

/// Each face of a mesh once, under its smallest corner and rotated to start
/// there (the orientation kept): the faces of a set of vertices, read
/// contiguously (`visit_patch_faces()`).
struct Owned_faces {
  std::vector<int> start;                 // vertex -> the faces it owns (CSR)
  std::vector<std::array<int, 3>> face;
};

/// The `Owned_faces` of the faces `face` of a mesh of `n` vertices.
inline Owned_faces owned_faces(std::size_t n, const std::vector<std::array<int, 3>>& face) {
  Owned_faces owned;
  std::vector<int> cursor = filled_on_huge_pages(n, 0);  // counts, then where each row goes next
  for (const auto& f : face) ++cursor[*std::min_element(f.begin(), f.end())];
  reserve_on_huge_pages(owned.start, n + 1);
  owned.start.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) owned.start[v + 1] = owned.start[v] + cursor[v];
  std::copy(owned.start.begin(), owned.start.end() - 1, cursor.begin());
  reserve_on_huge_pages(owned.face, face.size());
  owned.face.resize(face.size());
  for (auto f : face) {
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    owned.face[cursor[f[0]]++] = f;
  }
  return owned;
}

/// Flat, index-based copy of a triangle mesh: what every algorithm in the
/// package works on, built once from any CGAL FaceGraph.
///
/// Vertex i is the i-th vertex of `vertices(tm)`; face f the f-th of
/// `faces(tm)` with its corners in halfedge order (counter-clockwise for an
/// outward-oriented mesh).
struct Mesh_arrays {
  std::vector<Vector3> point;
  std::vector<std::array<int, 3>> face;
  std::vector<int> vertex_face_start, vertex_face;  // vertex -> incident faces (CSR)
  std::vector<int> neighbor_start, neighbor;        // vertex -> adjacent vertices (CSR)
  Owned_faces owned_faces;
  std::vector<double> neighbor_distance;            // length of each of those edges
  std::vector<int> component;                       // connected component of each vertex
  std::vector<int> component_size;
  double mean_edge_length = 0;
  int max_degree = 0;
  /// Empty unless the vertices were renumbered (`renumbered_mesh_arrays`):
  /// then the index in the user's mesh of each vertex, and its inverse. A
  /// part of a mesh (a subdomain) has no inverse: its `original_index` is
  /// increasing and searched.
  std::vector<int> original_index, index_of_original;

  std::size_t number_of_vertices() const { return point.size(); }
  /// The vertex an index of the user's mesh (the order of `vertices(tm)`)
  /// is stored as (-1 if a part of the mesh does not hold it), and back.
  int from_original(std::size_t v) const {
    if (!index_of_original.empty()) return index_of_original[v];
    if (original_index.empty()) return static_cast<int>(v);
    const auto it =
        std::lower_bound(original_index.begin(), original_index.end(), static_cast<int>(v));
    return it != original_index.end() && *it == static_cast<int>(v)
               ? static_cast<int>(it - original_index.begin())
               : -1;
  }
  std::size_t to_original(int v) const {
    return original_index.empty() ? static_cast<std::size_t>(v)
                                  : static_cast<std::size_t>(original_index[v]);
  }
  bool is_isolated(int v) const { return vertex_face_start[v] == vertex_face_start[v + 1]; }
  int degree(int v) const { return neighbor_start[v + 1] - neighbor_start[v]; }

  /// Edge lengths of the input mesh as an intrinsic triangulation.
  Intrinsic_triangulation intrinsic_triangulation() const {
    Intrinsic_triangulation t;
    t.number_of_vertices = point.size();
    t.face = face;
    t.length.resize(face.size());
    for (std::size_t f = 0; f < face.size(); ++f)
      for (int k = 0; k < 3; ++k)
        t.length[f][k] = norm(point[face[f][(k + 1) % 3]] - point[face[f][k]]);
    return t;
  }
};

// Compressed rows from per-row lists built by `fill(row, push)`.
template <class Fill>
void build_compressed_rows(std::size_t rows, const std::vector<int>& counts, Fill fill,
                           std::vector<int>& start, std::vector<int>& entries) {
  reserve_on_huge_pages(start, rows + 1);
  start.assign(rows + 1, 0);
  for (std::size_t r = 0; r < rows; ++r) start[r + 1] = start[r] + counts[r];
  reserve_on_huge_pages(entries, static_cast<std::size_t>(start[rows]));
  entries.assign(static_cast<std::size_t>(start[rows]), 0);
  std::vector<int> cursor;
  reserve_on_huge_pages(cursor, rows);
  cursor.assign(start.begin(), start.end() - 1);
  fill([&](int row, int value) { entries[cursor[row]++] = value; });
}

inline void compute_adjacency(Mesh_arrays& m) {
  const std::size_t n = m.point.size();
  std::vector<int> counts = filled_on_huge_pages(n, 0);
  for (const auto& f : m.face)
    for (int v : f) ++counts[v];
  build_compressed_rows(
      n, counts,
      [&](auto push) {
        for (std::size_t f = 0; f < m.face.size(); ++f)
          for (int v : m.face[f]) push(v, static_cast<int>(f));
      },
      m.vertex_face_start, m.vertex_face);

  m.owned_faces = owned_faces(n, m.face);

  // Neighbours: the other two corners of every incident face, sorted and
  // deduplicated, each with its distance. Gathered vertex by vertex, so the
  // rows are written in order; at most two per incident face.
  reserve_on_huge_pages(m.neighbor_start, n + 1);
  m.neighbor_start.assign(n + 1, 0);
  reserve_on_huge_pages(m.neighbor, 2 * m.vertex_face.size());
  reserve_on_huge_pages(m.neighbor_distance, 2 * m.vertex_face.size());
  std::vector<int> ring;
  double total = 0;
  std::size_t edges = 0;
  for (std::size_t v = 0; v < n; ++v) {
    ring.clear();
    for (int q = m.vertex_face_start[v]; q < m.vertex_face_start[v + 1]; ++q) {
      const std::array<int, 3>& f = m.face[m.vertex_face[q]];
      const int k = f[0] == static_cast<int>(v) ? 0 : f[1] == static_cast<int>(v) ? 1 : 2;
      ring.push_back(f[(k + 1) % 3]);
      ring.push_back(f[(k + 2) % 3]);
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    for (int u : ring) {
      m.neighbor.push_back(u);
      m.neighbor_distance.push_back(norm(m.point[u] - m.point[v]));
      if (u > static_cast<int>(v)) {
        total += m.neighbor_distance.back();
        ++edges;
      }
    }
    m.neighbor_start[v + 1] = static_cast<int>(m.neighbor.size());
    m.max_degree = std::max(m.max_degree, static_cast<int>(ring.size()));
  }
  m.mean_edge_length = edges > 0 ? total / static_cast<double>(edges) : 0.0;

  // Components by union-find over the faces' edges (`counts` holds the
  // links): one pass in face order, where a breadth-first search would
  // jump across the whole mesh. Numbered by their smallest vertex, as a
  // search from each unvisited vertex in turn would number them.
  std::vector<int>& link = counts;
  for (std::size_t v = 0; v < n; ++v) link[v] = static_cast<int>(v);
  auto root = [&](int v) {
    while (link[v] != v) v = link[v] = link[link[v]];
    return v;
  };
  for (const auto& f : m.face)
    for (int k = 1; k < 3; ++k) {
      const int a = root(f[0]), b = root(f[k]);
      if (a != b) link[std::max(a, b)] = std::min(a, b);
    }
  reserve_on_huge_pages(m.component, n);
  m.component.resize(n);
  m.component_size.clear();
  for (std::size_t v = 0; v < n; ++v) {
    const int r = root(static_cast<int>(v));
    if (r == static_cast<int>(v)) {
      m.component[v] = static_cast<int>(m.component_size.size());
      m.component_size.push_back(0);
    } else {
      m.component[v] = m.component[r];
    }
    ++m.component_size[m.component[v]];
  }
}

/// The same mesh with vertex i of the result being vertex `order[i]` of `m`
/// (faces keep their order and orientation). Error messages and results
/// report vertices by their index in the user's mesh (`to_original`).
inline Mesh_arrays renumbered_mesh_arrays(const Mesh_arrays& m, const std::vector<int>& order) {
  const std::size_t n = m.number_of_vertices();
  Mesh_arrays r;
  reserve_on_huge_pages(r.original_index, n);
  reserve_on_huge_pages(r.index_of_original, n);
  reserve_on_huge_pages(r.point, n);
  r.original_index.resize(n);
  r.index_of_original.resize(n);
  r.point.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int old = order[i];
    r.original_index[i] = static_cast<int>(m.to_original(old));
    r.index_of_original[r.original_index[i]] = static_cast<int>(i);
    r.point[i] = m.point[old];
  }
  std::vector<int> new_of_old = filled_on_huge_pages(n, 0);
  for (std::size_t i = 0; i < n; ++i) new_of_old[order[i]] = static_cast<int>(i);
  reserve_on_huge_pages(r.face, m.face.size());
  for (auto corners : m.face) {
    for (int& v : corners) v = new_of_old[v];
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    r.face.push_back(corners);
  }
  compute_adjacency(r);
  r.mean_edge_length = m.mean_edge_length;  // the same edges, summed in another order
  return r;
}

/// Rejects faces whose area is negligible against their longest edge: their
/// cotangents are unbounded and no Laplacian built from them is meaningful.
inline void check_face_shapes(const Mesh_arrays& m) {
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const auto& c = m.face[f];
    const Vector3 e1 = m.point[c[1]] - m.point[c[0]];
    const Vector3 e2 = m.point[c[2]] - m.point[c[0]];
    const Vector3 e3 = m.point[c[2]] - m.point[c[1]];
    const double longest2 = std::max({squared_norm(e1), squared_norm(e2), squared_norm(e3)});
    const double twice_area = norm(cross(e1, e2));
    // Finite coordinates near 1e308 still overflow here; that is not a
    // degenerate face, and removing degenerate faces would not help.
    if (!std::isfinite(longest2) || !std::isfinite(twice_area))
      throw Invalid_input("face " + std::to_string(f) + " (vertices " + std::to_string(c[0]) +
                          ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
                          ") is too large for double precision (its squared edge lengths "
                          "overflow); scale the mesh to coordinates well below 1e150");
    if (!(twice_area > 1e-10 * longest2))
      throw Invalid_input("face " + std::to_string(f) + " (vertices " + std::to_string(c[0]) +
                          ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
                          ") is degenerate (zero area); remove it first, e.g. with "
                          "CGAL::Polygon_mesh_processing::remove_degenerate_faces()");
  }
}

/// Copies and validates a CGAL FaceGraph: it must be non-empty, made of
/// triangles with three distinct vertices, and every coordinate finite.
/// \throws Invalid_input naming the first offending vertex or face.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap>
Mesh_arrays make_mesh_arrays(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim) {
  Mesh_arrays m;
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  if (n == 0 || faces(tm).first == faces(tm).second)
    throw Invalid_input("the mesh is empty (it has no vertex or no face)");
  reserve_on_huge_pages(m.point, n);
  m.point.resize(n);
  reserve_on_huge_pages(m.face, static_cast<std::size_t>(num_faces(tm)));
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    m.point[i] = Vector3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    if (!std::isfinite(m.point[i][0]) || !std::isfinite(m.point[i][1]) ||
        !std::isfinite(m.point[i][2]))
      throw Invalid_input("vertex " + std::to_string(i) +
                          " has a non-finite coordinate (NaN or infinity)");
  }
  std::size_t f_index = 0;
  for (auto f : faces(tm)) {
    std::array<int, 3> corners{{-1, -1, -1}};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if (k < 3) corners[k] = static_cast<int>(get(vim, v));
      ++k;
    }
    if (k != 3)
      throw Invalid_input("face " + std::to_string(f_index) + " has " + std::to_string(k) +
                          " vertices; the mesh must be triangulated first, e.g. with "
                          "CGAL::Polygon_mesh_processing::triangulate_faces()");
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2])
      throw Invalid_input("face " + std::to_string(f_index) + " repeats a vertex");
    // Start every face at its smallest vertex (orientation kept): data
    // structures that list a face from different corners then give the same
    // arrays, and so bit-identical results.
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    m.face.push_back(corners);
    ++f_index;
  }
  check_face_shapes(m);
  compute_adjacency(m);
  return m;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_MESH_ARRAYS_H
