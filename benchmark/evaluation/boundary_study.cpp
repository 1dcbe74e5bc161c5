// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-boundary-study: the four methods at sources on and near the
// boundary of every demo mesh that has one, against the exact map, and at
// sources of the same mesh whose patch stays clear of the boundary.
//
// For each mesh with a boundary (read as the `expmap` program reads it),
// Boundary_sources.h picks up to --sources boundary vertices spread along
// the loops and, for each, the nearest vertex one and two rings in (rings
// 0, 1, 2), and up to --interior vertices spread over the mesh where no
// method's patch holds a boundary vertex (ring "interior"). Each
// method maps a --fraction patch from each source; each map gets its
// flipped triangles and, against the exact map, its mean |dtheta| after the
// best rotation (no reflection) and its mean relative |dr|
// (Map_agreement.h). A CSV gets one row per (mesh, source, ring, method);
// stdout a summary per mesh and ring with the targets of
// Boundary_quality_targets.h, PASS or FAIL, where "all" pools the three
// boundary rings and leaves the interior out. A second table tells per
// mesh whether the interior sources miss the targets the boundary rings
// miss: if they do, the miss is what the mesh costs the heat method, not
// what the boundary costs it.
//
//   --meshes DIR        the demo meshes (default: the project's data/meshes)
//   --mesh NAME         only this file of DIR (repeatable)
//   --fraction F        patch size as a fraction of the mesh (default 0.05)
//   --sources N         boundary sources per mesh (default 12)
//   --interior N        interior sources per mesh (default 12; 0: none)
//   --max-vertices N    skip meshes with more vertices (default: none);
//                       the exact map costs most on the big ones
//   --heat-fallback F   the heat method's fallback: geodesic-front (the
//                       default) or none (the paper's map everywhere)
//   --csv FILE          per-map rows (default boundary_study.csv)
//   --summary-csv FILE  the summary rows as CSV too (default: none)

#include "Boundary_quality_targets.h"
#include "Boundary_sources.h"
#include "Common.h"
#include "Map_agreement.h"
#include "Methods.h"

#include <expmap/Discrete_exponential_map.h>
#include <expmap/Errors.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>
#include <expmap/Patch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace expmap_evaluation;

struct Options {
  fs::path meshes = EXPMAP_BOUNDARY_STUDY_MESHES;
  std::vector<std::string> only;
  double fraction = 0.05;
  std::size_t sources = 12;
  std::size_t interior = 12;
  std::size_t max_vertices = 0;  // 0: no limit
  expmap::Heat_fallback heat_fallback = expmap::Heat_fallback::geodesic_front;
  fs::path csv = "boundary_study.csv";
  fs::path summary_csv;
};

const char* usage_text() {
  return "usage: expmap-boundary-study [--meshes DIR] [--mesh NAME ...] [--fraction F]\n"
         "                             [--sources N] [--interior N] [--max-vertices N]\n"
         "                             [--heat-fallback F] [--csv FILE] [--summary-csv FILE]\n";
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--meshes") o.meshes = value();
    else if (a == "--mesh") o.only.push_back(value());
    else if (a == "--fraction") o.fraction = std::stod(value());
    else if (a == "--sources") o.sources = std::stoul(value());
    else if (a == "--interior") o.interior = std::stoul(value());
    else if (a == "--max-vertices") o.max_vertices = std::stoul(value());
    else if (a == "--heat-fallback") o.heat_fallback = expmap::from_string<expmap::Heat_fallback>(value());
    else if (a == "--csv") o.csv = value();
    else if (a == "--summary-csv") o.summary_csv = value();
    else throw std::invalid_argument("unknown argument " + a);
  }
  expmap::Patch::fraction(o.fraction);  // throws with a message if out of range
  if (o.sources == 0) throw std::invalid_argument("--sources must be positive");
  return o;
}

/// A source as the study labels it.
struct Study_source {
  std::size_t vertex = 0;
  std::string ring;  // "0", "1", "2" (hops from the boundary) or "interior"
  std::optional<std::size_t> boundary_vertex;  // the boundary source it was chosen for
};

/// The boundary sources, labelled by ring, then the interior ones.
std::vector<Study_source> study_sources(const std::vector<Boundary_source>& boundary,
                                        const std::vector<std::size_t>& interior) {
  std::vector<Study_source> sources;
  for (const Boundary_source& s : boundary)
    sources.push_back({s.vertex, std::to_string(s.ring), s.boundary_vertex});
  for (std::size_t v : interior) sources.push_back({v, "interior", std::nullopt});
  return sources;
}

