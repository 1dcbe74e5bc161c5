// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_SUBDOMAIN_CACHE_H
#define EXPMAP_INTERNAL_HEAT_SUBDOMAIN_CACHE_H

// Which subdomain answers a query, and which ones are kept. A query needs
// the ball of radius D around its source s (D from its patch, see
// Subdomain.h). D is rounded up to a rung L of a ladder of radii a factor
// 2^(1/4) apart; the query is answered on the ball of radius 1.25 L around
// the center of s at reach L / 4 (`Ball_search::center_within`), which
// holds s's ball. Sources near one another share a center, so a batch
// walked in locality order, or a decal moved across the surface, factors
// each ball once; and the ball depends on s and D alone, so a map is the
// same whatever queries came before (across threads up to the round-off of
// the ball's factorization).

#include <expmap/Heat_options.h>
#include <expmap/Patch.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Vector3.h>
#include <expmap/internal/Workspace_pool.h>
#include <expmap/internal/operators/Boundary_loops.h>
#include <expmap/internal/heat/Subdomain.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <future>
#include <memory>
#include <mutex>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

/// Balls larger than this (or than a quarter of the mesh) are not built:
/// the patch is answered on the whole mesh's factors.
constexpr std::size_t max_ball_vertices = 262144;
/// The ladder's rungs per factor 2 of radius: a ball is at most 2^(1/4)
/// wider than its query needs, ...
constexpr double rungs_per_octave = 4;
/// ... and its center within this share of the rung from the source: the
/// ball's radius is (1 + center_reach) times the rung.
constexpr double center_reach = 0.25;

template <class Solver>
class Subdomain_cache {
 public:
  /// For the mesh `whole`, stored in the user's vertex order, which every
  /// call takes; `options` are `checked()` (their progress callback unused).
  Subdomain_cache(const Mesh_arrays& whole, const Heat_options& options)
      : m_options(options),
        m_long_boundary(vertices_on_long_boundary_loops(
            whole, std::sqrt(options.time_factor * whole.mean_edge_length *
                             whole.mean_edge_length))) {
    m_options.progress = nullptr;
    double area = 0;
    for (const std::array<int, 3>& f : whole.face)
      area += 0.5 * norm(cross(whole.point[f[1]] - whole.point[f[0]],
                               whole.point[f[2]] - whole.point[f[0]]));
    m_area_per_vertex = area / static_cast<double>(whole.number_of_vertices());
  }

  /// About the radius of a patch: a radius patch's, or that of the flat
  /// disk holding a count patch's vertices at the mesh's mean area per
  /// vertex. Where the mesh is coarser than its mean, the query's region
  /// reaches the ball's cut and is answered again on a wider ball.
  double patch_radius(const Patch& patch, std::size_t target) const {
    if (patch.kind() == Patch::Kind::geodesic_radius) return patch.radius();
    return std::sqrt(static_cast<double>(target) * m_area_per_vertex / M_PI);
  }

