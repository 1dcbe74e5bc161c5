// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_EXACT_EXPONENTIAL_MAP_H
#define EXPMAP_EXACT_EXPONENTIAL_MAP_H

/// \file Exact_exponential_map.h
/// The exponential map of exact polyhedral geodesics, through
/// `CGAL::Surface_mesh_shortest_path`: the reference of the package.

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
#include <expmap/internal/front/Geodesic_ball_submesh.h>
#include <expmap/internal/front/Point_direction.h>

#include <CGAL/Default.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// The exponential map of exact polyhedral geodesics (Mitchell, Mount &
/// Papadimitriou, as implemented by `CGAL::Surface_mesh_shortest_path`):
/// r is the length of the shortest path on the surface from the source
/// vertex, theta the angle of the path's first segment at the source,
/// projected onto the tangent plane of `internal::tangent_frame()` (the
/// frame all methods share), so results compare vertex by vertex. From a
/// point of a face (`compute()` with a `Surface_point`) the paths start at
/// the point and theta is read in the face's unfolding, as DGPC reads it
/// (see `compute_at_point()`).
///
/// Cost: a query builds the sequence tree of one source once and reads the
/// distances (and, for the patch vertices, the paths) from it. The tree is
/// built on the smallest part of the mesh that provably holds every
/// shortest path the patch needs (`internal::extract_ball_submesh()`): the
/// faces within Euclidean distance R of the source, where R is the radius,
/// or for count and set patches the Dijkstra graph distance that reaches
/// them (an upper bound of their geodesic distances; from a point, that of
/// its nearest corner plus the corner's distance from the point). So a query costs
/// about what the exact algorithm costs on that region, which grows faster
/// than linearly with it (up to about 1 GB of memory at 40,000 faces, 2.5 GB at
/// 83,000: doc/viewer.md); `region_faces()` counts its faces before a
/// query. Meant as a reference, not for interactive use.
///
/// Patches: a radius patch holds every vertex within geodesic distance R;
/// a count or fraction patch the k nearest by geodesic distance; a vertex
/// set its vertices. Boundaries are supported (the source may lie on one).
/// The computation runs on an internal `CGAL::Surface_mesh` with the
/// kernel `Exact_predicates_inexact_constructions_kernel` and double
/// coordinates, so any face graph works and all representations of a mesh
/// give the same result.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
///         (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`).
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertex descriptors to
///         points with `x()`, `y()`, `z()` convertible by `CGAL::to_double`.
///         Default: the internal `vertex_point` map.
///
/// \code
/// expmap::Exact_exponential_map<Mesh> exact(mesh);
/// auto map = exact.compute(source, expmap::Patch::geodesic_radius(0.1));
/// \endcode
/// \sa `Heat_exponential_map`, `Discrete_exponential_map`, `Geodesic_polar_coordinates`
template <class TriangleMesh, class VertexPointMap = CGAL::Default>
class Exact_exponential_map
    : public internal::Method_front<Exact_exponential_map<TriangleMesh, VertexPointMap>,
                                    TriangleMesh, VertexPointMap> {
  using Front = internal::Method_front<Exact_exponential_map, TriangleMesh, VertexPointMap>;

 public:
  using typename Front::Result;

  /// How far (as a fraction of the way to the opposite corner) a source
  /// point on an edge is moved into its face; see `compute_at_point()`.
  static constexpr double edge_shift = 1e-11;

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

  /// The number of faces of the submesh a query from `source` with `patch`
  /// builds its sequence tree on (see the class's cost), found without
  /// building the tree: the query's memory and time grow with it, faster
  /// than linearly (doc/viewer.md measures them). Counts up to `at_most`
  /// and stops there, returning `at_most` + 1, so that asking about a
  /// large patch costs no more than its graph search; 0 for a patch of no
  /// vertex but the source.
  /// \throws Invalid_input as `compute()`.
  std::size_t region_faces(typename Front::vertex_descriptor source, const Patch& patch,
                           std::size_t at_most = static_cast<std::size_t>(-1)) const {
    const internal::Checked_query q =
        internal::checked_query(m_indexed.arrays, m_indexed.index_of(source), patch, {});
    auto ws = workspace();
    return vertex_submesh(q, patch, *ws, at_most) ? ws->ball.face.size() : 0;
  }

  /// As above, from a point of a face (`compute(const Surface_point&, ...)`).
  std::size_t region_faces(const Surface_point<typename Front::face_descriptor>& source,
                           const Patch& patch,
                           std::size_t at_most = static_cast<std::size_t>(-1)) const {
    const internal::Point_source p = this->point_source(source);
    if (p.vertex >= 0)
      return region_faces(m_indexed.descriptors[m_indexed.arrays.to_original(p.vertex)], patch,
                          at_most);
    const internal::Checked_query q = internal::checked_point_query(m_indexed.arrays, p, patch, {});
    auto ws = workspace();
    return point_submesh(p, q, patch, *ws, at_most) ? ws->ball.face.size() : 0;
  }

 private:
  friend Front;  // calls compute_at_point()

  /// A point source that is no vertex (reached through `compute()` with a
  /// `Surface_point`): the sequence tree grows from the face location
  /// itself (`add_source_point(face, barycentric)`), so distances are the
  /// exact polyhedral ones from the point. theta is the first segment's
  /// direction, read in the face's unfolding (`internal::point_native_angle()`)
  /// and converted to the point's frame as DGPC's angles are: minus the
  /// native angle of the frame's e1 (`internal::point_one_ring()`). On a
  /// plane both are exact.
  Result compute_at_point(const internal::Point_source& point, const Patch& patch,
                          const Query_options& query = {}) const;

  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Submesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Shortest_paths =
      CGAL::Surface_mesh_shortest_path<CGAL::Surface_mesh_shortest_path_traits<Kernel, Submesh>>;

  struct Workspace {
    Workspace(std::size_t vertices, std::size_t faces) : tentative(vertices) {
      face_marks.resize(faces);
      vertex_marks.resize(vertices);
      in_region.resize(vertices);
      seen.resize(vertices);
      wanted.resize(vertices);
      map_position.resize(vertices);
    }
    internal::Vertex_marks face_marks, vertex_marks, in_region, seen, wanted;
    internal::Vertex_marks map_position;  // assemble_local_map's scratch
    std::vector<double> tentative;
    std::vector<int> region, face_queue;
    internal::Ball_submesh ball;
    std::vector<internal::Polar_entry> entries;
    std::vector<Kernel::Point_3> path;
  };

  // Direction of the first segment at the source `ps` of a path listed from
  // its far end to the source, of length `r`; path points within `near`
  // of `ps` (at least 1e-9 r) are taken for the source itself.
  static internal::Vector3 first_direction(const std::vector<Kernel::Point_3>& path,
                                           const internal::Vector3& ps, double r,
                                           double near = 0);

  // The patch's distances and first directions from the sequence tree,
  // built on `submesh` (the soup of `ws.ball`); `s` is the source vertex,
  // -1 for a point source (whose count patches count vertices only).
  // `angle_of(d)` is theta of a first direction d; `near` as in
  // `first_direction()`.
  template <class AngleOf>
  Result read_map(const internal::Checked_query& q, int s, Shortest_paths& shortest_paths,
                  const Patch& patch, const Query_options& query, Workspace& ws,
                  const internal::Vector3& source_point, double near, AngleOf angle_of) const;

  // The ball's soup as a CGAL mesh.
  static void to_submesh(const internal::Ball_submesh& ball, Submesh& submesh);

  // Radius of the Euclidean ball that holds the geodesics the patch needs.
  double ball_radius(int s, const Patch& patch, std::size_t target, const std::vector<int>& wanted,
                     Workspace& ws) const;

  // The submesh of a query from the vertex `q.source` (or the point
  // `point`) in `ws.ball`, stopped past `max_faces` faces; false, and none,
  // for a patch of no vertex but the source. Marks the wanted vertices of a
  // vertex-set patch in `ws.wanted` and clears `ws.entries`.
  bool vertex_submesh(const internal::Checked_query& q, const Patch& patch, Workspace& ws,
                      std::size_t max_faces) const;
  bool point_submesh(const internal::Point_source& point, const internal::Checked_query& q,
                     const Patch& patch, Workspace& ws, std::size_t max_faces) const;

  auto workspace() const {
    return m_workspaces.acquire([this] {
      return std::make_unique<Workspace>(this->number_of_vertices(), m_indexed.arrays.face.size());
    });
  }

  using Front::m_indexed;
  mutable internal::Workspace_pool<Workspace> m_workspaces;
};

