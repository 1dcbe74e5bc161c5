// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_GEODESIC_POLAR_COORDINATES_H
#define EXPMAP_GEODESIC_POLAR_COORDINATES_H

/// \file Geodesic_polar_coordinates.h
/// Discrete geodesic polar coordinates (DGPC) of Melvaer & Reimers (2012):
/// a baseline of the package.

#include <expmap/Errors.h>
#include <expmap/Patch.h>
#include <expmap/internal/Fibonacci_vertex_queue.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Method_front.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Virtual_source.h>
#include <expmap/internal/Workspace_pool.h>

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
  static constexpr double relative_improvement = 1e-12;

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
                          const Query_options& query = {}) const;

 private:
  friend Front;  // calls compute_at_point()

  /// A point source that is no vertex (reached through `compute()` with a
  /// `Surface_point`): the front starts at the face's corners and the
  /// apexes of its neighbours, with the distances and angles of the face's
  /// unfolding (`internal::point_one_ring()`), and propagates as from a
  /// vertex. On a plane the map is exact, as from a vertex.
  Result compute_at_point(const internal::Point_source& point, const Patch& patch,
                          const Query_options& query = {}) const;

  struct Workspace {
    explicit Workspace(std::size_t n) : distance(n), angle(n) {
      queue.resize(n);
      known.resize(n);
      popped.resize(n);
      wanted.resize(n);
      map_position.resize(n);
    }
    internal::Fibonacci_vertex_queue queue;
    internal::Vertex_marks known;   // distance and angle are current
    internal::Vertex_marks popped;  // popped at least once
    internal::Vertex_marks wanted;
    internal::Vertex_marks map_position;  // assemble_local_map's scratch
    std::vector<double> distance, angle;  // native angles
    std::vector<int> popped_order;
    std::vector<internal::Polar_entry> entries;
  };

  // Where the front starts: the vertices around the source with their
  // distances and native angles.
  struct Start {
    internal::Source_one_ring ring;
    std::vector<double> distance;
  };

  struct Propagation {
    int source;
    bool closed;   // angles wrap modulo 2 pi
    double limit;  // vertices farther than this are not queued
  };

  static bool improves(int j, double distance, const Workspace& ws) {
    return !ws.known.is_marked(j) || ws.distance[j] > distance * (1 + relative_improvement);
  }

  Result propagate(const internal::Checked_query& q, int s, const Start& start, const Patch& patch,
                   const Query_options& query) const;

  // Offers vertex j a distance through the edge (i, k) of one of its faces.
  void update(int j, int i, int k, const Propagation& run, Workspace& ws) const;

  using Front::m_indexed;
  mutable internal::Workspace_pool<Workspace> m_workspaces;
};

template <class TM, class VPM>
void Geodesic_polar_coordinates<TM, VPM>::update(int j, int i, int k, const Propagation& run,
                                                 Workspace& ws) const {
  using internal::operator-;
  if (j == run.source) return;
  const auto& p = m_indexed.arrays.point;
  double distance, angle;
  if (k == run.source || !ws.known.is_marked(k)) {
    // Through the edge (source, i) the virtual source is the source itself
    // and gives j nothing it did not get from the one-ring; with k unknown
    // only the edge from i is left.
    distance = ws.distance[i] + internal::norm(p[j] - p[i]);
    angle = ws.angle[i];
  } else {
    const internal::Triangle_update t =
        internal::virtual_source_update(p[i], p[k], p[j], ws.distance[i], ws.distance[k]);
    distance = t.distance;
    if (!improves(j, distance, ws)) return;
    double phi_i = ws.angle[i], phi_k = ws.angle[k];
    if (run.closed && std::abs(phi_i - phi_k) > M_PI) (phi_i < phi_k ? phi_i : phi_k) += 2 * M_PI;
    const double alpha = t.alpha();
    angle = (1 - alpha) * phi_i + alpha * phi_k;
    if (run.closed && angle >= 2 * M_PI) angle -= 2 * M_PI;
  }
  if (!improves(j, distance, ws)) return;
  ws.known.mark(j, 0);
  ws.distance[j] = distance;
  ws.angle[j] = angle;
  if (distance <= run.limit) ws.queue.push_or_decrease(j, distance);
}

template <class TM, class VPM>
typename Geodesic_polar_coordinates<TM, VPM>::Result
Geodesic_polar_coordinates<TM, VPM>::compute_by_index(std::size_t source_index, const Patch& patch,
                                                       const Query_options& query) const {
  using internal::operator-;
  const internal::Checked_query q =
      internal::checked_query(m_indexed.arrays, source_index, patch, query);
  const int s = q.source;
  Start start;
  start.ring = internal::source_one_ring(m_indexed.arrays, s, q.frame);
  for (int v : start.ring.vertex)
    start.distance.push_back(internal::norm(m_indexed.arrays.point[v] - m_indexed.arrays.point[s]));
  return propagate(q, s, start, patch, query);
}

