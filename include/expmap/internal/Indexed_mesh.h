// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_INDEXED_MESH_H
#define EXPMAP_INTERNAL_INDEXED_MESH_H

#include <expmap/internal/Mesh_arrays.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

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

  /// \throws Invalid_input as `make_mesh_arrays()`.
  Indexed_mesh(const TriangleMesh& tm, Vertex_point_map vpm)
      : vertex_index(CGAL::get_initialized_vertex_index_map(tm)) {
    descriptors.resize(num_vertices(tm));
    for (auto v : vertices(tm)) descriptors[get(vertex_index, v)] = v;
    arrays = make_mesh_arrays(tm, vpm, vertex_index);
  }

  std::size_t index_of(vertex_descriptor v) const {
    return static_cast<std::size_t>(get(vertex_index, v));
  }
  std::size_t number_of_vertices() const { return descriptors.size(); }

  Vertex_index_map vertex_index;
  std::vector<vertex_descriptor> descriptors;
  Mesh_arrays arrays;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_INDEXED_MESH_H
