// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_DISCRETE_EXPONENTIAL_MAP_H
#define EXPMAP_DISCRETE_EXPONENTIAL_MAP_H

/// \file Discrete_exponential_map.h
/// The discrete exponential map (DEM) of Schmidt, Grimm & Wyvill (2006) in
/// the robust form of Schmidt (2010): a baseline of the package.

#include <expmap/Errors.h>
#include <expmap/Patch.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Method_front.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/Workspace_pool.h>
#include <expmap/internal/front/Fibonacci_dijkstra.h>
#include <expmap/internal/front/Vertex_tangent_frames.h>

#include <CGAL/Default.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Discrete exponential map: Dijkstra's algorithm on Euclidean edge lengths
/// decides the order in which vertices are frozen, and each vertex, when
/// frozen, gets its coordinates u (in the source's tangent frame) from the
/// upwind average over its already-frozen neighbours p,
///
///     u_q = sum_p w_p (u_p + R_p t_pq) / sum_p w_p,   w_p = 1 / |p - q|,
///
/// where t_pq is the edge q - p in p's tangent frame (projected onto the
/// tangent plane, keeping its length) and R_p the turn from p's frame to
/// the source's: the frame of p carried onto the source's tangent plane by
/// the minimal rotation between their normals. The source's frame is the
/// frame of `internal::tangent_frame()` shared by all methods, so its
/// neighbours get their edge vectors in that frame and angles compare
/// vertex by vertex with the other methods. On a plane every term of the
/// average is exact, so DEM is exact there.
///
/// Guard: a surface path is never shorter than the geodesic, so |u_q| is
/// clamped to the Dijkstra distance d_q; and an average of upwind vectors
/// that nearly cancel (near a cut locus) is stretched back to d_q /
/// `dilation_bound`. Dijkstra distances exceed true ones by the dilation of
/// the triangulation (below 2 for Delaunay triangulations; 1.08 on the
/// regular grid, 1.28 with half its edges flipped), so on planar meshes with
/// dilation below 2 the lower bound never bites; on curved ones it only
/// catches averages that have already failed (seen on 20% patches of the
/// armadillo, where geodesics from both sides of a limb meet). Where the
/// dilation exceeds 2 (a hexagonal grid with 47% of its edges flipped:
/// doc/mesh_quality.md) the lower bound does bite and DEM is no longer
/// exact on a plane (mean angle error 3e-4 rad there).
///
/// Patches: a radius patch holds every vertex with |u| <= R; thanks to the
/// guard no vertex with d > dilation_bound * R can qualify, so the search
/// stops there (it explores about dilation_bound^2 times the patch). A count
/// or fraction patch holds the k vertices frozen first (nearest in graph
/// distance: DEM has no better estimate before freezing), reported nearest
/// first by |u|. A vertex set is reached by freezing until every vertex of
/// the set is frozen. Boundaries need no special care: Dijkstra and the
/// average only use existing edges. Work and memory touched per query are
/// proportional to the search, never to the mesh.
///
/// From a point of a face (`compute()` with a `Surface_point`), the search
/// starts at the face's corners, which take their exact vectors from the
/// point in the face's plane; see `compute_at_point()`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
///         (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`).
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertex descriptors to
///         points with `x()`, `y()`, `z()` convertible by `CGAL::to_double`.
///         Default: the internal `vertex_point` map.
///
/// \code
/// expmap::Discrete_exponential_map<Mesh> dem(mesh);
/// auto map = dem.compute(source, expmap::Patch::fraction(0.05));
/// \endcode
/// \sa `Heat_exponential_map`, `Geodesic_polar_coordinates`, `Exact_exponential_map`
template <class TriangleMesh, class VertexPointMap = CGAL::Default>
class Discrete_exponential_map
    : public internal::Method_front<Discrete_exponential_map<TriangleMesh, VertexPointMap>,
                                    TriangleMesh, VertexPointMap> {
  using Front = internal::Method_front<Discrete_exponential_map, TriangleMesh, VertexPointMap>;

 public:
  using typename Front::Result;

  /// Bound assumed on (Dijkstra distance) / (geodesic distance); see the guard.
  static constexpr double dilation_bound = 2.0;

  /// Built from a mesh `tm` and optionally its vertex point map `vpm`:
  /// `(tm)` or `(tm, vpm)`; copies the mesh and computes a tangent frame per
  /// vertex.
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
  /// `Surface_point`). The search starts at the face's corners (and, for a
  /// point on an edge, the apex across it: the same vertices from either
  /// face of the edge), at their distances from the point; they take their
  /// vectors from the point in the face's unfolding, read in the point's
  /// frame (native angles of `internal::point_one_ring()` minus its
  /// reference angle, as DGPC's). Every other vertex gets the upwind
  /// average, its frame turn taken relative to the point's normal. On a
  /// plane the map is exact, as from a vertex.
  Result compute_at_point(const internal::Point_source& point, const Patch& patch,
                          const Query_options& query = {}) const;

  struct Workspace {
    explicit Workspace(std::size_t n) : dijkstra(n), u(n), turn(n) {
      wanted.resize(n);
      map_position.resize(n);
    }
    internal::Dijkstra_workspace dijkstra;
    std::vector<std::array<double, 2>> u;     // coordinates of frozen vertices
    std::vector<std::array<double, 2>> turn;  // their frame turn (cos, sin)
    internal::Vertex_marks wanted;
    internal::Vertex_marks map_position;  // assemble_local_map's scratch
    std::vector<internal::Polar_entry> entries;
  };

  // A vertex whose coordinates are known before the search: the source
  // vertex, or the corners around a point source.
  struct Seed {
    int vertex;
    double distance;
    std::array<double, 2> u;
  };

  // The search from the seeds; `s` is the source vertex (-1 for a point),
  // whose neighbours take their edge vectors as they are.
  Result propagate(const internal::Checked_query& q, int s, const std::vector<Seed>& seeds,
                   const Patch& patch, const Query_options& query) const;

  // Coordinates of the frozen vertex q from its frozen neighbours.
  std::array<double, 2> upwind_average(int q, double d, int source,
                                       const internal::Tangent_frame& frame,
                                       const Workspace& ws) const;

  using Front::m_indexed;
  // Computed by every constructor, after the mesh is copied.
  internal::Vertex_tangent_frames m_frames = internal::vertex_tangent_frames(m_indexed.arrays);
  mutable internal::Workspace_pool<Workspace> m_workspaces;
};

