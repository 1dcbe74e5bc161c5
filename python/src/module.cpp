// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module `expmap._expmap`: the four methods as classes over a
// `CGAL::Surface_mesh` built from NumPy arrays. Queries run without the GIL,
// so Python threads (and Dask workers) can query one object at once.

#include "Face_points.h"
#include "Map_arrays.h"
#include "Mesh_from_arrays.h"

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
#include <climits>
#include <limits>
#include <fstream>
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

/// An option given as a member of the bound enum `E` or by its name.
template <class E>
E enum_argument(py::handle value, const char* option) {
  const py::dict members = py::type::of<E>().attr("__members__");
  if (py::isinstance<py::str>(value)) {
    std::string name = value.cast<std::string>();
    std::replace(name.begin(), name.end(), '-', '_');  // the CLI spells them with hyphens
    if (members.contains(name)) return members[name.c_str()].template cast<E>();
  } else if (py::isinstance<E>(value)) {
    return value.cast<E>();
  }
  std::string known;
  for (auto item : members) known += (known.empty() ? "" : ", ") + item.first.cast<std::string>();
  throw expmap::Invalid_input(std::string(option) + " must be one of " + known + " (got " +
                              py::repr(value).cast<std::string>() + ")");
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

/// The namedtuple type `expmap.BatchMap` (made once, in the module's init;
/// the module keeps it alive for as long as any function can run).
py::handle batch_map_type;

/// Source `i` of `b` (0 <= i < len(b)) as a `BatchMap`: its rows of the flat
/// arrays as NumPy views (basic slices: no copies, and each keeps the flat
/// array alive) and its error, None if its query succeeded.
py::object batch_map(const Batch_arrays& b, std::size_t i) {
  const std::int64_t* offset = b.offsets.data();
  const py::slice rows(static_cast<py::ssize_t>(offset[i]), static_cast<py::ssize_t>(offset[i + 1]),
                       1);
  py::object error = py::none();
  if (!b.errors[i].empty()) error = py::str(b.errors[i]);
  return batch_map_type(b.sources.data()[i], b.vertex[rows], b.r[rows], b.theta[rows], b.u[rows],
                        b.v[rows], error);
}

/// The index `batch[index]` names: any Python integer, negative from the end.
std::size_t batch_index(const Batch_arrays& b, py::handle index) {
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

}  // namespace

// The queries from points of faces, written with the helpers above.
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
         py::handle reference, py::handle threads_object, bool trim_folds,
         const py::kwargs& settings) {
        const Index_array checked = checked_indices(sources_object, "sources", b.rows);
        const std::vector<std::size_t> sources(checked.data(), checked.data() + checked.size());
        const expmap::Patch patch = patch_argument(b, radius, fraction, vertices, vertex_set);
        const typename Method::Query query =
            query_argument<Method>("compute_many", reference, trim_folds, settings);
        const expmap::Batch_options options = batch_options_argument(threads_object);
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
      py::arg("threads") = 0, py::arg("trim_folds") = false,
      (std::string("compute_many(sources, *, radius=None, fraction=None, vertices=None, "
                   "vertex_set=None, reference=None, threads=0, trim_folds=False)\n"
                   "    -> BatchMaps\n\n"
                   "One map per source (a 1-D integer array), computed on ``threads``\n"
                   "threads (0: one per core) without holding the GIL. ") +
       patch_doc +
       "\nA query that fails does not end the batch: its source gets no rows and\n"
       "its message in ``errors``. ``batch[i]`` and ``for m in batch`` give each\n"
       "source's map as a BatchMap of views into the flat arrays. Raises ValueError\n"
       "for invalid arguments (sources out of range, a bad patch).")
          .c_str());
  add_point_queries(c);
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
  py::class_<Bound> c(
      m, "HeatExponentialMap",
      "The smoothed exponential map of Herholz & Alexa (Computer Graphics Forum\n"
      "2019): distances and angles from heat diffusion, by localized solves on\n"
      "Cholesky factors of the whole mesh, computed once at construction.\n\n"
      "    heat = expmap.HeatExponentialMap(V, F)\n"
      "    local = heat.compute(0, fraction=0.05)\n"
      "    local.uv  # n x 2, the patch vertices local.vertices, nearest first\n");
  c.def(py::init([](py::handle vertices, py::handle faces, double time_factor,
                    py::handle laplacian, py::handle vertex_area, py::handle factor_precision,
                    py::handle regularization, double poisson_compression_tolerance,
                    const py::kwargs& rest) {
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
        "Precomputes operators and factorizations of the mesh (vertices: float\n"
        "array n x 3; faces: integer array m x 3, made a mesh as for\n"
        "DiscreteExponentialMap).\n\n"
        "time_factor: diffusion time t = time_factor * h^2, h the mean edge length;\n"
        "    larger is smoother.\n"
        "laplacian: a LaplacianMode or its name ('intrinsic_delaunay', 'direct').\n"
        "vertex_area: a VertexArea or its name ('mixed_voronoi', 'barycentric'): the\n"
        "    heat step's mass matrix.\n"
        "factor_precision: a FactorPrecision or its name ('double_precision',\n"
        "    'single_precision'): how the factors are kept between queries; single\n"
        "    about halves their memory and is faster on large meshes, and moves the\n"
        "    distances by about 2e-7 of the radius.\n"
        "regularization: a PoissonRegularization or its name.\n"
        "poisson_compression_tolerance: the Poisson factor's large separators\n"
        "    compressed to this relative tolerance, their rows below as truncated\n"
        "    SVDs (in [0, 1e-10]; 0: dense); fewer entries read per query on large\n"
        "    meshes.\n\n"
        "compute() and compute_many() take these query settings as keywords too:\n"
        "region_growth: a query solves on a region this many times larger than the\n"
        "    patch (at least 1; default 2).\n"
        "pruning_tolerance: heat solves of small patches of large meshes skip\n"
        "    entries below this times the smallest heat read (in [0, 1e-10]; 0:\n"
        "    never; default 1e-12).\n"
        "angle_estimator: an AngleEstimator or its name (default heat_quadratic_fit:\n"
        "    a quadratic fit of the heat on the two-ring, two solves per query).\n"
        "near_source_blend: (begin, end) in mean edge lengths: chord directions (and\n"
        "    the source's neighbours' edge lengths) up to begin from the source, heat\n"
        "    coordinates from end on, blended between; each query scales both so\n"
        "    the blend ends where the normal has turned by 1 rad (at most 1.5x);\n"
        "    (0, 0) for the paper's pure heat coordinates.\n"
        "fallback: a HeatFallback or its name (default geodesic_front: where the\n"
        "    heat's map folds a triangle over, meets a boundary or fails, the geodesic\n"
        "    front's (DGPC's) map if it folds fewer; 'none': the paper's map always).\n"
        "query_threads: 1 or 2, threads one query runs on; with 2 the angles' solve\n"
        "    runs beside the distance's (the same maps up to round-off, 0.79-0.93x\n"
        "    the time on patches of 750+ vertices). compute_many on more than one\n"
        "    thread runs a source per thread, each on one, and gives the same maps\n"
        "    bit for bit on any number of threads.\n\n"
        "Raises ValueError for bad arrays (see DiscreteExponentialMap) and options\n"
        "(a query's settings when it is asked).");
  add_queries(c);
  c.def_property_readonly(
      "time_step", [](const Bound& b) { return b.method->time_step(); },
      "Diffusion time t = time_factor * h^2.");
  c.def_property_readonly(
      "mean_edge_length", [](const Bound& b) { return b.method->mean_edge_length(); },
      "Mean edge length h of the mesh.");
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

  // The enums are listed once, here; Python code reads them from
  // __members__, never from a list of its own.
  py::enum_<expmap::Laplacian_mode>(m, "LaplacianMode",
                                    "Which triangulation the Laplacian is built on.")
      .value("direct", expmap::Laplacian_mode::direct)
      .value("intrinsic_delaunay", expmap::Laplacian_mode::intrinsic_delaunay);
  py::enum_<expmap::Vertex_area>(m, "VertexArea",
                                 "The area each vertex stands for in the heat step's mass matrix.")
      .value("barycentric", expmap::Vertex_area::barycentric)
      .value("mixed_voronoi", expmap::Vertex_area::mixed_voronoi);
  py::enum_<expmap::Factor_precision>(m, "FactorPrecision",
                                      "The precision the Cholesky factors are kept in.")
      .value("double_precision", expmap::Factor_precision::double_precision)
      .value("single_precision", expmap::Factor_precision::single_precision);
  py::enum_<expmap::Poisson_regularization>(
      m, "PoissonRegularization", "How the singular Poisson system of the distance is made definite.")
      .value("pinned_vertex", expmap::Poisson_regularization::pinned_vertex)
      .value("cgal_compatible", expmap::Poisson_regularization::cgal_compatible);
  py::enum_<expmap::Angle_estimator>(m, "AngleEstimator",
                                     "How the direction of the geodesic is read off the heat.")
      .value("heat_gradient", expmap::Angle_estimator::heat_gradient)
      .value("log_heat_gradient", expmap::Angle_estimator::log_heat_gradient)
      .value("log_heat_quadratic_fit", expmap::Angle_estimator::log_heat_quadratic_fit)
      .value("heat_quadratic_fit", expmap::Angle_estimator::heat_quadratic_fit);

  py::enum_<expmap::Heat_fallback>(m, "HeatFallback",
                                   "What a heat query returns where the heat's angles are blind.")
      .value("geodesic_front", expmap::Heat_fallback::geodesic_front)
      .value("none", expmap::Heat_fallback::none);

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
}
