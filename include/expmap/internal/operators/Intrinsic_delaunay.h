// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_INTRINSIC_DELAUNAY_H
#define EXPMAP_INTERNAL_OPERATORS_INTRINSIC_DELAUNAY_H

#include <expmap/internal/operators/Intrinsic_triangulation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace expmap {
namespace internal {

/// Slack in the intrinsic Delaunay test: an edge is flipped only when
/// cot(alpha) + cot(beta) < -intrinsic_delaunay_tolerance.
///
/// Cotangents are scale free, so an absolute slack is meaningful. It is
/// positive so that co-circular configurations (a square split by a diagonal,
/// where the exact sum is 0 and the computed one is +-1e-16) are left alone
/// instead of being flipped back and forth by rounding noise; 1e-12 is far
/// above that noise and far below any cotangent weight that matters to the
/// Laplacian.
inline constexpr double intrinsic_delaunay_tolerance = 1e-12;

namespace intrinsic_delaunay_detail {

/// Halfedge view of an `Intrinsic_triangulation`, edited in place by flips.
///
/// Halfedge `3 * f + k` goes from `face[f][k]` to `face[f][(k + 1) % 3]` and
/// has length `length[f][k]`, so `next` and the lengths come for free from
/// the face arrays; only `m_twin` is stored (-1 on the boundary). Twins cannot
/// be re-derived from vertex pairs after flips, because flips may create
/// several edges between the same two vertices, hence the explicit array.
class Delaunay_flipper {
 public:
  explicit Delaunay_flipper(Intrinsic_triangulation& tri) : m_tri(tri) {
    check_input();
    build_twins();
    m_area.resize(m_tri.face.size());
    for (std::size_t f = 0; f < m_tri.face.size(); ++f) {
      m_area[f] = triangle_shape(m_tri.length[f]).area;
    }
  }

  std::size_t run() {
    const std::size_t halfedge_count = m_twin.size();
    m_in_queue.assign(halfedge_count, 0);
    // Only non-Delaunay edges are queued up front: a Delaunay edge can only
    // become non-Delaunay when a neighbouring flip changes one of its two
    // triangles, and such flips queue it. This skips ~all queue traffic on
    // meshes that are already (nearly) Delaunay.
    std::size_t edge_count = 0;
    for (std::size_t h = 0; h < halfedge_count; ++h) {
      const int t = m_twin[h];
      if (t < 0 || static_cast<std::size_t>(t) > h) ++edge_count;
      if (t > static_cast<int>(h) && !is_delaunay(static_cast<int>(h))) {
        push(static_cast<int>(h));
      }
    }

    const std::size_t flip_limit = compute_flip_limit(edge_count);
    std::size_t flips = 0;
    while (!m_queue.empty()) {
      const int h = m_queue.back();
      m_queue.pop_back();
      m_in_queue[h] = 0;
      // The slot may hold a different edge than when it was queued (flips
      // renumber halfedges inside the two faces they touch); examining
      // whatever edge is there now is still correct, see flip().
      if (m_twin[h] < 0 || is_delaunay(h)) continue;
      if (!flip(h)) continue;
      if (++flips > flip_limit) {
        throw std::runtime_error(
            "make_intrinsic_delaunay: exceeded the flip limit of " + std::to_string(flip_limit) +
            " flips; the edge lengths are probably inconsistent or contain NaN");
      }
    }
    return flips;
  }

  const std::vector<int>& twin() const { return m_twin; }

 private:
  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  int source(int h) const { return m_tri.face[h / 3][h % 3]; }
  int target(int h) const { return m_tri.face[h / 3][(h + 1) % 3]; }
  double length(int h) const { return m_tri.length[h / 3][h % 3]; }

  static std::string edge_name(int u, int v) {
    return "(" + std::to_string(u) + ", " + std::to_string(v) + ")";
  }

