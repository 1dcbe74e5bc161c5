// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_POINT_QUERIES_H
#define EXPMAP_PYTHON_POINT_QUERIES_H

// The method classes' queries from points of faces: locate(),
// compute_at(), compute_at_point() and compute_many_at_points(). Part of
// module.cpp, which includes it after its argument helpers (Bound_method,
// patch_argument, query_argument, mesh_patch, index_argument, patch_doc) and
// `using namespace expmap_python`; it uses both.

#include "Face_points.h"
#include "Map_arrays.h"

#include <expmap/Batch.h>
#include <expmap/internal/Locality_order.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace {

/// The points of `b`'s faces, made on first use (while holding the GIL, so
/// by one thread at a time; then only read).
template <class Method>
const Face_points& face_points(const Bound_method<Method>& b) {
  if (!b.points) b.points = std::make_unique<const Face_points>(*b.mesh, b.original, b.faces);
  return *b.points;
}

/// Points of space: an array of shape (k, 3), or (3,) for one point (then
/// `single` is set), of finite numbers.
Real_array points_argument(py::handle object, const char* name, bool& single) {
  py::array array = py::array::ensure(object);
  single = array && array.ndim() == 1 && array.shape(0) == 3;
  if (single) array = array.reshape({py::ssize_t(1), py::ssize_t(3)});
  const Real_array points = Real_array::ensure(
      checked_array(array ? py::handle(array) : object, name, 3, "iuf",
                    "a number array of shape (k, 3) or (3,)"));
  const double* x = points.data();
  for (py::ssize_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(x[i]))
      throw expmap::Invalid_input(std::string(name) + " has a coordinate that is not finite (row " +
                                  std::to_string(i / 3) + ")");
  return points;
}

/// Three barycentric coordinates, finite with a finite sum (they are
/// divided by it), none negative, not all zero.
std::array<double, 3> barycentric_argument(py::handle object) {
  bool single = false;
  const Real_array w = points_argument(object, "barycentric", single);
  if (!single) throw expmap::Invalid_input("barycentric must be 3 numbers");
  const std::array<double, 3> b{{w.at(0, 0), w.at(0, 1), w.at(0, 2)}};
  if (b[0] < 0 || b[1] < 0 || b[2] < 0 || !(b[0] + b[1] + b[2] > 0))
    throw expmap::Invalid_input("barycentric must not be negative or all zero (got " +
                                py::repr(object).cast<std::string>() + ")");
  if (!std::isfinite(b[0] + b[1] + b[2]))
    throw expmap::Invalid_input("barycentric must have a finite sum, to be rescaled to sum 1 (got " +
                                py::repr(object).cast<std::string>() + ")");
  return b;
}

/// The mesh vertex of `p`'s corner of largest coordinate: the map's source.
std::size_t nearest_corner(const Mesh& mesh, const Surface_point& p) {
  const auto h = mesh.halfedge(p.face);
  const Mesh::Vertex_index corners[3] = {mesh.source(h), mesh.target(h),
                                         mesh.target(mesh.next(h))};
  const auto k = std::max_element(p.barycentric.begin(), p.barycentric.end()) -
                 p.barycentric.begin();
  return static_cast<std::size_t>(corners[k]);
}

/// The map from `p` (called without the GIL).
template <class Method>
Map compute_from_point(const Bound_method<Method>& b, const Surface_point& p,
                       const expmap::Patch& patch, const typename Method::Query& query) {
  return b.method->compute(p, mesh_patch(b, nearest_corner(*b.mesh, p), patch), query);
}

/// The keywords every point query shares with compute().
#define EXPMAP_PATCH_KEYWORDS                                                            \
  py::kw_only(), py::arg("radius") = py::none(), py::arg("fraction") = py::none(),       \
      py::arg("vertices") = py::none(), py::arg("vertex_set") = py::none(),              \
      py::arg("reference") = py::none()

