// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_WRITE_CSV_H
#define EXPMAP_IO_WRITE_CSV_H

/// \file write_csv.h
/// A local map as a table, one row per patch vertex.

#include <expmap/Local_map.h>

#include <cstddef>
#include <ios>
#include <limits>
#include <ostream>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// Writes `map` as CSV with the header `vertex,r,theta,u,v` and one row per
/// patch vertex, in the map's order (nearest to the source first).
///
/// `vertex` is the 0-based index of the vertex in `vertices(tm)`
/// (`Local_map::indices`; for a `CGAL::Surface_mesh` read from a file, the
/// order of the file). `theta` is in radians in (-pi, pi]. Numbers are
/// written with 17 significant digits, so they read back bit for bit.
/// The stream's formatting flags are restored afterwards.
///
/// \code
/// std::ofstream out("map.csv");
/// expmap::IO::write_local_map_csv(out, map);
/// \endcode
/// \returns `out`, whose state tells whether writing succeeded.
template <class VertexDescriptor>
std::ostream& write_local_map_csv(std::ostream& out, const Local_map<VertexDescriptor>& map) {
  const std::ios_base::fmtflags flags = out.flags();
  const std::streamsize precision = out.precision();
  out.unsetf(std::ios_base::floatfield);  // %g style: shortest of fixed and scientific
  out.precision(std::numeric_limits<double>::max_digits10);
  out << "vertex,r,theta,u,v\n";
  for (std::size_t i = 0; i < map.size(); ++i) {
    const auto uv = map.uv(i);
    out << map.indices[i] << ',' << map.distance[i] << ',' << map.angle[i] << ',' << uv[0] << ','
        << uv[1] << '\n';
  }
  out.flags(flags);
  out.precision(precision);
  return out;
}

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_WRITE_CSV_H
