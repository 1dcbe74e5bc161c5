// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_WRITE_TEXTURED_OBJ_H
#define EXPMAP_IO_WRITE_TEXTURED_OBJ_H

/// \file write_textured_obj.h
/// The patch of a local map as a textured OBJ mesh, ready for a decal or
/// a checkerboard texture in any viewer.

#include <expmap/Fold_overs.h>
#include <expmap/Local_map.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ios>
#include <limits>
#include <ostream>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// The texture coordinates `write_textured_obj()` gives patch vertex `i`:
/// `(u / (2R) + 1/2, v / (2R) + 1/2)` with `R` the largest distance in the
/// map (1 if the map is the source alone). The disk of radius R around the
/// source fills the unit texture square, the source sits at its centre, and
/// lengths keep their proportions (no stretch between u and v).
template <class VertexDescriptor>
std::array<double, 2> texture_coordinates(const Local_map<VertexDescriptor>& map, std::size_t i,
                                          double max_distance) {
  const double scale = max_distance > 0 ? 0.5 / max_distance : 0.5;
  const auto uv = map.uv(i);
  return {{uv[0] * scale + 0.5, uv[1] * scale + 0.5}};
}

/// \ingroup PkgExpmapIO
/// Writes the patch of `map` as a Wavefront OBJ: its vertices (`v x y z`, in
/// the map's order, nearest to the source first), their texture coordinates
/// (`vt s t`, see `texture_coordinates()`; the mapping is repeated in a
/// comment line of the file), and every face of `tm` whose three vertices
/// are in the patch (`f a/a b/b c/c`, in the face's orientation).
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertex descriptors to
///         points with `x()`, `y()`, `z()`.
/// \returns `out`, whose state tells whether writing succeeded.
///
/// \code
/// std::ofstream out("patch.obj");
/// expmap::IO::write_textured_obj(out, mesh, map);
/// \endcode
template <class TriangleMesh, class VertexDescriptor, class VertexPointMap>
std::ostream& write_textured_obj(std::ostream& out, const TriangleMesh& tm,
                                 const Local_map<VertexDescriptor>& map, VertexPointMap vpm) {
  const double max_distance =
      map.size() == 0 ? 0.0 : *std::max_element(map.distance.begin(), map.distance.end());
  const auto triangles = patch_triangles(tm, map);

  const std::ios_base::fmtflags flags = out.flags();
  const std::streamsize precision = out.precision();
  out.unsetf(std::ios_base::floatfield);
  out.precision(std::numeric_limits<double>::max_digits10);
  // A map from a point of a face has no vertex at the source.
  const bool source_is_a_vertex = map.size() > 0 && map.distance[0] == 0;
  out << "# expmap local map: " << map.size() << " vertices, " << triangles.size()
      << (source_is_a_vertex ? " faces; source = first vertex\n"
                             : " faces; source = a point of a face, at vt (0.5, 0.5)\n")
      << "# vt = (u / (2R) + 0.5, v / (2R) + 0.5), R = max geodesic distance = " << max_distance
      << "\n";
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto& p = get(vpm, map.vertices[i]);
    out << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' '
        << CGAL::to_double(p.z()) << '\n';
  }
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto st = texture_coordinates(map, i, max_distance);
    out << "vt " << st[0] << ' ' << st[1] << '\n';
  }
  for (const auto& t : triangles) {
    out << 'f';
    for (std::size_t c : t.corner) out << ' ' << c + 1 << '/' << c + 1;  // OBJ counts from 1
    out << '\n';
  }
  out.flags(flags);
  out.precision(precision);
  return out;
}

/// \ingroup PkgExpmapIO
/// As above, with the mesh's internal `vertex_point` map.
template <class TriangleMesh, class VertexDescriptor>
std::ostream& write_textured_obj(std::ostream& out, const TriangleMesh& tm,
                                 const Local_map<VertexDescriptor>& map) {
  return write_textured_obj(out, tm, map, get(CGAL::vertex_point, tm));
}

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_WRITE_TEXTURED_OBJ_H
