// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_FACES_BY_SMALLEST_CORNER_H
#define EXPMAP_INTERNAL_OPERATORS_FACES_BY_SMALLEST_CORNER_H

#include <expmap/internal/operators/Intrinsic_triangulation.h>
#include <expmap/internal/operators/Normalized_gradient_divergence.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {

/// The faces of a triangulation grouped under their smallest corner, with
/// each face's corners and divergence stencil (step 3 of a query) stored
/// side by side.
///
/// A query that visits the faces of a set of vertices then finds every face
/// exactly once (under one vertex, without marking faces already seen), and
/// the faces of a vertex are contiguous in memory: one or two cache lines
/// per vertex instead of an incidence list, a face index and a separate
/// shape array, each in a different place.
class Faces_by_smallest_corner {
 public:
  struct Face {
    std::array<int, 3> corner;
    Divergence_stencil divergence;
  };

  Faces_by_smallest_corner() = default;

  Faces_by_smallest_corner(const Intrinsic_triangulation& tri,
                           const std::vector<Triangle_shape>& shapes) {
    const std::size_t n = tri.number_of_vertices;
    m_start.assign(n + 1, 0);
    auto owner = [&](std::size_t f) {
      return *std::min_element(tri.face[f].begin(), tri.face[f].end());
    };
    for (std::size_t f = 0; f < tri.face.size(); ++f) ++m_start[owner(f) + 1];
    for (std::size_t v = 0; v < n; ++v) m_start[v + 1] += m_start[v];
    m_face.resize(tri.face.size());
    std::vector<int> cursor(m_start.begin(), m_start.end() - 1);
    for (std::size_t f = 0; f < tri.face.size(); ++f)
      m_face[cursor[owner(f)]++] = Face{tri.face[f], Divergence_stencil(shapes[f])};
  }

  /// The faces whose smallest corner is `v`.
  const Face* begin(int v) const { return m_face.data() + m_start[v]; }
  const Face* end(int v) const { return m_face.data() + m_start[v + 1]; }

 private:
  std::vector<int> m_start;
  std::vector<Face> m_face;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_FACES_BY_SMALLEST_CORNER_H
