// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_MESH_FROM_ARRAYS_H
#define EXPMAP_PYTHON_MESH_FROM_ARRAYS_H

// NumPy arrays in, `CGAL::Surface_mesh` out, and back. Everything a caller
// can get wrong about the arrays (shape, dtype, NaN, indices) is checked
// here, before CGAL sees it: in a Release build CGAL's own assertions are
// off, so a bad index would be a crash, not an exception.

#include <expmap/Errors.h>
#include <expmap/IO/read_triangle_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace expmap_python {

namespace py = pybind11;
/// The mesh type of the command-line program, for the same results.
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

using Index_array = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using Real_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// `object` as a NumPy array of `rows` x `columns` (rows = -1: any number,
// at least one) whose dtype kind is one of `kinds` ("f" real, "iu" integer).
inline py::array checked_array(py::handle object, const char* name, py::ssize_t columns,
                               const char* kinds, const char* expected) {
  py::array array = py::array::ensure(object);
  if (!array) throw expmap::Invalid_input(std::string(name) + " must be " + expected);
  const char kind = array.dtype().kind();
  if (std::string(kinds).find(kind) == std::string::npos)
    throw expmap::Invalid_input(std::string(name) + " must be " + expected + " (got dtype " +
                                py::str(array.dtype()).cast<std::string>() + ")");
  const bool shape_ok = columns < 0 ? array.ndim() == 1
                                    : array.ndim() == 2 && array.shape(1) == columns;
  if (!shape_ok) {
    std::string shape;
    for (py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d ? " x " : "") + std::to_string(array.shape(d));
    throw expmap::Invalid_input(std::string(name) + " must be " + expected + " (got shape " +
                                (shape.empty() ? "scalar" : shape) + ")");
  }
  if (array.shape(0) == 0) throw expmap::Invalid_input(std::string(name) + " is empty");
  return array;
}

/// Indices (1-D, integer dtype) as int64, each checked to be in [0, bound).
inline Index_array checked_indices(py::handle object, const char* name, std::size_t bound) {
  Index_array indices =
      Index_array::ensure(checked_array(object, name, -1, "iu", "a 1-D array of integers"));
  const std::int64_t* p = indices.data();
  for (py::ssize_t i = 0; i < indices.size(); ++i)
    if (p[i] < 0 || static_cast<std::uint64_t>(p[i]) >= bound)
      throw expmap::Invalid_input(std::string(name) + "[" + std::to_string(i) + "] = " +
                                  std::to_string(p[i]) + " is out of range (the mesh has " +
                                  std::to_string(bound) + " vertices)");
  return indices;
}

/// A mesh built from the caller's arrays, and how its vertices relate to
/// the caller's rows.
struct Arrays_mesh {
  Mesh mesh;
  /// Rows of the caller's vertex array (vertex i of `mesh` is row i for
  /// every i below `rows`; the copies made of split vertices follow).
  std::size_t rows = 0;
  /// `original[i]` is the row vertex i of `mesh` copies; empty if nothing
  /// was split (then the identity).
  std::vector<std::size_t> original;
  /// The caller's faces, rows of vertex rows (the mesh's may be reordered,
  /// reversed or fewer).
  std::vector<std::array<std::size_t, 3>> faces;
  /// What was changed to make a mesh of the arrays, one sentence each.
  std::vector<std::string> notes;
};

