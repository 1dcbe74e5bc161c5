// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `expmap` command-line program: parse, read the mesh, call the library,
// write. Exit status: 0 success, 1 runtime error (files, mesh, library),
// 2 usage error (options and their values). Every error is one line on
// stderr starting with "expmap: error: ".

#include "Batch_output.h"
#include "Batch_table.h"
#include "Command_line.h"
#include "Exact_memory.h"
#include "Help_text.h"
#include "Point_sources.h"
#include "Progress_bar.h"
#ifdef EXPMAP_WITH_VIEWER
#include "viewer/View_command.h"
#endif

#include <expmap/Batch.h>
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Errors.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Fold_overs.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>
#include <expmap/IO/write_csv.h>
#include <expmap/IO/write_svg.h>
#include <expmap/IO/write_textured_obj.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/Surface_point.h>
#include <expmap/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Map = expmap::Local_map<Mesh::Vertex_index>;
using Surface_point = expmap::Surface_point<Mesh::Face_index>;
/// The source of `expmap compute`: a vertex or a point of a face.
using Source = std::variant<Mesh::Vertex_index, Surface_point>;
using expmap_cli::Batch_arguments;
using expmap_cli::Batch_output;
using expmap_cli::Compute_arguments;
using expmap_cli::Runtime_error;
using expmap_cli::Usage_error;

