// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_INPUT_FACES_H
#define EXPMAP_IO_INPUT_FACES_H

/// \file Input_faces.h
/// Points of faces named as the input names them: by the position of the
/// face in a file or array and barycentric coordinates in the order of its
/// corners there, converted to and from `Surface_point`s of the mesh made of
/// that input.

#include <expmap/Errors.h>
#include <expmap/Surface_point.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// The faces of an input (a file's polygons, a caller's array of
/// triangles) matched with the faces of the mesh made of it. Reading may
/// reorder a face's corners, reverse it, drop a duplicate, split a vertex
/// into copies, triangulate polygons and remove degenerate faces; a
/// triangle of the input is matched with the mesh face whose corners stand
/// for the same three input vertices, whatever their order.
///
/// \tparam TriangleMesh a `FaceListGraph` of triangles.
template <class TriangleMesh>
class Input_faces {
 public:
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  /// A point of a face of the input: its position among the input's faces
  /// and the barycentric coordinates of its corners, in the input's order.
  struct Input_point {
    std::size_t face = 0;
    std::array<double, 3> barycentric{{1, 0, 0}};
  };

  /// `input_faces` are the input's polygons, each the input indices of its
  /// vertices in order; `input_vertex[i]` is the input index of the `i`th
  /// vertex of `vertices(tm)` (e.g. `Mesh_reading_report::file_index`).
  /// The mesh must outlive this object.
  /// \throws Invalid_input if `input_vertex` has not one entry per vertex.
  Input_faces(const TriangleMesh& tm, const std::vector<std::size_t>& input_vertex,
              std::vector<std::vector<std::size_t>> input_faces)
      : m_tm(tm), m_faces(std::move(input_faces)) {
    const auto all = vertices(tm);
    const auto n = static_cast<std::size_t>(std::distance(all.begin(), all.end()));
    if (input_vertex.size() != n)
      throw Invalid_input("the input vertex list has " + std::to_string(input_vertex.size()) +
                          " entries but the mesh has " + std::to_string(n) +
                          " vertices: give one input index per vertex of the mesh");
    std::size_t i = 0;
    for (vertex_descriptor v : vertices(tm)) m_input_vertex[v] = input_vertex[i++];
    for (face_descriptor f : faces(tm)) m_mesh_face.emplace(key(corners(f)), f);
    for (std::size_t j = m_faces.size(); j-- > 0;)
      if (m_faces[j].size() == 3) m_first_row[key(input_corners(j))] = j;
  }

  /// The number of faces of the input.
  std::size_t size() const { return m_faces.size(); }

  /// The surface point at `p`.
  /// \throws Invalid_input if `p.face` is out of range, not a triangle, or
  ///         has no face in the mesh (a repair removed it). The coordinates
  ///         are checked where the point is used (see `Surface_point`).
  Surface_point<face_descriptor> surface_point(const Input_point& p) const {
    if (p.face >= m_faces.size())
      throw Invalid_input("source face " + std::to_string(p.face) +
                          " is out of range (there are " + std::to_string(m_faces.size()) +
                          " faces)");
    if (m_faces[p.face].size() != 3)
      throw Invalid_input("source face " + std::to_string(p.face) + " has " +
                          std::to_string(m_faces[p.face].size()) +
                          " corners, not 3; a polygon is split into triangles when read, so "
                          "give the point by its position instead");
    const std::array<std::size_t, 3> row = input_corners(p.face);
    const auto found = m_mesh_face.find(key(row));
    if (found == m_mesh_face.end())
      throw Invalid_input("source face " + std::to_string(p.face) +
                          " is not a face of the mesh (it was removed as degenerate)");
    Surface_point<face_descriptor> point;
    point.face = found->second;
    const std::array<std::size_t, 3> mesh_order = corners(point.face);
    for (int k = 0; k < 3; ++k)
      point.barycentric[k] =
          p.barycentric[std::find(row.begin(), row.end(), mesh_order[k]) - row.begin()];
    return point;
  }

  /// The input face (the first of duplicates) holding `p` and its
  /// coordinates there; none if the mesh face is no face of the input (a
  /// triangle of a split polygon).
  std::optional<Input_point> input_point(const Surface_point<face_descriptor>& p) const {
    const std::array<std::size_t, 3> mesh_order = corners(p.face);
    const auto found = m_first_row.find(key(mesh_order));
    if (found == m_first_row.end()) return std::nullopt;
    Input_point q;
    q.face = found->second;
    const std::array<std::size_t, 3> row = input_corners(q.face);
    for (int k = 0; k < 3; ++k)
      q.barycentric[k] = p.barycentric[std::find(mesh_order.begin(), mesh_order.end(), row[k]) -
                                       mesh_order.begin()];
    return q;
  }

 private:
  using Key = std::array<std::size_t, 3>;
  static Key key(Key corners) {
    std::sort(corners.begin(), corners.end());
    return corners;
  }
  // The input vertices of the corners of `f`, in the order of `Surface_point`.
  std::array<std::size_t, 3> corners(face_descriptor f) const {
    const auto h = halfedge(f, m_tm);
    return {{m_input_vertex.at(source(h, m_tm)), m_input_vertex.at(target(h, m_tm)),
             m_input_vertex.at(target(next(h, m_tm), m_tm))}};
  }
  std::array<std::size_t, 3> input_corners(std::size_t j) const {
    return {{m_faces[j][0], m_faces[j][1], m_faces[j][2]}};
  }

  const TriangleMesh& m_tm;
  std::vector<std::vector<std::size_t>> m_faces;
  std::map<vertex_descriptor, std::size_t> m_input_vertex;
  std::map<Key, face_descriptor> m_mesh_face;
  std::map<Key, std::size_t> m_first_row;
};

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_INPUT_FACES_H
