// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_INDEXED_MESH_H
#define EXPMAP_INTERNAL_INDEXED_MESH_H

#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/Mesh_arrays.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// What every method keeps of the user's mesh: the vertex index map (the
/// order of `vertices(tm)`), the descriptor of each index, and the flat,
/// validated copy the algorithms run on.
template <class TriangleMesh, class VertexPointMap>
struct Indexed_mesh {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Vertex_point_map = typename CGAL::Default::Get<
      VertexPointMap,
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type;
  using Vertex_index_map =
      decltype(CGAL::get_initialized_vertex_index_map(std::declval<const TriangleMesh&>()));
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Face_index_map =
      decltype(CGAL::get_initialized_face_index_map(std::declval<const TriangleMesh&>()));

  /// \throws Invalid_input as `make_mesh_arrays()`.
  Indexed_mesh(const TriangleMesh& tm, Vertex_point_map vpm)
      : vertex_index(CGAL::get_initialized_vertex_index_map(tm)),
        face_index(CGAL::get_initialized_face_index_map(tm)) {
    reserve_on_huge_pages(descriptors, num_vertices(tm));
    descriptors.resize(num_vertices(tm));
    for (auto v : vertices(tm)) descriptors[get(vertex_index, v)] = v;
    arrays = make_mesh_arrays(tm, vpm, vertex_index);
    // The arrays start every face at its smallest vertex; a Surface_point's
    // coordinates follow the user's halfedge, so where it starts is kept.
    reserve_on_huge_pages(face_of_index, num_faces(tm));
    face_of_index.resize(num_faces(tm), -1);
    reserve_on_huge_pages(face_rotation, num_faces(tm));
    face_rotation.resize(num_faces(tm));
    int f_position = 0;
    for (auto f : faces(tm)) {
      const std::size_t fi = static_cast<std::size_t>(get(face_index, f));
      const int first = static_cast<int>(get(vertex_index, source(halfedge(f, tm), tm)));
      const std::array<int, 3>& corners = arrays.face[static_cast<std::size_t>(f_position)];
      face_of_index[fi] = f_position++;
      face_rotation[fi] = static_cast<std::uint8_t>(
          std::find(corners.begin(), corners.end(), first) - corners.begin());
    }
  }

  std::size_t index_of(vertex_descriptor v) const {
    return static_cast<std::size_t>(get(vertex_index, v));
  }
  std::size_t number_of_vertices() const { return descriptors.size(); }

  Vertex_index_map vertex_index;
  Face_index_map face_index;
  std::vector<vertex_descriptor> descriptors;
  /// By face index: the position of the face in `arrays.face`, and where
  /// its first corner in the order of `Surface_point` (the source of
  /// `halfedge(f)`) is among its corners listed from the smallest user's
  /// index on (see `Point_source.h`).
  std::vector<int> face_of_index;
  std::vector<std::uint8_t> face_rotation;
  Mesh_arrays arrays;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_INDEXED_MESH_H