template <class TM, class VPM>
std::array<double, 2> Discrete_exponential_map<TM, VPM>::upwind_average(
    int q, double d, int source, const internal::Tangent_frame& frame, const Workspace& ws) const {
  using internal::operator-;
  const internal::Vertex_marks& frozen = ws.dijkstra.settled;
  double x = 0, y = 0, weights = 0;
  std::array<double, 2> through_parent{{0, 0}};  // the single-path DEM value
  double parent_distance = std::numeric_limits<double>::infinity();
  for (int p = m_indexed.arrays.neighbor_start[q]; p < m_indexed.arrays.neighbor_start[q + 1]; ++p) {
    const int v = m_indexed.arrays.neighbor[p];
    if (!frozen.is_marked(v)) continue;
    const internal::Vector3 edge = m_indexed.arrays.point[q] - m_indexed.arrays.point[v];
    const double length = internal::norm(edge);
    // The source's neighbours get their edge in the source's frame, as is.
    if (v == source) return internal::stretched_coordinates(edge, frame.e1, frame.e2);
    const auto t = m_frames.local_edge(v, edge);
    const auto& c = ws.turn[v];
    const std::array<double, 2> candidate{
        {ws.u[v][0] + c[0] * t[0] - c[1] * t[1], ws.u[v][1] + c[1] * t[0] + c[0] * t[1]}};
    const double w = 1.0 / length;
    x += w * candidate[0];
    y += w * candidate[1];
    weights += w;
    if (ws.dijkstra.distance[v] + length < parent_distance) {
      parent_distance = ws.dijkstra.distance[v] + length;
      through_parent = candidate;
    }
  }
  std::array<double, 2> u{{x / weights, y / weights}};
  double length = std::sqrt(u[0] * u[0] + u[1] * u[1]);
  const double lower = d / dilation_bound;
  if (length < lower && !(length > 1e-12 * d)) {
    // The average cancelled out: no direction left to stretch.
    u = through_parent;
    length = std::sqrt(u[0] * u[0] + u[1] * u[1]);
  }
  if (length > 0) {
    const double target = std::min(d, std::max(lower, length));
    if (target != length) {
      u[0] *= target / length;
      u[1] *= target / length;
    }
  }
  return u;
}