template <class TM, class VPM>
internal::Vector3 Exact_exponential_map<TM, VPM>::first_direction(
    const std::vector<Kernel::Point_3>& path, const internal::Vector3& ps, double r, double near) {
  using internal::operator-;
  const double tolerance = 1e-9 * r;
  const double skip = std::max(tolerance, near);
  auto at = [&](std::size_t i) {
    const auto& p = path[i];
    return internal::Vector3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) length += internal::norm(at(i + 1) - at(i));
  if (std::abs(length - r) <= tolerance) {
    for (std::size_t i = path.size(); i-- > 0;) {
      const internal::Vector3 d = at(i) - ps;
      if (internal::norm(d) > skip) return d;
    }
    return {{0, 0, 0}};
  }
  // With a floating-point kernel, CGAL can report a corrupted path (points
  // off the geodesic, out of order) when a geodesic runs exactly along mesh
  // edges, as on regular grids; distances stay right. Then the farthest
  // point from the source up to which the path is still consistent with its
  // length is aimed at: the rest of the path must be at least as long as the
  // straight line to the source. On planar meshes this direction is exact.
  internal::Vector3 aim = at(0) - ps;
  double travelled = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    travelled += internal::norm(at(i) - at(i - 1));
    const internal::Vector3 d = at(i) - ps;
    if (r - travelled < internal::norm(d) - tolerance) break;
    if (internal::norm(d) > skip) aim = d;
  }
  return aim;
}

