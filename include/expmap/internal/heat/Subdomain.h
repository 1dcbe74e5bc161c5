// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_SUBDOMAIN_H
#define EXPMAP_INTERNAL_HEAT_SUBDOMAIN_H

// A geodesic ball of a large mesh with factorizations of its own
// (manual, section 2, "Subdomains"). A query's solves read the top of the
// elimination tree they run on, whatever the patch's size; on a ball a few
// patch radii wide that tree is small, so a small patch costs about its
// own size. The heat a source spreads has fallen below rounding well
// before the ball's edge (the cut), so the ball's maps are the whole
// mesh's up to the cut-off the localized solves make anyway.

#include <expmap/Heat_options.h>
#include <expmap/internal/Huge_pages.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Point_source.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Workspace_pool.h>
#include <expmap/internal/heat/Heat_factors.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

/// A query's subdomain holds every vertex within this many patch radii
/// (graph distance) of its source, ...
constexpr double subdomain_patch_radii = 2;
/// ... and at least this many sqrt(t) beyond the patch: there the heat from
/// the source is below exp(-25/4) of its value at the patch's edge, and the
/// cut's reflection of it does not reach the Poisson solve's region.
constexpr double subdomain_heat_margin = 5;

/// The vertices within a graph distance (Dijkstra over the edges) of a
/// center, in increasing order.
struct Ball {
  int center = -1;
  std::vector<int> vertex;
};

/// The reusable O(n) arrays of the Dijkstra searches that size and collect
/// balls (only the visited part is touched per search).
struct Ball_search {
  explicit Ball_search(std::size_t n) {
    reserve_on_huge_pages(tentative, n);
    tentative.resize(n);
    in_region.resize(n);
    seen.resize(n);
  }
  Vertex_marks in_region, seen;
  std::vector<double> tentative;
  std::vector<int> region;

  /// The center of the balls that answer queries from `s` at `reach`: of
  /// the vertices within graph distance `reach` of `s`, the one of least
  /// `center_priority`. Neighbouring sources mostly share it, and it
  /// depends on nothing but `s` and `reach`, so a map does not depend on
  /// which queries came before.
  int center_within(const Mesh_arrays& m, int s, double reach) {
    int center = s;
    std::uint64_t least = center_priority(s);
    grow_region(m, s, in_region, seen, tentative, region, [&](int v, double d, std::size_t) {
      if (d > reach) return false;
      const std::uint64_t priority = center_priority(v);
      if (priority < least) {
        least = priority;
        center = v;
      }
      return true;
    });
    return center;
  }

  /// The ball of graph radius `radius` around `c`; empty if it holds more
  /// than `most` vertices.
  Ball ball(const Mesh_arrays& m, int c, double radius, std::size_t most) {
    Ball b;
    b.center = c;
    bool too_large = false;
    grow_region(m, c, in_region, seen, tentative, region, [&](int, double d, std::size_t size) {
      const bool inside = d <= radius;
      too_large = inside && size >= most;
      return inside && !too_large;
    });
    if (too_large) return {};
    b.vertex = region;
    std::sort(b.vertex.begin(), b.vertex.end());
    return b;
  }

  /// A fixed pseudo-random order of the vertices (SplitMix64 of the index).
  static std::uint64_t center_priority(int v) {
    std::uint64_t z = static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
};

/// A ball's mesh, factors and query workspaces. Its vertices keep their
/// increasing order from the whole mesh, whose indices are the user's.
struct Subdomain {
  Ball ball;
  int rung = 0;                 // of the ladder of radii (Subdomain_cache.h)
  std::vector<int> whole_face;  // each face's index in the whole mesh, increasing
  Mesh_arrays mesh;             // original_index: the user's vertex indices
  std::vector<char> is_cut;     // a vertex missing some of its whole-mesh neighbours
  Heat_factors factors;
  mutable Workspace_pool<Workspace> workspaces;
  std::size_t bytes = 0;  // about what the subdomain holds, for the cache's bound