/// One method's map of one source.
struct Measured_map {
  std::optional<Map_agreement> agreement;  // none if the query failed
  std::string error;
  std::size_t patch_vertices = 0;
  std::size_t boundary_vertices = 0;  // of the patch
  double seconds = 0;
};

/// The study's order of methods; the exact map first, as the others are
/// compared with it.
const std::vector<std::string> method_keys = {"exact", "heat", "dem", "dgpc"};

Method_set make_methods(const Mesh& mesh, expmap::Heat_fallback fallback) {
  Method_set set(mesh);
  set.add<expmap::Exact_exponential_map>("exact", "exact");
  expmap::Heat_query_options query;
  query.fallback = fallback;
  set.add_heat("heat", "heat", expmap::Heat_options(), query);
  set.add<expmap::Discrete_exponential_map>("dem", "DEM");
  set.add<expmap::Geodesic_polar_coordinates>("dgpc", "DGPC");
  return set;
}

std::size_t boundary_vertices_in(const Map& map, const std::vector<bool>& on_boundary) {
  return static_cast<std::size_t>(std::count_if(
      map.indices.begin(), map.indices.end(), [&](std::size_t v) { return on_boundary[v]; }));
}

/// The four maps of one source, measured against the exact one.
std::map<std::string, Measured_map> measure_source(const Mesh& mesh, const Method_set& set,
                                                   std::size_t source, const expmap::Patch& patch,
                                                   const std::vector<bool>& on_boundary) {
  std::map<std::string, Measured_map> measured;
  std::optional<Map> exact;
  for (const Method& method : set.methods) {
    Measured_map& m = measured[method.key];
    const auto start = std::chrono::steady_clock::now();
    try {
      const Map map = method.compute(source, patch);
      m.seconds = seconds_since(start);
      m.patch_vertices = map.size();
      m.boundary_vertices = boundary_vertices_in(map, on_boundary);
      if (method.key == "exact") exact = map;
      m.agreement = exact ? map_agreement(mesh, map, *exact) : map_agreement(mesh, map);
    } catch (const expmap::Invalid_input& e) {
      m.error = e.what();
    } catch (const expmap::Computation_error& e) {
      m.error = e.what();
    }
    if (!m.agreement) m.seconds = seconds_since(start);
  }
  return measured;
}