/// The mesh of the triangles in the rows of `faces` (integer m x 3) over the
/// points in the rows of `vertices` (float n x 3), made as a file's faces
/// are (`expmap::IO::mesh_from_polygon_soup`, shared with
/// `read_triangle_mesh`): faces oriented consistently, duplicate faces
/// dropped, and vertices at non-manifold edges and vertices split into one
/// copy per sheet, each change said in `notes`.
/// \throws expmap::Invalid_input naming the first problem found in the
/// arrays (shape, dtype, a non-finite coordinate, an index out of range, a
/// face repeating a vertex).
inline Arrays_mesh mesh_from_arrays(py::handle vertices_object, py::handle faces_object) {
  const Real_array vertices = Real_array::ensure(checked_array(
      vertices_object, "vertices", 3, "f", "a float array of shape (n, 3)"));
  const Index_array faces = Index_array::ensure(checked_array(
      faces_object, "faces", 3, "iu", "an integer array of shape (m, 3)"));
  const py::ssize_t n = vertices.shape(0), m = faces.shape(0);
  const double* x = vertices.data();
  for (py::ssize_t i = 0; i < 3 * n; ++i)
    if (!std::isfinite(x[i]))
      throw expmap::Invalid_input("vertex " + std::to_string(i / 3) +
                                  " has a coordinate that is not finite (NaN or infinity)");
  const std::int64_t* f = faces.data();
  std::vector<std::vector<std::size_t>> triangles(static_cast<std::size_t>(m));
  for (py::ssize_t j = 0; j < m; ++j) {
    const std::int64_t* t = f + 3 * j;
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= n)
        throw expmap::Invalid_input("face " + std::to_string(j) + " names vertex " +
                                    std::to_string(t[k]) + ", out of range (there are " +
                                    std::to_string(n) + " vertices)");
    // A file's such faces are dropped; in arrays built by a program it is
    // more likely a mistake the caller wants to hear about.
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw expmap::Invalid_input("face " + std::to_string(j) + " repeats a vertex (" +
                                  std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                                  std::to_string(t[2]) + ")");
    triangles[static_cast<std::size_t>(j)] = {static_cast<std::size_t>(t[0]),
                                              static_cast<std::size_t>(t[1]),
                                              static_cast<std::size_t>(t[2])};
  }
  std::vector<Mesh::Point> points;
  points.reserve(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) points.emplace_back(x[3 * i], x[3 * i + 1], x[3 * i + 2]);

  Arrays_mesh result;
  result.rows = static_cast<std::size_t>(n);
  result.faces.reserve(triangles.size());
  for (const auto& t : triangles) result.faces.push_back({{t[0], t[1], t[2]}});
  const expmap::IO::Mesh_reading_report report =
      expmap::IO::mesh_from_polygon_soup(std::move(points), std::move(triangles), result.mesh);
  result.notes = report.notes;
  if (report.file_index.size() > result.rows) result.original = report.file_index;
  return result;
}

/// (vertices float64 n x 3, faces int64 m x 3) of a triangle mesh, vertices
/// in the mesh's index order.
/// \throws expmap::Invalid_input if some face is not a triangle.
inline py::tuple arrays_from_mesh(const Mesh& mesh) {
  Real_array vertices({static_cast<py::ssize_t>(mesh.number_of_vertices()), py::ssize_t(3)});
  Index_array faces({static_cast<py::ssize_t>(mesh.number_of_faces()), py::ssize_t(3)});
  // Surface_mesh indices are dense after reading (nothing was removed), but
  // map them through a table so that stays an assumption checked, not made.
  std::vector<std::int64_t> row(mesh.num_vertices() + mesh.number_of_removed_vertices(), -1);
  double* x = vertices.mutable_data();
  std::int64_t next = 0;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    x[3 * next] = p.x(), x[3 * next + 1] = p.y(), x[3 * next + 2] = p.z();
    row[v] = next++;
  }
  std::int64_t* f = faces.mutable_data();
  std::size_t j = 0;
  for (Mesh::Face_index face : mesh.faces()) {
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(face), mesh)) {
      if (k == 3) break;
      f[3 * j + k++] = row[v];
    }
    if (k != 3 || CGAL::halfedges_around_face(mesh.halfedge(face), mesh).size() != 3)
      throw expmap::Invalid_input("face " + std::to_string(j) +
                                  " is not a triangle (read_mesh(path) splits polygons unless "
                                  "triangulate=False)");
    ++j;
  }
  return py::make_tuple(vertices, faces);
}

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_MESH_FROM_ARRAYS_H
