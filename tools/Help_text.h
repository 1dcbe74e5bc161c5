// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_HELP_TEXT_H
#define EXPMAP_TOOLS_HELP_TEXT_H

/// \file Help_text.h
/// The help texts of `expmap`, `expmap compute` and `expmap batch`
/// (`expmap view` has its own, in viewer/).

#include <expmap/Heat_options.h>
#include <expmap/Option_names.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace expmap_cli {

/// What `expmap --help` prints first.
inline std::string general_help() {
  return "usage: expmap compute MESH (--source V | --source-point X,Y,Z |\n"
         "                      --source-face F --barycentric A,B,C)\n"
         "                      (--radius R | --fraction F | --vertices K)\n"
         "                      [options] -o OUT [-o OUT ...]\n"
         "       expmap batch MESH (--sources all|I,J,K|@FILE | --source-points FILE)\n"
         "                    (--radius R | --fraction F | --vertices K) [options]\n"
         "                    -o OUT [-o OUT ...]\n"
         "       expmap patches MESH --radius R [--rings K] [--rays L] [options]\n"
         "                      -o OUT.npz\n"
         "       expmap view MESH [--port P] [--host H]\n"
         "       expmap --help | expmap compute --help | expmap batch --help\n"
         "       expmap patches --help | expmap view --help\n"
         "       expmap --version\n"
         "\n"
         "Computes local exponential maps (geodesic polar coordinates r, theta and\n"
         "u = r cos theta, v = r sin theta) around source vertices or points of a\n"
         "triangle mesh.\n"
         "\n"
         "commands:\n"
         "  compute   map one patch and write it as CSV, textured OBJ or SVG\n"
         "  batch     map a patch around each of many sources on all cores and write\n"
         "            them as one CSV or NumPy .npz\n"
         "  patches   the polar patch operator of geodesic convolutional networks\n"
         "            around each of many sources, as a SciPy sparse .npz\n"
         "  view      serve an interactive view in the web browser: click or drag\n"
         "            on the surface to place the source, compare two methods\n"
         "\n"
         "exit status: 0 success, 1 runtime error (file, mesh, computation),\n"
         "             2 usage error (options and their values)\n";
}

/// `text` wrapped to lines of at most 79 characters, each after `indent`
/// spaces but the first, which continues a line `first_column` long.
inline std::string wrapped(const std::string& text, std::size_t indent,
                           std::size_t first_column) {
  std::istringstream words(text);
  std::string out, word;
  std::size_t column = first_column;
  bool line_empty = true;
  while (words >> word) {
    if (!line_empty && column + 1 + word.size() > 79) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
      line_empty = true;
    }
    if (!line_empty) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    line_empty = false;
  }
  return out + "\n";
}

/// The help of a heat setting chosen by name (expmap/Option_names.h): the
/// option, what it sets, and each value with its line of help, the default
/// marked.
template <class Enum>
std::string named_option_help(const char* metavar, Enum default_value) {
  using Names = expmap::Option_names<Enum>;
  std::string head = "  --" + std::string(Names::option) + " " + metavar;
  head.resize(std::max<std::size_t>(head.size() + 1, 23), ' ');
  std::string h = head + wrapped(std::string("heat only: ") + Names::help + "; one of", 23,
                                 head.size());
  for (const auto& v : Names::values) {
    const std::string name = std::string(25, ' ') + v.name +
                             (v.alias ? std::string(" (or ") + v.alias + ")" : "") + ": ";
    h += name + wrapped(std::string(v.help) + (v.value == default_value ? " (default)" : ""),
                        27, name.size());
  }
  return h;
}

/// The help of a numeric heat setting (expmap/Setting_ranges.h): the
/// option, its line of help, `more` after it, its range and `default_text`.
inline std::string numeric_option_help(const expmap::Setting_range& setting, const char* metavar,
                                       const std::string& default_text,
                                       const std::string& more = "") {
  std::string flag = setting.name;
  std::replace(flag.begin(), flag.end(), '_', '-');
  std::string head = "  --" + flag + " " + metavar;
  head.resize(std::max<std::size_t>(head.size() + 1, 23), ' ');
  return head + wrapped(std::string("heat only: ") + setting.help + more + " (" + setting.range +
                            "; default: " + default_text + ")",
                        23, head.size());
}