struct Run {
  Map map;
  std::string description;  // the method and its settings, for summary and caption
  double precompute_seconds = 0, query_seconds = 0;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Precomputes with `make()` and answers one query, timing both: the two
// numbers a user of a precompute-once method cares about. `check(method)`
// comes between them.
template <class Make, class Check, class Query>
Run timed_run(Make make, Check check, const Source& source, const expmap::Patch& patch,
              const Query& query) {
  Run run;
  auto start = std::chrono::steady_clock::now();
  const auto method = make();
  run.precompute_seconds = seconds_since(start);
  check(method);
  start = std::chrono::steady_clock::now();
  run.map = std::visit([&](const auto& s) { return method.compute(s, patch, query); },
                       source);
  run.query_seconds = seconds_since(start);
  return run;
}

using Heat = expmap::Heat_exponential_map<Mesh>;

expmap::Heat_options heat_options(const Compute_arguments& a) {
  expmap::Heat_options options;
  if (a.time_factor) options.time_factor = *a.time_factor;
  if (a.laplacian) options.laplacian = *a.laplacian;
  if (a.vertex_area) options.vertex_area = *a.vertex_area;
  if (a.factor_precision) options.factor_precision = *a.factor_precision;
  return options;
}

// The settings of one query: those all methods share, and the heat
// method's own.
template <class Method_class>
typename Method_class::Query query_settings(const Compute_arguments&,
                                            const expmap::Query_options& shared) {
  return shared;
}
template <>
expmap::Heat_query_options query_settings<Heat>(const Compute_arguments& a,
                                                const expmap::Query_options& shared) {
  expmap::Heat_query_options query(shared);
  if (a.angles) query.angle_estimator = *a.angles;
  if (a.near_source_blend) query.near_source_blend = *a.near_source_blend;
  if (a.fallback) query.fallback = *a.fallback;
  if (a.query_threads) query.query_threads = *a.query_threads;
  return query;
}

// How a method is built from the command line for maps of `patch`: from
// the mesh alone, or for the heat method with its settings (and, on a
// large mesh whose maps of `patch` need the whole mesh's factors, those,
// with their progress shown).
template <class Method_class>
Method_class make_method(const Mesh& mesh, const Compute_arguments&, const expmap::Patch&) {
  return Method_class(mesh);
}
template <>
Heat make_method<Heat>(const Mesh& mesh, const Compute_arguments& a, const expmap::Patch& patch) {
  expmap::Heat_options options = heat_options(a);
  expmap_cli::Precomputation_line line;
  options.progress = line.callback();
  Heat heat(mesh, options);
  if (heat.may_factor_whole_mesh(patch)) heat.factor_whole_mesh(line.callback());
  return heat;
}

// The method's settings in words for the summary and the SVG caption; ""
// for methods without settings (the table's description is used).
template <class Method_class>
std::string settings_description(const Compute_arguments&) {
  return "";
}
template <>
std::string settings_description<Heat>(const Compute_arguments& a) {
  const expmap::Heat_options options = heat_options(a);
  const expmap::Heat_query_options query = query_settings<Heat>(a, {});
  std::ostringstream d;
  // Short enough for the SVG caption's one line.
  d << "heat (m = " << options.time_factor;
  d << ", "
    << (options.laplacian == expmap::Laplacian_mode::direct ? "direct" : "iDT")
    << (options.vertex_area == expmap::Vertex_area::barycentric ? ", barycentric areas" : "")
    << (options.factor_precision == expmap::Factor_precision::single_precision
            ? ", single-precision factors"
            : "")
    << (query.query_threads > 1 ? ", 2 threads per query" : "")
    << ", "
    << expmap::to_string(query.angle_estimator) << " angles, chords "
    << query.near_source_blend.begin << "h to " << query.near_source_blend.end
    << "h scaled by the bend"
    << (query.fallback == expmap::Heat_fallback::none ? ", no fallback" : "") << ")";
  return d.str();
}

// Before maps of `method`, `maps_at_once` at a time, from `sources`: an
// exact run whose largest submesh may not fit in memory is refused
// (Exact_memory.h); the other methods' maps need no such check.
template <class Method_class>
void check_memory(const Method_class&, const Compute_arguments&, const std::vector<Source>&,
                  const expmap::Patch&, unsigned) {}
template <>
void check_memory(const expmap::Exact_exponential_map<Mesh>& method, const Compute_arguments& a,
                  const std::vector<Source>& sources, const expmap::Patch& patch,
                  unsigned maps_at_once) {
  const std::size_t cap = expmap_cli::exact_region_faces_to_count(maps_at_once);
  if (cap == 0) return;  // the memory available is not known
  std::size_t largest = 0;
  for (const Source& source : sources) {
    try {
      const auto count = [&](const auto& s) { return method.region_faces(s, patch, cap); };
      largest = std::max(largest, std::visit(count, source));
    } catch (const expmap::Invalid_input&) {
      // The query fails with the same message, for this source only.
    }
  }
  expmap_cli::check_exact_memory(largest, maps_at_once, a.force);
}

template <class Method_class>
Run run_one(const Mesh& mesh, const Compute_arguments& a, const Source& source,
            const expmap::Patch& patch, const expmap::Query_options& query) {
  Run run = timed_run([&] { return make_method<Method_class>(mesh, a, patch); },
                      [&](const Method_class& m) { check_memory(m, a, {source}, patch, 1); }, source,
                      patch, query_settings<Method_class>(a, query));
  run.description = settings_description<Method_class>(a);
  return run;
}

struct Batch_run {
  std::string description;  // as Run::description
  double precompute_seconds = 0, batch_seconds = 0;
  std::size_t rows = 0;
  std::vector<std::string> errors;  // one per failed source, in source order
};

/// The sources of `expmap batch`: mesh vertex indices, or (if not empty)
/// points of faces.
struct Batch_sources {
  std::vector<std::size_t> vertices;
  std::vector<Surface_point> points;
  std::size_t size() const { return points.empty() ? vertices.size() : points.size(); }
};

// The maps of `sources[first, first + count)`, from vertices or points.
template <class Method_class, class Query>
expmap::Batch_result<Mesh::Vertex_index> compute_part(const Method_class& method,
                                                      const Batch_sources& sources,
                                                      std::size_t first, std::size_t count,
                                                      const expmap::Patch& patch,
                                                      const expmap::Batch_options& options,
                                                      const Query& query) {
  if (sources.points.empty())
    return method.compute_many_by_index(
        {sources.vertices.begin() + first, sources.vertices.begin() + first + count}, patch,
        options, query);
  return method.compute_many(
      std::vector<Surface_point>(sources.points.begin() + first,
                                 sources.points.begin() + first + count),
      patch, options, query);
}

// check_memory() for a batch of `sources`: at 16 of them (radius patches
// differ from source to source), as many maps at once as it runs threads.
template <class Method_class>
void check_batch_memory(const Method_class& method, const Batch_arguments& a,
                        const Batch_sources& sources, const expmap::Patch& patch) {
  std::vector<Source> sampled;
  for (std::size_t i = 0; i < sources.size(); i += std::max<std::size_t>(1, sources.size() / 16))
    sampled.push_back(sources.points.empty()
                          ? Source(Mesh::Vertex_index(static_cast<Mesh::size_type>(sources.vertices[i])))
                          : Source(sources.points[i]));
  const unsigned threads = a.threads ? a.threads : std::max(1u, std::thread::hardware_concurrency());
  check_memory(method, a, sampled, patch,
               static_cast<unsigned>(std::min<std::size_t>(threads, sources.size())));
}

// Precomputes and maps every source, a chunk of sources at a time: a chunk
// holds about `rows_in_flight` rows (the first, small one measures the patch
// size), so memory does not grow with the number of sources.
template <class Method_class>
Batch_run run_many(const Mesh& mesh, const Batch_arguments& a, const Batch_sources& sources,
                   const expmap::Patch& patch, const expmap::Query_options& query,
                   Batch_output& output) {
  const std::size_t rows_in_flight = std::size_t(1) << 22;
  Batch_run run;
  auto start = std::chrono::steady_clock::now();
  const auto method = make_method<Method_class>(mesh, a, patch);
  run.precompute_seconds = seconds_since(start);
  run.description = settings_description<Method_class>(a);
  check_batch_memory(method, a, sources, patch);

  start = std::chrono::steady_clock::now();
  expmap_cli::Progress_bar bar(sources.size());
  expmap::Batch_options options;
  options.threads = a.threads;
  std::size_t done = 0;
  options.progress = [&](std::size_t k, std::size_t) { bar.update(done + k); };
  while (done < sources.size()) {
    const std::size_t rows_per_map = done ? std::max<std::size_t>(1, run.rows / done) : 0;
    const std::size_t chunk = std::min(sources.size() - done,
                                       rows_per_map ? std::max<std::size_t>(64, rows_in_flight / rows_per_map) : 64);
    const auto result = compute_part(method, sources, done, chunk, patch, options,
                                     query_settings<Method_class>(a, query));
    expmap_cli::Batch_table table;
    for (std::size_t i = 0; i < chunk; ++i) {
      table.append(sources.points.empty() ? sources.vertices[done + i] : done + i, result.maps[i]);
      if (!result.errors[i].empty()) run.errors.push_back(result.errors[i]);
    }
    output.write(table);
    run.rows += table.rows();
    done += chunk;
  }
  bar.finish();
  run.batch_seconds = seconds_since(start);
  return run;
}

}  // namespace

