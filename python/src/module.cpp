// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module `expmap._expmap`: the four methods as classes over a
// `CGAL::Surface_mesh` built from NumPy arrays. Queries run without the GIL,
// so Python threads (and Dask workers) can query one object at once.

#include "Face_points.h"
#include "Map_arrays.h"
#include "Mesh_from_arrays.h"
#include "Named_enums.h"
#include "Numeric_setting_docs.h"
#include "Result_classes.h"

#include <expmap/Batch.h>
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Errors.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>
#include <expmap/Patch.h>
#include <expmap/version.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <string>

namespace py = pybind11;
using namespace expmap_python;

namespace {

/// A mesh file that cannot be opened: Python's OSError, as for open().
class Mesh_file_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A method object and the mesh it was built on (kept alive with it), with
/// the caller's numbering: the mesh may have more vertices than the caller's
/// arrays rows, copies of split non-manifold vertices.
template <class Method>
struct Bound_method {
  std::unique_ptr<Mesh> mesh;
  std::unique_ptr<const Method> method;
  std::size_t rows = 0;                ///< rows of the caller's vertex array
  std::vector<std::size_t> original;   ///< row of each mesh vertex; empty: the identity
  std::vector<std::size_t> component;  ///< of each mesh vertex, if `original` is not empty
  std::vector<std::array<std::size_t, 3>> faces;  ///< the caller's faces, for point sources
  /// Made by the first point query (`face_points()`), while holding the GIL.
  mutable std::unique_ptr<const Face_points> points;
};

/// A label per vertex of `mesh`, equal for vertices joined by faces.
inline std::vector<std::size_t> vertex_components(const Mesh& mesh) {
  std::vector<std::size_t> parent(mesh.number_of_vertices());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (Mesh::Face_index f : mesh.faces()) {
    const std::size_t first = root(mesh.source(mesh.halfedge(f)));
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      parent[root(v)] = first;
  }
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = root(v);
  return parent;
}

/// Says what was changed to make a mesh of the arrays as a UserWarning each.
inline void warn(const std::vector<std::string>& notes) {
  for (const std::string& note : notes)
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 2) != 0)
      throw py::error_already_set();  // warnings turned into errors
}

template <class Method, class Make>
Bound_method<Method> bind_to_arrays(py::handle vertices, py::handle faces, Make make) {
  Arrays_mesh arrays = mesh_from_arrays(vertices, faces);
  warn(arrays.notes);
  Bound_method<Method> bound;
  bound.mesh = std::make_unique<Mesh>(std::move(arrays.mesh));
  bound.rows = arrays.rows;
  bound.original = std::move(arrays.original);
  bound.faces = std::move(arrays.faces);
  if (!bound.original.empty()) bound.component = vertex_components(*bound.mesh);
  py::gil_scoped_release release;  // the precomputation can take seconds
  bound.method = make(*bound.mesh);
  return bound;
}

/// A non-negative integer from any Python integer (int, numpy.int64, ...).
std::size_t index_argument(py::handle value, const char* name) {
  py::int_ integer;
  try {
    integer = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
    if (!integer) throw py::error_already_set();
  } catch (py::error_already_set&) {
    throw expmap::Invalid_input(std::string(name) + " must be an integer (got " +
                                py::repr(value).cast<std::string>() + ")");
  }
  const long long i = PyLong_AsLongLong(integer.ptr());
  if (i == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    throw expmap::Invalid_input(std::string(name) + " is out of range (got " +
                                py::str(integer).cast<std::string>() + ")");
  }
  if (i < 0)
    throw expmap::Invalid_input(std::string(name) + " must not be negative (got " +
                                std::to_string(i) + ")");
  return static_cast<std::size_t>(i);
}

/// A source vertex: a row of the caller's vertex array (a copy made of a
/// split vertex is not one).
template <class Method>
std::size_t source_argument(const Bound_method<Method>& b, py::handle value) {
  const std::size_t s = index_argument(value, "source");
  if (s >= b.rows)
    throw expmap::Invalid_input("source vertex " + std::to_string(s) +
                                " is out of range (the mesh has " + std::to_string(b.rows) +
                                " vertices)");
  return s;
}