/// The options of the method and the input, which every command that maps
/// shares; `method_list` lists the methods, one indented line each.
inline std::string method_and_input_help(const std::string& method_list,
                                         const std::string& default_method = "heat") {
  std::ostringstream h;
  const expmap::Heat_options defaults;
  const expmap::Heat_query_options query_defaults;
  h << "method:\n"
       "  --method M           default: " << default_method << "; one of\n";
  h << method_list;
  h << "  --force              exact only: try a map even where its memory estimate\n"
       "                       (by the faces of its submesh: about 1 GB at 40,000,\n"
       "                       some 15,000 patch vertices; per thread in a batch)\n"
       "                       exceeds the memory available; without it such a run\n"
       "                       stops with an error before its first map\n"
    << numeric_option_help(expmap::setting_ranges::time_factor, "T",
                           expmap::setting_value_text(defaults.time_factor))
    << named_option_help("L", defaults.laplacian)
    << named_option_help("A", defaults.vertex_area)
    << named_option_help("P", defaults.factor_precision)
    << numeric_option_help(expmap::setting_ranges::query_threads, "N",
                           std::to_string(query_defaults.query_threads),
                           "; expmap batch on more than one thread gives each a source and "
                           "each map one thread")
    << named_option_help("A", query_defaults.angle_estimator)
    << numeric_option_help(
           expmap::setting_ranges::near_source_blend, "B,E",
           expmap::setting_value_text(query_defaults.near_source_blend.begin) + "," +
               expmap::setting_value_text(query_defaults.near_source_blend.end))
    << named_option_help("F", query_defaults.fallback)
    << "  --reference X,Y,Z    direction of angle 0, projected onto the source's\n"
       "                       tangent plane (default: the x axis, or the y axis where\n"
       "                       the normal is within 30 degrees of x)\n"
       "input (what is repaired is said on stderr as 'expmap: note: ...'):\n"
       "                       The counts a file declares are checked against its\n"
       "                       size first. Faces that are not an oriented 2-manifold\n"
       "                       (random orientation, duplicates, non-manifold\n"
       "                       vertices) are read as a polygon soup and oriented.\n"
       "  --no-triangulate     refuse faces with more than three vertices instead of\n"
       "                       splitting them into triangles (the default, which adds\n"
       "                       no vertex, so indices keep file order; --triangulate\n"
       "                       asks for the default explicitly)\n"
       "  --repair             remove degenerate faces (zero area), needles and caps\n"
       "                       by collapsing and flipping edges; vertex indices in the\n"
       "                       output stay those of the file\n";
  return h.str();
}

/// The options of the patch, the method and the input, which `compute` and
/// `batch` share.
inline std::string map_options_help(const std::string& method_list) {
  return "patch (exactly one):\n"
         "  --radius R           every vertex within geodesic distance R > 0 (mesh units)\n"
         "  --fraction F         the nearest F of all vertices, 0 < F <= 1;\n"
         "                       1 maps the source's whole connected component\n"
         "  --vertices K         the K >= 1 vertices nearest to the source\n"
         "  --trim-folds         with any of them: cut each map to its fold-free disk,\n"
         "                       the vertices nearer than the nearest flipped\n"
         "                       triangle's farthest corner, so none is flipped\n" +
         method_and_input_help(method_list);
}

/// `expmap compute --help`.
inline std::string compute_help(const std::string& method_list) {
  return "usage: expmap compute MESH (--source V | --source-point X,Y,Z |\n"
         "                      --source-face F --barycentric A,B,C)\n"
         "                      (--radius R | --fraction F | --vertices K) [--method M] [--force]\n"
         "                      [--time-factor T]\n"
         "                      [--laplacian L] [--vertex-area A]\n"
         "                      [--factor-precision P] [--query-threads N] [--angles A]\n"
         "                      [--near-source-blend B,E] [--fallback F] [--reference X,Y,Z]\n"
         "                      [--no-triangulate] [--repair] [--trim-folds]\n"
         "                      -o OUT [-o OUT ...]\n"
         "\n"
         "  MESH                 triangle mesh: .off, .obj, .ply or .stl\n"
         "source (exactly one):\n"
         "  --source V           source vertex, 0-based index in file order (STL lists\n"
         "                       no vertices: order of first appearance)\n"
         "  --source-point X,Y,Z the surface point nearest to (X, Y, Z); a note on stderr\n"
         "                       if that is off the surface by more than 1e-6 of the\n"
         "                       bounding box's diagonal\n"
         "  --source-face F      the point of face F (0-based, file order) with\n"
         "  --barycentric A,B,C  barycentric coordinates A, B, C of its corners in the\n"
         "                       file's order (not negative; rescaled to sum 1);\n"
         "                       1,0,0 is the first corner\n"
         "                       A point that is no vertex has no row at r = 0, the\n"
         "                       nearest corner counts as the map's source, and\n"
         "                       --vertices and --fraction count vertices only.\n" +
         map_options_help(method_list) +
         "output (at least one, format by extension; may repeat):\n"
         "  -o, --output OUT     .csv  header vertex,r,theta,u,v; one row per patch\n"
         "                             vertex, nearest first; theta in (-pi, pi]\n"
         "                       .obj  the patch with texture coordinates\n"
         "                             vt = (u/(2R) + 0.5, v/(2R) + 0.5), R = max r\n"
         "                       .svg  the patch flattened in the (u, v) plane, shaded\n"
         "                             by distance, flipped triangles in red\n"
         "  -h, --help           this help\n"
         "\n"
         "Options also accept --name=value. The heat method's precomputation shows its\n"
         "progress on stderr when that is a terminal. A summary (mesh size, timings, patch size,\n"
         "max r, flipped triangles, fold-free radius) goes to stdout; errors go to stderr as\n"
         "'expmap: error: ...' with exit status 1 (runtime) or 2 (usage).\n";
}

