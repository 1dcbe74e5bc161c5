// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_POLAR_GRID_SAMPLER_H
#define EXPMAP_INTERNAL_POLAR_GRID_SAMPLER_H

// Where a polar grid's points fall in a map: the patch triangle that holds
// each, and its barycentric weights. The map's faces come from the method's
// own flat copy of the mesh and the grid's points are binned once, so that
// sampling a map reads flat arrays and reuses its scratch memory; the
// triangles then come to the points (each meets a few cells of points)
// rather than each map building a search structure over its triangles.

#include <expmap/Local_map.h>
#include <expmap/Polar_grid.h>
#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Mesh_arrays.h>
#include <expmap/internal/Region_growing.h>
#include <expmap/internal/Workspace_pool.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// A grid point a map holds: its ray-major position i * rays + j, the three
/// corners' vertex indices (ascending) and their weights.
struct Sampled_point {
  std::uint32_t point;
  std::array<std::size_t, 3> corner;
  std::array<double, 3> weight;
};

/// Samples polar grids in the maps of one mesh (`polar_patch_operator()`).
class Polar_grid_sampler {
 public:
  /// For the maps of a method on `grid`, `mesh` the method's copy of the
  /// mesh (`Method_front::mesh_arrays()`), whose faces it reads.
  Polar_grid_sampler(const Mesh_arrays& mesh, const Polar_grid& grid) : m_mesh(mesh), m_grid(grid) {
    // The grid points in square cells over [-radius, radius]^2, about a
    // ring's spacing wide: a patch triangle meets a few cells.
    const std::size_t count = grid.rings * grid.rays;
    m_points.reserve(count);
    for (std::size_t i = 0; i < grid.rings; ++i)
      for (std::size_t j = 0; j < grid.rays; ++j) m_points.push_back(grid.point(i, j));
    m_cells = std::min<std::size_t>(256, 2 * grid.rings);
    m_cells_per_length = double(m_cells) / (2 * grid.radius);
    m_cell_start.assign(m_cells * m_cells + 1, 0);
    for (const auto& q : m_points) ++m_cell_start[cell_of(q) + 1];
    for (std::size_t c = 1; c < m_cell_start.size(); ++c) m_cell_start[c] += m_cell_start[c - 1];
    m_cell_point.resize(count);
    std::vector<std::uint32_t> cursor(m_cell_start.begin(), m_cell_start.end() - 1);
    for (std::size_t p = 0; p < count; ++p)  // ascending within each cell
      m_cell_point[cursor[cell_of(m_points[p])]++] = static_cast<std::uint32_t>(p);
  }

