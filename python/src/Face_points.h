// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_FACE_POINTS_H
#define EXPMAP_PYTHON_FACE_POINTS_H

// Points of faces as Python names them, (row of the faces array,
// barycentric coordinates of that row's corners in its order), converted to
// and from the library's `Surface_point`s, and points of space located on
// the surface.

#include "Mesh_from_arrays.h"

#include <expmap/Errors.h>
#include <expmap/IO/Input_faces.h>
#include <expmap/Locate_surface_point.h>
#include <expmap/Surface_point.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace expmap_python {

using Surface_point = expmap::Surface_point<Mesh::Face_index>;

/// The faces of the caller's arrays and an AABB tree of the mesh made of
/// them. Made on a method object's first point query (they cost O(F log F)
/// time and memory that vertex queries do not need), then only read, so
/// safe to use from many threads.
class Face_points {
 public:
  using Input_point = expmap::IO::Input_faces<Mesh>::Input_point;

  /// `faces` the caller's rows of vertex rows; `original` as in
  /// `Arrays_mesh` (empty: vertex i of `mesh` is row i).
  Face_points(const Mesh& mesh, const std::vector<std::size_t>& original,
              const std::vector<std::array<std::size_t, 3>>& faces)
      : m_faces(mesh, vertex_rows(mesh, original), polygons(faces)), m_locator(mesh) {}

  /// The surface point at `barycentric` in row `face` of the faces array.
  /// \throws expmap::Invalid_input for a row out of range.
  Surface_point surface_point(std::size_t face, const std::array<double, 3>& barycentric) const {
    if (face >= m_faces.size())
      throw expmap::Invalid_input("face " + std::to_string(face) +
                                  " is out of range (the mesh has " +
                                  std::to_string(m_faces.size()) + " faces)");
    return m_faces.surface_point({face, barycentric});
  }

  /// The surface point nearest to `xyz`.
  Surface_point locate(const std::array<double, 3>& xyz) const { return m_locator.locate(xyz); }

  /// `p` as a row of the faces array (the first of duplicates) and the
  /// coordinates of its corners.
  /// \throws expmap::Computation_error if the face of `p` is none of the
  ///         rows: the mesh is built from the rows as they are, so this
  ///         would be a bug, not bad input.
  Input_point input_point(const Surface_point& p) const {
    const std::optional<Input_point> q = m_faces.input_point(p);
    if (!q)
      throw expmap::Computation_error("mesh face " + std::to_string(static_cast<std::size_t>(p.face)) +
                                      " matches no row of the faces array");
    return *q;
  }

 private:
  static std::vector<std::vector<std::size_t>> polygons(
      const std::vector<std::array<std::size_t, 3>>& faces) {
    std::vector<std::vector<std::size_t>> p;
    p.reserve(faces.size());
    for (const auto& t : faces) p.push_back({t[0], t[1], t[2]});
    return p;
  }
  static std::vector<std::size_t> vertex_rows(const Mesh& mesh,
                                              const std::vector<std::size_t>& original) {
    if (!original.empty()) return original;
    std::vector<std::size_t> rows(mesh.number_of_vertices());
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
    return rows;
  }

  expmap::IO::Input_faces<Mesh> m_faces;
  expmap::Surface_point_locator<Mesh> m_locator;
};

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_FACE_POINTS_H