/// The patch from exactly one of the keyword arguments; a `vertex_set` in
/// the caller's rows (see `mesh_patch()`).
template <class Method>
expmap::Patch patch_argument(const Bound_method<Method>& b, std::optional<double> radius,
                             std::optional<double> fraction, py::object count,
                             py::object vertex_set) {
  const int given = radius.has_value() + fraction.has_value() + !count.is_none() +
                    !vertex_set.is_none();
  if (given != 1)
    throw expmap::Invalid_input(
        "give exactly one of radius=, fraction=, vertices= or vertex_set= (got " +
        std::to_string(given) + ")");
  if (radius) return expmap::Patch::geodesic_radius(*radius);
  if (fraction) return expmap::Patch::fraction(*fraction);
  if (!count.is_none()) {
    const std::size_t k = index_argument(count, "vertices");
    return expmap::Patch::vertex_count(k);
  }
  const Index_array set = checked_indices(vertex_set, "vertex_set", b.rows);
  return expmap::Patch::vertex_set(std::vector<std::size_t>(set.data(), set.data() + set.size()));
}

/// The patch of a query from `source` in the mesh's vertices: a vertex set
/// of the caller's rows becomes, for each row, its mesh vertices (a split
/// vertex's copies) connected to `source`, or the row's own vertex if none
/// is (which the library then names as not connected). Other patches, and
/// every patch where nothing was split, as they are.
template <class Method>
expmap::Patch mesh_patch(const Bound_method<Method>& b, std::size_t source,
                         const expmap::Patch& patch) {
  if (b.original.empty() || patch.kind() != expmap::Patch::Kind::vertex_set) return patch;
  std::vector<bool> chosen(b.rows, false), reached(b.rows, false);
  for (std::size_t row : patch.vertices()) chosen[row] = true;
  std::vector<std::size_t> vertices;
  for (std::size_t v = 0; v < b.original.size(); ++v)
    if (chosen[b.original[v]] && b.component[v] == b.component[source]) {
      vertices.push_back(v);
      reached[b.original[v]] = true;
    }
  for (std::size_t row : patch.vertices())
    if (!reached[row]) vertices.push_back(row);
  return expmap::Patch::vertex_set(std::move(vertices));
}

/// The shared query options from `reference` (None or 3 numbers; the
/// library checks that they are finite and not along the normal) and
/// `trim_folds`.
expmap::Query_options shared_query_argument(py::handle reference, bool trim_folds) {
  expmap::Query_options query;
  query.trim_folds = trim_folds;
  query.find_fold_free_radius = true;  // LocalMap.fold_free_radius, BatchMaps.fold_free_radius
  if (reference.is_none()) return query;
  py::array array = py::array::ensure(reference);
  if (!array || array.ndim() != 1 || array.shape(0) != 3 ||
      std::string("iuf").find(array.dtype().kind()) == std::string::npos)
    throw expmap::Invalid_input("reference must be 3 numbers (got " +
                                py::repr(reference).cast<std::string>() + ")");
  const Real_array xyz = Real_array::ensure(array);
  query.reference_direction = std::array<double, 3>{{xyz.at(0), xyz.at(1), xyz.at(2)}};
  return query;
}

/// A float from any Python real number.
double number_argument(py::handle value, const char* name) {
  const double x = PyFloat_AsDouble(value.ptr());
  if (x == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw expmap::Invalid_input(std::string(name) + " must be a number (got " +
                                py::repr(value).cast<std::string>() + ")");
  }
  return x;
}

/// The TypeError Python raises for a keyword a function does not take.
[[noreturn]] void unexpected_keyword(const char* function, py::handle key) {
  throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                       py::str(key).cast<std::string>() + "'");
}

/// The settings of one query of `Method`: the shared ones from `reference`;
/// the methods without settings of their own take no other keyword.
template <class Method>
typename Method::Query query_argument(const char* function, py::handle reference,
                                      bool trim_folds, const py::kwargs& settings) {
  for (auto item : settings) unexpected_keyword(function, item.first);
  return shared_query_argument(reference, trim_folds);
}

/// Whether `key` names one of the heat method's query settings.
bool is_heat_query_setting(const std::string& key) {
  for (const char* name : {"region_growth", "pruning_tolerance", "angle_estimator",
                           "near_source_blend", "query_threads", "fallback"})
    if (key == name) return true;
  return false;
}