const char* const point_doc =
    "A point that is no vertex has no row at r = 0; LocalMap.source is its\n"
    "corner of largest coordinate, ``vertices`` and ``fraction`` count vertices\n"
    "only, and angle 0 is ``reference`` projected onto the tangent plane at the\n"
    "point (its normal interpolated from the corners'). A point at a corner\n"
    "gives that vertex's map exactly. ";

template <class Method>
void add_point_queries(py::class_<Bound_method<Method>>& c) {
  using Bound = Bound_method<Method>;
  c.def(
      "locate",
      [](const Bound& b, py::handle points_object) {
        bool single = false;
        const Real_array points = points_argument(points_object, "points", single);
        const Face_points& lookup = face_points(b);
        const py::ssize_t k = points.shape(0);
        Index_array faces(k);
        Real_array barycentric({k, py::ssize_t(3)});
        {
          py::gil_scoped_release release;
          const double* x = points.data();
          std::int64_t* f = faces.mutable_data();
          double* w = barycentric.mutable_data();
          for (py::ssize_t i = 0; i < k; ++i) {
            const auto q = lookup.input_point(lookup.locate({{x[3 * i], x[3 * i + 1], x[3 * i + 2]}}));
            f[i] = static_cast<std::int64_t>(q.face);
            std::copy(q.barycentric.begin(), q.barycentric.end(), w + 3 * i);
          }
        }
        if (single) return py::make_tuple(py::int_(faces.at(0)), barycentric[py::int_(0)]);
        return py::make_tuple(faces, barycentric);
      },
      py::arg("points"),
      "locate(points) -> (faces, barycentric)\n\n"
      "The surface points nearest to ``points`` (float array k x 3): for each, the\n"
      "row of the faces array it lies in (int64, k) and its barycentric\n"
      "coordinates (k x 3) in that row's corner order, as compute_at() takes\n"
      "them (coordinates below 1e-12 are set to 0, so a point at a vertex is\n"
      "that corner exactly). One point (3 numbers) gives (int, 3 floats). An AABB\n"
      "tree of the faces is built on the first point query, O(F log F), then each\n"
      "point costs about O(log F), without the GIL. Raises ValueError for a bad\n"
      "array or a point too far from the mesh to locate: more than 1e8 times the\n"
      "mesh's size (the largest side of its bounding box) from that box.");
  c.def(
      "compute_at",
      [](const Bound& b, py::handle face, py::handle barycentric,
             std::optional<double> radius, std::optional<double> fraction, py::object vertices,
             py::object vertex_set, py::handle reference, bool trim_folds,
             const py::kwargs& settings) {
        const std::size_t f = index_argument(face, "face");
        const std::array<double, 3> w = barycentric_argument(barycentric);
        const expmap::Patch patch = patch_argument(b, radius, fraction, vertices, vertex_set);
        const typename Method::Query query =
            query_argument<Method>("compute_at", reference, trim_folds, settings);
        const Surface_point p = face_points(b).surface_point(f, w);
        Map map;
        {
          py::gil_scoped_release release;
          map = compute_from_point(b, p, patch, query);
        }
        return Map_arrays(map, b.original);
      },
      py::arg("face"), py::arg("barycentric"), EXPMAP_PATCH_KEYWORDS,
      py::arg("trim_folds") = false,
      (std::string("compute_at(face, barycentric, *, radius=None, fraction=None, vertices=None,\n"
                   "           vertex_set=None, reference=None, trim_folds=False) -> LocalMap\n\n"
                   "Geodesic polar coordinates around the point of row ``face`` of the faces\n"
                   "array with barycentric coordinates ``barycentric`` (3 numbers, not\n"
                   "negative, with a finite sum, rescaled to sum 1) of that row's corners, in\n"
                   "its order. ") +
       point_doc + patch_doc +
       "\nTakes the query settings compute() takes. Raises ValueError for a face out\n"
       "of range, bad coordinates or a bad patch.")
          .c_str());
  c.def(
      "compute_at_point",
      [](const Bound& b, py::handle point, std::optional<double> radius,
             std::optional<double> fraction, py::object vertices, py::object vertex_set,
             py::handle reference, bool trim_folds, const py::kwargs& settings) {
        bool single = false;
        const Real_array xyz = points_argument(point, "point", single);
        if (!single) throw expmap::Invalid_input("point must be 3 numbers (use compute_many_at_points)");
        const expmap::Patch patch = patch_argument(b, radius, fraction, vertices, vertex_set);
        const typename Method::Query query =
            query_argument<Method>("compute_at_point", reference, trim_folds, settings);
        const Face_points& lookup = face_points(b);
        Map map;
        {
          py::gil_scoped_release release;
          const Surface_point p = lookup.locate({{xyz.at(0, 0), xyz.at(0, 1), xyz.at(0, 2)}});
          map = compute_from_point(b, p, patch, query);
        }
        return Map_arrays(map, b.original);
      },
      py::arg("point"), EXPMAP_PATCH_KEYWORDS, py::arg("trim_folds") = false,
      (std::string("compute_at_point(point, *, radius=None, fraction=None, vertices=None,\n"
                   "                 vertex_set=None, reference=None, trim_folds=False)\n"
                   "    -> LocalMap\n\n"
                   "As compute_at() from the surface point nearest to ``point`` (3 numbers;\n"
                   "see locate()). ") +
       point_doc + patch_doc +
       "\nRaises ValueError for a bad point (not finite, or too far from the mesh;\n"
       "see locate()) or a bad patch.")
          .c_str());
  c.def(
      "compute_many_at_points",
      [](const Bound& b, py::handle points_object, std::optional<double> radius,
             std::optional<double> fraction, py::object vertices, py::object vertex_set,
             py::handle reference, py::handle threads_object, bool trim_folds,
             const py::kwargs& settings) {
        bool single = false;
        const Real_array points = points_argument(points_object, "points", single);
        const expmap::Patch patch = patch_argument(b, radius, fraction, vertices, vertex_set);
        const typename Method::Query query =
            query_argument<Method>("compute_many_at_points", reference, trim_folds, settings);
        const expmap::Batch_options options = batch_options_argument(threads_object);
        const Face_points& lookup = face_points(b);
        const std::size_t k = static_cast<std::size_t>(points.shape(0));
        std::vector<std::size_t> positions(k);
        for (std::size_t i = 0; i < k; ++i) positions[i] = i;
        expmap::Batch_result<Mesh::Vertex_index> batch;
        {
          py::gil_scoped_release release;
          std::vector<Surface_point> sources;
          std::vector<expmap::internal::Vector3> near;
          const double* x = points.data();
          for (std::size_t i = 0; i < k; ++i) {
            near.push_back({{x[3 * i], x[3 * i + 1], x[3 * i + 2]}});
            sources.push_back(lookup.locate(near.back()));
          }
          batch = expmap::internal::run_batch<Mesh::Vertex_index>(
              positions, options,
              [&](std::size_t i) { return compute_from_point(b, sources[i], patch, query); },
              "source point", expmap::internal::hilbert_order(near));
        }
        return Batch_arrays(positions, batch.maps, std::move(batch.errors), b.original);
      },
      py::arg("points"), EXPMAP_PATCH_KEYWORDS, py::arg("threads") = 0,
      py::arg("trim_folds") = false,
      (std::string("compute_many_at_points(points, *, radius=None, fraction=None,\n"
                   "                       vertices=None, vertex_set=None, reference=None,\n"
                   "                       threads=0, trim_folds=False) -> BatchMaps\n\n"
                   "One map per point of ``points`` (float array k x 3), each as\n"
                   "compute_at_point(), on ``threads`` threads (0: one per core) without\n"
                   "the GIL. BatchMaps.sources holds each map's position in ``points``\n"
                   "(0 to k - 1). ") +
       patch_doc +
       "\nA query that fails costs only its own map (see compute_many()). Every\n"
       "point is located before any map is computed: a bad point (not finite, or\n"
       "too far from the mesh; see locate()) or a bad patch raises ValueError for\n"
       "the whole call, and no map is returned.")
          .c_str());
}

#undef EXPMAP_PATCH_KEYWORDS

}  // namespace

#endif  // EXPMAP_PYTHON_POINT_QUERIES_H