  /// The subdomain holding the ball of `scale` times the radius a patch of
  /// graph radius `patch_radius` around `s` needs; built if it is not
  /// cached, null if it is too large for a subdomain. Queries on other
  /// threads that need the same ball meanwhile wait for this build.
  std::shared_ptr<const Subdomain> holding(const Mesh_arrays& whole, int s, double patch_radius,
                                           double scale) {
    const int rung = rung_of(whole.mean_edge_length, patch_radius, scale);
    const double reach = reach_of(whole.mean_edge_length, rung);
    auto search = m_searches.acquire([&] { return make_search(whole); });
    const int center = search->center_within(whole, s, center_reach * reach);
    std::promise<std::shared_ptr<const Subdomain>> promise;
    std::shared_future<std::shared_ptr<const Subdomain>> other;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      for (Entry& e : m_cached)
        if (e.subdomain->ball.center == center && e.subdomain->rung == rung) {
          e.last_use = ++m_clock;
          return e.subdomain;
        }
      for (const Build& b : m_building)
        if (b.center == center && b.rung == rung) other = b.result;
      if (!other.valid()) m_building.push_back({center, rung, promise.get_future().share()});
    }
    if (other.valid()) return other.get();  // rethrows the builder's exception
    std::shared_ptr<const Subdomain> sub;
    try {
      Ball ball = search->ball(whole, center, (1 + center_reach) * reach, most_ball_vertices(whole));
      if (!ball.vertex.empty())
        sub = make_subdomain<Solver>(whole, std::move(ball), rung, m_long_boundary, m_options);
    } catch (...) {
      finish_build(center, rung, nullptr);
      promise.set_exception(std::current_exception());
      throw;
    }
    finish_build(center, rung, sub);
    promise.set_value(sub);
    return sub;
  }

  /// Whether a count patch of `target` vertices surely needs a larger ball
  /// than a subdomain may have (its ball holds at least
  /// (subdomain_patch_radii (1 + center_reach))^2 times the patch's
  /// vertices): the query goes to the whole mesh without a search.
  static bool surely_too_large(const Mesh_arrays& whole, std::size_t target) {
    const double least = subdomain_patch_radii * (1 + center_reach);
    return least * least * static_cast<double>(target) >
           static_cast<double>(most_ball_vertices(whole));
  }

  /// Whether a query with `patch` (`target` vertices for a count patch)
  /// may be answered on the whole mesh's factors: a vertex-set patch, or a
  /// ball of the flat disk's vertex count above the subdomains' largest.
  bool may_need_whole_mesh(const Mesh_arrays& whole, const Patch& patch,
                           std::size_t target) const {
    if (patch.kind() == Patch::Kind::vertex_set) return true;
    const double h = whole.mean_edge_length;
    const double ball =
        (1 + center_reach) * reach_of(h, rung_of(h, patch_radius(patch, target)));
    return M_PI * ball * ball / m_area_per_vertex >
           static_cast<double>(most_ball_vertices(whole));
  }

  /// Bytes the cached subdomains hold.
  std::size_t bytes() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_bytes;
  }

 private:
  struct Entry {
    std::shared_ptr<const Subdomain> subdomain;
    std::uint64_t last_use;
  };
  // A ball being built, which other queries for it wait for.
  struct Build {
    int center, rung;
    std::shared_future<std::shared_ptr<const Subdomain>> result;
  };

  // The rung of the ladder that `scale` times the radius of the ball a
  // patch of radius `patch_radius` needs rounds up to, and a rung's reach.
  int rung_of(double h, double patch_radius, double scale = 1) const {
    const double needed =
        scale * std::max(subdomain_patch_radii * patch_radius,
                         patch_radius + subdomain_heat_margin * h * std::sqrt(m_options.time_factor));
    return static_cast<int>(std::ceil(rungs_per_octave * std::log2(std::max(needed / h, 1.0))));
  }
  static double reach_of(double h, int rung) { return h * std::exp2(rung / rungs_per_octave); }
  static std::size_t most_ball_vertices(const Mesh_arrays& whole) {
    return std::min(max_ball_vertices, whole.number_of_vertices() / 4);
  }
  static std::unique_ptr<Ball_search> make_search(const Mesh_arrays& whole) {
    return std::make_unique<Ball_search>(whole.number_of_vertices());
  }
  // Keeps `sub` (unless null) in place of its build, dropping the least
  // recently used others beyond the bound (queries still running on them
  // keep them alive until they finish).
  void finish_build(int center, int rung, const std::shared_ptr<const Subdomain>& sub) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_building.erase(std::find_if(m_building.begin(), m_building.end(), [&](const Build& b) {
      return b.center == center && b.rung == rung;
    }));
    if (!sub) return;
    m_cached.push_back({sub, ++m_clock});
    m_bytes += sub->bytes;
    while (m_bytes > m_options.subdomain_cache_bytes && m_cached.size() > 1) {
      const auto oldest = std::min_element(
          m_cached.begin(), m_cached.end() - 1,
          [](const Entry& a, const Entry& b) { return a.last_use < b.last_use; });
      m_bytes -= oldest->subdomain->bytes;
      m_cached.erase(oldest);
    }
  }

  Heat_options m_options;
  double m_area_per_vertex = 0;
  std::vector<char> m_long_boundary;
  Workspace_pool<Ball_search> m_searches;
  mutable std::mutex m_mutex;
  std::vector<Entry> m_cached;
  std::vector<Build> m_building;
  std::uint64_t m_clock = 0;
  std::size_t m_bytes = 0;
};

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_SUBDOMAIN_CACHE_H
