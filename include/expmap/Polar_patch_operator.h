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
#include <expmap/Polar_grid.h>
#include <expmap/internal/Locality_order.h>
#include <expmap/internal/Parallel_loop.h>
#include <expmap/internal/Polar_grid_sampler.h>

#include <Eigen/SparseCore>
#include <boost/graph/graph_traits.hpp>

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

/// \ingroup PkgExpmapRef
/// The polar patch operator of `method` (any of the library's methods,
/// built on `tm`) around the vertices of index `sources`, on `grid`: each
/// source is mapped to the geodesic disk of radius `grid.radius` plus two
/// mean edge lengths of the method's mesh (so that the triangles around the
/// outer ring are in the map) with the settings `query`, and each grid point inside the map's
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
///         out of range, more than 2^28 rows, `references` of another
///         size than `sources` or a method built on a mesh with another
///         number of vertices. A query that fails (e.g. an isolated source)
///         leaves its source's rows empty and says why in `errors`.
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
  const internal::Mesh_arrays& mesh = method.mesh_arrays();
  if (mesh.number_of_vertices() != n)
    throw Invalid_input("the method was built on a mesh of " +
                        std::to_string(mesh.number_of_vertices()) + " vertices, not on this one of " +
                        std::to_string(n));
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
  const Patch patch = Patch::geodesic_radius(grid.radius + 2 * mesh.mean_edge_length);

  const internal::Polar_grid_sampler sampler(mesh, grid);
  std::vector<std::vector<internal::Sampled_point>> sampled(sources.size());
  std::vector<std::string> errors(sources.size());
  std::mutex progress_mutex;
  std::size_t done = 0;
  const std::vector<std::size_t> order = internal::hilbert_order(mesh, sources);
  internal::parallel_loop(
      sources.size(), internal::batch_thread_count(batch.threads, sources.size()),
      [&](std::size_t k) {
        const std::size_t s = order[k];
        try {
          typename Method::Query own = query;
          if (!references.empty()) own.reference_direction = references[s];
          // Written to scratch, kept at its size: one allocation per source.
          thread_local std::vector<internal::Sampled_point> points;
          sampler.sample(method.compute_by_index(sources[s], patch, own), points);
          sampled[s].assign(points.begin(), points.end());
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
  for (const auto& points : sampled) entries += 3 * points.size();
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
    for (const internal::Sampled_point& point : sampled[s]) {
      const std::size_t r = s * per_source + point.point;
      for (; next_row <= r; ++next_row) start[next_row] = written;
      op.sampled[r] = 1;
      for (int c = 0; c < 3; ++c) {
        column[written] = static_cast<std::ptrdiff_t>(point.corner[c]);
        value[written] = point.weight[c];
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
