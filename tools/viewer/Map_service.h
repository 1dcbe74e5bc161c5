// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_MAP_SERVICE_H
#define EXPMAP_TOOLS_VIEWER_MAP_SERVICE_H

/// \file Map_service.h
/// What `GET /api/map` computes, without the HTTP: a checked request to a
/// map from the surface point nearest to the requested point.

#include "../Exact_memory.h"
#include "../Patch_size_estimate.h"
#include "Map_request.h"
#include "Method_cache.h"
#include "Viewer_methods.h"

#include <expmap/Fold_overs.h>
#include <expmap/Locate_surface_point.h>
#include <expmap/Option_names.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace expmap_view {

/// A request for a larger map than the method's limit here: HTTP 413,
/// with the limit and the size asked for.
class Too_large : public std::runtime_error {
 public:
  Too_large(const std::string& message, std::string method, std::string quantity,
            std::size_t maximum, std::size_t asked)
      : std::runtime_error(message),
        method(std::move(method)),
        quantity(std::move(quantity)),
        maximum(maximum),
        asked(asked) {}
  std::string method;
  std::string quantity;  ///< "patch_vertices", or the exact method's "region_faces"
  std::size_t maximum;
  std::size_t asked;  ///< where counting stopped at the limit, maximum + 1
};

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
  /// \param mesh_file its file, as the command line that would map a
  ///        request too large here names it.
  Map_service(const Mesh& mesh, const Cache_limits& cache_limits = {}, std::string mesh_file = "MESH")
      : m_mesh(mesh), m_mesh_file(std::move(mesh_file)), m_locator(mesh), m_cache(mesh, cache_limits) {
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
  /// \throws Too_large for a patch of more vertices than the method's
  ///         `max_patch_vertices` (for a radius, the vertices within the
  ///         radius in space are counted: `expmap_cli::vertices_within()`),
  ///         and for an exact map whose submesh has more faces than
  ///         `max_region_faces` (counted once the method is precomputed).
  /// \throws Busy, Precomputation_failed as `Method_cache::acquire()`.
  /// \throws expmap::Invalid_input, expmap::Computation_error from the query.
  Map_response compute(const std::multimap<std::string, std::string>& params) {
    const Map_request request = parse_map_request(params, m_limits);
    const Method_info* info = find_method(request.method);
    if (!info)
      throw Bad_request("unknown method '" + shown(request.method) +
                        "' (known: " + expmap::value_names<expmap::Map_method>() + ")");

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
    const auto start = std::chrono::steady_clock::now();
    r.source = m_locator.locate(request.point);
    r.position = expmap::surface_point_position(m_mesh, r.source);
    check_size(*info, request, patch, r);
    const auto located = std::chrono::steady_clock::now();

    const Method_cache::Lease lease = m_cache.acquire(*info, r.time_factor, patch);
    const auto leased = std::chrono::steady_clock::now();
    if (info->max_region_faces) check_region(*info, lease.method(), request, patch, r);
    r.map = lease.method().compute(r.source, patch);
    for (const auto& t : expmap::patch_triangles(m_mesh, r.map)) {
      ++r.triangles;
      if (expmap::is_flipped(r.map, t)) r.flipped_faces.push_back(static_cast<std::size_t>(t.face));
    }
    // The time of the work, not of a wait for the lease.
    r.query_ms = 1e3 * (std::chrono::duration<double>(located - start).count() +
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - leased).count());
    return r;
  }

 private:
  // Refuses a patch of more vertices than `info` allows, naming the limit
  // and the ways to the map: a smaller patch, or the command line.
  void check_size(const Method_info& info, const Map_request& request, const expmap::Patch& patch,
                  const Map_response& r) const {
    const std::size_t limit = info.max_patch_vertices;
    const std::size_t k =
        expmap_cli::estimated_patch_vertices(m_mesh, patch, r.source.face, r.position, limit);
    if (k <= limit) return;
    using expmap_cli::grouped;
    const std::string asked =
        request.radius ? "radius " + number(*request.radius) + " takes in more than " + grouped(limit) +
                             " vertices (counted within that distance in space)"
                       : "fraction " + number(*request.fraction) + " is " + grouped(k) + " patch vertices";
    throw Too_large(asked + "; this server maps at most " + grouped(limit) + " patch vertices with " +
                        info.name + ways_out(info, request, r, true),
                    info.name, "patch_vertices", limit, k);
  }

  // Refuses an exact map whose submesh has more faces than `info` allows:
  // its memory grows with them (Exact_memory.h).
  void check_region(const Method_info& info, const Viewer_method& method, const Map_request& request,
                    const expmap::Patch& patch, const Map_response& r) const {
    const std::size_t limit = info.max_region_faces;
    const std::size_t faces = method.region_faces(r.source, patch, limit);
    if (faces <= limit) return;
    using expmap_cli::grouped;
    using expmap_cli::memory_text;
    throw Too_large("this " + std::string(info.name) +
                        " map's submesh (the faces within reach of its geodesics) has more than " +
                        grouped(limit) + " faces, the most this server maps (up to " +
                        memory_text(expmap_cli::exact_query_mib(static_cast<double>(limit))) +
                        "; the surface may fold back within its reach)" + ways_out(info, request, r, false),
                    info.name, "region_faces", limit, faces);
  }

  // The end of a Too_large message: a smaller patch (with
  // `largest_fraction`, the largest fraction within the patch limit), or
  // the command line.
  std::string ways_out(const Method_info& info, const Map_request& request, const Map_response& r,
                       bool largest_fraction) const {
    const double n = static_cast<double>(m_mesh.number_of_vertices());
    const double fraction = std::floor(1e4 * static_cast<double>(info.max_patch_vertices) / n) / 1e4;
    const std::string patch_option = request.radius ? " --radius " + number(*request.radius)
                                                    : " --fraction " + number(*request.fraction);
    return ": ask for a smaller patch" +
           (largest_fraction && fraction < m_limits.max_fraction
                ? " (a fraction of at most " + number(fraction) + ")"
                : std::string()) +
           ", or compute the map with 'expmap compute " + m_mesh_file + " --method " + info.name +
           " --source-point " + number(r.position[0]) + "," + number(r.position[1]) + "," +
           number(r.position[2]) + patch_option +
           (r.time_factor > 0 ? " --time-factor " + number(r.time_factor) : "") + " -o map.csv'";
  }

  static std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", x);
    return text;
  }

  const Mesh& m_mesh;
  std::string m_mesh_file;
  expmap::Surface_point_locator<Mesh> m_locator;
  Method_cache m_cache;
  CGAL::Bbox_3 m_box;
  Request_limits m_limits;
};

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_MAP_SERVICE_H