#include "Patches_command.h"

namespace {

// The one place that knows the methods: parsing, help, dispatch and the
// caption all read this table, so a new method is one more row.
struct Method {
  expmap::Map_method id;    // its name and --help line are the library's (Option_names.h)
  const char* description;  // for the summary and the SVG caption (heat adds its settings)
  bool takes_heat_options;  // --time-factor, --laplacian, --angles and the like
  Run (*run)(const Mesh&, const Compute_arguments&, const Source&, const expmap::Patch&,
             const expmap::Query_options&);
  Batch_run (*run_many)(const Mesh&, const Batch_arguments&, const Batch_sources&,
                        const expmap::Patch&, const expmap::Query_options&, Batch_output&);
  Patches_run (*run_patches)(const Mesh&, const expmap_cli::Patches_arguments&,
                             const Batch_sources&, const expmap::Query_options&);
  std::string name() const { return expmap::to_string(id); }
};

template <class Method_class>
constexpr Method method_row(expmap::Map_method id, const char* description,
                            bool takes_heat_options) {
  return {id,           description,          takes_heat_options, run_one<Method_class>,
          run_many<Method_class>, run_patches<Method_class>};
}

const Method methods[] = {
    method_row<Heat>(expmap::Map_method::heat, "heat method", true),
    method_row<expmap::Discrete_exponential_map<Mesh>>(
        expmap::Map_method::dem, "DEM (discrete exponential map)", false),
    method_row<expmap::Geodesic_polar_coordinates<Mesh>>(
        expmap::Map_method::dgpc, "DGPC (discrete geodesic polar coordinates)", false),
    method_row<expmap::Exact_exponential_map<Mesh>>(
        expmap::Map_method::exact, "exact polyhedral exponential map", false),
};
static_assert(std::size(methods) == std::size(expmap::Option_names<expmap::Map_method>::values),
              "a method of expmap::Map_method has no row here");

const Method& find_method(const std::string& name) {
  try {
    const expmap::Map_method id = expmap::from_string<expmap::Map_method>(name);
    for (const Method& m : methods)
      if (m.id == id) return m;
  } catch (const expmap::Invalid_input& e) {
    throw Usage_error(e.what());
  }
  throw Usage_error("method '" + name + "' is not built into this program");
}

// The --method lines of the help, from the library's table.
std::string method_list() {
  std::string lines;
  for (const auto& m : expmap::Option_names<expmap::Map_method>::values) {
    std::string name = m.name;
    name.resize(std::max<std::size_t>(name.size() + 1, 7), ' ');
    lines += "                         " + name + m.help + "\n";
  }
  return lines;
}

std::string compute_help() { return expmap_cli::compute_help(method_list()); }
std::string batch_help() { return expmap_cli::batch_help(method_list()); }
std::string patches_help() { return expmap_cli::patches_help(method_list()); }

// The mesh as the methods need it, and where its vertices are in the file.
struct Input {
  Mesh mesh;
  expmap::IO::Mesh_reading_report report;
};

Input read_mesh(const Compute_arguments& a) {
  if (!std::ifstream(a.mesh))
    throw Runtime_error("cannot open mesh file '" + a.mesh + "' (missing or not readable)");
  Input input;
  expmap::IO::Mesh_reading_options options;
  options.triangulate = a.triangulate;
  options.repair = a.repair;
  input.report = expmap::IO::read_triangle_mesh(a.mesh, input.mesh, options);
  if (!input.report.notes.empty()) {
    std::string note;
    for (const std::string& n : input.report.notes) note += (note.empty() ? "" : "; ") + n;
    std::fflush(stdout);
    std::cerr << "expmap: note: '" << a.mesh << "': " << note << "\n";
  }
  if (!CGAL::is_triangle_mesh(input.mesh)) {
    std::size_t polygons = 0;
    for (auto f : input.mesh.faces()) polygons += input.mesh.degree(f) > 3;
    throw Runtime_error("'" + a.mesh + "' has " + std::to_string(polygons) +
                        " faces with more than three vertices and --no-triangulate was given");
  }
  return input;
}

// For each vertex of the file, the mesh vertex standing for it (the first,
// if a non-manifold vertex was split), or `removed_vertex` if --repair
// removed it.
constexpr std::size_t removed_vertex = static_cast<std::size_t>(-1);
std::vector<std::size_t> mesh_vertex_of_file_vertex(const Input& input) {
  std::vector<std::size_t> mesh_vertex(input.report.file_vertices, removed_vertex);
  for (std::size_t i = input.report.file_index.size(); i-- > 0;)
    mesh_vertex[input.report.file_index[i]] = i;
  return mesh_vertex;
}

// The mesh vertex at position `index` of the file; `what` says where the
// index came from ("--source").
Mesh::Vertex_index find_file_vertex(const std::string& what, std::size_t index,
                                    const std::vector<std::size_t>& mesh_vertex,
                                    const Compute_arguments& a) {
  if (index < mesh_vertex.size() && mesh_vertex[index] != removed_vertex)
    return Mesh::Vertex_index(static_cast<Mesh::size_type>(mesh_vertex[index]));
  const std::size_t n = mesh_vertex.size();
  if (index < n)
    throw Runtime_error(what + " " + std::to_string(index) +
                        " was removed by --repair (it lay on a degenerate face); choose another");
  throw Usage_error(what + " " + std::to_string(index) + " is out of range: '" + a.mesh + "' has " +
                    std::to_string(n) + " vertices" +
                    (n ? " (0 to " + std::to_string(n - 1) + ")" : ""));
}

expmap::Patch make_patch(const Compute_arguments& a) {
  if (a.radius) return expmap::Patch::geodesic_radius(*a.radius);
  if (a.fraction) return expmap::Patch::fraction(*a.fraction);
  return expmap::Patch::vertex_count(*a.vertex_count);
}

void write_output(const expmap_cli::Output& output, const Input& input, const Run& run) {
  const Mesh& mesh = input.mesh;
  std::ofstream out(output.path);
  if (!out) throw Runtime_error("cannot create output file '" + output.path + "'");
  switch (output.format) {
    case expmap_cli::Output_format::csv: {
      Map in_file_order = run.map;  // --repair renumbers the mesh; the CSV speaks of the file
      for (std::size_t& i : in_file_order.indices) i = input.report.file_index[i];
      expmap::IO::write_local_map_csv(out, in_file_order);
      break;
    }
    case expmap_cli::Output_format::obj:
      expmap::IO::write_textured_obj(out, mesh, run.map);
      break;
    case expmap_cli::Output_format::svg: {
      expmap::IO::Svg_options options;
      options.method = run.description;
      expmap::IO::write_svg(out, mesh, run.map, options);
      break;
    }
    case expmap_cli::Output_format::npz:  // refused by parse_compute_arguments
      break;
  }
  out.close();
  if (!out) throw Runtime_error("could not write all of '" + output.path + "'");
}

// The method asked for, after the checks both commands make before the
// costly part: its settings apply to it, and the outputs' folders exist.
const Method& checked_method(const Compute_arguments& a) {
  const Method& method = find_method(a.method);
  if (a.force && a.method != "exact") throw Usage_error("--force applies only to --method exact");
  if (!method.takes_heat_options && (a.time_factor || a.laplacian ||
                                     a.vertex_area || a.factor_precision || a.query_threads ||
                                     a.angles || a.near_source_blend || a.fallback))
    throw Usage_error(
        "--time-factor, --laplacian, --vertex-area, --factor-precision, --query-threads, "
        "--angles, --near-source-blend and --fallback apply only to --method heat");
  for (const auto& output : a.outputs) {
    const std::filesystem::path parent = std::filesystem::path(output.path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
      throw Runtime_error("cannot write '" + output.path + "': folder '" + parent.string() +
                          "' does not exist");
  }
  return method;
}

// Runs `f`, adding to the library's complaint about a degenerate face how
// to get past it.
template <class F>
auto with_repair_hint(const Compute_arguments& a, F f) -> decltype(f()) {
  try {
    return f();
  } catch (const expmap::Invalid_input& e) {
    // The library names the face; the program knows the option that helps.
    if (!a.repair && std::string(e.what()).find("degenerate") != std::string::npos)
      throw Runtime_error(std::string(e.what()) +
                          " (or run expmap with --repair to remove degenerate faces and needles)");
    throw;
  }
}

void print_mesh_summary(const Compute_arguments& a, const Mesh& mesh) {
  std::printf("mesh:        %s: %zu vertices, %zu faces\n", a.mesh.c_str(),
              static_cast<std::size_t>(num_vertices(mesh)),
              static_cast<std::size_t>(num_faces(mesh)));
}

// What every command does first: parse (or print help), check the method
// and the outputs, read the mesh; then `command(arguments, method, input)`.
template <class Arguments, class Command>
int run_command(const std::vector<std::string>& args, Arguments (*parse)(const std::vector<std::string>&),
                std::string (*help)(), Command command) {
  const Arguments a = parse(args);
  if (a.help) {
    std::cout << help();
    return 0;
  }
  const Method& method = checked_method(a);
  const Input input = read_mesh(a);
  return command(a, method, input);
}

// The source of `expmap compute` and how the summary names it.
std::pair<Source, std::string> compute_source(const Compute_arguments& a, const Input& input) {
  if (a.point_option.empty())
    return {find_file_vertex("--source", a.source, mesh_vertex_of_file_vertex(input), a),
            "source " + std::to_string(a.source)};
  expmap_cli::Point_sources<Mesh> points(input.mesh, input.report.file_index, a.mesh);
  const Surface_point p = a.source_point ? points.locate({*a.source_point}, "--source-point")[0]
                                         : points.from_file_face(*a.source_face, *a.barycentric);
  return {p, "source " + points.describe(p)};
}

int compute(const Compute_arguments& a, const Method& method, const Input& input) {
  const Mesh& mesh = input.mesh;
  const std::pair<Source, std::string> named_source = compute_source(a, input);
  const Source& source = named_source.first;
  const std::string& source_name = named_source.second;
  expmap::Query_options query;
  query.reference_direction = a.reference;
  query.trim_folds = a.trim_folds;
  query.find_fold_free_radius = true;  // the summary prints it

  Run run = with_repair_hint(a, [&] { return method.run(mesh, a, source, make_patch(a), query); });
  if (run.description.empty()) run.description = method.description;

  const auto folds = expmap::count_flipped_triangles(mesh, run.map);
  const double max_r =
      run.map.size() ? *std::max_element(run.map.distance.begin(), run.map.distance.end()) : 0.0;
  print_mesh_summary(a, mesh);
  std::printf("method:      %s\n", run.description.c_str());
  std::printf("precompute:  %.3f s\n", run.precompute_seconds);
  std::printf("query:       %.3f ms\n", 1e3 * run.query_seconds);
  std::printf("patch:       %zu vertices, %zu triangles, %s\n", run.map.size(), folds.total,
              source_name.c_str());
  std::printf("max r:       %.6g\n", max_r);
  std::printf("flipped:     %zu of %zu triangles\n", folds.flipped, folds.total);
  if (run.map.statistics.front_maps > 0)
    std::printf("angles:      carried outward along the geodesic front (the heat's map folds "
                "more here)\n");
  // Where the map is one-to-one, against the patch's own radius.
  const double fold_free = run.map.fold_free_radius.value_or(0.0);
  std::printf("fold-free:   %.6g", fold_free);
  if (max_r > 0) std::printf(" (%.3f of max r)", fold_free / max_r);
  std::printf("%s\n", a.trim_folds ? ", trimmed by --trim-folds" : "");
  for (const auto& output : a.outputs) {
    write_output(output, input, run);
    std::printf("wrote:       %s\n", output.path.c_str());
  }
  return 0;
}

// The sources in a file: indices separated by white space or commas, '#'
// to the end of a line a comment.
std::vector<std::size_t> read_source_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Runtime_error("cannot open source file '" + path + "' (missing or not readable)");
  std::vector<std::size_t> sources;
  std::size_t line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      try {
        sources.push_back(expmap_cli::parse_index("a source", word));
      } catch (const Usage_error&) {
        throw Runtime_error("source file '" + path + "', line " + std::to_string(line_number) +
                            ": '" + word + "' is not a vertex index (a non-negative integer)");
      }
    }
  }
  if (sources.empty()) throw Runtime_error("source file '" + path + "' lists no vertex");
  return sources;
}