template <class TM, class VPM>
double Exact_exponential_map<TM, VPM>::ball_radius(int s, const Patch& patch, std::size_t target,
                                                   const std::vector<int>& wanted,
                                                   Workspace& ws) const {
  if (patch.kind() == Patch::Kind::geodesic_radius) return patch.radius();
  // Graph distances bound geodesic ones from above: the k vertices nearest
  // in the graph (or the wanted ones) all lie within the graph distance
  // that reaches them, and so do the k geodesically nearest.
  double reach = 0;
  std::size_t missing = wanted.size();
  internal::grow_region(m_indexed.arrays, s, ws.in_region, ws.seen, ws.tentative, ws.region,
                        [&](int v, double d, std::size_t size) {
                          if (patch.kind() == Patch::Kind::vertex_set) {
                            if (missing == 0) return false;
                            if (ws.wanted.is_marked(v)) --missing;
                          } else if (size >= target) {
                            return false;
                          }
                          reach = d;
                          return true;
                        });
  return reach;
}

template <class TM, class VPM>
void Exact_exponential_map<TM, VPM>::to_submesh(const internal::Ball_submesh& ball,
                                                Submesh& submesh) {
  // The selection may pinch at vertices outside the ball (two fans of
  // faces meeting at a vertex); the soup is split there, which no geodesic
  // of the patch passes through. Duplicated vertices are appended.
  std::vector<Kernel::Point_3> points;
  points.reserve(ball.point.size());
  for (const auto& p : ball.point) points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::array<std::size_t, 3>> faces = ball.face;
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces))
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, faces);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, submesh);
}

template <class TM, class VPM>
bool Exact_exponential_map<TM, VPM>::vertex_submesh(const internal::Checked_query& q,
                                                    const Patch& patch, Workspace& ws,
                                                    std::size_t max_faces) const {
  ws.entries.clear();
  ws.wanted.next_query();
  for (int v : q.wanted) ws.wanted.mark(v, 0);
  if ((q.by_count && q.target <= 1) || (q.kind == Patch::Kind::vertex_set && q.wanted.empty()))
    return false;
  // A hair more than the radius, so that rounding cannot drop a face that
  // a geodesic of length exactly R touches.
  const double radius = ball_radius(q.source, patch, q.target, q.wanted, ws) * (1 + 1e-9);
  internal::extract_ball_submesh(m_indexed.arrays, q.source, radius, ws.face_marks, ws.vertex_marks,
                                 ws.face_queue, ws.ball, max_faces);
  return true;
}

