// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_PATCH_OPERATOR_BINDING_H
#define EXPMAP_PYTHON_PATCH_OPERATOR_BINDING_H

// The method classes' patch_operator(): the polar patch operator
// (expmap/Polar_patch_operator.h) as an expmap.patches.PolarPatchOperator.
// Part of module.cpp, which includes it after its argument helpers
// (Bound_method, checked_indices, query_argument, batch_options_argument,
// batch_progress_argument) and `using namespace expmap_python`.

#include "Map_arrays.h"

#include <expmap/Polar_patch_operator.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace {

template <class Method>
void add_patch_operator(py::class_<Bound_method<Method>>& c) {
  using Bound = Bound_method<Method>;
  c.def(
      "patch_operator",
      [](const Bound& b, py::object sources_object, double radius, py::handle rings,
         py::handle rays, py::handle reference, py::handle threads_object, py::object progress,
         const py::kwargs& settings) {
        std::vector<std::size_t> sources;
        if (sources_object.is_none()) {
          sources.resize(b.rows);
          std::iota(sources.begin(), sources.end(), std::size_t(0));
        } else {
          const Index_array checked = checked_indices(sources_object, "sources", b.rows);
          sources.assign(checked.data(), checked.data() + checked.size());
        }
        const expmap::Polar_grid grid{radius, index_argument(rings, "rings"),
                                      index_argument(rays, "rays")};
        expmap::checked(grid);
        // One direction for all sources, as compute() takes it, or one per source.
        std::vector<std::array<double, 3>> references;
        py::object shared_reference = py::none();
        if (!reference.is_none() && py::array::ensure(reference).ndim() == 2) {
          const Real_array xyz = Real_array::ensure(reference);
          if (xyz.shape(0) != static_cast<py::ssize_t>(sources.size()) || xyz.shape(1) != 3)
            throw expmap::Invalid_input(
                "reference must be 3 numbers or an array (sources, 3) (got shape (" +
                std::to_string(xyz.shape(0)) + ", " + std::to_string(xyz.shape(1)) + "))");
          for (py::ssize_t s = 0; s < xyz.shape(0); ++s)
            references.push_back({{xyz.at(s, 0), xyz.at(s, 1), xyz.at(s, 2)}});
        } else {
          shared_reference = py::reinterpret_borrow<py::object>(reference);
        }
        const typename Method::Query query =
            query_argument<Method>("patch_operator", shared_reference, false, settings);
        expmap::Batch_options options = batch_options_argument(threads_object);
        options.progress = batch_progress_argument(progress);
        expmap::Polar_patch_operator op;
        {
          py::gil_scoped_release release;
          op = expmap::polar_patch_operator(*b.mesh, *b.method, sources, grid, options, query,
                                            references);
        }
        // Columns are the caller's rows (a split vertex's copies are its row).
        const auto entries = static_cast<py::ssize_t>(op.weights.nonZeros());
        py::array_t<double> data(entries);
        py::array_t<std::int64_t> indices(entries);
        py::array_t<std::int64_t> indptr(op.weights.rows() + 1);
        std::copy(op.weights.valuePtr(), op.weights.valuePtr() + entries, data.mutable_data());
        for (py::ssize_t k = 0; k < entries; ++k)
          indices.mutable_data()[k] =
              row_of(b.original, static_cast<std::size_t>(op.weights.innerIndexPtr()[k]));
        std::copy(op.weights.outerIndexPtr(), op.weights.outerIndexPtr() + op.weights.rows() + 1,
                  indptr.mutable_data());
        py::array_t<bool> sampled({static_cast<py::ssize_t>(sources.size()),
                                   static_cast<py::ssize_t>(grid.rings),
                                   static_cast<py::ssize_t>(grid.rays)});
        std::copy(op.sampled.begin(), op.sampled.end(), sampled.mutable_data());
        py::array_t<std::int64_t> source_rows(static_cast<py::ssize_t>(sources.size()));
        std::copy(sources.begin(), sources.end(), source_rows.mutable_data());
        py::list errors;
        for (const std::string& e : op.errors) errors.append(e);
        return py::module_::import("expmap.patches")
            .attr("PolarPatchOperator")(data, indices, indptr, b.rows, source_rows, radius,
                                        grid.rings, grid.rays, sampled, errors);
      },
      py::arg("sources") = py::none(), py::kw_only(), py::arg("radius"), py::arg("rings") = 5,
      py::arg("rays") = 16, py::arg("reference") = py::none(), py::arg("threads") = 0,
      py::arg("progress") = py::none(),
      "patch_operator(sources=None, *, radius, rings=5, rays=16, reference=None,\n"
      "               threads=0, progress=None, **settings) -> PolarPatchOperator\n\n"
      "The polar patch operator of geodesic convolutional networks around\n"
      "``sources`` (rows of the vertex array; None: every vertex): a sparse\n"
      "matrix of shape (sources * rings * rays, vertices) whose row\n"
      "(s, i, j) holds the barycentric weights of the corners of the map's\n"
      "triangle at rho_i = (i + 1/2) radius / rings, theta_j = 2 pi j / rays\n"
      "around source s. Grid points beyond the map's fold-free disk, past a\n"
      "boundary or of a failed query have none (``sampled`` is False there).\n"
      "``op.patches(X)`` resamples a (vertices, channels) signal into\n"
      "(sources, rings, rays, channels). The maps run on ``threads`` threads\n"
      "(0: one per core) without the GIL; ``progress(done, total)`` as for\n"
      "compute_many; the method's query settings as for compute().\n"
      "``reference``: theta = 0, 3 numbers as for compute(), or an array\n"
      "(sources, 3) giving each source its own (e.g. a principal curvature\n"
      "direction, so patches do not depend on a global axis).");
}

}  // namespace

#endif  // EXPMAP_PYTHON_PATCH_OPERATOR_BINDING_H
