// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_MAP_ARRAYS_H
#define EXPMAP_PYTHON_MAP_ARRAYS_H

// The library's maps as the NumPy arrays Python sees: one map (`Map_arrays`)
// or a batch in the layout of `expmap batch -o OUT.npz` (`Batch_arrays`).
// Built while holding the GIL, from results computed without it.

#include "Mesh_from_arrays.h"

#include <expmap/Local_map.h>

#include <pybind11/stl.h>

#include <limits>
#include <string>
#include <vector>

namespace expmap_python {

using Map = expmap::Local_map<Mesh::Vertex_index>;

template <class T>
py::array_t<T> array_of(const std::vector<T>& values) {
  py::array_t<T> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

/// The caller's row of mesh vertex `v`: `original[v]`, or `v` if `original`
/// is empty (nothing was split).
inline std::int64_t row_of(const std::vector<std::size_t>& original, std::size_t v) {
  return static_cast<std::int64_t>(original.empty() ? v : original[v]);
}

inline Real_array vector3(const std::array<double, 3>& v) {
  Real_array array(3);
  std::copy(v.begin(), v.end(), array.mutable_data());
  return array;
}

/// One local map: the patch vertices nearest first and their coordinates,
/// each vertex as the caller's row (`original`, see `Arrays_mesh`).
struct Map_arrays {
  std::int64_t source = 0;
  Index_array vertices;
  Real_array r, theta, uv;  // uv: n x 2, (r cos theta, r sin theta)
  Real_array normal, axis_u, axis_v;
  expmap::Solve_statistics statistics;  // the heat query's work; zeros for the other methods
  double fold_free_radius = 0;          // as Local_map::fold_free_radius

  Map_arrays(const Map& map, const std::vector<std::size_t>& original)
      : source(row_of(original, map.source)),
        vertices(static_cast<py::ssize_t>(map.size())),
        r(array_of(map.distance)),
        theta(array_of(map.angle)),
        uv({static_cast<py::ssize_t>(map.size()), py::ssize_t(2)}),
        normal(vector3(map.normal)),
        axis_u(vector3(map.axis_u)),
        axis_v(vector3(map.axis_v)),
        statistics(map.statistics),
        fold_free_radius(map.fold_free_radius.value_or(std::numeric_limits<double>::quiet_NaN())) {
    std::int64_t* vertex = vertices.mutable_data();
    for (std::size_t i = 0; i < map.size(); ++i) vertex[i] = row_of(original, map.indices[i]);
    double* p = uv.mutable_data();
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto w = map.uv(i);
      p[2 * i] = w[0], p[2 * i + 1] = w[1];
    }
  }
};

/// Many maps, concatenated: rows offsets[i] to offsets[i + 1] belong to
/// sources[i]; a source whose query failed has no rows, a non-empty
/// errors[i] and a NaN fold_free_radius[i]. Vertices are the caller's rows,
/// as in `Map_arrays`.
struct Batch_arrays {
  Index_array sources, offsets, vertex;
  Real_array r, theta, u, v;
  Real_array fold_free_radius;  // one per source
  std::vector<std::string> errors;

  Batch_arrays(const std::vector<std::size_t>& source_indices, const std::vector<Map>& maps,
               std::vector<std::string> messages, const std::vector<std::size_t>& original)
      : sources(static_cast<py::ssize_t>(source_indices.size())),
        offsets(static_cast<py::ssize_t>(source_indices.size() + 1)),
        fold_free_radius(static_cast<py::ssize_t>(source_indices.size())),
        errors(std::move(messages)) {
    std::copy(source_indices.begin(), source_indices.end(), sources.mutable_data());
    std::int64_t* offset = offsets.mutable_data();
    offset[0] = 0;
    double* radius = fold_free_radius.mutable_data();
    for (std::size_t i = 0; i < maps.size(); ++i) {
      offset[i + 1] = offset[i] + static_cast<std::int64_t>(maps[i].size());
      // A successful map holds at least its source, a failed one nothing.
      radius[i] = maps[i].size() > 0 && maps[i].fold_free_radius
                      ? *maps[i].fold_free_radius
                      : std::numeric_limits<double>::quiet_NaN();
    }
    const py::ssize_t rows = static_cast<py::ssize_t>(offset[maps.size()]);
    vertex = Index_array(rows), r = Real_array(rows), theta = Real_array(rows);
    u = Real_array(rows), v = Real_array(rows);
    std::int64_t* vertex_out = vertex.mutable_data();
    double *r_out = r.mutable_data(), *theta_out = theta.mutable_data();
    double *u_out = u.mutable_data(), *v_out = v.mutable_data();
    for (std::size_t i = 0; i < maps.size(); ++i)
      for (std::size_t k = 0; k < maps[i].size(); ++k) {
        const std::size_t row = static_cast<std::size_t>(offset[i]) + k;
        const auto w = maps[i].uv(k);
        vertex_out[row] = row_of(original, maps[i].indices[k]);
        r_out[row] = maps[i].distance[k], theta_out[row] = maps[i].angle[k];
        u_out[row] = w[0], v_out[row] = w[1];
      }
  }

  std::size_t failures() const {
    return static_cast<std::size_t>(
        std::count_if(errors.begin(), errors.end(), [](const std::string& e) { return !e.empty(); }));
  }

  /// The arrays by name, as `numpy.savez` takes them.
  py::dict as_dict() const {
    py::dict d;
    d["sources"] = sources, d["offsets"] = offsets, d["vertex"] = vertex;
    d["r"] = r, d["theta"] = theta, d["u"] = u, d["v"] = v;
    d["fold_free_radius"] = fold_free_radius;
    return d;
  }
};

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_MAP_ARRAYS_H
