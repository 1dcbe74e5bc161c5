// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_METHOD_FRONT_H
#define EXPMAP_INTERNAL_METHOD_FRONT_H

#include <expmap/Batch.h>
#include <expmap/Errors.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/Surface_point.h>
#include <expmap/internal/Indexed_mesh.h>
#include <expmap/internal/Locality_order.h>
#include <expmap/internal/Point_source.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {

/// What the four method classes share in front of their algorithms:
/// construction (the copy of the user's mesh with its vertex index map),
/// queries by vertex descriptor, and batches. `Derived` (the method class, which derives from
/// this one) provides
///
///     Result compute_by_index(std::size_t source, const Patch&, const QueryOptions&) const;
///
/// which must be thread safe; everything here is written in terms of it.
/// `QueryOptions` is the method's per-query settings: `Query_options`, or a
/// type that extends it and converts from it. For a point of a face that is
/// no vertex (a vertex goes to `compute_by_index()`) it also provides
///
///     Result compute_at_point(const Point_source&, const Patch&, const QueryOptions&) const;
///
/// (private, with this class a friend: it takes an internal type).
template <class Derived, class TriangleMesh, class VertexPointMap,
          class QueryOptions = Query_options>
class Method_front {
 public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Vertex_point_map = typename Indexed_mesh<TriangleMesh, VertexPointMap>::Vertex_point_map;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Result = Local_map<vertex_descriptor>;
  /// The settings of one query.
  using Query = QueryOptions;

  /// Copies the mesh, with its `vertex_point` map.
  /// \throws Invalid_input for meshes that cannot be used (empty, not
  ///         triangulated, degenerate faces, non-finite coordinates).
  explicit Method_front(const TriangleMesh& tm) : Method_front(tm, get(CGAL::vertex_point, tm)) {}

  /// Copies the mesh, with the points of `vpm`.
  /// \throws Invalid_input as above.
  Method_front(const TriangleMesh& tm, Vertex_point_map vpm) : m_indexed(tm, vpm) {}

  /// Polar coordinates around `source` for the vertices of `patch`: the
  /// method's `compute_by_index()` for the index of `source`.
  /// \pre `source` is a vertex of the mesh given to the constructor.
  /// \throws Invalid_input, Computation_error as `compute_by_index()`.
  Result compute(vertex_descriptor source, const Patch& patch,
                 const Query& query = {}) const {
    return derived().compute_by_index(m_indexed.index_of(source), patch, query);
  }

  /// Polar coordinates around a point of a face for the vertices of
  /// `patch`. A point at a corner (one barycentric coordinate 1) gives that
  /// vertex's map, exactly. Otherwise the map has no row at r = 0 (no
  /// vertex is at the point), `source` is the face's corner of largest
  /// coordinate, a count or fraction patch counts only vertices, and the
  /// angles are measured in the frame at the point (doc/surface_points.md).
  /// \throws Invalid_input for a face that is not the mesh's, coordinates
  ///         that are not finite, negative or of sum 0, and as `compute()`.
  Result compute(const Surface_point<face_descriptor>& source, const Patch& patch,
                 const Query& query = {}) const {
    const internal::Point_source p = point_source(source);
    if (p.vertex >= 0)
      return derived().compute_by_index(m_indexed.arrays.to_original(p.vertex), patch, query);
    return derived().compute_at_point(p, patch, query);
  }

  /// One map per surface point, as `compute(const Surface_point&, ...)`,
  /// on `batch.threads` threads; a failed query is that point's error
  /// (named by its position in `sources`).
  Batch_result<vertex_descriptor> compute_many(
      const std::vector<Surface_point<face_descriptor>>& sources, const Patch& patch,
      const Batch_options& batch = {}, const Query& query = {}) const {
    std::vector<std::size_t> positions(sources.size());
    std::vector<Vector3> points(sources.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      positions[i] = i;
      try {
        points[i] = point_source(sources[i]).position;
      } catch (const Invalid_input&) {
        // Its query fails with this error; where it runs does not matter.
      }
    }
    return run_batch<vertex_descriptor>(
        positions, batch, [&](std::size_t i) { return compute(sources[i], patch, query); },
        "source point", hilbert_order(points));
  }

  /// One map per source, computed on `batch.threads` threads (each query as
  /// `compute()`); see `Batch_result` for the order and the failures.
  /// \pre every source is a vertex of the mesh given to the constructor.
  /// \throws only what `batch.progress` throws: a failed query is reported
  ///         in the result, at its source's position.
  ///
  /// \code
  /// auto batch = method.compute_many(sources, expmap::Patch::fraction(0.01), {/*threads*/ 2});
  /// \endcode
  Batch_result<vertex_descriptor> compute_many(const std::vector<vertex_descriptor>& sources,
                                               const Patch& patch, const Batch_options& batch = {},
                                               const Query& query = {}) const {
    std::vector<std::size_t> indices;
    indices.reserve(sources.size());
    for (vertex_descriptor v : sources) indices.push_back(m_indexed.index_of(v));
    return compute_many_by_index(indices, patch, batch, query);
  }

  /// As `compute_many()`, with the sources given by their indices in
  /// `vertices(tm)`; an index out of range is that source's error.
  Batch_result<vertex_descriptor> compute_many_by_index(const std::vector<std::size_t>& sources,
                                                        const Patch& patch,
                                                        const Batch_options& batch = {},
                                                        const Query& query = {}) const {
    return run_batch<vertex_descriptor>(
        sources, batch,
        [&](std::size_t source) { return derived().compute_by_index(source, patch, query); },
        "source vertex", hilbert_order(m_indexed.arrays, sources));
  }

  /// The number of vertices of the mesh given to the constructor.
  std::size_t number_of_vertices() const { return m_indexed.number_of_vertices(); }

  /// \cond SKIP_IN_MANUAL
  /// The method's copy of the mesh, for what the library builds on a
  /// method's queries (`polar_patch_operator()`): its faces and positions
  /// without another pass over the user's mesh.
  const Mesh_arrays& mesh_arrays() const { return m_indexed.arrays; }
  /// \endcond

 protected:
  Indexed_mesh<TriangleMesh, VertexPointMap> m_indexed;

  internal::Point_source point_source(const Surface_point<face_descriptor>& p) const {
    return resolve_point_source(m_indexed.arrays, m_indexed.face_of_index, m_indexed.face_rotation,
                                static_cast<std::size_t>(get(m_indexed.face_index, p.face)),
                                p.barycentric);
  }

 private:
  const Derived& derived() const { return static_cast<const Derived&>(*this); }
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_METHOD_FRONT_H