template <class TM, class VPM>
typename Geodesic_polar_coordinates<TM, VPM>::Result
Geodesic_polar_coordinates<TM, VPM>::compute_at_point(const internal::Point_source& point,
                                                       const Patch& patch,
                                                       const Query_options& query) const {
  const internal::Checked_query q =
      internal::checked_point_query(m_indexed.arrays, point, patch, query);
  internal::Point_ring ring = internal::point_one_ring(m_indexed.arrays, point, q.frame);
  Start start;
  start.ring = std::move(ring.ring);
  start.distance = std::move(ring.distance);
  return propagate(q, -1, start, patch, query);
}

template <class TM, class VPM>
typename Geodesic_polar_coordinates<TM, VPM>::Result
Geodesic_polar_coordinates<TM, VPM>::propagate(const internal::Checked_query& q, int s,
                                                const Start& start, const Patch& patch,
                                                const Query_options& query) const {
  const internal::Source_one_ring& ring = start.ring;
  // A vertex source is a row of the map; a point source is not, so a count
  // patch takes one more propagated vertex.
  const std::size_t source_rows = s >= 0 ? 1 : 0;
  auto ws = m_workspaces.acquire(
      [this] { return std::make_unique<Workspace>(this->number_of_vertices()); });
  ws->queue.clear();
  ws->known.next_query();
  ws->popped.next_query();
  ws->popped_order.clear();
  ws->wanted.next_query();
  for (int v : q.wanted) ws->wanted.mark(v, 0);
  std::size_t missing = q.wanted.size();

  Propagation run{s, ring.closed, std::numeric_limits<double>::infinity()};
  if (q.kind == Patch::Kind::geodesic_radius) run.limit = patch.radius();
  // Patches that the source alone fills need no propagation.
  bool done = (q.by_count && q.target <= source_rows) ||
              (q.kind == Patch::Kind::vertex_set && missing == 0);

  if (s >= 0) {
    ws->known.mark(s, 0);
    ws->distance[s] = 0;
    ws->angle[s] = 0;
  }
  for (std::size_t i = 0; i < ring.vertex.size() && !done; ++i) {
    const int v = ring.vertex[i];
    if (ws->known.is_marked(v)) continue;  // a non-manifold source lists it twice
    ws->known.mark(v, 0);
    ws->distance[v] = start.distance[i];
    ws->angle[v] = ring.angle[i];
    if (ws->distance[v] <= run.limit) ws->queue.push_or_decrease(v, ws->distance[v]);
  }

  double farthest_popped = 0;
  while (!done && !ws->queue.empty() && ws->queue.top_key() <= run.limit) {
    const auto [v, d] = ws->queue.pop();
    if (!ws->popped.is_marked(v)) {
      ws->popped.mark(v, 0);
      ws->popped_order.push_back(v);
      farthest_popped = std::max(farthest_popped, d);
      const bool complete =
          (q.by_count && ws->popped_order.size() + source_rows >= q.target) ||
          (q.kind == Patch::Kind::vertex_set && ws->wanted.is_marked(v) && --missing == 0);
      if (complete) run.limit = farthest_popped;
    }
    for (int p = m_indexed.arrays.vertex_face_start[v]; p < m_indexed.arrays.vertex_face_start[v + 1]; ++p) {
      const auto& f = m_indexed.arrays.face[m_indexed.arrays.vertex_face[p]];
      const int c = f[0] == v ? 0 : (f[1] == v ? 1 : 2);
      const int a = f[(c + 1) % 3], b = f[(c + 2) % 3];
      update(b, v, a, run, *ws);
      update(a, v, b, run, *ws);
    }
  }

  ws->entries.clear();
  for (int v : ws->popped_order) {
    if (q.kind == Patch::Kind::vertex_set && !ws->wanted.is_marked(v)) continue;
    ws->entries.push_back({v, ws->distance[v], ws->angle[v] - ring.reference_angle});
  }
  if (q.by_count && ws->entries.size() + source_rows > q.target) {
    const std::size_t keep = q.target - source_rows;
    std::nth_element(ws->entries.begin(), ws->entries.begin() + keep, ws->entries.end(),
                     [](const internal::Polar_entry& a, const internal::Polar_entry& b) {
                       return a.distance < b.distance ||
                              (a.distance == b.distance && a.vertex < b.vertex);
                     });
    ws->entries.resize(keep);
  }
  return internal::assemble_local_map(m_indexed.arrays, s >= 0 ? s : q.source, ws->entries,
                                      m_indexed.descriptors, q.frame, query, ws->map_position,
                                      s >= 0);
}

}  // namespace expmap

#endif  // EXPMAP_GEODESIC_POLAR_COORDINATES_H
