// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `expmap` command-line program: parse, read the mesh, call the library,
// write. Exit status: 0 success, 1 runtime error (files, mesh, library),
// 2 usage error (options and their values). Every error is one line on
// stderr starting with "expmap: error: ".

#include "Command_line.h"

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
#include <vector>

namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Map = expmap::Local_map<Mesh::Vertex_index>;
using expmap_cli::Compute_arguments;
using expmap_cli::Usage_error;

/// A failure of the run itself (files, mesh): exit status 1.
class Runtime_error : public std::runtime_error {
 public:
  explicit Runtime_error(const std::string& message) : std::runtime_error(message) {}
};

struct Run {
  Map map;
  std::string description;  // the method and its settings, for summary and caption
  double precompute_seconds = 0, query_seconds = 0;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Precomputes with `make()` and answers one query, timing both: the two
// numbers a user of a precompute-once method cares about.
template <class Make>
Run timed_run(Make make, Mesh::Vertex_index source, const expmap::Patch& patch,
              const expmap::Query_options& query) {
  Run run;
  auto start = std::chrono::steady_clock::now();
  const auto method = make();
  run.precompute_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  run.map = method.compute(source, patch, query);
  run.query_seconds = seconds_since(start);
  return run;
}

Run run_heat(const Mesh& mesh, const Compute_arguments& a, Mesh::Vertex_index source,
             const expmap::Patch& patch, const expmap::Query_options& query) {
  expmap::Heat_options options;
  if (a.time_factor) options.time_factor = *a.time_factor;
  if (a.laplacian == std::string("intrinsic-delaunay"))
    options.laplacian = expmap::Laplacian_mode::intrinsic_delaunay;
  else if (a.laplacian == std::string("direct"))
    options.laplacian = expmap::Laplacian_mode::direct;
  if (a.angles == std::string("quadratic-fit"))
    options.angle_estimator = expmap::Angle_estimator::log_heat_quadratic_fit;
  else if (a.angles == std::string("area-weighted"))
    options.angle_estimator = expmap::Angle_estimator::log_heat_gradient;
  Run run = timed_run([&] { return expmap::Heat_exponential_map<Mesh>(mesh, options); }, source,
                      patch, query);
  std::ostringstream d;
  d << "heat method (time factor " << options.time_factor << ", "
    << (options.laplacian == expmap::Laplacian_mode::direct ? "direct" : "intrinsic Delaunay")
    << " Laplacian, "
    << (options.angle_estimator == expmap::Angle_estimator::log_heat_quadratic_fit
            ? "quadratic-fit"
            : "area-weighted")
    << " angles)";
  run.description = d.str();
  return run;
}

// A method without settings of its own: built from the mesh alone.
template <class Method_class>
Run run_plain(const Mesh& mesh, const Compute_arguments&, Mesh::Vertex_index source,
              const expmap::Patch& patch, const expmap::Query_options& query) {
  return timed_run([&] { return Method_class(mesh); }, source, patch, query);
}

// The one place that knows the methods: parsing, help, dispatch and the
// caption all read this table, so a new method is one more row.
struct Method {
  const char* name;
  const char* summary;      // for --help
  const char* description;  // for the summary and the SVG caption (heat adds its settings)
  bool takes_heat_options;  // --time-factor, --laplacian and --angles
  Run (*run)(const Mesh&, const Compute_arguments&, Mesh::Vertex_index, const expmap::Patch&,
             const expmap::Query_options&);
};

const Method methods[] = {
    {"heat", "smoothed, by heat diffusion (Herholz & Alexa)", "heat method", true, run_heat},
    {"dem", "discrete exponential map (Schmidt et al.)", "DEM (discrete exponential map)", false,
     run_plain<expmap::Discrete_exponential_map<Mesh>>},
    {"dgpc", "geodesic polar coordinates (Melvaer & Reimers)",
     "DGPC (discrete geodesic polar coordinates)", false,
     run_plain<expmap::Geodesic_polar_coordinates<Mesh>>},
    {"exact", "exact polyhedral geodesics; slow, a reference", "exact polyhedral exponential map",
     false, run_plain<expmap::Exact_exponential_map<Mesh>>},
};

const Method& find_method(const std::string& name) {
  for (const Method& m : methods)
    if (name == m.name) return m;
  std::string known;
  for (const Method& m : methods) known += std::string(known.empty() ? "" : ", ") + m.name;
  throw Usage_error("unknown method '" + name + "' (known: " + known + ")");
}

std::string general_help() {
  return "usage: expmap compute MESH --source V (--radius R | --fraction F | --vertices K)\n"
         "                      [options] -o OUT [-o OUT ...]\n"
         "       expmap --help | expmap compute --help\n"
         "\n"
         "Computes a local exponential map (geodesic polar coordinates r, theta and\n"
         "u = r cos theta, v = r sin theta) around a source vertex of a triangle mesh.\n"
         "\n"
         "commands:\n"
         "  compute   map one patch and write it as CSV, textured OBJ or SVG\n"
         "\n"
         "exit status: 0 success, 1 runtime error (file, mesh, computation),\n"
         "             2 usage error (options and their values)\n";
}

std::string compute_help() {
  std::ostringstream h;
  const expmap::Heat_options defaults;
  h << "usage: expmap compute MESH --source V (--radius R | --fraction F | --vertices K)\n"
       "                      [--method M] [--time-factor T] [--laplacian L] [--angles A]\n"
       "                      [--reference X,Y,Z] [--no-triangulate] [--repair]\n"
       "                      -o OUT [-o OUT ...]\n"
       "\n"
       "  MESH                 triangle mesh: .off, .obj, .ply or .stl\n"
       "  --source V           source vertex, 0-based index in file order (required;\n"
       "                       STL lists no vertices: order of first appearance)\n"
       "patch (exactly one):\n"
       "  --radius R           every vertex within geodesic distance R > 0 (mesh units)\n"
       "  --fraction F         the nearest F of all vertices, 0 < F <= 1;\n"
       "                       1 maps the source's whole connected component\n"
       "  --vertices K         the K >= 1 vertices nearest to the source\n"
       "method:\n"
       "  --method M           default: heat; one of\n";
  for (const Method& m : methods) {
    std::string name = m.name;
    name.resize(std::max<std::size_t>(name.size() + 1, 7), ' ');
    h << "                         " << name << m.summary << "\n";
  }
  h << "  --time-factor T      heat only: diffusion time t = T h^2, h the mean edge\n"
       "                       length; larger is smoother (default: "
    << defaults.time_factor
    << ")\n"
       "  --laplacian L        heat only: intrinsic-delaunay | direct; the former is\n"
       "                       robust on poorly shaped triangles\n"
       "                       (default: intrinsic-delaunay)\n"
       "  --angles A           heat only: how the angle is read off the heat at the\n"
       "                       source's one-ring: area-weighted (the paper's gradient,\n"
       "                       of log h; smoothest maps) | quadratic-fit (least-squares\n"
       "                       quadratic; more accurate on irregular meshes)\n"
       "                       (default: area-weighted)\n"
       "  --reference X,Y,Z    direction of angle 0, projected onto the source's\n"
       "                       tangent plane (default: the x axis, or the y axis where\n"
       "                       the normal is within 30 degrees of x)\n"
       "input (what is repaired is said on stderr as 'expmap: note: ...'):\n"
       "  --no-triangulate     refuse faces with more than three vertices instead of\n"
       "                       splitting them into triangles (the default, which adds\n"
       "                       no vertex, so indices keep file order; --triangulate\n"
       "                       asks for the default explicitly)\n"
       "  --repair             remove degenerate faces (zero area), needles and caps\n"
       "                       by collapsing and flipping edges; vertex indices in the\n"
       "                       CSV stay those of the file\n"
       "                       Files whose faces are not an oriented 2-manifold (faces\n"
       "                       in random orientation, duplicates, non-manifold\n"
       "                       vertices) are read as a polygon soup and oriented.\n"
       "output (at least one, format by extension; may repeat):\n"
       "  -o, --output OUT     .csv  header vertex,r,theta,u,v; one row per patch\n"
       "                             vertex, nearest first; theta in (-pi, pi]\n"
       "                       .obj  the patch with texture coordinates\n"
       "                             vt = (u/(2R) + 0.5, v/(2R) + 0.5), R = max r\n"
       "                       .svg  the patch flattened in the (u, v) plane, shaded\n"
       "                             by distance, flipped triangles in red\n"
       "  -h, --help           this help\n"
       "\n"
       "Options also accept --name=value. A summary (mesh size, timings, patch size,\n"
       "max r, flipped triangles) goes to stdout; errors go to stderr as\n"
       "'expmap: error: ...' with exit status 1 (runtime) or 2 (usage).\n";
  return h.str();
}

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

// The mesh vertex at position `source` of the file.
Mesh::Vertex_index find_source(const Compute_arguments& a, const Input& input) {
  const auto& file_index = input.report.file_index;
  const auto found = std::find(file_index.begin(), file_index.end(), a.source);
  if (found != file_index.end())
    return Mesh::Vertex_index(static_cast<Mesh::size_type>(found - file_index.begin()));
  const std::size_t n = input.report.file_vertices;
  if (a.source < n)
    throw Runtime_error("--source " + std::to_string(a.source) +
                        " was removed by --repair (it lay on a degenerate face); choose another");
  throw Usage_error("--source " + std::to_string(a.source) + " is out of range: '" + a.mesh +
                    "' has " + std::to_string(n) + " vertices" +
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
  }
  out.close();
  if (!out) throw Runtime_error("could not write all of '" + output.path + "'");
}

int compute(const std::vector<std::string>& args) {
  const Compute_arguments a = expmap_cli::parse_compute_arguments(args);
  if (a.help) {
    std::cout << compute_help();
    return 0;
  }
  const Method& method = find_method(a.method);
  if (!method.takes_heat_options && (a.time_factor || a.laplacian || a.angles))
    throw Usage_error("--time-factor, --laplacian and --angles apply only to --method heat");

  // Fail before the costly part, not after it.
  for (const auto& output : a.outputs) {
    const std::filesystem::path parent = std::filesystem::path(output.path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
      throw Runtime_error("cannot write '" + output.path + "': folder '" + parent.string() +
                          "' does not exist");
  }

  const Input input = read_mesh(a);
  const Mesh& mesh = input.mesh;
  const Mesh::Vertex_index source = find_source(a, input);
  expmap::Query_options query;
  query.reference_direction = a.reference;

  Run run;
  try {
    run = method.run(mesh, a, source, make_patch(a), query);
  } catch (const expmap::Invalid_input& e) {
    // The library names the face; the program knows the option that helps.
    if (!a.repair && std::string(e.what()).find("degenerate") != std::string::npos)
      throw Runtime_error(std::string(e.what()) +
                          " (or run expmap with --repair to remove degenerate faces and needles)");
    throw;
  }
  if (run.description.empty()) run.description = method.description;

  const auto folds = expmap::count_flipped_triangles(mesh, run.map);
  const double max_r =
      run.map.size() ? *std::max_element(run.map.distance.begin(), run.map.distance.end()) : 0.0;
  std::printf("mesh:        %s: %zu vertices, %zu faces\n", a.mesh.c_str(),
              static_cast<std::size_t>(num_vertices(mesh)),
              static_cast<std::size_t>(num_faces(mesh)));
  std::printf("method:      %s\n", run.description.c_str());
  std::printf("precompute:  %.3f s\n", run.precompute_seconds);
  std::printf("query:       %.3f ms\n", 1e3 * run.query_seconds);
  std::printf("patch:       %zu vertices, %zu triangles, source %zu\n", run.map.size(), folds.total,
              a.source);
  std::printf("max r:       %.6g\n", max_r);
  std::printf("flipped:     %zu of %zu triangles\n", folds.flipped, folds.total);
  for (const auto& output : a.outputs) {
    write_output(output, input, run);
    std::printf("wrote:       %s\n", output.path.c_str());
  }
  return 0;
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
      std::cout << general_help() << "\nSee 'expmap compute --help' for the options.\n";
      return 0;
    }
    if (args[0] != "compute")
      throw Usage_error("unknown command '" + args[0] + "' (see expmap --help)");
    return compute(std::vector<std::string>(args.begin() + 1, args.end()));
  } catch (const Usage_error& e) {
    return fail(e.what(), 2);
  } catch (const std::bad_alloc&) {
    return fail("out of memory (try a smaller mesh or patch)", 1);
  } catch (const std::exception& e) {
    // expmap::Invalid_input / Computation_error and CGAL's exceptions: their
    // messages already say what was wrong.
    return fail(e.what(), 1);
  } catch (...) {
    return fail("unexpected internal error", 1);
  }
}