/// The heat method's query settings (Heat_query_options) by keyword.
template <>
expmap::Heat_query_options query_argument<expmap::Heat_exponential_map<Mesh>>(
    const char* function, py::handle reference, bool trim_folds, const py::kwargs& settings) {
  expmap::Heat_query_options query(shared_query_argument(reference, trim_folds));
  for (auto item : settings) {
    const std::string key = py::str(item.first);
    const py::handle value = item.second;
    if (key == "region_growth") {
      query.region_growth = number_argument(value, "region_growth");
    } else if (key == "pruning_tolerance") {
      query.pruning_tolerance = number_argument(value, "pruning_tolerance");
    } else if (key == "angle_estimator") {
      query.angle_estimator = enum_argument<expmap::Angle_estimator>(value, "angle_estimator");
    } else if (key == "near_source_blend") {
      if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
          py::len(value) != 2)
        throw expmap::Invalid_input("near_source_blend must be (begin, end) (got " +
                                    py::repr(value).cast<std::string>() + ")");
      const py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
      query.near_source_blend = {number_argument(pair[0], "near_source_blend"),
                                 number_argument(pair[1], "near_source_blend")};
    } else if (key == "fallback") {
      query.fallback = enum_argument<expmap::Heat_fallback>(value, "fallback");
    } else if (key == "query_threads") {
      query.query_threads = static_cast<int>(std::min<std::size_t>(
          index_argument(value, "query_threads"), std::numeric_limits<int>::max()));
    } else {
      unexpected_keyword(function, item.first);
    }
  }
  return expmap::checked(query);
}

const char* const patch_doc =
    "The patch is exactly one of: ``radius`` (every vertex within that geodesic\n"
    "distance), ``fraction`` (the nearest fraction of all vertices, in (0, 1]),\n"
    "``vertices`` (the k nearest vertices) or ``vertex_set`` (these vertex\n"
    "indices). ``reference`` is the direction of angle 0 (3 floats), projected\n"
    "onto the source's tangent plane; default: the x axis, or the y axis where\n"
    "the normal is within 30 degrees of x. ``trim_folds=True`` cuts each map to\n"
    "its fold-free disk: only the vertices nearer than ``fold_free_radius``\n"
    "(the source always) stay, so no triangle of the result is flipped.\n";

// The batch options of a `threads=` argument (0: one thread per core).
expmap::Batch_options batch_options_argument(py::handle threads_object) {
  const std::size_t threads = index_argument(threads_object, "threads");
  if (threads > 4096)
    throw expmap::Invalid_input("threads must be at most 4096 (got " + std::to_string(threads) +
                                ")");
  expmap::Batch_options options;
  options.threads = static_cast<unsigned>(threads);
  return options;
}

/// A batch's progress callback that calls the Python callable `progress`
/// (None: none) with (done, total) at most ten times a second and after the
/// last map. The batch calls it under a lock; it takes the GIL.
inline std::function<void(std::size_t, std::size_t)> batch_progress_argument(
    const py::object& progress) {
  if (progress.is_none()) return {};
  if (!PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be callable as progress(done, total) (got " +
                         py::repr(progress).cast<std::string>() + ")");
  using Clock = std::chrono::steady_clock;
  // A borrowed handle: `progress` outlives the batch, and copies of the
  // callback made without the GIL must not count references.
  return [callback = py::handle(progress), last = Clock::time_point()](
             std::size_t done, std::size_t total) mutable {
    const Clock::time_point now = Clock::now();
    if (done < total && now - last < std::chrono::milliseconds(100)) return;
    last = now;
    py::gil_scoped_acquire gil;
    callback(done, total);
  };
}

}  // namespace

// The queries from points of faces and the patch operator, written with the
// helpers above.
#include "Patch_operator_binding.h"
#include "Point_queries.h"

