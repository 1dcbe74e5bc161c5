// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_BATCH_TABLE_H
#define EXPMAP_TOOLS_BATCH_TABLE_H

/// \file Batch_table.h
/// The maps of `expmap batch` as columns, one row per (source, patch
/// vertex): the arrays of its `.npz` output and the rows of its `.csv`.

#include <expmap/IO/write_npz.h>
#include <expmap/Local_map.h>

#include <cstddef>
#include <cstdint>
#include <ios>
#include <limits>
#include <ostream>
#include <vector>

namespace expmap_cli {

struct Batch_table {
  std::vector<std::int64_t> sources;     // one per map, in the order asked for
  std::vector<double> fold_free_radius;  // one per map; NaN where its query failed
  std::vector<std::int64_t> offsets{0};  // rows offsets[i] .. offsets[i+1] belong to sources[i]
  std::vector<std::int64_t> vertex;      // patch vertex, 0-based index in file order
  std::vector<double> r, theta, u, v;

  std::size_t rows() const { return vertex.size(); }

  /// The map of `source`; an empty map (a failed query) adds no rows.
  template <class VertexDescriptor>
  void append(std::size_t source, const expmap::Local_map<VertexDescriptor>& map) {
    sources.push_back(static_cast<std::int64_t>(source));
    // A successful map holds at least its source, a failed one nothing.
    fold_free_radius.push_back(map.size() > 0 && map.fold_free_radius
                                   ? *map.fold_free_radius
                                   : std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto uv = map.uv(i);
      vertex.push_back(static_cast<std::int64_t>(map.indices[i]));
      r.push_back(map.distance[i]);
      theta.push_back(map.angle[i]);
      u.push_back(uv[0]);
      v.push_back(uv[1]);
    }
    offsets.push_back(static_cast<std::int64_t>(vertex.size()));
  }

  /// Appends the rows of `other`, whose offsets start again from 0.
  void append(const Batch_table& other) {
    const std::int64_t base = offsets.back();
    sources.insert(sources.end(), other.sources.begin(), other.sources.end());
    fold_free_radius.insert(fold_free_radius.end(), other.fold_free_radius.begin(),
                            other.fold_free_radius.end());
    for (std::size_t i = 1; i < other.offsets.size(); ++i) offsets.push_back(base + other.offsets[i]);
    vertex.insert(vertex.end(), other.vertex.begin(), other.vertex.end());
    r.insert(r.end(), other.r.begin(), other.r.end());
    theta.insert(theta.end(), other.theta.begin(), other.theta.end());
    u.insert(u.end(), other.u.begin(), other.u.end());
    v.insert(v.end(), other.v.begin(), other.v.end());
  }
};

/// The rows as CSV lines `source,vertex,r,theta,u,v,fold_free_radius` (no
/// header; the last the source's, on each of its rows), with 17 significant
/// digits so that numbers read back bit for bit.
inline void write_csv_rows(std::ostream& out, const Batch_table& t) {
  out.unsetf(std::ios_base::floatfield);
  out.precision(std::numeric_limits<double>::max_digits10);
  for (std::size_t m = 0; m < t.sources.size(); ++m)
    for (auto i = static_cast<std::size_t>(t.offsets[m]); i < static_cast<std::size_t>(t.offsets[m + 1]); ++i)
      out << t.sources[m] << ',' << t.vertex[i] << ',' << t.r[i] << ',' << t.theta[i] << ','
          << t.u[i] << ',' << t.v[i] << ',' << t.fold_free_radius[m] << '\n';
}

/// The columns as NumPy's `.npz`: arrays sources (k), offsets (k + 1),
/// vertex, r, theta, u, v and fold_free_radius (k).
inline void write_npz(std::ostream& out, const Batch_table& t) {
  using expmap::IO::npy_array;
  expmap::IO::write_npz(out, {npy_array("sources", t.sources), npy_array("offsets", t.offsets),
                              npy_array("vertex", t.vertex), npy_array("r", t.r),
                              npy_array("theta", t.theta), npy_array("u", t.u),
                              npy_array("v", t.v),
                              npy_array("fold_free_radius", t.fold_free_radius)});
}

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_BATCH_TABLE_H
