// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_POLAR_PATCH_OPERATOR_H
#define EXPMAP_POLAR_PATCH_OPERATOR_H

/// \file Polar_patch_operator.h
/// The polar patch operator of geodesic convolutional networks (Masci et
/// al., "Geodesic convolutional neural networks on Riemannian manifolds",
/// ICCV workshops 2015): for each source, a signal resampled on a polar
/// grid of its geodesic disk, as one sparse matrix.

#include <expmap/Batch.h>
#include <expmap/Errors.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/internal/Locality_order.h>
#include <expmap/internal/Parallel_loop.h>
#include <expmap/internal/Uv_triangle_locator.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// The points a patch is sampled at: `rings` x `rays` points of the
/// source's (u, v) plane at radii rho_i = (i + 1/2) radius / rings and
/// angles theta_j = 2 pi j / rays (theta = 0 along the map's reference
/// direction, `Query_options::reference_direction`).
struct Polar_grid {
  double radius = 0;       ///< R, in mesh units
  std::size_t rings = 5;   ///< points along each ray
  std::size_t rays = 16;   ///< points around each ring

  /// rho_i.
  double ring_radius(std::size_t i) const { return (double(i) + 0.5) * radius / double(rings); }
  /// theta_j.
  double ray_angle(std::size_t j) const {
    return 2 * 3.14159265358979323846 * double(j) / double(rays);
  }
  /// The grid point (i, j) in the (u, v) plane.
  std::array<double, 2> point(std::size_t i, std::size_t j) const {
    return {{ring_radius(i) * std::cos(ray_angle(j)), ring_radius(i) * std::sin(ray_angle(j))}};
  }
};

/// \ingroup PkgExpmapRef
/// `grid` if it can be sampled.
/// \throws Invalid_input for a radius that is not positive and finite, no
///         rings or rays, or more than 2^20 points per patch.
inline const Polar_grid& checked(const Polar_grid& grid) {
  if (!(grid.radius > 0) || !std::isfinite(grid.radius))
    throw Invalid_input("the polar grid's radius must be positive and finite (got " +
                        std::to_string(grid.radius) + ")");
  if (grid.rings == 0 || grid.rays == 0)
    throw Invalid_input("the polar grid needs at least one ring and one ray (got " +
                        std::to_string(grid.rings) + " x " + std::to_string(grid.rays) + ")");
  if (grid.rings > (std::size_t(1) << 20) / grid.rays)
    throw Invalid_input("the polar grid has more than 2^20 points (" +
                        std::to_string(grid.rings) + " x " + std::to_string(grid.rays) + ")");
  return grid;
}

/// \ingroup PkgExpmapRef
/// Patches of a per-vertex signal on the polar grids of many sources: a
/// sparse matrix with a row per grid point of each source, row
/// `row(s, i, j)` for source `sources[s]`, ring i and ray j, holding the
/// barycentric weights of the corners of the patch triangle that holds the
/// grid point in that source's map. `weights * X`, X a (vertices x
/// channels) signal, gives each source's patch, rings x rays per channel.
struct Polar_patch_operator {
  Polar_grid grid;                   ///< where each patch is sampled
  std::vector<std::size_t> sources;  ///< in the rows' order, as indices in `vertices(tm)`
  /// (sources * rings * rays) x vertices; a row without entries is a grid
  /// point the map does not hold (see `sampled`).
  Eigen::SparseMatrix<double, Eigen::RowMajor, std::ptrdiff_t> weights;
  /// Per row: 1 where the grid point was sampled, 0 where it lies beyond
  /// the map's fold-free disk (`Local_map::fold_free_radius`), outside the
  /// map (past a boundary or the patch's edge) or its source's query failed.
  std::vector<unsigned char> sampled;
  /// Per source: "" or why its query failed (its rows are then empty).
  std::vector<std::string> errors;

  /// The row of grid point (ring i, ray j) of the s-th source.
  std::size_t row(std::size_t s, std::size_t i, std::size_t j) const {
    return (s * grid.rings + i) * grid.rays + j;
  }
};