  void check_input() const {
    const auto& face = m_tri.face;
    if (m_tri.length.size() != face.size()) {
      throw std::invalid_argument("make_intrinsic_delaunay: " + std::to_string(face.size()) +
                                  " faces but " + std::to_string(m_tri.length.size()) +
                                  " length triples");
    }
    // Halfedge ids are ints (3 per face), like the vertex ids.
    if (face.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 3)) {
      throw std::invalid_argument("make_intrinsic_delaunay: too many faces");
    }
    const auto n = static_cast<std::int64_t>(m_tri.number_of_vertices);
    for (std::size_t f = 0; f < face.size(); ++f) {
      for (int k = 0; k < 3; ++k) {
        const int v = face[f][k];
        if (v < 0 || v >= n) {
          throw std::invalid_argument("make_intrinsic_delaunay: face " + std::to_string(f) +
                                      " has vertex index " + std::to_string(v) +
                                      " outside [0, " + std::to_string(n) + ")");
        }
        // NaN fails this test too. Zero is accepted: such an edge always
        // passes the Delaunay test and is never flipped, and no layout ever
        // divides by it.
        const double l = m_tri.length[f][k];
        if (!(l >= 0.0) || !std::isfinite(l)) {
          throw std::invalid_argument("make_intrinsic_delaunay: face " + std::to_string(f) +
                                      " has invalid length " + std::to_string(l) +
                                      " for edge " + edge_name(v, face[f][(k + 1) % 3]));
        }
      }
      // Twins are matched by vertex pair, which is ambiguous for loops.
      if (face[f][0] == face[f][1] || face[f][1] == face[f][2] || face[f][2] == face[f][0]) {
        throw std::invalid_argument("make_intrinsic_delaunay: face " + std::to_string(f) +
                                    " repeats a vertex");
      }
    }
  }

  /// Matches halfedges by unordered vertex pair in linear time: halfedges
  /// are bucketed by their smaller endpoint (counting sort), then each
  /// bucket is scanned with per-vertex scratch arrays stamped by the bucket
  /// owner, so nothing is sorted or hashed per edge.
  void build_twins() {
    const auto& face = m_tri.face;
    const std::size_t nv = m_tri.number_of_vertices;
    const int halfedge_count = static_cast<int>(3 * face.size());
    m_twin.assign(halfedge_count, -1);

    std::vector<int> offset(nv + 1, 0);
    for (int h = 0; h < halfedge_count; ++h) ++offset[std::min(source(h), target(h)) + 1];
    for (std::size_t v = 0; v < nv; ++v) offset[v + 1] += offset[v];
    std::vector<int> bucket(halfedge_count);
    {
      std::vector<int> fill(offset.begin(), offset.end() - 1);
      for (int h = 0; h < halfedge_count; ++h) {
        bucket[fill[std::min(source(h), target(h))]++] = h;
      }
    }

    std::vector<int> stamp(nv, -1);  // bucket owner that last touched `other`
    std::vector<int> count(nv, 0);   // halfedges (lo, other) in this bucket
    std::vector<int> first(nv, -1);  // first unmatched halfedge (lo, other)
    for (std::size_t lo = 0; lo < nv; ++lo) {
      const int begin = offset[lo], end = offset[lo + 1];
      for (int i = begin; i < end; ++i) {
        const int h = bucket[i];
        const int other = std::max(source(h), target(h));
        if (stamp[other] != static_cast<int>(lo)) {
          stamp[other] = static_cast<int>(lo);
          count[other] = 0;
          first[other] = -1;
        }
        ++count[other];
      }
      for (int i = begin; i < end; ++i) {
        const int h = bucket[i];
        const int other = std::max(source(h), target(h));
        if (count[other] > 2) {
          throw std::invalid_argument(
              "make_intrinsic_delaunay: non-manifold edge " +
              edge_name(static_cast<int>(lo), other) + " is shared by " +
              std::to_string(count[other]) + " faces");
        }
        const int g = first[other];
        if (g < 0) {
          first[other] = h;
          continue;
        }
        if (source(g) == source(h)) {
          throw std::invalid_argument(
              "make_intrinsic_delaunay: faces " + std::to_string(g / 3) + " and " +
              std::to_string(h / 3) + " both contain the directed edge " +
              edge_name(source(h), target(h)) + " (inconsistent orientation)");
        }
        m_twin[g] = h;
        m_twin[h] = g;
      }
    }
  }

  /// Bound on the number of flips before giving up. Lawson's argument bounds
  /// planar flips by V(V-1)/2 and a handful per edge is typical in practice;
  /// intrinsic flips are only known to terminate (Bobenko & Springborn 2007),
  /// so this only catches cycling caused by broken input, capped so a failure
  /// costs seconds, not hours.
  std::size_t compute_flip_limit(std::size_t edge_count) const {
    const double v = static_cast<double>(m_tri.number_of_vertices);
    const double lawson = std::min(0.5 * v * (v - 1.0), 1e8);
    return std::max<std::size_t>(100 * edge_count + 1000, static_cast<std::size_t>(lawson));
  }