// The sources of a batch: the points of --source-points located on the
// surface, or mesh vertex indices from file indices that must all be in
// range; "all" is every vertex of the file in file order but those --repair
// removed and isolated ones, which have no map.
Batch_sources batch_sources(const Batch_arguments& a, const Input& input) {
  using Kind = expmap_cli::Source_selection::Kind;
  Batch_sources sources;
  if (!a.source_points_file.empty()) {
    expmap_cli::Point_sources<Mesh> points(input.mesh, input.report.file_index, a.mesh);
    sources.points = points.locate(expmap_cli::read_point_file(a.source_points_file),
                                   "--source-points '" + a.source_points_file + "'");
    return sources;
  }
  const std::vector<std::size_t> mesh_vertex = mesh_vertex_of_file_vertex(input);
  if (a.sources.kind == Kind::all) {
    for (std::size_t v : mesh_vertex)
      if (v != removed_vertex && !input.mesh.is_isolated(Mesh::Vertex_index(static_cast<Mesh::size_type>(v))))
        sources.vertices.push_back(v);
    return sources;
  }
  for (std::size_t s : a.sources.kind == Kind::list ? a.sources.list : read_source_file(a.sources.file))
    sources.vertices.push_back(
        static_cast<std::size_t>(find_file_vertex("--sources: vertex", s, mesh_vertex, a)));
  return sources;
}