  /// The grid points that `map` holds inside its fold-free disk
  /// (`map.fold_free_radius`, which the query found), in ray-major order,
  /// written to `out`. A point on an edge goes to the first triangle that
  /// holds it, in the order `visit_patch_faces()` lists them; flipped and
  /// collapsed triangles hold none. Safe to call from several threads.
  template <class VertexDescriptor>
  void sample(const Local_map<VertexDescriptor>& map, std::vector<Sampled_point>& out) const {
    out.clear();
    const double disk = map.fold_free_radius ? *map.fold_free_radius : 0.0;
    std::size_t rings = 0;
    while (rings < m_grid.rings && m_grid.ring_radius(rings) < disk) ++rings;
    if (rings == 0) return;
    const std::size_t wanted = rings * m_grid.rays;  // the points of those rings
    const double reach = m_grid.ring_radius(rings - 1);

    auto scratch = m_scratch.acquire([this] {
      auto s = std::make_unique<Scratch>();
      s->position.resize(m_mesh.number_of_vertices());
      s->hit.resize(m_points.size());
      s->found.resize(m_points.size());
      return s;
    });
    std::vector<std::array<double, 2>>& uv = scratch->uv;
    uv.resize(map.size());
    for (std::size_t i = 0; i < map.size(); ++i) uv[i] = map.uv(i);
    std::vector<Sampled_point>& hit = scratch->hit;
    std::vector<char>& found = scratch->found;
    std::fill(found.begin(), found.begin() + wanted, 0);
    std::size_t left = wanted;

    // Each patch triangle that reaches into the square around the sampled
    // rings takes the grid points of the cells it meets that it holds.
    const auto vertex = [&](std::size_t i) { return m_mesh.from_original(map.indices[i]); };
    const auto take_points = [&](const std::array<std::size_t, 3>& corner) {
      const std::array<double, 2>&a = uv[corner[0]], &b = uv[corner[1]], &c = uv[corner[2]];
      const double lo_u = std::min({a[0], b[0], c[0]}), hi_u = std::max({a[0], b[0], c[0]});
      const double lo_v = std::min({a[1], b[1], c[1]}), hi_v = std::max({a[1], b[1], c[1]});
      if (lo_u > reach || hi_u < -reach || lo_v > reach || hi_v < -reach) return false;
      const double area = cross(a, b, c);
      if (!(area > 0)) return false;
      const double inverse_area = 1 / area;
      const std::size_t x0 = cell(lo_u), x1 = cell(hi_u), y1 = cell(hi_v);
      for (std::size_t y = cell(lo_v); y <= y1; ++y)
        for (std::uint32_t e = m_cell_start[y * m_cells + x0];
             e < m_cell_start[y * m_cells + x1 + 1]; ++e) {  // cells x0..x1 of row y
          const std::uint32_t p = m_cell_point[e];
          if (p >= wanted || found[p]) continue;
          const std::array<double, 2>& q = m_points[p];
          const double w0 = cross(b, c, q) * inverse_area;
          const double w1 = cross(c, a, q) * inverse_area;
          const double w2 = cross(a, b, q) * inverse_area;
          // A point on an edge shared by two triangles belongs to both; the
          // tolerance keeps it from falling between them by rounding.
          constexpr double on_edge = -1e-12;
          if (w0 < on_edge || w1 < on_edge || w2 < on_edge) continue;
          hit[p] = sampled_point(p, {map.indices[corner[0]], map.indices[corner[1]],
                                     map.indices[corner[2]]},
                                 {std::max(w0, 0.0), std::max(w1, 0.0), std::max(w2, 0.0)});
          found[p] = 1;
          --left;
        }
      return left == 0;  // stop listing faces once every point is placed
    };
    visit_patch_faces(m_mesh.owned_faces, map.size(), vertex, scratch->position, take_points);
    for (std::size_t p = 0; p < wanted; ++p)
      if (found[p]) out.push_back(hit[p]);
  }

 private:
  struct Scratch {
    Vertex_marks position;  // a vertex's position in the map
    std::vector<std::array<double, 2>> uv;
    std::vector<Sampled_point> hit;  // per grid point, where `found`
    std::vector<char> found;
  };

  // The point `p` with its corners in ascending order and its weights
  // summing to 1.
  static Sampled_point sampled_point(std::uint32_t p, std::array<std::size_t, 3> corner,
                                     std::array<double, 3> weight) {
    const auto order = [&](int i, int j) {
      if (corner[j] < corner[i]) {
        std::swap(corner[i], corner[j]);
        std::swap(weight[i], weight[j]);
      }
    };
    order(0, 1);
    order(1, 2);
    order(0, 1);
    const double sum = weight[0] + weight[1] + weight[2];
    return Sampled_point{p, corner, {weight[0] / sum, weight[1] / sum, weight[2] / sum}};
  }
  static double cross(const std::array<double, 2>& a, const std::array<double, 2>& b,
                      const std::array<double, 2>& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  std::size_t cell(double x) const {
    const double i = (x + m_grid.radius) * m_cells_per_length;
    return i > 0 ? std::min(m_cells - 1, static_cast<std::size_t>(i)) : 0;
  }
  std::size_t cell_of(const std::array<double, 2>& q) const {
    return cell(q[1]) * m_cells + cell(q[0]);
  }

  const Mesh_arrays& m_mesh;
  Polar_grid m_grid;
  std::vector<std::array<double, 2>> m_points;  // the grid points, ray-major
  std::size_t m_cells = 1;                      // per side of the square of cells
  double m_cells_per_length = 1;
  std::vector<std::uint32_t> m_cell_start;  // cell c's points: m_cell_point[start[c], start[c + 1])
  std::vector<std::uint32_t> m_cell_point;
  mutable Workspace_pool<Scratch> m_scratch;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_POLAR_GRID_SAMPLER_H