template <class TM, class VPM>
bool Exact_exponential_map<TM, VPM>::point_submesh(const internal::Point_source& point,
                                                   const internal::Checked_query& q,
                                                   const Patch& patch, Workspace& ws,
                                                   std::size_t max_faces) const {
  using internal::operator-;
  ws.entries.clear();
  ws.wanted.next_query();
  for (int v : q.wanted) ws.wanted.mark(v, 0);
  if ((q.by_count && q.target == 0) || (q.kind == Patch::Kind::vertex_set && q.wanted.empty()))
    return false;
  // The vertices the graph search from the nearest corner reaches are
  // within that distance plus the corner's from the point; so are the
  // patch's vertices and their geodesics.
  const double reach =
      patch.kind() == Patch::Kind::geodesic_radius
          ? patch.radius()
          : internal::norm(m_indexed.arrays.point[q.source] - point.position) +
                ball_radius(q.source, patch, q.target, q.wanted, ws);
  internal::extract_ball_submesh_around_point(m_indexed.arrays, point.face, point.position,
                                              reach * (1 + 1e-9), ws.face_marks, ws.vertex_marks,
                                              ws.face_queue, ws.ball, max_faces);
  return true;
}

template <class TM, class VPM>
typename Exact_exponential_map<TM, VPM>::Result
Exact_exponential_map<TM, VPM>::compute_by_index(std::size_t source_index, const Patch& patch,
                                                  const Query_options& query) const {
  const internal::Checked_query q =
      internal::checked_query(m_indexed.arrays, source_index, patch, query);
  const int s = q.source;
  auto ws = workspace();
  if (!vertex_submesh(q, patch, *ws, static_cast<std::size_t>(-1)))
    return internal::assemble_local_map(m_indexed.arrays, s, ws->entries, m_indexed.descriptors,
                                        q.frame, query, ws->map_position);
  Submesh submesh;
  to_submesh(ws->ball, submesh);
  Shortest_paths shortest_paths(submesh);
  shortest_paths.add_source_point(
      Submesh::Vertex_index(static_cast<Submesh::size_type>(ws->ball.source)));
  shortest_paths.build_sequence_tree();
  return read_map(q, s, shortest_paths, patch, query, *ws, m_indexed.arrays.point[s], 0.0,
                  [&q](const internal::Vector3& d) { return q.frame.angle_of(d); });
}

template <class TM, class VPM>
typename Exact_exponential_map<TM, VPM>::Result
Exact_exponential_map<TM, VPM>::compute_at_point(const internal::Point_source& point,
                                                  const Patch& patch,
                                                  const Query_options& query) const {
  using internal::operator-;
  const internal::Checked_query q =
      internal::checked_point_query(m_indexed.arrays, point, patch, query);
  const double reference_angle =
      internal::point_one_ring(m_indexed.arrays, point, q.frame).ring.reference_angle;

  auto ws = workspace();
  if (!point_submesh(point, q, patch, *ws, static_cast<std::size_t>(-1)))
    return internal::assemble_local_map(m_indexed.arrays, q.source, ws->entries,
                                        m_indexed.descriptors, q.frame, query, ws->map_position,
                                        false);
  Submesh submesh;
  to_submesh(ws->ball, submesh);

  // A point on an edge is moved into its face by a hair (edge_shift of the
  // way to the opposite corner): from a location exactly on an edge, CGAL
  // 5.5's sequence tree gives wrong distances (mean |r error| 7e-3 on the
  // 10,242-vertex unit sphere, against 3e-5 from inside a face). The move
  // changes distances by at most edge_shift times the face's size; path points
  // within `near` of the point (the crossing of the edge, if the path
  // leaves across it) are taken for the point itself.
  std::array<double, 3> weight = point.weight;
  double shortest_edge = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const auto& c = point.corner;
    shortest_edge = std::min(shortest_edge, internal::norm(m_indexed.arrays.point[c[(k + 1) % 3]] -
                                                           m_indexed.arrays.point[c[k]]));
  }
  // The point is no corner: one coordinate at most is 0, or below the
  // shift (as near the edge as that, the location is on it for CGAL too).
  const auto smallest = std::min_element(point.weight.begin(), point.weight.end());
  if (*smallest < edge_shift) {
    const std::size_t k = static_cast<std::size_t>(smallest - point.weight.begin());
    for (double& w : weight) w *= (1 - edge_shift) / (1 - *smallest);
    weight[k] = edge_shift;
  }
  const double near = 1e-7 * shortest_edge;

  // The point's face in the submesh (the soup's first face, maybe turned
  // around by the orientation), with the coordinates in its corner order.
  const Submesh::Face_index face(0);
  Shortest_paths::Barycentric_coordinates location;
  // CGAL's order: source(h), target(h), target(next(h)) for h = halfedge(face).
  const auto h = submesh.halfedge(face);
  const Submesh::Vertex_index corners[3] = {submesh.source(h), submesh.target(h),
                                            submesh.target(submesh.next(h))};
  for (int k = 0; k < 3; ++k) {
    const auto& x = submesh.point(corners[k]);
    const internal::Vector3 at{{x.x(), x.y(), x.z()}};
    int corner = 0;
    while (corner < 3 && !(m_indexed.arrays.point[point.corner[corner]] == at)) ++corner;
    if (corner == 3)
      throw Computation_error("the face of the source point in face " +
                              std::to_string(point.user_face) +
                              " is not the first face of the exact map's submesh");
    location[k] = weight[corner];
  }
  Shortest_paths shortest_paths(submesh);
  shortest_paths.add_source_point(face, location);
  shortest_paths.build_sequence_tree();
  return read_map(q, -1, shortest_paths, patch, query, *ws, point.position, near,
                  [&](const internal::Vector3& d) {
                    return internal::point_native_angle(m_indexed.arrays, point, d) -
                           reference_angle;
                  });
}