  /// True when cot(alpha) + cot(beta) >= -tolerance for interior halfedge h.
  ///
  /// With e the edge, p, q the other sides of one triangle (area A1) and
  /// r, s of the other (area A2), cot(alpha) = (p^2 + q^2 - e^2) / (4 A1).
  /// The test is evaluated multiplied by 4 A1 A2 >= 0 so that a flat
  /// triangle (area 0, an angle of pi, cot = -inf) is correctly seen as
  /// non-Delaunay instead of dividing by zero; flipping it away is exactly
  /// what intrinsic Delaunay is for on meshes with slivers.
  bool is_delaunay(int h) const {
    const int t = m_twin[h];
    const double e = length(h);
    const double p = length(next(h)), q = length(prev(h));
    const double r = length(next(t)), s = length(prev(t));
    const double a1 = m_area[h / 3], a2 = m_area[t / 3];
    const double e2 = e * e;
    const double lhs = (p * p + q * q - e2) * a2 + (r * r + s * s - e2) * a1;
    // NaN compares false and counts as Delaunay: never loop on garbage.
    return !(lhs < -4.0 * intrinsic_delaunay_tolerance * a1 * a2);
  }

  void push(int h) {
    if (m_twin[h] < 0 || m_in_queue[h] || m_in_queue[m_twin[h]]) return;
    m_in_queue[h] = 1;
    m_queue.push_back(h);
  }

  /// Flips the edge of interior halfedge h; returns false (and changes
  /// nothing) when the flip would be degenerate.
  ///
  /// Triangles (a, b, c) through h = a->b and (b, a, d) through its twin are
  /// unfolded into the plane along ab: a = (0, 0), b = (|ab|, 0), c above,
  /// d below. The new edge is the segment cd, and the quad a, d, b, c
  /// (counter-clockwise) becomes triangles (a, d, c) and (d, b, c).
  bool flip(int h) {
    const int t = m_twin[h];
    const int f1 = h / 3, f2 = t / 3;
    const int h_bc = next(h), h_ca = prev(h);
    const int t_ad = next(t), t_db = prev(t);
    const int a = source(h), b = target(h), c = source(h_ca), d = source(t_db);
    // c == d means a or b has degree 2 inside this very pair of triangles;
    // the flip would create a loop edge (c, c) and a degree-1 vertex, which
    // the face/vertex representation (and twin matching by vertex pair)
    // cannot express. Leave such an edge alone.
    if (c == d) return false;

    const double l_ab = length(h);
    const double l_bc = length(h_bc), l_ca = length(h_ca);
    const double l_ad = length(t_ad), l_db = length(t_db);
    const double a1 = m_area[f1], a2 = m_area[f2];
    if (!(l_ab > 0.0) || !(a1 + a2 > 0.0)) return false;

    // x coordinates from the law of cosines, with differences of squares
    // factored to limit cancellation; heights from the (Kahan) areas rather
    // than sqrt(l^2 - x^2), which is inaccurate for flat triangles.
    const double inv_2ab = 0.5 / l_ab;
    const double ca_bc = (l_ca - l_bc) * (l_ca + l_bc);
    const double ad_db = (l_ad - l_db) * (l_ad + l_db);
    const double cx = (l_ab * l_ab + ca_bc) * inv_2ab;
    const double dx = (l_ab * l_ab + ad_db) * inv_2ab;
    const double cy = 2.0 * a1 / l_ab;
    const double dy = -2.0 * a2 / l_ab;
    // cx - dx computed directly so the l_ab^2 terms cancel exactly.
    const double diff_x = (ca_bc - ad_db) * inv_2ab;
    const double diff_y = cy - dy;  // = cy + |dy|, no cancellation
    const double l_cd = std::hypot(diff_x, diff_y);

    // The quad must be strictly convex at a and b, i.e. both new triangles
    // positively oriented. This always holds for a non-Delaunay edge in
    // exact arithmetic (the angles at a and b sum to less than pi each), so
    // this only rejects rounding-level near-degenerate cases.
    const double twice_adc = dx * cy - dy * cx;
    const double twice_dbc = (l_ab - dx) * diff_y + dy * diff_x;
    if (!(twice_adc > 0.0) || !(twice_dbc > 0.0)) return false;

    const std::array<double, 3> len1{{l_ad, l_cd, l_ca}};
    const std::array<double, 3> len2{{l_db, l_bc, l_cd}};
    const double new_a1 = triangle_shape(len1).area;
    const double new_a2 = triangle_shape(len2).area;
    if (!(new_a1 > 0.0) || !(new_a2 > 0.0)) return false;

    // Outer twins, read before any slot of f1 or f2 is rewritten. With
    // c != d none of them lies in f1 or f2 (e.g. the twin of b->c would be
    // c->b, which is d->b only if c == d).
    const int o_bc = m_twin[h_bc], o_ca = m_twin[h_ca];
    const int o_ad = m_twin[t_ad], o_db = m_twin[t_db];

    m_tri.face[f1] = {{a, d, c}};
    m_tri.length[f1] = len1;
    m_tri.face[f2] = {{d, b, c}};
    m_tri.length[f2] = len2;
    m_area[f1] = new_a1;
    m_area[f2] = new_a2;

    const int n_ad = 3 * f1, n_dc = 3 * f1 + 1, n_ca = 3 * f1 + 2;
    const int n_db = 3 * f2, n_bc = 3 * f2 + 1, n_cd = 3 * f2 + 2;
    link(n_ad, o_ad);
    link(n_ca, o_ca);
    link(n_db, o_db);
    link(n_bc, o_bc);
    m_twin[n_dc] = n_cd;
    m_twin[n_cd] = n_dc;

    // Only the four outer edges can have lost the Delaunay property. Slots
    // of f1, f2 still flagged from before now hold other edges of these two
    // faces; they stay queued and are re-examined, which is harmless. An
    // edge is skipped here only if a queued slot already holds it.
    push(n_ad);
    push(n_ca);
    push(n_db);
    push(n_bc);
    return true;
  }