namespace {

/// compute(), compute_many(), the queries from points and the shared
/// properties of every method class.
template <class Method>
void add_queries(py::class_<Bound_method<Method>>& c) {
  using Bound = Bound_method<Method>;
  c.def(
      "compute",
      [](const Bound& b, py::handle source, std::optional<double> radius,
         std::optional<double> fraction, py::object vertices, py::object vertex_set,
         py::handle reference, bool trim_folds, const py::kwargs& settings) {
        const std::size_t s = source_argument(b, source);
        const expmap::Patch patch =
            mesh_patch(b, s, patch_argument(b, radius, fraction, vertices, vertex_set));
        const typename Method::Query query =
            query_argument<Method>("compute", reference, trim_folds, settings);
        Map map;
        {
          py::gil_scoped_release release;
          map = b.method->compute_by_index(s, patch, query);
        }
        return Map_arrays(map, b.original);
      },
      py::arg("source"), py::kw_only(), py::arg("radius") = py::none(),
      py::arg("fraction") = py::none(), py::arg("vertices") = py::none(),
      py::arg("vertex_set") = py::none(), py::arg("reference") = py::none(),
      py::arg("trim_folds") = false,
      (std::string("compute(source, *, radius=None, fraction=None, vertices=None, "
                   "vertex_set=None, reference=None, trim_folds=False) -> LocalMap\n\n"
                   "Geodesic polar coordinates around vertex ``source`` (0-based row of\n"
                   "the vertex array). ") +
       patch_doc +
       "\nRaises ValueError (InvalidInput) for invalid input (a source out of range\n"
       "or isolated, a bad patch) and RuntimeError (ComputationError) when the\n"
       "computation fails (e.g. heat underflow: choose a larger time factor or a\n"
       "smaller patch).")
          .c_str());
  c.def(
      "compute_many",
      [](const Bound& b, py::handle sources_object, std::optional<double> radius,
         std::optional<double> fraction, py::object vertices, py::object vertex_set,
         py::handle reference, py::handle threads_object, bool trim_folds, py::object progress,
         const py::kwargs& settings) {
        const Index_array checked = checked_indices(sources_object, "sources", b.rows);
        const std::vector<std::size_t> sources(checked.data(), checked.data() + checked.size());
        const expmap::Patch patch = patch_argument(b, radius, fraction, vertices, vertex_set);
        const typename Method::Query query =
            query_argument<Method>("compute_many", reference, trim_folds, settings);
        expmap::Batch_options options = batch_options_argument(threads_object);
        options.progress = batch_progress_argument(progress);
        expmap::Batch_result<Mesh::Vertex_index> batch;
        {
          py::gil_scoped_release release;
          if (b.original.empty() || patch.kind() != expmap::Patch::Kind::vertex_set)
            batch = b.method->compute_many_by_index(sources, patch, options, query);
          else  // a vertex set on the sheets of each source
            batch = expmap::internal::run_batch<Mesh::Vertex_index>(
                sources, options, [&](std::size_t s) {
                  return b.method->compute_by_index(s, mesh_patch(b, s, patch), query);
                });
        }
        return Batch_arrays(sources, batch.maps, std::move(batch.errors), b.original);
      },
      py::arg("sources"), py::kw_only(), py::arg("radius") = py::none(),
      py::arg("fraction") = py::none(), py::arg("vertices") = py::none(),
      py::arg("vertex_set") = py::none(), py::arg("reference") = py::none(),
      py::arg("threads") = 0, py::arg("trim_folds") = false, py::arg("progress") = py::none(),
      (std::string("compute_many(sources, *, radius=None, fraction=None, vertices=None, "
                   "vertex_set=None, reference=None, threads=0, trim_folds=False,\n"
                   "             progress=None) -> BatchMaps\n\n"
                   "One map per source (a 1-D integer array), computed on ``threads``\n"
                   "threads (0: one per core) without holding the GIL. ") +
       patch_doc +
       "\nA query that fails does not end the batch: its source gets no rows and\n"
       "its message in ``errors``. ``batch[i]`` and ``for m in batch`` give each\n"
       "source's map as a BatchMap of views into the flat arrays. ``progress``:\n"
       "None, or a callable progress(done, total) called about ten times a\n"
       "second and after the last map; an exception it raises stops the batch.\n"
       "Raises ValueError for invalid arguments (sources out of range, a bad\n"
       "patch).")
          .c_str());
  add_point_queries(c);
  add_patch_operator(c);
  c.def_property_readonly(
      "number_of_vertices", [](const Bound& b) { return b.rows; },
      "Number of vertices of the mesh: rows of the vertex array it was built from.");
}

template <class Method>
py::class_<Bound_method<Method>> bind_plain_method(py::module_& m, const char* name,
                                                   const std::string& doc) {
  py::class_<Bound_method<Method>> c(m, name, doc.c_str());
  c.def(py::init([](py::handle vertices, py::handle faces) {
          return bind_to_arrays<Method>(vertices, faces, [](const Mesh& mesh) {
            return std::make_unique<const Method>(mesh);
          });
        }),
        py::arg("vertices"), py::arg("faces"),
        "Builds the method on the mesh (vertices: float array n x 3; faces:\n"
        "integer array m x 3, each row a triangle of vertex rows).\n"
        "The faces are made a mesh as a file's are (read_mesh): if they are not\n"
        "an oriented 2-manifold they are oriented and duplicates dropped, and a\n"
        "vertex at a non-manifold edge or where sheets touch (a bow tie) is split\n"
        "into one copy per sheet; each change is a UserWarning naming the split\n"
        "vertices. Results name a copy by its vertex's row, so one row may appear\n"
        "twice in a map; a source row maps the sheet that kept the row (the\n"
        "manual, section 11).\n"
        "Raises ValueError for arrays of the wrong shape or dtype, non-finite\n"
        "coordinates, out-of-range indices, a face repeating a vertex, and\n"
        "meshes the method rejects.");
  add_queries(c);
  return c;
}

void bind_heat(py::module_& m) {
  using Method = expmap::Heat_exponential_map<Mesh>;
  using Bound = Bound_method<Method>;
  const expmap::Heat_options defaults;
  const expmap::Heat_query_options query_defaults;
  namespace ranges = expmap::setting_ranges;
  py::class_<Bound> c(
      m, "HeatExponentialMap",
      "The smoothed exponential map of Herholz & Alexa (Computer Graphics Forum\n"
      "2019): distances and angles from heat diffusion, by localized solves on\n"
      "Cholesky factors of the whole mesh, computed once at construction, or on\n"
      "large meshes of geodesic balls around the sources, factored as queries\n"
      "need them.\n\n"
      "    heat = expmap.HeatExponentialMap(V, F)\n"
      "    local = heat.compute(0, fraction=0.05)\n"
      "    local.uv  # n x 2, the patch vertices local.vertices, nearest first\n");
  c.def(py::init([](py::handle vertices, py::handle faces, double time_factor,
                    py::handle laplacian, py::handle vertex_area, py::handle factor_precision,
                    py::handle regularization, double poisson_compression_tolerance,
                    std::size_t subdomain_min_vertices, std::size_t subdomain_cache_bytes,
                    py::object progress, const py::kwargs& rest) {
          for (auto item : rest) {
            const std::string key = py::str(item.first);
            if (is_heat_query_setting(key))
              throw py::type_error("HeatExponentialMap() got an unexpected keyword argument '" +
                                   key + "': it is a query setting, given to compute() and "
                                   "compute_many()");
            unexpected_keyword("HeatExponentialMap", item.first);
          }
          expmap::Heat_options options;
          options.time_factor = time_factor;
          options.laplacian = enum_argument<expmap::Laplacian_mode>(laplacian, "laplacian");
          options.vertex_area = enum_argument<expmap::Vertex_area>(vertex_area, "vertex_area");
          options.factor_precision =
              enum_argument<expmap::Factor_precision>(factor_precision, "factor_precision");
          options.regularization =
              enum_argument<expmap::Poisson_regularization>(regularization, "regularization");
          options.poisson_compression_tolerance = poisson_compression_tolerance;
          options.subdomain_min_vertices = subdomain_min_vertices;
          options.subdomain_cache_bytes = subdomain_cache_bytes;
          if (!progress.is_none()) {
            if (!PyCallable_Check(progress.ptr()))
              throw py::type_error("progress must be callable as progress(step, fraction) (got " +
                                   py::repr(progress).cast<std::string>() + ")");
            // A borrowed handle: `progress` outlives the precomputation, and
            // copies of the callback made without the GIL must not count
            // references.
            options.progress = [callback = py::handle(progress)](const char* step,
                                                                 double fraction) {
              py::gil_scoped_acquire gil;
              callback(step, fraction);
            };
          }
          return bind_to_arrays<Method>(vertices, faces, [&](const Mesh& mesh) {
            return std::make_unique<const Method>(mesh, options);
          });
        }),
        py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("time_factor") = defaults.time_factor,
        py::arg("laplacian") = defaults.laplacian,
        py::arg("vertex_area") = defaults.vertex_area,
        py::arg("factor_precision") = defaults.factor_precision,
        py::arg("regularization") = defaults.regularization,
        py::arg("poisson_compression_tolerance") = defaults.poisson_compression_tolerance,
        py::arg("subdomain_min_vertices") = defaults.subdomain_min_vertices,
        py::arg("subdomain_cache_bytes") = defaults.subdomain_cache_bytes,
        py::arg("progress") = py::none(),
        std::string("Precomputes operators and factorizations of the mesh (vertices: float\n"
        "array n x 3; faces: integer array m x 3, made a mesh as for\n"
        "DiscreteExponentialMap).\n\n" +
         numeric_setting_doc(ranges::time_factor, expmap::setting_value_text(defaults.time_factor)) +
         enum_setting_doc("laplacian", "LaplacianMode", defaults.laplacian) +
         enum_setting_doc("vertex_area", "VertexArea", defaults.vertex_area) +
         enum_setting_doc("factor_precision", "FactorPrecision", defaults.factor_precision) +
         enum_setting_doc("regularization", "PoissonRegularization", defaults.regularization) +
         numeric_setting_doc(ranges::poisson_compression_tolerance,
                             expmap::setting_value_text(defaults.poisson_compression_tolerance)) +
         numeric_setting_doc(ranges::subdomain_min_vertices,
                             std::to_string(defaults.subdomain_min_vertices)) +
         numeric_setting_doc(ranges::subdomain_cache_bytes,
                             std::to_string(defaults.subdomain_cache_bytes)) +
        "progress: None, or a callable progress(step, fraction) called at the start\n"
        "    of each step of the precomputation with its name and the estimated\n"
        "    share of the time done before it, and at the end with ('done', 1.0);\n"
        "    an exception it raises cancels the precomputation and leaves the\n"
        "    constructor.\n"
        "\ncompute() and compute_many() take these query settings as keywords too:\n" +
         numeric_setting_doc(ranges::region_growth,
                             expmap::setting_value_text(query_defaults.region_growth)) +
         numeric_setting_doc(ranges::pruning_tolerance,
                             expmap::setting_value_text(query_defaults.pruning_tolerance)) +
         enum_setting_doc("angle_estimator", "AngleEstimator", query_defaults.angle_estimator) +
         numeric_setting_doc(ranges::near_source_blend,
                             "(" + expmap::setting_value_text(query_defaults.near_source_blend.begin) +
                                 ", " +
                                 expmap::setting_value_text(query_defaults.near_source_blend.end) + ")",
                             "; each query scales both so "
                             "the blend ends where the normal has turned by 1 rad (at most 1.5x)") +
         enum_setting_doc("fallback", "HeatFallback", query_defaults.fallback) +
         numeric_setting_doc(ranges::query_threads, std::to_string(query_defaults.query_threads),
                             "; compute_many on more than one thread runs a source per thread, "
                             "each on one, and gives the same maps bit for bit on any number of "
                             "threads") +
        "\n"
        "Raises ValueError for bad arrays (see DiscreteExponentialMap) and options\n"
        "(a query's settings when it is asked).")
            .c_str());
  add_queries(c);
  c.def_property_readonly(
      "time_step", [](const Bound& b) { return b.method->time_step(); },
      "Diffusion time t = time_factor * h^2.");
  c.def_property_readonly(
      "mean_edge_length", [](const Bound& b) { return b.method->mean_edge_length(); },
      "Mean edge length h of the mesh.");
  c.def_property_readonly(
      "uses_subdomains", [](const Bound& b) { return b.method->uses_subdomains(); },
      "Whether queries solve on geodesic balls around their sources (meshes of\n"
      "subdomain_min_vertices or more) instead of the whole mesh's factors.");
  c.def_property_readonly(
      "subdomain_bytes", [](const Bound& b) { return b.method->subdomain_bytes(); },
      "Bytes the cached subdomains hold now (bounded by subdomain_cache_bytes).");
  c.def(
      "factor_whole_mesh",
      [](const Bound& b, py::object progress) {
        if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
          throw py::type_error("progress must be callable as progress(step, fraction) (got " +
                               py::repr(progress).cast<std::string>() + ")");
        expmap::Precomputation_callback callback;
        if (!progress.is_none())
          callback = [handle = py::handle(progress)](const char* step, double fraction) {
            py::gil_scoped_acquire gil;
            handle(step, fraction);
          };
        py::gil_scoped_release release;
        b.method->factor_whole_mesh(callback);
      },
      py::arg("progress") = py::none(),
      "factor_whole_mesh(progress=None)\n\n"
      "On subdomains (uses_subdomains), factors the whole mesh now, as the first\n"
      "query with a large or vertex-set patch would (a minute on millions of\n"
      "vertices), reporting its steps to progress(step, fraction) as the\n"
      "constructor does; does nothing once it is factored.");
  c.def(
      "near_source_blend_at",
      [](const Bound& b, py::handle source, const py::kwargs& settings) {
        const expmap::Heat_query_options query =
            query_argument<Method>("near_source_blend_at", py::none(), false, settings);
        const expmap::Near_source_blend blend =
            b.method->near_source_blend_at(source_argument(b, source), query);
        return std::make_pair(blend.begin, blend.end);
      },
      py::arg("source"),
      "near_source_blend_at(source, **settings) -> (begin, end)\n\n"
      "The near-source blend a query from vertex ``source`` with these query\n"
      "settings (e.g. near_source_blend=(2, 6)) uses, in mean edge lengths: the\n"
      "setting's, scaled so that it ends where the surface normal has turned by\n"
      "1 rad (at most 1.5x). Raises ValueError for a source out of range or\n"
      "isolated.");
}

}  // namespace