template <class TM, class VPM>
template <class AngleOf>
typename Exact_exponential_map<TM, VPM>::Result Exact_exponential_map<TM, VPM>::read_map(
    const internal::Checked_query& q, int s, Shortest_paths& shortest_paths,
    const Patch& patch, const Query_options& query, Workspace& ws,
    const internal::Vector3& source_point, double near, AngleOf angle_of) const {
  const internal::Ball_submesh& ball = ws.ball;
  const std::size_t n_local = ball.mesh_vertex.size();
  for (std::size_t i = 0; i < n_local; ++i) {
    const int v = ball.mesh_vertex[i];
    if (v == s || (q.kind == Patch::Kind::vertex_set && !ws.wanted.is_marked(v))) continue;
    const double r = CGAL::to_double(
        shortest_paths
            .shortest_distance_to_source_points(Submesh::Vertex_index(static_cast<Submesh::size_type>(i)))
            .first);
    if (r < 0) continue;  // not reached (cannot happen for the vertices a patch needs)
    if (q.kind == Patch::Kind::geodesic_radius && r > patch.radius()) continue;
    ws.entries.push_back({static_cast<int>(i), r, 0.0});  // the ball's index; the mesh's below
  }
  auto nearer = [](const internal::Polar_entry& a, const internal::Polar_entry& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.vertex < b.vertex);
  };
  // A vertex source is a row of the map; a point source is not.
  const std::size_t source_rows = s >= 0 ? 1 : 0;
  if (q.by_count && ws.entries.size() + source_rows > q.target) {
    const std::size_t keep = q.target - source_rows;
    std::nth_element(ws.entries.begin(), ws.entries.begin() + keep, ws.entries.end(), nearer);
    ws.entries.resize(keep);
  }

  for (internal::Polar_entry& e : ws.entries) {
    ws.path.clear();
    shortest_paths.shortest_path_points_to_source_points(
        Submesh::Vertex_index(static_cast<Submesh::size_type>(e.vertex)),
        std::back_inserter(ws.path));
    e.angle = angle_of(first_direction(ws.path, source_point, e.distance, near));
    e.vertex = ball.mesh_vertex[e.vertex];
  }
  return internal::assemble_local_map(m_indexed.arrays, s >= 0 ? s : q.source, ws.entries,
                                      m_indexed.descriptors, q.frame, query, ws.map_position,
                                      s >= 0);
}

}  // namespace expmap

#endif  // EXPMAP_EXACT_EXPONENTIAL_MAP_H