int batch(const Batch_arguments& a, const Method& method, const Input& input) {
  const Mesh& mesh = input.mesh;
  const Batch_sources sources = batch_sources(a, input);
  expmap::Query_options query;
  query.reference_direction = a.reference;
  query.trim_folds = a.trim_folds;
  query.find_fold_free_radius = true;  // a column of every output
  const unsigned threads = a.threads ? a.threads : std::max(1u, std::thread::hardware_concurrency());

  Batch_output output(a.outputs, input.report.file_index, !sources.points.empty());
  Batch_run run = with_repair_hint(
      a, [&] { return method.run_many(mesh, a, sources, make_patch(a), query, output); });
  output.finish();
  if (run.description.empty()) run.description = method.description;

  const std::size_t maps = sources.size() - run.errors.size();
  print_mesh_summary(a, mesh);
  std::printf("method:      %s\n", run.description.c_str());
  std::printf("precompute:  %.3f s\n", run.precompute_seconds);
  std::printf("maps:        %zu of %zu sources in %.3f s on %u threads, %.1f maps/s\n", maps,
              sources.size(), run.batch_seconds,
              threads,
              run.batch_seconds > 0 ? static_cast<double>(sources.size()) / run.batch_seconds : 0.0);
  std::printf("rows:        %zu (%.1f patch vertices per map)\n", run.rows,
              maps ? static_cast<double>(run.rows) / static_cast<double>(maps) : 0.0);
  for (const auto& out : a.outputs) std::printf("wrote:       %s\n", out.path.c_str());
  if (run.errors.empty()) return 0;
  std::fflush(stdout);
  for (const std::string& e : run.errors) std::cerr << "expmap: warning: " << e << "\n";
  std::cerr << "expmap: error: " << run.errors.size() << " of " << sources.size()
            << " sources failed (see the warnings above); the other maps were written\n";
  return 1;
}