/// The interior sources of `mesh` (Boundary_sources.h) for patches of
/// `patch`: those where the exact map exists and no method's patch holds a
/// boundary vertex. Each method grows its patch by its own distances, and
/// the heat method's patch can take in boundary vertices where the exact
/// one stays clear; such a source would measure the boundary again.
/// `declined` counts the candidates turned down.
std::vector<std::size_t> checked_interior_sources(const Mesh& mesh, const Method_set& set,
                                                  const expmap::Patch& patch, std::size_t budget,
                                                  std::size_t& declined) {
  const std::vector<bool> on_boundary = vertex_graph(mesh).on_boundary;
  const auto no_patch_reaches_boundary = [&](std::size_t v) {
    const auto measured = measure_source(mesh, set, v, patch, on_boundary);
    bool clear = measured.at("exact").agreement.has_value();
    for (const auto& [key, m] : measured) clear = clear && m.boundary_vertices == 0;
    if (!clear) ++declined;
    return clear;
  };
  return interior_sources(mesh, patch.target_count(num_vertices(mesh)), budget,
                          no_patch_reaches_boundary);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string number(double x, int digits = 4) {
  if (std::isnan(x)) return "nan";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

const char* csv_header =
    "mesh,mesh_vertices,source,ring,boundary_vertex,method,patch_vertices,"
    "patch_boundary_vertices,triangles,flipped,flipped_fraction,mean_dtheta,rotation,"
    "mean_relative_dr,common_vertices,seconds,error\n";

void write_csv_row(std::ostream& csv, const std::string& mesh_name, std::size_t mesh_vertices,
                   const Study_source& s, const std::string& method, const Measured_map& m) {
  csv << csv_field(mesh_name) << ',' << mesh_vertices << ',' << s.vertex << ',' << s.ring << ','
      << (s.boundary_vertex ? std::to_string(*s.boundary_vertex) : "") << ',' << method << ','
      << m.patch_vertices << ',' << m.boundary_vertices << ',';
  if (m.agreement) {
    const Map_agreement& a = *m.agreement;
    csv << a.triangles << ',' << a.flipped << ',' << number(a.flipped_fraction(), 5) << ','
        << number(a.angle_error, 5) << ',' << number(a.rotation, 5) << ','
        << number(a.relative_distance_error, 5) << ',' << a.common_vertices;
  } else {
    csv << ",,,,,,";
  }
  csv << ',' << number(m.seconds, 4) << ',' << csv_field(m.error) << '\n';
}

/// Heat's and DGPC's maps of the sources of one ring.
struct Ring_maps {
  std::vector<Heat_and_dgpc> maps;  // sources where both have a map
  std::size_t heat_errors = 0;      // sources where heat failed and DGPC did not
};

/// Everything measured on one mesh.
struct Mesh_maps {
  std::map<std::string, Ring_maps> rings;
  std::map<std::string, double> method_seconds;
};

/// Maps every source of `sources` with every method of `set`, writing
/// one CSV row per map.
Mesh_maps measure_mesh(const std::string& name, const Mesh& mesh, const Method_set& set,
                       const std::vector<Study_source>& sources, const expmap::Patch& patch,
                       std::ostream& csv) {
  const std::vector<bool> on_boundary = vertex_graph(mesh).on_boundary;
  const std::size_t n = num_vertices(mesh);
  Mesh_maps result;
  for (const Study_source& s : sources) {
    const auto measured = measure_source(mesh, set, s.vertex, patch, on_boundary);
    for (const std::string& key : method_keys) {
      result.method_seconds[key] += measured.at(key).seconds;
      write_csv_row(csv, name, n, s, key, measured.at(key));
    }
    Ring_maps& ring = result.rings[s.ring];
    const Measured_map& heat = measured.at("heat");
    const Measured_map& dgpc = measured.at("dgpc");
    if (heat.agreement && dgpc.agreement)
      ring.maps.push_back({*heat.agreement, *dgpc.agreement});
    else if (dgpc.agreement)
      ++ring.heat_errors;
  }
  return result;
}

/// The summary of one mesh, per ring, over all boundary rings ("all"), and
/// over the interior sources.
struct Summary_row {
  std::string mesh, ring;
  std::size_t heat_errors = 0;  // sources where heat failed and DGPC did not
  Boundary_quality quality;
};

/// The rows of one mesh: its boundary rings, "all" (the boundary rings
/// pooled), then "interior" (with no sources if the mesh has none).
std::vector<Summary_row> summarise_mesh(const std::string& name, const Mesh_maps& measured) {
  std::vector<Summary_row> rows;
  std::vector<Heat_and_dgpc> all;
  std::size_t all_heat_errors = 0;
  for (const auto& [ring, r] : measured.rings) {
    // A ring gets a row, and its heat errors count, only if some source
    // of it has both maps.
    if (ring == "interior" || r.maps.empty()) continue;
    rows.push_back({name, ring, r.heat_errors, boundary_quality(r.maps)});
    all.insert(all.end(), r.maps.begin(), r.maps.end());
    all_heat_errors += r.heat_errors;
  }
  rows.push_back({name, "all", all_heat_errors, boundary_quality(all)});
  const auto interior = measured.rings.find("interior");
  if (interior == measured.rings.end())
    rows.push_back({name, "interior", 0, boundary_quality({})});
  else
    rows.push_back({name, "interior", interior->second.heat_errors,
                    boundary_quality(interior->second.maps)});
  return rows;
}

/// The targets a row misses, "heat errors" counting as one.
std::vector<std::string> missed_targets(const Summary_row& r) {
  const Boundary_quality& q = r.quality;
  std::vector<std::string> missed;
  if (!q.flips_pass) missed.push_back("flips");
  if (!q.collapse_pass) missed.push_back("collapse");
  if (!q.angles_pass) missed.push_back("angles");
  if (r.heat_errors) missed.push_back("heat errors");
  return missed;
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : separator) + p;
  return s;
}

/// PASS, FAIL(the targets missed, joined by '+' so that the summary CSV
/// needs no quoting), none for a ring without sources, or n/a where the
/// patches have no triangles (the tiny meshes: 5% of a few vertices),
/// which would pass every target without measuring anything.
std::string verdict(const Summary_row& r) {
  if (r.quality.sources == 0 && r.heat_errors == 0) return "none";
  if (r.quality.heat_triangles == 0 && r.heat_errors == 0) return "n/a";
  const std::vector<std::string> missed = missed_targets(r);
  return missed.empty() ? "PASS" : "FAIL(" + joined(missed, "+") + ")";
}

/// Whether the targets a mesh misses at the boundary (`all`, the boundary
/// rings pooled) are missed at its interior sources too. If they are, the
/// miss is the heat method's accuracy on this mesh, not the boundary's
/// doing. `kind`: "met", "n/a" (as `verdict()`), "no interior" (nothing
/// measured there), "interior too" (every target), "boundary only" (none
/// of them) or "split"; `targets` names the targets for a split.
struct Boundary_misses {
  std::string kind;
  std::string targets;
};

Boundary_misses boundary_vs_interior(const Summary_row& all, const Summary_row& interior) {
  const std::string boundary = verdict(all), inside = verdict(interior);
  if (boundary == "PASS") return {"met", ""};
  if (boundary == "n/a") return {"n/a", ""};
  if (inside == "none" || inside == "n/a") return {"no interior", ""};
  const std::vector<std::string> missed_inside = missed_targets(interior);
  std::vector<std::string> both, boundary_only;
  for (const std::string& target : missed_targets(all)) {
    const bool inside_too =
        std::find(missed_inside.begin(), missed_inside.end(), target) != missed_inside.end();
    (inside_too ? both : boundary_only).push_back(target);
  }
  if (boundary_only.empty()) return {"interior too", ""};
  if (both.empty()) return {"boundary only", ""};
  return {"split",
          "interior too: " + joined(both, "+") + "; boundary only: " + joined(boundary_only, "+")};
}

void print_summary_header(std::ostream& out) {
  char line[256];
  std::snprintf(line, sizeof line, "%-34s %8s %4s %9s %9s %9s %5s %8s %8s %8s  %s\n", "mesh",
                "ring", "src", "heatflip", "dgpcflip", "fliplim", "coll", "heat_dth", "dgpc_dth",
                "dth_lim", "verdict");
  out << line;
}

void print_summary_row(std::ostream& out, const Summary_row& r) {
  const Boundary_quality& q = r.quality;
  char line[256];
  std::snprintf(line, sizeof line, "%-34s %8s %4zu %9zu %9zu %9.0f %5zu %8s %8s %8s  %s%s\n",
                r.mesh.c_str(), r.ring.c_str(), q.sources, q.heat_flipped, q.dgpc_flipped,
                q.flip_limit, q.collapsed_sources, number(q.heat_angle_error, 3).c_str(),
                number(q.dgpc_angle_error, 3).c_str(), number(q.angle_limit, 3).c_str(),
                verdict(r).c_str(),
                r.heat_errors ? (" (heat failed at " + std::to_string(r.heat_errors) + ")").c_str()
                              : "");
  out << line;
}

/// Per mesh with a boundary, its boundary and interior verdicts and
/// `boundary_vs_interior()`; then how the meshes that miss a boundary
/// target split. Takes the rows in the order of `summarise_mesh()`.
void print_mesh_verdicts(std::ostream& out, const std::vector<Summary_row>& summary) {
  out << "\nPer mesh: the boundary targets (all rings) against the interior sources' "
         "(interior too: the interior misses the same targets).\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-34s %-32s %-24s %s\n", "mesh", "boundary", "interior",
                "boundary misses");
  out << line;
  std::map<std::string, std::size_t> kinds;
  for (std::size_t i = 0; i + 1 < summary.size(); ++i) {
    if (summary[i].ring != "all") continue;
    const Summary_row& all = summary[i];
    const Summary_row& interior = summary[i + 1];
    const Boundary_misses misses = boundary_vs_interior(all, interior);
    ++kinds[misses.kind];
    std::snprintf(line, sizeof line, "%-34s %-32s %-24s %s\n", all.mesh.c_str(),
                  verdict(all).c_str(), verdict(interior).c_str(),
                  (misses.kind == "split" ? misses.targets : misses.kind).c_str());
    out << line;
  }
  out << "\nMeshes that miss a boundary target: the interior misses the same targets on "
      << kinds["interior too"] << ", none of them on " << kinds["boundary only"] << ", some on "
      << kinds["split"] << "; no interior source on " << kinds["no interior"] << ".\n";
}