namespace internal {

/// The mean length of the edges of `tm`.
template <class TriangleMesh>
double mean_edge_length(const TriangleMesh& tm) {
  const auto point = get(CGAL::vertex_point, tm);
  double total = 0;
  std::size_t count = 0;
  for (auto e : edges(tm)) {
    const auto a = get(point, source(e, tm)), b = get(point, target(e, tm));
    const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
    total += std::sqrt(dx * dx + dy * dy + dz * dz);
    ++count;
  }
  return count > 0 ? total / double(count) : 0;
}

/// The order in which `polar_patch_operator` maps `sources`: along a
/// Hilbert curve through their points (see `run_batch`).
template <class TriangleMesh, class VertexIndexMap>
std::vector<std::size_t> source_order(const TriangleMesh& tm, VertexIndexMap vertex_index,
                                      const std::vector<std::size_t>& sources) {
  const auto point = get(CGAL::vertex_point, tm);
  std::vector<Vector3> where(static_cast<std::size_t>(num_vertices(tm)));
  for (auto v : vertices(tm)) {
    const auto p = get(point, v);
    where[static_cast<std::size_t>(get(vertex_index, v))] = {{p.x(), p.y(), p.z()}};
  }
  std::vector<Vector3> points;
  points.reserve(sources.size());
  for (std::size_t s : sources) points.push_back(where[s]);
  return hilbert_order(points);
}

/// One source's grid points that its map holds: for each, its ray-major
/// position i * rays + j, the three corners' vertex indices (ascending) and
/// their weights.
struct Sampled_points {
  std::vector<std::size_t> point;
  std::vector<std::array<std::size_t, 3>> corner;
  std::vector<std::array<double, 3>> weight;
};

/// The faces of `tm` whose three corners are in `map`, as the corners'
/// positions in the map, each face once, from its corner nearest the
/// source (`patch_triangles()`'s order). `position` is scratch space of
/// `num_vertices(tm)` entries, all -1, and is left so: a lookup per corner
/// instead of a hash, which is most of the sampling's cost otherwise.
template <class TriangleMesh, class VertexDescriptor, class VertexIndexMap>
void map_triangles(const TriangleMesh& tm, const Local_map<VertexDescriptor>& map,
                   VertexIndexMap vertex_index, std::vector<int>& position,
                   std::vector<std::array<std::size_t, 3>>& triangles) {
  using Traits = boost::graph_traits<TriangleMesh>;
  triangles.clear();
  for (std::size_t i = 0; i < map.size(); ++i) position[map.indices[i]] = static_cast<int>(i);
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto h = halfedge(map.vertices[i], tm);
    if (h == Traits::null_halfedge()) continue;
    for (auto f : CGAL::faces_around_target(h, tm)) {
      if (f == Traits::null_face()) continue;
      std::array<std::size_t, 3> corner{};
      int k = 0;
      bool inside = true;
      for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
        const int at = k < 3 ? position[static_cast<std::size_t>(get(vertex_index, v))] : -1;
        if (at < 0) {
          inside = false;
          break;
        }
        corner[k++] = static_cast<std::size_t>(at);
      }
      if (inside && k == 3 && i == std::min({corner[0], corner[1], corner[2]}))
        triangles.push_back(corner);
    }
  }
  for (std::size_t i = 0; i < map.size(); ++i) position[map.indices[i]] = -1;
}

/// The grid points of `grid` that `map` holds inside its fold-free disk
/// (`map.fold_free_radius`, which the query found). `position` as for
/// `map_triangles()`.
template <class TriangleMesh, class VertexDescriptor, class VertexIndexMap>
Sampled_points sample_polar_grid(const TriangleMesh& tm, const Local_map<VertexDescriptor>& map,
                                 const Polar_grid& grid, VertexIndexMap vertex_index,
                                 std::vector<int>& position) {
  using Corners = Uv_triangle_locator::Corners;
  std::vector<std::array<std::size_t, 3>> triangles;
  map_triangles(tm, map, vertex_index, position, triangles);
  std::vector<std::array<double, 2>> vertex_uv(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) vertex_uv[i] = map.uv(i);
  std::vector<Corners> uv(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) uv[t][k] = vertex_uv[triangles[t][k]];
  const double disk = map.fold_free_radius ? *map.fold_free_radius : 0.0;
  double extent = 0;
  for (double r : map.distance) extent = std::max(extent, r);
  const Uv_triangle_locator locator(uv, extent);

  Sampled_points out;
  for (std::size_t i = 0; i < grid.rings; ++i) {
    if (!(grid.ring_radius(i) < disk)) break;
    for (std::size_t j = 0; j < grid.rays; ++j) {
      const auto found = locator.locate(grid.point(i, j));
      if (!found) continue;
      std::array<std::pair<std::size_t, double>, 3> corner;
      for (int k = 0; k < 3; ++k)
        corner[k] = {map.indices[triangles[found->triangle][k]], found->weight[k]};
      std::sort(corner.begin(), corner.end());
      out.point.push_back(i * grid.rays + j);
      out.corner.push_back({corner[0].first, corner[1].first, corner[2].first});
      out.weight.push_back({corner[0].second, corner[1].second, corner[2].second});
    }
  }
  return out;
}

}  // namespace internal

