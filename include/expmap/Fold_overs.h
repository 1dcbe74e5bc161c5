// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_FOLD_OVERS_H
#define EXPMAP_FOLD_OVERS_H

/// \file Fold_overs.h
/// The triangles of a patch and which of them a local map turns over.
///
/// A local map is injective near its source; far out (past the injectivity
/// radius, or where a method's angles are noisy) triangles can fold over in
/// the (u, v) plane. Counting them is the simplest measure of whether a map
/// can be used as a parameterization, and the writers and the evaluation
/// share this one definition.

#include <expmap/Local_map.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// A face of the mesh whose three vertices all belong to a local map.
template <class FaceDescriptor>
struct Patch_triangle {
  FaceDescriptor face;  ///< the face in the mesh
  /// Positions of the corners in the local map (indices into
  /// `Local_map::vertices`), in the face's halfedge order.
  std::array<std::size_t, 3> corner;
};

/// \ingroup PkgExpmapRef
/// The faces of `tm` whose three vertices are in `map`, ordered by their
/// corner nearest to the source (so the list is deterministic).
///
/// Faces that are not triangles are skipped. The cost is proportional to
/// the patch (plus one pass over the vertices for meshes without an
/// internal vertex index, as for `vertices(tm)` indexing everywhere else).
///
/// \tparam TriangleMesh a model of `FaceGraph`.
template <class TriangleMesh, class VertexDescriptor>
std::vector<Patch_triangle<typename boost::graph_traits<TriangleMesh>::face_descriptor>>
patch_triangles(const TriangleMesh& tm, const Local_map<VertexDescriptor>& map) {
  using Traits = boost::graph_traits<TriangleMesh>;
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(tm);
  // vertex index -> position in the map; hashed so a small patch of a large
  // mesh costs nothing per mesh vertex.
  std::unordered_map<std::size_t, std::size_t> position;
  position.reserve(map.size());
  for (std::size_t i = 0; i < map.size(); ++i)
    position.emplace(static_cast<std::size_t>(get(vertex_index, map.vertices[i])), i);

  std::vector<Patch_triangle<typename Traits::face_descriptor>> triangles;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto h = halfedge(map.vertices[i], tm);
    if (h == Traits::null_halfedge()) continue;  // isolated vertex
    for (auto f : CGAL::faces_around_target(h, tm)) {
      if (f == Traits::null_face()) continue;  // border
      std::array<std::size_t, 3> corner{};
      int k = 0;
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
        const auto it = position.find(static_cast<std::size_t>(get(vertex_index, v)));
        if (k >= 3 || it == position.end()) {
          inside = false;
          break;
        }
        corner[k++] = it->second;
      }
      // Report each face once: from its corner nearest to the source.
      if (inside && k == 3 && i == std::min({corner[0], corner[1], corner[2]}))
        triangles.push_back({f, corner});
    }
  }
  return triangles;
}

namespace internal {

/// Twice the signed (u, v) area of the triangle whose corners are at these
/// positions of a map (in the face's order), `uv(i)` giving the coordinates
/// of position i, evaluated from the corner nearest the source: rounding
/// then does not depend on which corner a mesh lists first, so the methods
/// (on their copy of the mesh) and `patch_triangles()` (on the user's) agree
/// on every sign.
template <class Uv>
double signed_uv_area2(const Uv& uv, std::array<std::size_t, 3> corner) {
  std::rotate(corner.begin(), std::min_element(corner.begin(), corner.end()), corner.end());
  const std::array<double, 2> a = uv(corner[0]), b = uv(corner[1]), c = uv(corner[2]);
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

}  // namespace internal

/// \ingroup PkgExpmapRef
/// Twice the signed area of a patch triangle in the (u, v) plane: positive
/// when the map keeps the face's orientation (counter-clockwise about the
/// source normal), negative when it turns it over.
template <class VertexDescriptor, class FaceDescriptor>
double signed_uv_area2(const Local_map<VertexDescriptor>& map,
                       const Patch_triangle<FaceDescriptor>& triangle) {
  return internal::signed_uv_area2([&](std::size_t i) { return map.uv(i); }, triangle.corner);
}

/// \ingroup PkgExpmapRef
/// Whether a map turns a patch triangle over. Triangles collapsed to zero
/// area count as flipped too: they are not invertible either.
template <class VertexDescriptor, class FaceDescriptor>
bool is_flipped(const Local_map<VertexDescriptor>& map,
                const Patch_triangle<FaceDescriptor>& triangle) {
  return !(signed_uv_area2(map, triangle) > 0);
}

/// \ingroup PkgExpmapRef
/// Result of `count_flipped_triangles()`.
struct Fold_over_count {
  std::size_t flipped = 0;  ///< patch triangles the map turns over (or collapses)
  std::size_t total = 0;    ///< all patch triangles (faces with three patch vertices)
};

/// \ingroup PkgExpmapRef
/// Counts the triangles of the patch that `map` folds over: faces whose
/// three vertices are in the patch and whose signed area in the (u, v)
/// plane is not positive.
///
/// The source normal, and with it the sense of increasing angle, agrees with
/// the orientation of the faces around the source, so a faithful map keeps
/// every triangle counter-clockwise.
/// \pre `tm` is consistently oriented over the patch (on a non-orientable or
///      inconsistently oriented patch, the reversed faces count as flipped).
///
/// \code
/// const auto folds = expmap::count_flipped_triangles(mesh, map);
/// std::cout << folds.flipped << " of " << folds.total << " triangles flipped\n";
/// \endcode
template <class TriangleMesh, class VertexDescriptor>
Fold_over_count count_flipped_triangles(const TriangleMesh& tm,
                                        const Local_map<VertexDescriptor>& map) {
  Fold_over_count count;
  for (const auto& t : patch_triangles(tm, map)) {
    ++count.total;
    if (is_flipped(map, t)) ++count.flipped;
  }
  return count;
}

}  // namespace expmap

#endif  // EXPMAP_FOLD_OVERS_H