int patches(const expmap_cli::Patches_arguments& a, const Method& method, const Input& input) {
  const Batch_sources sources = batch_sources(a, input);
  expmap::Query_options query;
  query.reference_direction = a.reference;
  const Patches_run run = with_repair_hint(
      a, [&] { return method.run_patches(input.mesh, a, sources, query); });
  const expmap::Polar_patch_operator& op = run.op;
  write_patch_operator_npz(a.outputs[0].path, op, input.report.file_index,
                           input.report.file_vertices);
  std::size_t sampled = 0;
  for (unsigned char s : op.sampled) sampled += s;
  print_mesh_summary(a, input.mesh);
  std::printf("method:      %s\n", run.description.empty() ? method.description
                                                          : run.description.c_str());
  std::printf("precompute:  %.3f s\n", run.precompute_seconds);
  std::printf("operator:    %zu sources, %zu x %zu grid of radius %g, in %.3f s\n",
              op.sources.size(), a.rings, a.rays, *a.radius, run.operator_seconds);
  std::printf("sampled:     %zu of %zu grid points (%zu weights)\n", sampled, op.sampled.size(),
              static_cast<std::size_t>(op.weights.nonZeros()));
  std::printf("wrote:       %s\n", a.outputs[0].path.c_str());
  std::size_t failed = 0;
  std::fflush(stdout);
  for (const std::string& e : op.errors)
    if (!e.empty()) {
      std::cerr << "expmap: warning: " << e << "\n";
      ++failed;
    }
  if (failed == 0) return 0;
  std::cerr << "expmap: error: " << failed << " of " << op.sources.size()
            << " sources failed (see the warnings above); their grid points have no weights\n";
  return 1;
}