/// \ingroup PkgExpmapRef
/// The polar patch operator of `method` (any of the library's methods,
/// built on `tm`) around the vertices of index `sources`, on `grid`: each
/// source is mapped to the geodesic disk of radius `grid.radius` plus two
/// mean edge lengths (so that the triangles around the outer ring are in
/// the map) with the settings `query`, and each grid point inside the map's
/// fold-free disk gets the barycentric weights of the (u, v) triangle that
/// holds it. The sources are mapped on the threads `batch` asks for, one
/// map in memory per thread; `batch.progress` is called as for a batch.
/// The operator is the same on any number of threads. `references`, if
/// not empty, gives each source its own direction of theta = 0 (e.g. a
/// principal curvature direction, so that the patches do not depend on a
/// global axis), in place of `query.reference_direction`.
///
/// \code
/// expmap::Geodesic_polar_coordinates<Mesh> dgpc(mesh);
/// const auto op = expmap::polar_patch_operator(mesh, dgpc, sources, {radius, 5, 16});
/// Eigen::MatrixXd patches = op.weights * signal;  // (sources * 80) x channels
/// \endcode
/// \throws Invalid_input for a grid that cannot be sampled, a source index
///         out of range, more than 2^28 rows or `references` of another
///         size than `sources`. A query that fails (e.g.
///         an isolated source) leaves its source's rows empty and says why
///         in `errors`.
template <class TriangleMesh, class Method>
Polar_patch_operator polar_patch_operator(
    const TriangleMesh& tm, const Method& method, const std::vector<std::size_t>& sources,
    const Polar_grid& grid, const Batch_options& batch = {}, typename Method::Query query = {},
    const std::vector<std::array<double, 3>>& references = {}) {
  checked(grid);
  if (!references.empty() && references.size() != sources.size())
    throw Invalid_input("give one reference direction per source (got " +
                        std::to_string(references.size()) + " for " +
                        std::to_string(sources.size()) + " sources)");
  for (std::size_t s = 0; s < references.size(); ++s) {
    const auto& d = references[s];
    if (!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2]) ||
        (d[0] == 0 && d[1] == 0 && d[2] == 0))
      throw Invalid_input("the reference direction of source " + std::to_string(s) +
                          " is zero or not finite");
  }
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  for (std::size_t s : sources)
    if (s >= n)
      throw Invalid_input("source vertex " + std::to_string(s) + " is out of range (the mesh has " +
                          std::to_string(n) + " vertices)");
  // Rows of 8 (row start) + 1 (mask) bytes, entries of 16: refused before
  // any map is computed rather than failing to allocate after.
  constexpr std::size_t max_rows = std::size_t(1) << 28;
  if (sources.size() > max_rows / (grid.rings * grid.rays))
    throw Invalid_input("a polar patch operator of " + std::to_string(sources.size()) +
                        " sources x " + std::to_string(grid.rings * grid.rays) +
                        " grid points has more than 2^28 rows; split the sources");
  query.find_fold_free_radius = true;
  const Patch patch = Patch::geodesic_radius(grid.radius + 2 * internal::mean_edge_length(tm));

  const auto vertex_index = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<internal::Sampled_points> sampled(sources.size());
  std::vector<std::string> errors(sources.size());
  std::mutex progress_mutex;
  std::size_t done = 0;
  const std::vector<std::size_t> order = internal::source_order(tm, vertex_index, sources);
  internal::parallel_loop(
      sources.size(), internal::batch_thread_count(batch.threads, sources.size()),
      [&](std::size_t k) {
        const std::size_t s = order[k];
        try {
          typename Method::Query own = query;
          if (!references.empty()) own.reference_direction = references[s];
          // Scratch space of each thread, kept between its sources.
          thread_local std::vector<int> position;
          if (position.size() != n) position.assign(n, -1);
          sampled[s] = internal::sample_polar_grid(
              tm, method.compute_by_index(sources[s], patch, own), grid, vertex_index, position);
        } catch (const std::exception& e) {
          errors[s] = internal::batch_error_message(sources[s], internal::user_message(e),
                                                    "source vertex");
        }
        std::lock_guard<std::mutex> lock(progress_mutex);
        ++done;
        if (batch.progress) batch.progress(done, sources.size());
      },
      /*runs=*/true);

  Polar_patch_operator op;
  op.grid = grid;
  op.sources = sources;
  op.errors = std::move(errors);
  const std::size_t per_source = grid.rings * grid.rays;
  const std::size_t rows = sources.size() * per_source;
  op.sampled.assign(rows, 0);
  std::size_t entries = 0;
  for (const auto& points : sampled) entries += 3 * points.point.size();
  // The compressed rows written directly: the sources' points come in row
  // order already.
  op.weights.resize(static_cast<std::ptrdiff_t>(rows), static_cast<std::ptrdiff_t>(n));
  op.weights.resizeNonZeros(static_cast<std::ptrdiff_t>(entries));
  std::ptrdiff_t* start = op.weights.outerIndexPtr();
  std::ptrdiff_t* column = op.weights.innerIndexPtr();
  double* value = op.weights.valuePtr();
  std::ptrdiff_t written = 0;
  std::size_t next_row = 0;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const internal::Sampled_points& points = sampled[s];
    for (std::size_t k = 0; k < points.point.size(); ++k) {
      const std::size_t r = s * per_source + points.point[k];
      for (; next_row <= r; ++next_row) start[next_row] = written;
      op.sampled[r] = 1;
      for (int c = 0; c < 3; ++c) {
        column[written] = static_cast<std::ptrdiff_t>(points.corner[k][c]);
        value[written] = points.weight[k][c];
        ++written;
      }
    }
    sampled[s] = {};
  }
  for (; next_row <= rows; ++next_row) start[next_row] = written;
  return op;
}

}  // namespace expmap

#endif  // EXPMAP_POLAR_PATCH_OPERATOR_H