PYBIND11_MODULE(_expmap, m) {
  m.doc() =
      "Local exponential maps (geodesic polar coordinates) on triangle meshes: the\n"
      "compiled part of the `expmap` package.";
  m.attr("__version__") = EXPMAP_VERSION_STRING;

  py::register_exception<expmap::Invalid_input>(m, "InvalidInput", PyExc_ValueError)
      .attr("__doc__") = "Input the library cannot use (expmap::Invalid_input); a ValueError.";
  static py::exception<expmap::Computation_error>& computation_error =
      py::register_exception<expmap::Computation_error>(m, "ComputationError",
                                                        PyExc_RuntimeError);
  computation_error.attr("__doc__") =
      "A computation that failed on valid input (expmap::Computation_error), e.g. heat\n"
      "underflow; a RuntimeError.";
  py::register_exception<Mesh_file_error>(m, "MeshFileError", PyExc_OSError)
      .attr("__doc__") = "A mesh file that is missing or cannot be opened; an OSError.";
  // Any other C++ exception from this module (a dependency's or the standard
  // library's, whose text speaks of their internals) is a ComputationError
  // in the library's words; ours, pybind11's and Python's own pass on to the
  // translators above.
  py::register_local_exception_translator([](std::exception_ptr thrown) {
    try {
      std::rethrow_exception(thrown);
    } catch (const expmap::Invalid_input&) {
      throw;
    } catch (const expmap::Computation_error&) {
      throw;
    } catch (const Mesh_file_error&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw;  // MemoryError
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const py::error_already_set&) {
      throw;
    } catch (const std::exception& e) {
      computation_error(expmap::internal::user_message(e).c_str());
    }
  });

  // Python code reads the enums' names from __members__, never from a list of
  // its own; the names are the library's (expmap/Option_names.h).
  bind_named_enum<expmap::Laplacian_mode>(m, "LaplacianMode");
  bind_named_enum<expmap::Vertex_area>(m, "VertexArea");
  bind_named_enum<expmap::Factor_precision>(m, "FactorPrecision");
  bind_named_enum<expmap::Poisson_regularization>(m, "PoissonRegularization");
  bind_named_enum<expmap::Angle_estimator>(m, "AngleEstimator");
  bind_named_enum<expmap::Heat_fallback>(m, "HeatFallback");
  bind_result_classes(m);

  m.def(
      "read_mesh",
      [](py::handle path_object, bool triangulate, bool repair, bool return_file_index) {
        // str, bytes or any os.PathLike (pathlib.Path).
        const std::string path =
            py::module_::import("os").attr("fsdecode")(path_object).cast<std::string>();
        if (!std::ifstream(path))
          throw Mesh_file_error("cannot open mesh file '" + path + "' (missing or not readable)");
        Mesh mesh;
        expmap::IO::Mesh_reading_options options;
        options.triangulate = triangulate;
        options.repair = repair;
        expmap::IO::Mesh_reading_report report;
        {
          py::gil_scoped_release release;
          report = expmap::IO::read_triangle_mesh(path, mesh, options);
        }
        // What the reader repaired, as the command-line program's notes.
        for (const std::string& note : report.notes)
          if (PyErr_WarnEx(PyExc_UserWarning, ("'" + path + "': " + note).c_str(), 1) != 0)
            throw py::error_already_set();  // warnings turned into errors
        py::tuple arrays = arrays_from_mesh(mesh);
        if (!return_file_index) return py::object(arrays);
        return py::object(py::make_tuple(arrays[0], arrays[1], array_of(std::vector<std::int64_t>(
                                                                   report.file_index.begin(),
                                                                   report.file_index.end()))));
      },
      py::arg("path"), py::arg("triangulate") = true, py::arg("repair") = false,
      py::arg("return_file_index") = false,
      "read_mesh(path, triangulate=True, repair=False, return_file_index=False)\n"
      "    -> (vertices, faces) or (vertices, faces, file_index)\n\n"
      "Reads a .off, .obj, .ply or .stl mesh with the library's reader\n"
      "(expmap::IO::read_triangle_mesh, as the command-line program does): vertices\n"
      "float64 n x 3, faces int64 m x 3. Faces that are not an oriented 2-manifold\n"
      "are read as a polygon soup and oriented; a vertex where sheets meet is\n"
      "split into one copy per sheet, the copies after the file's vertices;\n"
      "polygons are split into triangles (no vertex added) unless triangulate is\n"
      "False; repair removes degenerate faces and needles, and with them\n"
      "vertices. Vertex i is file vertex file_index[i] (the identity unless a\n"
      "vertex was split or removed). Each repair is reported as a UserWarning.\n"
      "Raises OSError (MeshFileError) if the file cannot be opened and ValueError\n"
      "if it is malformed or (triangulate=False) has a face that is not a triangle.");

  bind_heat(m);
  bind_plain_method<expmap::Discrete_exponential_map<Mesh>>(
      m, "DiscreteExponentialMap",
      "The discrete exponential map (Schmidt et al., SIGGRAPH 2006): a Dijkstra\n"
      "front that carries tangent vectors from vertex to vertex.\n\n"
      "    dem = expmap.DiscreteExponentialMap(V, F)\n"
      "    local = dem.compute(0, radius=0.1)\n");
  bind_plain_method<expmap::Geodesic_polar_coordinates<Mesh>>(
      m, "GeodesicPolarCoordinates",
      "Discrete geodesic polar coordinates (Melvaer & Reimers, Computer Graphics\n"
      "Forum 2012): a Dijkstra-like front with distances and angles updated\n"
      "across triangles.\n\n"
      "    dgpc = expmap.GeodesicPolarCoordinates(V, F)\n"
      "    local = dgpc.compute(0, vertices=200)\n");
  bind_plain_method<expmap::Exact_exponential_map<Mesh>>(
      m, "ExactExponentialMap",
      "The exact polyhedral exponential map (CGAL's Surface_mesh_shortest_path):\n"
      "slow, a reference for the others.\n\n"
      "    exact = expmap.ExactExponentialMap(V, F)\n"
      "    local = exact.compute(0, fraction=0.01)\n");

  // expmap.METHODS: the classes by the library's method names.
  using expmap::Map_method;
  const std::pair<Map_method, const char*> classes[] = {
      {Map_method::heat, "HeatExponentialMap"},
      {Map_method::dem, "DiscreteExponentialMap"},
      {Map_method::dgpc, "GeodesicPolarCoordinates"},
      {Map_method::exact, "ExactExponentialMap"}};
  static_assert(std::size(classes) == std::size(expmap::Option_names<Map_method>::values),
                "a method of expmap::Map_method has no Python class");
  py::dict methods;
  for (const auto& [method, name] : classes) methods[expmap::to_string(method).c_str()] = m.attr(name);
  m.attr("METHODS") = methods;
}