template <class TM, class VPM>
typename Discrete_exponential_map<TM, VPM>::Result
Discrete_exponential_map<TM, VPM>::compute_by_index(std::size_t source_index, const Patch& patch,
                                                     const Query_options& query) const {
  const internal::Checked_query q =
      internal::checked_query(m_indexed.arrays, source_index, patch, query);
  return propagate(q, q.source, {Seed{q.source, 0.0, {{0.0, 0.0}}}}, patch, query);
}

template <class TM, class VPM>
typename Discrete_exponential_map<TM, VPM>::Result
Discrete_exponential_map<TM, VPM>::compute_at_point(const internal::Point_source& point,
                                                     const Patch& patch,
                                                     const Query_options& query) const {
  const internal::Checked_query q =
      internal::checked_point_query(m_indexed.arrays, point, patch, query);
  const internal::Point_ring ring = internal::point_one_ring(m_indexed.arrays, point, q.frame);
  // Only the vertices every face naming the point sees: a point on an edge
  // then gets the same map from both faces. (The other apexes of the ring
  // would be exact too, but would make the start depend on the face.)
  std::vector<Seed> seeds;
  for (std::size_t i = 0; i < ring.ring.vertex.size(); ++i) {
    if (!ring.face_independent[i]) continue;
    const double theta = ring.ring.angle[i] - ring.ring.reference_angle;
    const double r = ring.distance[i];
    seeds.push_back({ring.ring.vertex[i], r, {{r * std::cos(theta), r * std::sin(theta)}}});
  }
  return propagate(q, -1, seeds, patch, query);
}

template <class TM, class VPM>
typename Discrete_exponential_map<TM, VPM>::Result
Discrete_exponential_map<TM, VPM>::propagate(const internal::Checked_query& q, int s,
                                              const std::vector<Seed>& seeds, const Patch& patch,
                                              const Query_options& query) const {
  auto ws = m_workspaces.acquire(
      [this] { return std::make_unique<Workspace>(this->number_of_vertices()); });
  ws->wanted.next_query();
  for (int v : q.wanted) ws->wanted.mark(v, 0);
  std::size_t missing = q.wanted.size();
  const double search_radius =
      q.kind == Patch::Kind::geodesic_radius ? dilation_bound * patch.radius()
                                           : std::numeric_limits<double>::infinity();

  std::vector<internal::Dijkstra_seed> starts;
  for (const Seed& seed : seeds) starts.push_back({seed.vertex, seed.distance});
  internal::fibonacci_dijkstra(
      m_indexed.arrays, starts.data(), starts.data() + starts.size(), ws->dijkstra,
      [&](int v, double d) {
        if (d > search_radius) return false;
        if ((q.kind == Patch::Kind::vertex_count || q.kind == Patch::Kind::fraction) &&
            ws->dijkstra.order.size() >= q.target)
          return false;
        if (q.kind == Patch::Kind::vertex_set && missing == 0) return false;
        const auto seed = std::find_if(seeds.begin(), seeds.end(),
                                       [v](const Seed& x) { return x.vertex == v; });
        if (v == s) {
          ws->u[v] = {{0.0, 0.0}};
          ws->turn[v] = {{1.0, 0.0}};
        } else {
          ws->turn[v] = internal::frame_rotation(m_frames.normal[v], m_frames.e1[v], q.frame);
          ws->u[v] = seed != seeds.end() ? seed->u : upwind_average(v, d, s, q.frame, *ws);
        }
        if (q.kind == Patch::Kind::vertex_set && ws->wanted.is_marked(v)) --missing;
        return true;
      });

  ws->entries.clear();
  for (int v : ws->dijkstra.order) {
    if (v == s) continue;
    if (q.kind == Patch::Kind::vertex_set && !ws->wanted.is_marked(v)) continue;
    const double r = std::hypot(ws->u[v][0], ws->u[v][1]);
    if (q.kind == Patch::Kind::geodesic_radius && r > patch.radius()) continue;
    ws->entries.push_back({v, r, std::atan2(ws->u[v][1], ws->u[v][0])});
  }
  // A point source is no vertex, so no row of the map (doc/surface_points.md).
  return internal::assemble_local_map(m_indexed.arrays, s >= 0 ? s : q.source, ws->entries,
                                      m_indexed.descriptors, q.frame, query, ws->map_position,
                                      s >= 0);
}

}  // namespace expmap

#endif  // EXPMAP_DISCRETE_EXPONENTIAL_MAP_H