/// `expmap batch --help`.
inline std::string batch_help(const std::string& method_list) {
  return "usage: expmap batch MESH (--sources all|I,J,K|@FILE | --source-points FILE)\n"
         "                    (--radius R | --fraction F | --vertices K)\n"
         "                    [--method M] [--force] [--threads N] [--time-factor T]\n"
         "                    [--laplacian L] [--vertex-area A]\n"
         "                    [--factor-precision P] [--query-threads N] [--angles A]\n"
         "                    [--near-source-blend B,E] [--fallback F]\n"
         "                    [--reference X,Y,Z] [--no-triangulate] [--repair]\n"
         "                    [--trim-folds]\n"
         "                    -o OUT [-o OUT ...]\n"
         "\n"
         "  MESH                 triangle mesh: .off, .obj, .ply or .stl\n"
         "  --sources S          the source vertices, 0-based indices in file order\n"
         "                       (required): all (every vertex with a face), a list\n"
         "                       I,J,K, or @FILE (indices separated by spaces, commas\n"
         "                       or newlines; '#' starts a comment); maps come in\n"
         "                       this order, repeats included\n"
         "  --source-points FILE instead of --sources: points, one X,Y,Z a line (commas\n"
         "                       or spaces; '#' starts a comment), each mapped from the\n"
         "                       surface point nearest to it (as compute's\n"
         "                       --source-point); the outputs' source is then the\n"
         "                       point's 0-based position in FILE\n"
         "  --threads N          queries run on N threads (default: 0, all cores)\n" +
         map_options_help(method_list) +
         "output (at least one, format by extension; may repeat):\n"
         "  -o, --output OUT     .csv  header source,vertex,r,theta,u,v,fold_free_radius;\n"
         "                             per source its patch vertices, nearest first,\n"
         "                             each row with its source's fold-free radius\n"
         "                       .npz  NumPy arrays (numpy.load): sources (k),\n"
         "                             offsets (k+1), vertex, r, theta, u, v,\n"
         "                             fold_free_radius (k, NaN where a query failed);\n"
         "                             rows offsets[i] to offsets[i+1] belong to\n"
         "                             sources[i]\n"
         "  -h, --help           this help\n"
         "\n"
         "A progress bar (maps done, maps per second, time left) goes to stderr when it\n"
         "is a terminal; a summary to stdout. A source whose query fails (e.g. an\n"
         "isolated vertex, heat underflow) costs only its own map: it gets a line\n"
         "'expmap: warning: ...' on stderr and no rows (in .npz an empty range), the\n"
         "other maps are written, and the exit status is 1. Other errors go to stderr\n"
         "as 'expmap: error: ...' with exit status 1 (runtime) or 2 (usage), and no\n"
         "output is left behind.\n";
}

/// `expmap patches --help`.
inline std::string patches_help(const std::string& method_list) {
  return "usage: expmap patches MESH --radius R [--rings K] [--rays L]\n"
         "                      [--sources all|I,J,K|@FILE] [--method M] [--threads N]\n"
         "                      [heat options as for batch] [--reference X,Y,Z]\n"
         "                      [--no-triangulate] [--repair] -o OUT.npz\n"
         "\n"
         "The polar patch operator of geodesic convolutional networks: for each source,\n"
         "the grid points rho_i = (i + 1/2) R / rings, theta_j = 2 pi j / rays of its\n"
         "map, each with the barycentric weights of the map's triangle that holds it.\n"
         "\n"
         "  MESH                 triangle mesh: .off, .obj, .ply or .stl\n"
         "  --radius R           the grid's radius R > 0 (mesh units); each source is\n"
         "                       mapped to R plus two mean edge lengths\n"
         "  --rings K            grid points along each ray (default: 5)\n"
         "  --rays L             grid points around each ring (default: 16)\n"
         "  --sources S          as for batch (default: all)\n"
         "  --threads N          maps run on N threads (default: 0, all cores)\n" +
         method_and_input_help(method_list, "dgpc") +
         "output:\n"
         "  -o, --output OUT.npz the operator in SciPy's sparse layout\n"
         "                       (scipy.sparse.load_npz gives a CSR matrix of shape\n"
         "                       (sources * rings * rays, vertices), row\n"
         "                       (s * rings + i) * rays + j for ring i, ray j of source\n"
         "                       s, columns the file's vertices), and the arrays\n"
         "                       sources (k), sampled (k, rings, rays; 0 where a grid\n"
         "                       point lies beyond the map's fold-free disk, past a\n"
         "                       boundary, or its source failed) and radius\n"
         "  -h, --help           this help\n"
         "\n"
         "--method defaults to dgpc here: its maps place grid points closer to the\n"
         "exact map's than the heat method's smoothed ones (manual, section 15).\n"
         "A source whose query fails gets 'expmap: warning: ...' and no weights; the\n"
         "exit status is then 1.\n";
}

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_HELP_TEXT_H