void write_summary_csv(const fs::path& path, const std::vector<Summary_row>& rows) {
  std::ofstream out(path);
  out << "mesh,ring,sources,heat_flipped,dgpc_flipped,heat_triangles,flip_limit,"
         "collapsed_sources,heat_median_dtheta,dgpc_median_dtheta,angle_limit,heat_errors,"
         "verdict\n";
  for (const auto& r : rows) {
    const Boundary_quality& q = r.quality;
    out << csv_field(r.mesh) << ',' << r.ring << ',' << q.sources << ',' << q.heat_flipped << ','
        << q.dgpc_flipped << ',' << q.heat_triangles << ',' << number(q.flip_limit, 1) << ','
        << q.collapsed_sources << ',' << number(q.heat_angle_error, 5) << ','
        << number(q.dgpc_angle_error, 5) << ',' << number(q.angle_limit, 5) << ','
        << r.heat_errors << ',' << verdict(r) << '\n';
  }
}

std::vector<fs::path> mesh_files(const Options& options) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(options.meshes))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (!options.only.empty())
    files.erase(std::remove_if(files.begin(), files.end(),
                               [&](const fs::path& f) {
                                 return std::find(options.only.begin(), options.only.end(),
                                                  f.filename().string()) == options.only.end();
                               }),
                files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "expmap-boundary-study: " << e.what() << "\n" << usage_text();
    return 2;
  }
  std::ofstream csv(options.csv);
  csv << csv_header;
  const expmap::Patch patch = expmap::Patch::fraction(options.fraction);
  std::vector<Summary_row> summary;
  std::vector<std::string> skipped;
  std::size_t closed = 0;
  const auto study_start = std::chrono::steady_clock::now();

  for (const fs::path& file : mesh_files(options)) {
    const std::string name = file.filename().string();
    Mesh mesh;
    try {
      expmap::IO::read_triangle_mesh(file.string(), mesh);
    } catch (const expmap::Invalid_input& e) {
      skipped.push_back(name + ": unreadable: " + e.what());
      continue;
    }
    const std::vector<Boundary_source> boundary = boundary_sources(mesh, options.sources);
    if (boundary.empty()) {
      ++closed;
      continue;
    }
    const std::size_t n = num_vertices(mesh);
    if (options.max_vertices && n > options.max_vertices) {
      skipped.push_back(name + ": " + std::to_string(n) + " vertices > --max-vertices");
      continue;
    }
    std::optional<Method_set> set;
    try {
      set.emplace(make_methods(mesh, options.heat_fallback));
    } catch (const expmap::Invalid_input& e) {
      skipped.push_back(name + ": a method refuses it: " + e.what());
      continue;
    }

    const auto mesh_start = std::chrono::steady_clock::now();
    std::size_t declined = 0;
    const std::vector<std::size_t> interior =
        checked_interior_sources(mesh, *set, patch, options.interior, declined);
    const std::vector<Study_source> sources = study_sources(boundary, interior);
    const Mesh_maps measured = measure_mesh(name, mesh, *set, sources, patch, csv);
    const std::vector<Summary_row> rows = summarise_mesh(name, measured);
    summary.insert(summary.end(), rows.begin(), rows.end());
    std::cerr << name << ": " << n << " vertices, " << boundary.size() << " boundary and "
              << interior.size() << " interior sources (" << declined
              << " candidates declined: a patch on the boundary), "
              << number(seconds_since(mesh_start), 1) << " s (";
    for (const std::string& key : method_keys)
      std::cerr << key << ' ' << number(measured.method_seconds.at(key), 1) << " s"
                << (key == method_keys.back() ? ")\n" : ", ");
  }

  std::cout << "Boundary study: patches of " << options.fraction * 100 << "% of the mesh, up to "
            << options.sources << " boundary sources per mesh plus one and two rings in, up to "
            << options.interior << " interior sources.\n"
            << "ring: hops from the boundary; all: rings 0-2 pooled; interior: sources where no "
               "method's patch holds a boundary vertex.\n"
            << "heatflip/dgpcflip: flipped triangles summed over the sources; fliplim = "
               "max(2 dgpc, dgpc + 2% of the patch triangles);\n"
            << "coll: sources with heat > 30% flipped where DGPC < 5%; *_dth: median over the "
               "sources of mean |dtheta| (rad, best rotation)\nagainst the exact map; dth_lim = "
               "max(0.05, 3 dgpc_dth).\n\n";
  print_summary_header(std::cout);
  for (const Summary_row& r : summary) print_summary_row(std::cout, r);

  std::map<std::string, std::size_t> verdicts;  // over all rings: PASS, FAIL, n/a
  for (const Summary_row& r : summary)
    if (r.ring == "all") ++verdicts[verdict(r).substr(0, verdict(r).find('('))];
  print_mesh_verdicts(std::cout, summary);
  std::cout << "\nMeshes with a boundary studied: "
            << verdicts["PASS"] + verdicts["FAIL"] + verdicts["n/a"]
            << " (over all rings: " << verdicts["PASS"] << " PASS, " << verdicts["FAIL"]
            << " FAIL, " << verdicts["n/a"] << " n/a); closed meshes: " << closed
            << "; skipped: " << skipped.size() << "\n";
  for (const std::string& s : skipped) std::cout << "  skipped " << s << "\n";
  std::cout << "Total time " << number(seconds_since(study_start), 1) << " s; per-map rows in "
            << options.csv.string() << "\n";
  if (!options.summary_csv.empty()) write_summary_csv(options.summary_csv, summary);
  return 0;
}
