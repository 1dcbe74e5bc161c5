// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_GEODESIC_FRONT_H
#define EXPMAP_INTERNAL_FRONT_GEODESIC_FRONT_H

/// \file Geodesic_front.h
/// The geodesic front of discrete geodesic polar coordinates (Melvaer &
/// Reimers 2012): distances and angles carried outward from the source
/// through triangles, in order of distance. DGPC's map, and the heat
/// method's where the heat's own reading of the angles is blind
/// (internal/heat/Map_choice.h).

#include <expmap/Patch.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Query_validation.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Source_one_ring.h>
#include <expmap/internal/Tangent_frame.h>
#include <expmap/internal/front/Fibonacci_vertex_queue.h>
#include <expmap/internal/front/Virtual_source.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace expmap {
namespace internal {

/// Where a front starts: the vertices around the source, with their
/// distances and native angles (`Source_one_ring`).
struct Front_start {
  Source_one_ring ring;
  std::vector<double> distance;
};

/// The start around vertex `s`: its neighbours at their edges' lengths.
inline Front_start vertex_front_start(const Mesh_arrays& m, int s, const Tangent_frame& frame) {
  Front_start start;
  start.ring = source_one_ring(m, s, frame);
  for (int v : start.ring.vertex) start.distance.push_back(norm(m.point[v] - m.point[s]));
  return start;
}

/// The start around a point of a face that is no vertex: the face's corners
/// and the apexes of its neighbours, with the distances and angles of the
/// face's unfolding (`point_one_ring()`).
inline Front_start point_front_start(const Mesh_arrays& m, const Point_source& point,
                                     const Tangent_frame& frame) {
  Point_ring ring = point_one_ring(m, point, frame);
  Front_start start;
  start.ring = std::move(ring.ring);
  start.distance = std::move(ring.distance);
  return start;
}

/// Where the front is held to another map's coordinates: an anchored
/// vertex takes the other map's angle, blended by its weight with the
/// front's own update, and the front carries the blend on outward; its
/// reported distance is blended likewise. The front's own distances stay
/// its own, so its geometry (where it arrives from) is untouched.
struct Front_anchor {
  Vertex_marks position;        // vertex (as stored) -> its row below, if anchored
  std::vector<double> weight;   // in (0, 1]: 1 takes the other map's angle
  std::vector<double> angle;    // native, as the front's start measures them
  std::vector<double> distance;
};

/// The front's propagation over a mesh, as `Geodesic_polar_coordinates`
/// documents it (updates through triangles from a virtual source, a
/// Fibonacci heap with decrease-key, the patch kinds), with O(n) scratch
/// reused query after query (one per thread): stamps tell which entries are
/// current, so a query costs in proportion to its patch.
class Geodesic_front {
 public:
  /// A vertex takes a new distance only if it is smaller by this relative
  /// amount (the authors' epsilon): it stops endless requeueing on rounding.
  static constexpr double relative_improvement = 1e-12;

  explicit Geodesic_front(std::size_t number_of_vertices)
      : m_distance(number_of_vertices), m_angle(number_of_vertices) {
    m_queue.resize(number_of_vertices);
    m_known.resize(number_of_vertices);
    m_popped.resize(number_of_vertices);
    m_wanted.resize(number_of_vertices);
  }

