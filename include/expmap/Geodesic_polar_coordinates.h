// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_GEODESIC_POLAR_COORDINATES_H
#define EXPMAP_GEODESIC_POLAR_COORDINATES_H

/// \file Geodesic_polar_coordinates.h
/// Discrete geodesic polar coordinates (DGPC) of Melvaer & Reimers (2012):
/// a baseline of the package.

#include <expmap/Errors.h>
#include <expmap/Patch.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Method_front.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/Workspace_pool.h>
#include <expmap/internal/front/Geodesic_front.h>

#include <CGAL/Default.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Discrete geodesic polar coordinates: a Dijkstra-like propagation through
/// triangles. A vertex j of a triangle (i, k, j) whose corners i and k have
/// distances gets the distance of j from a virtual source, the point of the
/// unfolded triangle's plane at the distances of i and k, and an angle
/// interpolated between theirs (`internal::virtual_source_update()`). A
/// Fibonacci heap with decrease-key orders the vertices; a vertex that
/// improves after it was popped is queued again, as in the authors' code.
///
/// Angles: the source's neighbours get the corner angles at the source
/// summed counter-clockwise from the first neighbour (the one of smallest
/// index, so the result does not depend on the mesh's face order),
/// rescaled to sum to 2 pi as the authors do. A boundary source starts at
/// the boundary neighbour that begins its fan and keeps its plain angle sum
/// (pi on a straight boundary), and its angles never wrap across the
/// missing wedge: rescaling would spread the surface's directions over
/// directions that do not exist (see `internal::Source_one_ring`). Away
/// from the source, boundaries need no care: updates only use faces. These native angles are converted to the
/// package's convention by subtracting the native angle of the frame's
/// axis e1 (found in the one-ring wedge its projection falls in, linearly
/// interpolated), then wrapping to (-pi, pi]. On a plane the conversion is
/// exact, and so are DGPC's distances and angles.
///
/// Patches: a radius patch holds every vertex with distance at most R;
/// as in the authors' code, only vertices within R are propagated from. A
/// count or fraction patch takes the k nearest of the vertices popped until
/// k have been (then propagates on up to the largest distance popped, so
/// late improvements still land). A vertex set is propagated until all its
/// vertices are popped. Unlike the authors' code, a query never clears
/// whole-mesh arrays: stamps tell which entries are current, so a query
/// costs in proportion to its patch.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
///         (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`).
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertex descriptors to
///         points with `x()`, `y()`, `z()` convertible by `CGAL::to_double`.
///         Default: the internal `vertex_point` map.
///
/// \code
/// expmap::Geodesic_polar_coordinates<Mesh> dgpc(mesh);
/// auto map = dgpc.compute(source, expmap::Patch::geodesic_radius(0.1));
/// \endcode
/// \sa `Heat_exponential_map`, `Discrete_exponential_map`, `Exact_exponential_map`
template <class TriangleMesh, class VertexPointMap = CGAL::Default>
class Geodesic_polar_coordinates
    : public internal::Method_front<Geodesic_polar_coordinates<TriangleMesh, VertexPointMap>,
                                    TriangleMesh, VertexPointMap> {
  using Front = internal::Method_front<Geodesic_polar_coordinates, TriangleMesh, VertexPointMap>;

 public:
  using typename Front::Result;

  /// A vertex takes a new distance only if it is smaller by this relative
  /// amount (the authors' epsilon): it stops endless requeueing on rounding.
  static constexpr double relative_improvement = internal::Geodesic_front::relative_improvement;

  /// Built from a mesh `tm` and optionally its vertex point map `vpm`:
  /// `(tm)` or `(tm, vpm)`; copies the mesh.
  /// \throws Invalid_input for meshes that cannot be used (empty, not
  ///         triangulated, degenerate faces, non-finite coordinates).
  using Front::Front;

  /// Polar coordinates around the vertex of index `source` in
  /// `vertices(tm)` for the vertices of `patch`; `compute()` takes a vertex
  /// descriptor, `compute_many()` and `compute_many_by_index()` many sources.
  /// \throws Invalid_input if the index is out of range, the source is
  ///         isolated, the reference direction is parallel to its normal,
  ///         or the patch names vertices out of range or outside the
  ///         source's component.
  Result compute_by_index(std::size_t source, const Patch& patch,
                          const Query_options& query = {}) const {
    const internal::Checked_query q =
        internal::checked_query(m_indexed.arrays, source, patch, query);
    return propagate(q, q.source, internal::vertex_front_start(m_indexed.arrays, q.source, q.frame),
                     patch, query);
  }

 private:
  friend Front;  // calls compute_at_point()

  /// A point source that is no vertex (reached through `compute()` with a
  /// `Surface_point`): the front starts at the face's corners and the
  /// apexes of its neighbours, with the distances and angles of the face's
  /// unfolding (`internal::point_one_ring()`), and propagates as from a
  /// vertex. On a plane the map is exact, as from a vertex.
  Result compute_at_point(const internal::Point_source& point, const Patch& patch,
                          const Query_options& query = {}) const {
    const internal::Checked_query q =
        internal::checked_point_query(m_indexed.arrays, point, patch, query);
    return propagate(q, -1, internal::point_front_start(m_indexed.arrays, point, q.frame), patch,
                     query);
  }

  struct Workspace {
    explicit Workspace(std::size_t n) : front(n) { map_position.resize(n); }
    internal::Geodesic_front front;
    internal::Vertex_marks map_position;  // assemble_local_map's scratch
    std::vector<internal::Polar_entry> entries;
  };

  Result propagate(const internal::Checked_query& q, int s, const internal::Front_start& start,
                   const Patch& patch, const Query_options& query) const {
    auto ws = m_workspaces.acquire(
        [this] { return std::make_unique<Workspace>(this->number_of_vertices()); });
    ws->entries.clear();
    const double radius = q.kind == Patch::Kind::geodesic_radius ? patch.radius() : 0.0;
    ws->front.propagate(m_indexed.arrays, s, start, q, radius, ws->entries);
    return internal::assemble_local_map(m_indexed.arrays, s >= 0 ? s : q.source, ws->entries,
                                        m_indexed.descriptors, q.frame, query, ws->map_position,
                                        s >= 0);
  }

  using Front::m_indexed;
  mutable internal::Workspace_pool<Workspace> m_workspaces;
};

}  // namespace expmap

#endif  // EXPMAP_GEODESIC_POLAR_COORDINATES_H
