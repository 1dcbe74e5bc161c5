// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_MAP_SERVICE_H
#define EXPMAP_TOOLS_VIEWER_MAP_SERVICE_H

/// \file Map_service.h
/// What `GET /api/map` computes, without the HTTP: a checked request to a
/// map from the surface point nearest to the requested point.

#include "Map_request.h"
#include "Method_cache.h"
#include "Viewer_methods.h"

#include <expmap/Fold_overs.h>
#include <expmap/Locate_surface_point.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace expmap_view {

/// One answered map query.
struct Map_response {
  std::string method;
  double time_factor = 0;       ///< heat's m; 0 for the others
  Point_on_surface source;      ///< the surface point nearest to the request's
  std::array<double, 3> position{};  ///< where that point is
  Map map;
  std::size_t triangles = 0;             ///< patch triangles
  std::vector<std::size_t> flipped_faces;  ///< those the map turns over
  double query_ms = 0;  ///< locating the point, the map and its folds
};

/// The mesh, its locator and its methods; answers map requests from any
/// number of threads at once.
class Map_service {
 public:
  /// \param mesh a triangle mesh without removed elements; must outlive
  ///        the service.
  Map_service(const Mesh& mesh, unsigned queries_per_method = 2, unsigned time_factors_kept = 3)
      : m_mesh(mesh), m_locator(mesh), m_cache(mesh, queries_per_method, time_factors_kept) {
    m_box = CGAL::Polygon_mesh_processing::bbox(mesh);
    m_limits.max_radius = std::sqrt(CGAL::square(m_box.xmax() - m_box.xmin()) +
                                    CGAL::square(m_box.ymax() - m_box.ymin()) +
                                    CGAL::square(m_box.zmax() - m_box.zmin()));
  }

  const Mesh& mesh() const { return m_mesh; }
  const Request_limits& limits() const { return m_limits; }
  const Method_cache& cache() const { return m_cache; }

  /// The map `params` (the query parameters of `GET /api/map`) ask for.
  /// \throws Bad_request for parameters that make no request, an unknown
  ///         method or a point far from the mesh.
  /// \throws Busy, Precomputation_failed as `Method_cache::acquire()`.
  /// \throws expmap::Invalid_input, expmap::Computation_error from the query.
  Map_response compute(const std::multimap<std::string, std::string>& params) {
    const Map_request request = parse_map_request(params, m_limits);
    const Method_info* info = find_method(request.method);
    if (!info) {
      std::string known;
      for (const Method_info& m : viewer_methods()) known += (known.empty() ? "" : ", ") + std::string(m.name);
      throw Bad_request("unknown method '" + shown(request.method) + "' (known: " + known + ")");
    }

    // The page sends points of the surface. Far ones are refused before any
    // precomputation: their nearest surface points mean nothing to a viewer
    // (the locator itself refuses only points too far to locate at all).
    for (int d = 0; d < 3; ++d)
      if (request.point[d] < m_box.min(d) - m_limits.max_radius ||
          request.point[d] > m_box.max(d) + m_limits.max_radius)
        throw Bad_request("point must be near the mesh: within its bounding box grown by its diagonal");

    Map_response r;
    r.method = info->name;
    r.time_factor = info->takes_time_factor ? request.time_factor.value_or(default_time_factor()) : 0;
    const expmap::Patch patch = request.fraction ? expmap::Patch::fraction(*request.fraction)
                                                 : expmap::Patch::geodesic_radius(*request.radius);
    const Method_cache::Lease lease = m_cache.acquire(*info, r.time_factor);

    const auto start = std::chrono::steady_clock::now();
    r.source = m_locator.locate(request.point);
    r.position = position_of(r.source);
    r.map = lease.method().compute(r.source, patch);
    for (const auto& t : expmap::patch_triangles(m_mesh, r.map)) {
      ++r.triangles;
      if (expmap::is_flipped(r.map, t)) r.flipped_faces.push_back(static_cast<std::size_t>(t.face));
    }
    r.query_ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

 private:
  // The corners in the order of Surface_point (as CGAL's Face_location):
  // source(h), target(h), target(next(h)) for h = halfedge(face).
  std::array<double, 3> position_of(const Point_on_surface& p) const {
    const auto h = m_mesh.halfedge(p.face);
    const Mesh::Vertex_index corner[3] = {m_mesh.source(h), m_mesh.target(h),
                                          m_mesh.target(m_mesh.next(h))};
    std::array<double, 3> x{};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) x[d] += p.barycentric[k] * CGAL::to_double(m_mesh.point(corner[k])[d]);
    return x;
  }

  const Mesh& m_mesh;
  expmap::Surface_point_locator<Mesh> m_locator;
  Method_cache m_cache;
  CGAL::Bbox_3 m_box;
  Request_limits m_limits;
};

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_MAP_SERVICE_H
