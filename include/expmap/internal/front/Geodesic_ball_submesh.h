// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_GEODESIC_BALL_SUBMESH_H
#define EXPMAP_INTERNAL_FRONT_GEODESIC_BALL_SUBMESH_H

#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Vector3.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/squared_distance_3.h>

#include <array>
#include <cstddef>
#include <vector>

namespace expmap {
namespace internal {

/// The part of a mesh that holds every geodesic of length at most `radius`
/// from a source vertex, as a triangle soup with its own vertex numbering.
struct Ball_submesh {
  std::vector<Vector3> point;
  std::vector<std::array<std::size_t, 3>> face;
  std::vector<int> mesh_vertex;  ///< index in the whole mesh of each point
  std::size_t source = 0;        ///< the source's index in `point`
};

namespace ball_detail {

// Grows the selection from the faces [first, last) (already marked in
// `face_marks` and queued), adding each face that shares a vertex with a
// selected one and lies within `radius` of `center`; stops once it holds
// more than `max_faces`.
inline void grow(const Mesh_arrays& m, const Vector3& center, double radius,
                 Vertex_marks& face_marks, Vertex_marks& vertex_marks,
                 std::vector<int>& face_queue, Ball_submesh& out, std::size_t max_faces) {
  using K = CGAL::Simple_cartesian<double>;
  auto point = [&](int v) { return K::Point_3(m.point[v][0], m.point[v][1], m.point[v][2]); };
  const K::Point_3 s(center[0], center[1], center[2]);
  const double squared_radius = radius * radius;
  auto local = [&](int v) {
    if (!vertex_marks.is_marked(v)) {
      vertex_marks.mark(v, static_cast<int>(out.point.size()));
      out.point.push_back(m.point[v]);
      out.mesh_vertex.push_back(v);
    }
    return static_cast<std::size_t>(vertex_marks.value(v));
  };
  for (std::size_t head = 0; head < face_queue.size() && out.face.size() <= max_faces; ++head) {
    const auto& f = m.face[face_queue[head]];
    out.face.push_back({{local(f[0]), local(f[1]), local(f[2])}});
    for (int v : f)
      for (int p = m.vertex_face_start[v]; p < m.vertex_face_start[v + 1]; ++p) {
        const int g = m.vertex_face[p];
        if (face_marks.is_marked(g)) continue;
        face_marks.mark(g, 0);
        const auto& c = m.face[g];
        const K::Triangle_3 triangle(point(c[0]), point(c[1]), point(c[2]));
        if (CGAL::squared_distance(s, triangle) <= squared_radius) face_queue.push_back(g);
      }
  }
}

inline void clear(Vertex_marks& face_marks, Vertex_marks& vertex_marks,
                  std::vector<int>& face_queue, Ball_submesh& out) {
  out.point.clear();
  out.face.clear();
  out.mesh_vertex.clear();
  face_marks.next_query();
  vertex_marks.next_query();
  face_queue.clear();
}

}  // namespace ball_detail

/// Collects the faces within Euclidean distance `radius` of the source
/// that are connected to its star (through shared vertices).
///
/// Why this holds every geodesic of length <= radius: every point of such a
/// geodesic is within geodesic, hence Euclidean, distance `radius` of the
/// source, so the faces it crosses are all selected and connected to the
/// source; and a path inside the selection is a path in the mesh. So
/// distances computed on the submesh equal the mesh's wherever they are at
/// most `radius`, and are larger elsewhere. Every vertex within the ball
/// keeps its whole star. Touches only the selected faces and their
/// neighbours; `face_marks` and `vertex_marks` are sized for the mesh's
/// faces and vertices and reused across queries. With `max_faces` it stops
/// once it holds more faces than that (to count them up to a limit).
inline void extract_ball_submesh(const Mesh_arrays& m, int source, double radius,
                                 Vertex_marks& face_marks, Vertex_marks& vertex_marks,
                                 std::vector<int>& face_queue, Ball_submesh& out,
                                 std::size_t max_faces = static_cast<std::size_t>(-1)) {
  ball_detail::clear(face_marks, vertex_marks, face_queue, out);
  vertex_marks.mark(source, 0);
  out.point.push_back(m.point[source]);
  out.mesh_vertex.push_back(source);
  out.source = 0;
  for (int p = m.vertex_face_start[source]; p < m.vertex_face_start[source + 1]; ++p) {
    face_marks.mark(m.vertex_face[p], 0);
    face_queue.push_back(m.vertex_face[p]);
  }
  ball_detail::grow(m, m.point[source], radius, face_marks, vertex_marks, face_queue, out,
                    max_faces);
}

/// The same for a source at the point `center` of the face `face` (stored
/// index): the faces within `radius` of the point connected to that face,
/// which is `out.face[0]`; `out.source` is its first corner. The argument
/// above holds as it is.
inline void extract_ball_submesh_around_point(const Mesh_arrays& m, int face, const Vector3& center,
                                              double radius, Vertex_marks& face_marks,
                                              Vertex_marks& vertex_marks,
                                              std::vector<int>& face_queue, Ball_submesh& out,
                                              std::size_t max_faces = static_cast<std::size_t>(-1)) {
  ball_detail::clear(face_marks, vertex_marks, face_queue, out);
  face_marks.mark(face, 0);
  face_queue.push_back(face);
  ball_detail::grow(m, center, radius, face_marks, vertex_marks, face_queue, out, max_faces);
  out.source = 0;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_GEODESIC_BALL_SUBMESH_H
