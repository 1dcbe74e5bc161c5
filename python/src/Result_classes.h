// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_RESULT_CLASSES_H
#define EXPMAP_PYTHON_RESULT_CLASSES_H

// The Python classes of the results: LocalMap (one map), BatchMaps (many, in
// the layout of `expmap batch -o OUT.npz`), and BatchMap, the namedtuple of
// one source's rows of a batch.

#include "Map_arrays.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

namespace expmap_python {

/// The namedtuple type `expmap.BatchMap` (made once, in the module's init;
/// the module keeps it alive for as long as any function can run).
inline py::handle batch_map_type;

/// Source `i` of `b` (0 <= i < len(b)) as a `BatchMap`: its rows of the flat
/// arrays as NumPy views (basic slices: no copies, and each keeps the flat
/// array alive) and its error, None if its query succeeded.
inline py::object batch_map(const Batch_arrays& b, std::size_t i) {
  const std::int64_t* offset = b.offsets.data();
  const py::slice rows(static_cast<py::ssize_t>(offset[i]), static_cast<py::ssize_t>(offset[i + 1]),
                       1);
  py::object error = py::none();
  if (!b.errors[i].empty()) error = py::str(b.errors[i]);
  return batch_map_type(b.sources.data()[i], b.vertex[rows], b.r[rows], b.theta[rows], b.u[rows],
                        b.v[rows], error);
}

/// The index `batch[index]` names: any Python integer, negative from the end.
inline std::size_t batch_index(const Batch_arrays& b, py::handle index) {
  const py::object integer = py::reinterpret_steal<py::object>(PyNumber_Index(index.ptr()));
  if (!integer) {
    PyErr_Clear();
    throw py::type_error("BatchMaps indices must be integers (got " +
                         std::string(py::str(py::type::of(index).attr("__name__"))) + ")");
  }
  const py::ssize_t n = static_cast<py::ssize_t>(b.errors.size());
  const py::ssize_t i = PyLong_AsSsize_t(integer.ptr());
  if (i == -1 && PyErr_Occurred()) PyErr_Clear();  // too large either way: out of range below
  const bool overflow = i == -1 && !integer.equal(py::int_(-1));
  if (overflow || i < -n || i >= n)
    throw py::index_error("BatchMaps index " + std::string(py::str(integer)) +
                          " is out of range (" + std::to_string(n) + " sources)");
  return static_cast<std::size_t>(i < 0 ? i + n : i);
}

/// What `iter(batch)` returns: the `BatchMap` of each source in turn. It
/// holds the batch, so the loop may outlive the caller's reference.
struct Batch_iterator {
  py::object batch;
  std::size_t next = 0;
};

/// Adds LocalMap, BatchMap, BatchMaps and BatchMapsIterator to `m`.
inline void bind_result_classes(py::module_& m) {
  py::class_<Map_arrays>(m, "LocalMap",
                         "One local map: the patch vertices, nearest first, and their polar\n"
                         "(r, theta) and Cartesian (uv) coordinates.")
      .def_readonly("source", &Map_arrays::source, "The source vertex.")
      .def_readonly("vertices", &Map_arrays::vertices, "Patch vertex indices (int64), nearest first.")
      .def_readonly("r", &Map_arrays::r, "Geodesic distance of each patch vertex.")
      .def_readonly("theta", &Map_arrays::theta, "Polar angle in (-pi, pi].")
      .def_readonly("uv", &Map_arrays::uv, "n x 2: (r cos theta, r sin theta).")
      .def_readonly("normal", &Map_arrays::normal, "Unit normal of the tangent plane.")
      .def_readonly("axis_u", &Map_arrays::axis_u, "Tangent axis of angle 0.")
      .def_readonly("axis_v", &Map_arrays::axis_v, "Tangent axis of angle pi/2.")
      .def_readonly("fold_free_radius", &Map_arrays::fold_free_radius,
                    "Where the map is one-to-one: the largest r such that no triangle with\n"
                    "all corners nearer than r is flipped or collapsed in uv; max(r) if\n"
                    "none is flipped.")
      .def_property_readonly(
          "statistics",
          [](const Map_arrays& a) {
            py::dict d;
            d["forward_nodes"] = a.statistics.forward_nodes;
            d["backward_nodes"] = a.statistics.backward_nodes;
            d["factor_entries"] = a.statistics.factor_entries;
            d["solve_seconds"] = a.statistics.solve_seconds;
            d["region_retries"] = a.statistics.region_retries;
            d["front_checks"] = a.statistics.front_checks;
            d["front_maps"] = a.statistics.front_maps;
            return d;
          },
          "The heat query's work (zeros for the other methods): elimination-tree nodes\n"
          "visited by forward and back substitution, factor entries read, seconds in\n"
          "the solves, how often the region was doubled because the patch came\n"
          "too close to its edge (region_retries), and whether the geodesic front's\n"
          "map was computed (front_checks) and returned (front_maps; see fallback).")
      .def("__len__", [](const Map_arrays& a) { return a.vertices.size(); })
      .def("__repr__", [](const Map_arrays& a) {
        return "<LocalMap source " + std::to_string(a.source) + ", " +
               std::to_string(a.vertices.size()) + " vertices>";
      });

  // A namedtuple: it unpacks, compares and prints as Python users expect,
  // and its fields are the arrays themselves (views), not copies.
  py::object batch_map_namedtuple = py::module_::import("collections").attr("namedtuple")(
      "BatchMap", py::make_tuple("source", "vertices", "r", "theta", "u", "v", "error"));
  batch_map_namedtuple.attr("__module__") = "expmap";
  batch_map_namedtuple.attr("__doc__") =
      "One source's map in a BatchMaps (batch[i]): source (int), vertices, r, theta,\n"
      "u, v (NumPy views of the batch's rows offsets[i] to offsets[i+1] of vertex,\n"
      "r, theta, u, v: no copies, writing to them writes to the batch) and error\n"
      "(None, or why the source's query failed; its arrays are then empty).";
  m.attr("BatchMap") = batch_map_namedtuple;
  batch_map_type = batch_map_namedtuple;

  py::class_<Batch_iterator>(m, "BatchMapsIterator", "Iterates over a BatchMaps' BatchMap values.")
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", [](Batch_iterator& it) {
        const Batch_arrays& b = it.batch.cast<const Batch_arrays&>();
        if (it.next >= b.errors.size()) throw py::stop_iteration();
        return batch_map(b, it.next++);
      });

  py::class_<Batch_arrays>(
      m, "BatchMaps",
      "Many maps in the layout of `expmap batch -o OUT.npz`: rows offsets[i] to\n"
      "offsets[i+1] of vertex, r, theta, u, v belong to sources[i]. A source whose\n"
      "query failed has no rows and its message in errors[i] ('' otherwise).\n"
      "A sequence of the sources' maps: batch[i] (negative i counts from the end)\n"
      "is the BatchMap of sources[i], its arrays views into the flat ones, and\n"
      "iterating gives them in order, e.g. ``for s, m in zip(sources, batch)``.")
      .def_readonly("sources", &Batch_arrays::sources, "The sources (int64, k).")
      .def_readonly("offsets", &Batch_arrays::offsets, "Row range of each source (int64, k + 1).")
      .def_readonly("vertex", &Batch_arrays::vertex, "Patch vertex of each row (int64).")
      .def_readonly("r", &Batch_arrays::r, "Geodesic distance of each row.")
      .def_readonly("theta", &Batch_arrays::theta, "Polar angle of each row.")
      .def_readonly("u", &Batch_arrays::u, "r cos theta of each row.")
      .def_readonly("v", &Batch_arrays::v, "r sin theta of each row.")
      .def_readonly("fold_free_radius", &Batch_arrays::fold_free_radius,
                    "Per source: its map's fold-free radius (LocalMap.fold_free_radius;\n"
                    "NaN where the query failed).")
      .def_readonly("errors", &Batch_arrays::errors, "Per source: '' or why its query failed.")
      .def_property_readonly("failures", &Batch_arrays::failures, "How many queries failed.")
      .def("as_dict", &Batch_arrays::as_dict,
           "The eight arrays by name (sources, offsets, vertex, r, theta, u, v,\n"
           "fold_free_radius), as numpy.savez takes them.")
      .def("__len__", [](const Batch_arrays& b) { return b.errors.size(); })
      .def(
          "__getitem__",
          [](const Batch_arrays& b, py::handle index) {
            return batch_map(b, batch_index(b, index));
          },
          py::arg("index"),
          "batch[i] -> BatchMap: the map of sources[i] (i < 0 counts from the end).\n"
          "Raises IndexError if i is out of range, TypeError if it is not an integer.")
      .def(
          "__iter__", [](py::object self) { return Batch_iterator{self}; },
          "The BatchMap of each source, in the order of sources.")
      .def("__repr__", [](const Batch_arrays& b) {
        return "<BatchMaps " + std::to_string(b.errors.size()) + " sources, " +
               std::to_string(b.vertex.size()) + " rows, " + std::to_string(b.failures()) +
               " failed>";
      });
}

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_RESULT_CLASSES_H