  void link(int h, int outer) {
    m_twin[h] = outer;
    if (outer >= 0) m_twin[outer] = h;
  }

  Intrinsic_triangulation& m_tri;
  std::vector<int> m_twin;
  std::vector<double> m_area;
  std::vector<char> m_in_queue;
  std::vector<int> m_queue;  // used as a stack; the order only affects speed
};

}  // namespace intrinsic_delaunay_detail

/// Flips edges of `tri` (in place) until every interior edge is intrinsically
/// Delaunay.
///
/// An interior edge is Delaunay when cot(alpha) + cot(beta) >= -tolerance,
/// alpha and beta being the two angles opposite to it and the tolerance
/// `intrinsic_delaunay_tolerance` (so co-circular edges are not flipped).
/// Boundary edges are never flipped. This is the classical queue-based
/// flip algorithm of Fisher, Springborn, Bobenko and Schröder (2006): the
/// result keeps the vertices and the intrinsic metric (cone angles, area) of
/// the input, but its cotan Laplacian has non-negative weights, which is what
/// the heat method needs on poorly shaped meshes.
///
/// On return faces are consistently oriented as in the input, `length[f][k]`
/// is the length of the edge `face[f][k]` -> `face[f][(k + 1) % 3]`, the
/// number of faces and `number_of_vertices` are unchanged, but a face index
/// may now refer to a different triangle. The result can contain several
/// edges between the same two vertices (normal for intrinsic triangulations
/// of curved surfaces); use the overload returning `twin` when adjacency is
/// needed, since it can then no longer be recovered from vertex pairs.
///
/// Edges whose flip would be degenerate (a loop edge, or a quad that is not
/// strictly convex because of rounding) are left as they are, so on such
/// pathological input a few edges may remain non-Delaunay.
///
/// \param tri triangulation with non-negative, finite edge lengths; each
///        face has three distinct vertices in [0, number_of_vertices).
/// \return the number of flips performed.
/// \throws std::invalid_argument on malformed input, in particular an edge
///         shared by more than two faces or two faces using the same directed
///         edge (the message names both vertex indices of the edge).
/// \throws std::runtime_error if a generous flip limit is exceeded (only
///         conceivable with inconsistent lengths; guarantees termination).
inline std::size_t make_intrinsic_delaunay(Intrinsic_triangulation& tri) {
  intrinsic_delaunay_detail::Delaunay_flipper flipper(tri);
  return flipper.run();
}

/// Same as `make_intrinsic_delaunay(tri)`, and also returns the adjacency of
/// the result: `twin[3 * f + k]` is the halfedge `3 * g + j` running along
/// the same edge in the opposite direction (edge `face[f][k]` ->
/// `face[f][(k + 1) % 3]`), or -1 on the boundary.
inline std::size_t make_intrinsic_delaunay(Intrinsic_triangulation& tri, std::vector<int>& twin) {
  intrinsic_delaunay_detail::Delaunay_flipper flipper(tri);
  const std::size_t flips = flipper.run();
  twin = flipper.twin();
  return flips;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_INTRINSIC_DELAUNAY_H