  /// The ball's index of a vertex of the whole mesh, -1 if it is outside.
  int vertex_of(int whole) const { return mesh.from_original(static_cast<std::size_t>(whole)); }
  /// The ball's index of a face of the whole mesh, -1 if it is outside.
  int face_of(int whole) const {
    const auto it = std::lower_bound(whole_face.begin(), whole_face.end(), whole);
    return it != whole_face.end() && *it == whole ? static_cast<int>(it - whole_face.begin())
                                                  : -1;
  }
  /// A point of a whole-mesh face in the ball's indices; empty if the face
  /// is outside.
  std::optional<Point_source> point_of(const Point_source& whole) const {
    Point_source p = whole;
    p.face = face_of(whole.face);
    if (p.face < 0) return std::nullopt;
    for (int& c : p.corner) c = vertex_of(c);
    if (p.vertex >= 0) p.vertex = vertex_of(p.vertex);
    return p;
  }
  /// Whether a query's region reached the cut, where the ball's heat and
  /// distance are not the whole mesh's.
  bool reaches_cut(const std::vector<int>& region) const {
    return std::any_of(region.begin(), region.end(),
                       [&](int v) { return is_cut[static_cast<std::size_t>(v)] != 0; });
  }
};

/// The subdomain of `ball` in `whole` (stored in the user's order):
/// faces with all corners in the ball, whole-mesh boundary loops as
/// `long_boundary` marks them, h the whole mesh's (so t and the settings
/// measured in h are the whole mesh's), factored with `options`.
template <class Solver>
std::unique_ptr<Subdomain> make_subdomain(const Mesh_arrays& whole, Ball ball, int rung,
                                          const std::vector<char>& long_boundary,
                                          const Heat_options& options) {
  auto sub = std::make_unique<Subdomain>();
  sub->ball = std::move(ball);
  sub->rung = rung;
  const std::vector<int>& vertex = sub->ball.vertex;
  Mesh_arrays& m = sub->mesh;
  m.original_index = vertex;
  m.point.reserve(vertex.size());
  for (int v : vertex) m.point.push_back(whole.point[static_cast<std::size_t>(v)]);
  const auto inside = [&](int v) { return m.from_original(static_cast<std::size_t>(v)) >= 0; };
  for (int v : vertex)
    for (int p = whole.vertex_face_start[v]; p < whole.vertex_face_start[v + 1]; ++p) {
      const std::array<int, 3>& f = whole.face[static_cast<std::size_t>(whole.vertex_face[p])];
      if (f[0] == v && inside(f[1]) && inside(f[2])) sub->whole_face.push_back(whole.vertex_face[p]);
    }
  std::sort(sub->whole_face.begin(), sub->whole_face.end());
  // The whole mesh's faces start at their smallest corner; the ball keeps
  // the vertices' order, so its faces do too.
  m.face.reserve(sub->whole_face.size());
  for (int f : sub->whole_face) {
    std::array<int, 3> corners = whole.face[static_cast<std::size_t>(f)];
    for (int& c : corners) c = m.from_original(static_cast<std::size_t>(c));
    m.face.push_back(corners);
  }
  compute_adjacency(m);
  m.mean_edge_length = whole.mean_edge_length;

  const std::size_t n = vertex.size();
  Subdomain_topology topology;
  topology.is_cut.assign(n, 0);
  topology.long_boundary.assign(n, 0);
  bool any_boundary = false;
  for (std::size_t i = 0; i < n; ++i) {
    const int v = vertex[i];
    topology.is_cut[i] = whole.degree(v) != m.degree(static_cast<int>(i));
    if (!long_boundary.empty() && long_boundary[static_cast<std::size_t>(v)]) {
      topology.long_boundary[i] = 1;
      any_boundary = true;
    }
  }
  if (!any_boundary) topology.long_boundary.clear();
  sub->factors = factor_heat_operators<Solver>(m, options, &topology);
  sub->is_cut = std::move(topology.is_cut);
  // The factors, the mesh's arrays (about 200 bytes a vertex) and one
  // query's workspace (about 100).
  sub->bytes = sub->factors.heat.entry_bytes() + sub->factors.poisson.entry_bytes() +
               sub->factors.boundary_heat.entry_bytes() + 300 * n;
  return sub;
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_SUBDOMAIN_H