int fail(const std::string& message, int status) {
  std::fflush(stdout);
  std::cerr << "expmap: error: " << message << "\n";
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw Usage_error("no command given (see expmap --help)");
    if (args[0] == "-h" || args[0] == "--help") {
      std::cout << expmap_cli::general_help()
                << "\nSee 'expmap compute --help', 'expmap batch --help' and 'expmap patches "
                   "--help' for the options.\n";
      return 0;
    }
    if (args[0] == "--version") {
      if (args.size() > 1) throw Usage_error("--version takes no other arguments");
      std::cout << "expmap " EXPMAP_VERSION_STRING "\n";
      return 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "compute")
      return run_command(rest, expmap_cli::parse_compute_arguments, compute_help, compute);
    if (args[0] == "batch")
      return run_command(rest, expmap_cli::parse_batch_arguments, batch_help, batch);
    if (args[0] == "patches")
      return run_command(rest, expmap_cli::parse_patches_arguments, patches_help, patches);
    if (args[0] == "view") {
#ifdef EXPMAP_WITH_VIEWER
      return expmap_view::run_view_command(rest);
#else
      throw Runtime_error(
          "this expmap was built without the viewer (it needs cpp-httplib and npm: run "
          "scripts/install-dependencies.sh and configure again)");
#endif
    }
    throw Usage_error("unknown command '" + args[0] + "' (see expmap --help)");
  } catch (const Usage_error& e) {
    return fail(e.what(), 2);
  } catch (const std::bad_alloc&) {
    return fail("out of memory (try a smaller mesh or patch)", 1);
  } catch (const Runtime_error& e) {
    return fail(e.what(), 1);
  } catch (const std::exception& e) {
    // The library's own messages as they are, any other in its words.
    return fail(expmap::internal::user_message(e), 1);
  } catch (...) {
    return fail("unexpected internal error", 1);
  }
}