  /// The polar coordinates of the patch `q` asks for (radius `radius` for
  /// a radius patch), from `start` around the vertex `s` of `m` (-1 for a
  /// point that is no vertex): one entry per patch vertex other than `s`,
  /// vertices as `m` stores them, angles in the frame of `start.ring`
  /// (native angles minus its reference angle). Appended to `entries`.
  /// With `anchor`, anchored vertices are held to its coordinates.
  void propagate(const Mesh_arrays& m, int s, const Front_start& start, const Checked_query& q,
                 double radius, std::vector<Polar_entry>& entries,
                 const Front_anchor* anchor = nullptr) {
    m_anchor = anchor;
    const Source_one_ring& ring = start.ring;
    // A vertex source is a row of the map; a point source is not, so a
    // count patch takes one more propagated vertex.
    const std::size_t source_rows = s >= 0 ? 1 : 0;
    m_queue.clear();
    m_known.next_query();
    m_popped.next_query();
    m_popped_order.clear();
    m_wanted.next_query();
    for (int v : q.wanted) m_wanted.mark(v, 0);
    std::size_t missing = q.wanted.size();

    Run run{s, ring.closed, std::numeric_limits<double>::infinity()};
    if (q.kind == Patch::Kind::geodesic_radius) run.limit = radius;
    // Patches that the source alone fills need no propagation.
    bool done = (q.by_count && q.target <= source_rows) ||
                (q.kind == Patch::Kind::vertex_set && missing == 0);

    if (s >= 0) {
      m_known.mark(s, 0);
      m_distance[s] = 0;
      m_angle[s] = 0;
    }
    for (std::size_t i = 0; i < ring.vertex.size() && !done; ++i) {
      const int v = ring.vertex[i];
      if (m_known.is_marked(v)) continue;  // a non-manifold source lists it twice
      m_known.mark(v, 0);
      m_distance[v] = start.distance[i];
      m_angle[v] = anchored_angle(v, ring.angle[i], run);
      if (m_distance[v] <= run.limit) m_queue.push_or_decrease(v, m_distance[v]);
    }

    double farthest_popped = 0;
    while (!done && !m_queue.empty() && m_queue.top_key() <= run.limit) {
      const auto [v, d] = m_queue.pop();
      if (!m_popped.is_marked(v)) {
        m_popped.mark(v, 0);
        m_popped_order.push_back(v);
        farthest_popped = std::max(farthest_popped, d);
        const bool complete =
            (q.by_count && m_popped_order.size() + source_rows >= q.target) ||
            (q.kind == Patch::Kind::vertex_set && m_wanted.is_marked(v) && --missing == 0);
        if (complete) run.limit = farthest_popped;
      }
      for (int p = m.vertex_face_start[v]; p < m.vertex_face_start[v + 1]; ++p) {
        const auto& f = m.face[m.vertex_face[p]];
        const int c = f[0] == v ? 0 : (f[1] == v ? 1 : 2);
        const int a = f[(c + 1) % 3], b = f[(c + 2) % 3];
        update(m, b, v, a, run);
        update(m, a, v, b, run);
      }
    }

    const std::size_t first = entries.size();
    for (int v : m_popped_order) {
      if (q.kind == Patch::Kind::vertex_set && !m_wanted.is_marked(v)) continue;
      entries.push_back({v, reported_distance(v), m_angle[v] - ring.reference_angle});
    }
    const std::size_t found = entries.size() - first;
    if (q.by_count && found + source_rows > q.target) {
      const std::size_t keep = q.target - source_rows;
      std::nth_element(entries.begin() + static_cast<std::ptrdiff_t>(first),
                       entries.begin() + static_cast<std::ptrdiff_t>(first + keep), entries.end(),
                       [](const Polar_entry& a, const Polar_entry& b) {
                         return a.distance < b.distance ||
                                (a.distance == b.distance && a.vertex < b.vertex);
                       });
      entries.resize(first + keep);
    }
  }

 private:
  struct Run {
    int source;
    bool closed;   // angles wrap modulo 2 pi
    double limit;  // vertices farther than this are not queued
  };

  bool improves(int j, double distance) const {
    return !m_known.is_marked(j) || m_distance[j] > distance * (1 + relative_improvement);
  }

  // Offers vertex j a distance through the edge (i, k) of one of its faces.
  void update(const Mesh_arrays& m, int j, int i, int k, const Run& run) {
    if (j == run.source) return;
    const auto& p = m.point;
    double distance, angle;
    if (k == run.source || !m_known.is_marked(k)) {
      // Through the edge (source, i) the virtual source is the source
      // itself and gives j nothing it did not get from the one-ring; with k
      // unknown only the edge from i is left.
      distance = m_distance[i] + norm(p[j] - p[i]);
      angle = m_angle[i];
    } else {
      const Triangle_update t =
          virtual_source_update(p[i], p[k], p[j], m_distance[i], m_distance[k]);
      distance = t.distance;
      if (!improves(j, distance)) return;
      double phi_i = m_angle[i], phi_k = m_angle[k];
      if (run.closed && std::abs(phi_i - phi_k) > M_PI) (phi_i < phi_k ? phi_i : phi_k) += 2 * M_PI;
      const double alpha = t.alpha();
      angle = (1 - alpha) * phi_i + alpha * phi_k;
      if (run.closed && angle >= 2 * M_PI) angle -= 2 * M_PI;
    }
    if (!improves(j, distance)) return;
    m_known.mark(j, 0);
    m_distance[j] = distance;
    m_angle[j] = anchored_angle(j, angle, run);
    if (distance <= run.limit) m_queue.push_or_decrease(j, distance);
  }

  // The front's angle `angle` of v, held to the anchor's where v is
  // anchored: turned towards it by the anchor's weight, the short way round.
  double anchored_angle(int v, double angle, const Run& run) const {
    if (!m_anchor || !m_anchor->position.is_marked(v)) return angle;
    const auto row = static_cast<std::size_t>(m_anchor->position.value(v));
    const double turn = std::remainder(m_anchor->angle[row] - angle, 2 * M_PI);
    double held = angle + m_anchor->weight[row] * turn;
    if (run.closed) {
      held = std::fmod(held, 2 * M_PI);
      if (held < 0) held += 2 * M_PI;
    }
    return held;
  }

  double reported_distance(int v) const {
    if (!m_anchor || !m_anchor->position.is_marked(v)) return m_distance[v];
    const auto row = static_cast<std::size_t>(m_anchor->position.value(v));
    const double w = m_anchor->weight[row];
    return w * m_anchor->distance[row] + (1 - w) * m_distance[v];
  }

  const Front_anchor* m_anchor = nullptr;
  Fibonacci_vertex_queue m_queue;
  Vertex_marks m_known;   // distance and angle are current
  Vertex_marks m_popped;  // popped at least once
  Vertex_marks m_wanted;
  std::vector<double> m_distance, m_angle;  // native angles
  std::vector<int> m_popped_order;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_GEODESIC_FRONT_H
