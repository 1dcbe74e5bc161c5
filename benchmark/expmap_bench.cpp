// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-bench: query time of the exponential-map methods against patch
// fraction and mesh size (Herholz & Alexa 2019, Figs. 7 and 8), through the
// public API only. `expmap-bench --help` lists the options;
// scripts/benchmark.sh runs the whole study and benchmark/plot.py draws it.
//
// Per mesh: load it; precompute the heat method (Heat_exponential_map) and
// read the peak memory right after; pick --sources random vertices
// (std::mt19937(seed), the same for every method); construct the baselines
// (dem, dgpc, exact); then one untimed warm-up query per method (first
// source, first fraction) and, per fraction and source, Patch::fraction(f)
// from every method in turn (the order rotates from source to source), each
// query --repeats times (default 3) and its fastest run kept, timed with
// steady_clock around compute_by_index() alone. On a shared machine whose
// load drifts, taking turns makes a slow stretch hit every method alike, and
// the fastest of the repeats drops interruptions; medians over the sources
// are then medians of these per-source times.
//
// heat-full is the whole-mesh cost: Heat_query_options::region_growth cannot turn
// the localization off, so the same object is queried with
// Patch::fraction(1), which solves over the whole component (both factors,
// every column) and maps all of it -- what a non-localized solver has to do
// for any patch. Its time does not depend on the fraction; its rows repeat
// it for each fraction with that fraction's patch size, so heat-full / heat
// at a fraction is the speedup of localization. --full-sources N times it
// from the first N sources only; each of its queries is also the fastest of
// --repeats runs.
//
// --csv (one row per mesh, method, fraction):
//   mesh, vertices            mesh name (file stem) and vertex count
//   method, fraction          heat | heat-full | dem | dgpc | exact; Patch::fraction(f)
//   patch_vertices            median size of the returned map (heat-full:
//                             the patch size of the localized query)
//   median_ms, p90_ms         query time over the sources (p90: nearest rank)
//   us_per_patch_vertex       1000 * median_ms / patch_vertices
//   median_factor_entries     heat only: median Solve_statistics::factor_entries
//   median_stream_floor_ms    heat only: median stream floor (Stream_floor.h)
//   floor_ratio               heat only: median over queries of ms / floor_ms
//                             (whole query time over the floor: an upper
//                             bound of solve time / floor)
//   solve_floor_ratio         heat only: median over queries of solve_ms /
//                             floor_ms, solve_ms the time inside the localized
//                             triangular solves (Solve_statistics::solve_seconds)
//   queries, failures         successful and failed queries in the row
//   retried                   heat only: queries that doubled their region at
//                             least once (Solve_statistics::region_retries)
// --stats (one row per mesh):
//   mesh, vertices, faces
//   precompute_s              construction of Heat_exponential_map (operators,
//                             both factorizations); empty without heat methods
//   peak_rss_mb               VmHWM (MiB) right after that construction; the
//                             mark is reset after loading the mesh (Peak_memory.h),
//                             so it is this mesh's precompute peak, mesh included
//   heat_tree_height, poisson_tree_height, factor_nonzeros   of the two factors
//   mesh_rss_mb               VmRSS (MiB) before the precompute (mesh loaded)
//   hwm_reset                 1 if VmHWM could be reset; 0: peak_rss_mb is the
//                             peak of the whole process so far
// --detail (one row per timed query):
//   mesh, method, fraction, source, patch_vertices, ms, and for heat and
//   heat-full forward_nodes, backward_nodes, factor_entries (Solve_statistics)
//   and stream_floor_ms, solve_ms, region_retries. heat-full rows have
//   fraction 1 and the size of the whole map.

#include "Bench_options.h"
#include "Loop_subdivided_mesh.h"
#include "Mesh_loading.h"
#include "Peak_memory.h"
#include "Sample_statistics.h"
#include "Stream_floor.h"
#include "Timing.h"

#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/Local_map.h>
#include <expmap/Patch.h>
#include <expmap/Solve_statistics.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace expmap_bench;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Heat = expmap::Heat_exponential_map<Mesh>;
using Inspection = expmap::internal::heat::Factor_inspection;
using Dem = expmap::Discrete_exponential_map<Mesh>;
using Dgpc = expmap::Geodesic_polar_coordinates<Mesh>;
using Exact = expmap::Exact_exponential_map<Mesh>;

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

// Patches above this many vertices make `exact` slow (seconds per query).
constexpr std::size_t exact_slow_patch = 5000;

/// One timed query.
struct Query_record {
  std::string method;
  double fraction = 0;  // 1 for heat-full: it maps the whole component
  std::size_t source = 0;
  std::size_t patch_vertices = 0;
  double ms = nan_value;
  expmap::Solve_statistics statistics;
  double floor_ms = nan_value;  // heat and heat-full only
};

/// One row of the main CSV: a method at a fraction on a mesh.
struct Summary_row {
  std::string mesh;
  std::size_t vertices = 0;
  std::string method;
  double fraction = 0;
  double patch_vertices = 0;
  double median_ms = nan_value, p90_ms = nan_value;
  double us_per_patch_vertex = nan_value;
  double factor_entries = nan_value, floor_ms = nan_value, floor_ratio = nan_value;
  double solve_floor_ratio = nan_value;
  std::size_t queries = 0, failures = 0;
  std::size_t retried = 0;  // heat: queries that doubled their region at least once
};

/// One row of the --stats CSV.
struct Mesh_statistics {
  std::string mesh;
  std::size_t vertices = 0, faces = 0;
  double precompute_s = nan_value, peak_rss_mb = nan_value;
  double heat_tree_height = nan_value, poisson_tree_height = nan_value;
  double factor_nonzeros = nan_value;
  double mesh_rss_mb = nan_value;  // resident after loading, before precompute
  bool hwm_reset = false;
  double first_map_s = nan_value;        // precompute and the first heat query
  double query_peak_rss_mb = nan_value;  // peak once all queries ran
  double subdomain_mb = nan_value;       // cached subdomains at the end
};

/// A mesh to benchmark: its name and how to get it.
struct Mesh_job {
  std::string name;
  std::function<Mesh()> load;
};

std::string fmt(double x, int digits = 6) {
  if (std::isnan(x)) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

std::string fixed(double x, int decimals) {
  if (std::isnan(x)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  return buffer;
}

std::string pad(const std::string& s, std::size_t width, bool left = false) {
  if (s.size() >= width) return s;
  return left ? s + std::string(width - s.size(), ' ') : std::string(width - s.size(), ' ') + s;
}

bool uses_heat(const std::vector<std::string>& methods) {
  return std::count(methods.begin(), methods.end(), "heat") +
             std::count(methods.begin(), methods.end(), "heat-paper") +
             std::count(methods.begin(), methods.end(), "heat-full") >
         0;
}

/// `count` random non-isolated vertices from std::mt19937(seed), distinct
/// while the mesh has enough vertices.
std::vector<std::size_t> pick_sources(const Mesh& mesh, std::size_t count, unsigned seed) {
  std::vector<std::size_t> usable;
  const std::size_t n = num_vertices(mesh);
  std::size_t non_isolated = 0;
  for (auto v : vertices(mesh))
    if (!mesh.is_isolated(v)) ++non_isolated;
  if (non_isolated == 0) throw std::runtime_error("the mesh has no face");
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  std::set<std::size_t> taken;
  while (usable.size() < count) {
    const std::size_t v = pick(rng);
    if (mesh.is_isolated(Mesh::Vertex_index(static_cast<Mesh::size_type>(v)))) continue;
    if (taken.size() < non_isolated && !taken.insert(v).second) continue;
    usable.push_back(v);
  }
  return usable;
}

/// A method whose queries take turns with the others' in `time_interleaved`.
struct Query_method {
  std::string name;
  std::function<expmap::Local_map<Mesh::Vertex_index>(std::size_t, const expmap::Patch&)> query;
};

/// Times every method's `compute_by_index` for every fraction and source
/// after one untimed warm-up query each: per fraction and source the methods
/// take turns (starting with a different one from source to source), each
/// query is run `repeats` times, and the fastest run is kept.
std::vector<Query_record> time_interleaved(const std::vector<Query_method>& methods,
                                           const std::vector<std::size_t>& sources,
                                           const std::vector<double>& fractions,
                                           std::size_t repeats) {
  for (const Query_method& method : methods) {
    try {
      (void)method.query(sources.front(), expmap::Patch::fraction(fractions.front()));
    } catch (const std::exception& e) {
      std::cerr << "  warning: " << method.name << " warm-up query failed: " << e.what() << "\n";
    }
  }
  std::vector<Query_record> records;
  for (double f : fractions) {
    const expmap::Patch patch = expmap::Patch::fraction(f);
    for (std::size_t i = 0; i < sources.size(); ++i) {
      std::vector<Query_record> turn(methods.size());
      for (std::size_t k = 0; k < methods.size(); ++k) {
        turn[k].method = methods[k].name;
        turn[k].fraction = f;
        turn[k].source = sources[i];
      }
      std::vector<bool> failed(methods.size(), false);
      for (std::size_t repeat = 0; repeat < repeats; ++repeat) {
        for (std::size_t j = 0; j < methods.size(); ++j) {
          const std::size_t k = (i + repeat + j) % methods.size();
          if (failed[k]) continue;
          Query_record& r = turn[k];
          try {
            Stopwatch watch;
            const auto map = methods[k].query(sources[i], patch);
            const double ms = watch.milliseconds();
            if (std::isnan(r.ms) || ms < r.ms) {
              r.ms = ms;
              r.patch_vertices = map.size();
              r.statistics = map.statistics;
            }
          } catch (const std::exception& e) {
            std::cerr << "  warning: " << methods[k].name << " fraction " << f << " source "
                      << sources[i] << " failed: " << e.what() << "\n";
            failed[k] = true;
            r.ms = nan_value;
          }
        }
      }
      records.insert(records.end(), turn.begin(), turn.end());
    }
  }
  return records;
}

/// Measures the stream floor of every query of `method` (after all queries were
/// timed, so the floor's buffers do not disturb the queries' caches).
void measure_stream_floors(std::vector<Query_record>& records, const std::string& method,
                           Stream_floor& floor) {
  std::size_t largest = 0;
  for (const auto& r : records)
    if (r.method == method) largest = std::max(largest, r.statistics.factor_entries);
  if (largest == 0) return;
  floor.prepare(largest);
  for (auto& r : records)
    if (r.method == method && !std::isnan(r.ms))
      r.floor_ms = floor.measure_ms(r.statistics.factor_entries);
}

/// Summarizes the successful records among `records` into a row.
Summary_row summarize(const std::string& mesh, std::size_t n, const std::string& method,
                      double fraction, const std::vector<const Query_record*>& records,
                      double patch_vertices_override = nan_value) {
  Summary_row row;
  row.mesh = mesh;
  row.vertices = n;
  row.method = method;
  row.fraction = fraction;
  std::vector<double> ms, sizes, entries, floors, ratios, solve_ratios;
  for (const Query_record* r : records) {
    if (std::isnan(r->ms)) {
      ++row.failures;
      continue;
    }
    ms.push_back(r->ms);
    sizes.push_back(static_cast<double>(r->patch_vertices));
    if (r->statistics.region_retries > 0) ++row.retried;
    if (!std::isnan(r->floor_ms)) {
      entries.push_back(static_cast<double>(r->statistics.factor_entries));
      floors.push_back(r->floor_ms);
      if (r->floor_ms > 0) {
        ratios.push_back(r->ms / r->floor_ms);
        solve_ratios.push_back(1e3 * r->statistics.solve_seconds / r->floor_ms);
      }
    }
  }
  row.queries = ms.size();
  row.median_ms = median(ms);
  row.p90_ms = percentile(ms, 90);
  row.patch_vertices = std::isnan(patch_vertices_override) ? median(sizes) : patch_vertices_override;
  if (row.patch_vertices > 0) row.us_per_patch_vertex = 1e3 * row.median_ms / row.patch_vertices;
  row.factor_entries = median(entries);
  row.floor_ms = median(floors);
  row.floor_ratio = median(ratios);
  row.solve_floor_ratio = median(solve_ratios);
  return row;
}

class Benchmark {
 public:
  explicit Benchmark(const Bench_options& options) : m_options(options) {
    open(m_csv, options.csv,
         "mesh,vertices,method,fraction,patch_vertices,median_ms,p90_ms,"
         "us_per_patch_vertex,median_factor_entries,median_stream_floor_ms,floor_ratio,"
         "queries,failures,solve_floor_ratio,retried");
    open(m_stats, options.stats,
         "mesh,vertices,faces,precompute_s,peak_rss_mb,heat_tree_height,poisson_tree_height,"
         "factor_nonzeros,mesh_rss_mb,hwm_reset,first_map_s,query_peak_rss_mb,subdomain_mb");
    open(m_detail, options.detail,
         "mesh,method,fraction,source,patch_vertices,ms,forward_nodes,backward_nodes,"
         "factor_entries,stream_floor_ms,solve_ms,region_retries");
    if (options.time_factor > 0) m_heat_options.time_factor = options.time_factor;
    m_heat_options.factor_precision = options.factor_precision;
    m_heat_options.subdomain_min_vertices = options.subdomain_min_vertices;
    if (options.poisson_compression >= 0)
      m_heat_options.poisson_compression_tolerance = options.poisson_compression;
    m_heat_query.query_threads = options.query_threads;
  }

  void run(const std::vector<Mesh_job>& jobs) {
    for (const auto& job : jobs) run_mesh(job);
    print_summary();
  }

 private:
  static void open(std::ofstream& out, const std::string& path, const char* header) {
    if (path.empty()) return;
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    out.open(path);
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
    out << header << "\n";
  }

  void run_mesh(const Mesh_job& job) {
    Mesh_statistics st;
    st.mesh = job.name;
    std::cout << "\n== " << job.name << " ==\n" << std::flush;
    Stopwatch load_watch;
    const Mesh mesh = job.load();
    st.vertices = num_vertices(mesh);
    st.faces = num_faces(mesh);
    // The peak of this mesh's precompute alone: give freed memory back to
    // the system and reset VmHWM to the current resident set (the mesh,
    // without the transient memory of reading or subdividing it).
    release_free_memory();
    st.hwm_reset = reset_peak_rss();
    st.mesh_rss_mb = current_rss_mib();
    std::cout << st.vertices << " vertices, " << st.faces << " faces, loaded in "
              << fixed(load_watch.seconds(), 2) << " s\n";

    const std::vector<std::size_t> sources = pick_sources(mesh, m_options.sources, m_options.seed);

    // Precompute the heat method first, and read the peak right after it.
    std::unique_ptr<Heat> heat;
    if (uses_heat(m_options.methods)) {
      Stopwatch watch;
      heat = std::make_unique<Heat>(mesh, m_heat_options);
      st.precompute_s = watch.seconds();
      st.peak_rss_mb = peak_rss_mib();
      // The first map, cold: on subdomains it factors the first one.
      heat->compute_by_index(sources.front(), expmap::Patch::fraction(m_options.fractions.front()),
                             m_heat_query);
      st.first_map_s = watch.seconds();
    }
    if (heat && heat->uses_subdomains()) {
      std::cout << "heat precompute " << fixed(st.precompute_s, 2) << " s (queries on subdomains), "
                << "first map (fraction " << fmt(m_options.fractions.front(), 4) << ") after "
                << fixed(st.first_map_s, 2) << " s, t = " << fmt(heat->time_step(), 4) << "\n";
    } else if (heat) {
      st.heat_tree_height = Inspection::heat_tree_height(*heat);
      st.poisson_tree_height = Inspection::poisson_tree_height(*heat);
      st.factor_nonzeros = static_cast<double>(Inspection::factor_entries(*heat));
      std::cout << "heat precompute " << fixed(st.precompute_s, 2) << " s, peak RSS "
                << fixed(st.peak_rss_mb, 1) << " MiB (" << fixed(st.mesh_rss_mb, 1)
                << " MiB before precompute" << (st.hwm_reset ? "" : "; VmHWM NOT reset")
                << "), tree heights heat " << st.heat_tree_height << " / Poisson "
                << st.poisson_tree_height << ", factor entries " << Inspection::factor_entries(*heat)
                << ", Poisson supernodes with rows below in low-rank form "
                << Inspection::poisson_compressed_supernodes(*heat) << ", t = " << fmt(heat->time_step(), 4)
                << ", first map after " << fixed(st.first_map_s, 2) << " s\n";
    }

    const std::size_t n = st.vertices;
    std::vector<Query_record> records;
    std::vector<Summary_row> rows;
    Stream_floor floor;
    // The per-fraction methods take turns (time_interleaved); the baselines
    // are constructed first. heat-full runs on its own afterwards: its time
    // does not depend on the fraction.
    std::unique_ptr<Dem> dem;
    std::unique_ptr<Dgpc> dgpc;
    std::unique_ptr<Exact> exact;
    std::vector<Query_method> turns, point_turns;
    for (const std::string& method : m_options.methods) {
      if (method == "heat") {
        turns.push_back(query_method(method, *heat, m_heat_query));
        if (m_options.source_points)
          point_turns.push_back(point_query_method(method, *heat, mesh, m_heat_query));
      } else if (method == "heat-paper") {
        expmap::Heat_query_options paper = m_heat_query;
        paper.fallback = expmap::Heat_fallback::none;
        turns.push_back(query_method(method, *heat, paper));
        if (m_options.source_points)
          point_turns.push_back(point_query_method(method, *heat, mesh, paper));
      } else if (method == "dem") {
        dem = construct_baseline<Dem>(method, mesh);
        turns.push_back(query_method(method, *dem));
        if (m_options.source_points) point_turns.push_back(point_query_method(method, *dem, mesh));
      } else if (method == "dgpc") {
        dgpc = construct_baseline<Dgpc>(method, mesh);
        turns.push_back(query_method(method, *dgpc));
        if (m_options.source_points) point_turns.push_back(point_query_method(method, *dgpc, mesh));
      } else if (method == "exact") {
        const std::size_t largest = expmap::Patch::fraction(*std::max_element(
            m_options.fractions.begin(), m_options.fractions.end())).target_count(n);
        if (largest > exact_slow_patch)
          std::cerr << "  warning: exact is slow for big patches (up to " << largest
                    << " vertices here; expect up to seconds per query, minutes on 100k-vertex patches)\n";
        exact = construct_baseline<Exact>(method, mesh);
        turns.push_back(query_method(method, *exact));
        if (m_options.source_points) point_turns.push_back(point_query_method(method, *exact, mesh));
      }
    }
    // The point twins after all vertex queries: next to their vertex twin they
    // would find its neighbourhood in the caches.
    turns.insert(turns.end(), point_turns.begin(), point_turns.end());
    if (!turns.empty()) {
      Stopwatch watch;
      std::vector<Query_record> r =
          time_interleaved(turns, sources, m_options.fractions, m_options.repeats);
      measure_stream_floors(r, "heat", floor);
      floor.release();
      std::cout << "  ";
      for (std::size_t k = 0; k < turns.size(); ++k) std::cout << (k ? ", " : "") << turns[k].name;
      std::cout << ": " << r.size() << " queries, each the fastest of " << m_options.repeats
                << ", in " << fixed(watch.seconds(), 1) << " s\n"
                << std::flush;
      records.insert(records.end(), r.begin(), r.end());
    }
    if (std::count(m_options.methods.begin(), m_options.methods.end(), "heat-full") > 0) {
      Stopwatch watch;
      // The same object queried for the whole component (Patch::fraction(1)),
      // i.e. solving over the whole mesh, from the first sources.
      const std::size_t count =
          std::min(m_options.full_sources > 0 ? m_options.full_sources : sources.size(),
                   sources.size());
      const std::vector<std::size_t> full_sources(
          sources.begin(), sources.begin() + static_cast<std::ptrdiff_t>(count));
      std::vector<Query_record> r = time_interleaved({query_method("heat-full", *heat, m_heat_query)},
                                                     full_sources, {1.0}, m_options.repeats);
      measure_stream_floors(r, "heat-full", floor);
      floor.release();
      std::cout << "  heat-full: " << r.size() << " queries, each the fastest of "
                << m_options.repeats << ", in " << fixed(watch.seconds(), 1) << " s\n"
                << std::flush;
      records.insert(records.end(), r.begin(), r.end());
    }

    // Rows, in the order of the methods and fractions asked for (each
    // method's point twin after it).
    std::vector<std::string> timed;
    for (const std::string& method : m_options.methods) {
      timed.push_back(method);
      if (m_options.source_points && method != "heat-full") timed.push_back(method + "@point");
    }
    for (const std::string& method : timed) {
      for (double f : m_options.fractions) {
        std::vector<const Query_record*> selected;
        double patch_override = nan_value;
        if (method == "heat-full") {
          std::vector<double> full_sizes;
          for (const auto& r : records)
            if (r.method == method) {
              selected.push_back(&r);
              if (!std::isnan(r.ms)) full_sizes.push_back(static_cast<double>(r.patch_vertices));
            }
          // The same patch as the localized query (capped at the component
          // the whole-mesh query mapped); its time is that of the whole map.
          patch_override = std::min(
              static_cast<double>(expmap::Patch::fraction(f).target_count(n)), median(full_sizes));
        } else {
          for (const auto& r : records)
            if (r.method == method && r.fraction == f) selected.push_back(&r);
        }
        rows.push_back(summarize(job.name, n, method, f, selected, patch_override));
      }
    }
    st.query_peak_rss_mb = peak_rss_mib();
    if (heat) st.subdomain_mb = static_cast<double>(heat->subdomain_bytes()) / (1 << 20);
    m_mesh_statistics.push_back(st);
    if (m_stats.is_open()) {
      m_stats << st.mesh << "," << st.vertices << "," << st.faces << "," << fmt(st.precompute_s)
              << "," << fmt(st.peak_rss_mb) << "," << fmt(st.heat_tree_height) << ","
              << fmt(st.poisson_tree_height) << "," << fmt(st.factor_nonzeros, 12) << ","
              << fmt(st.mesh_rss_mb) << "," << (st.hwm_reset ? 1 : 0) << ","
              << fmt(st.first_map_s) << "," << fmt(st.query_peak_rss_mb) << ","
              << fmt(st.subdomain_mb) << "\n"
              << std::flush;
    }
    print_mesh_table(rows);
    write_rows(job.name, rows, records);
    m_rows.insert(m_rows.end(), rows.begin(), rows.end());
  }

  template <class Method>
  static std::unique_ptr<Method> construct_baseline(const std::string& name, const Mesh& mesh) {
    Stopwatch watch;
    auto method = std::make_unique<Method>(mesh);
    std::cout << "  " << name << " precompute " << fixed(watch.seconds(), 2) << " s\n";
    return method;
  }

  template <class Method>
  static Query_method query_method(const std::string& name, const Method& method,
                                   const typename Method::Query& query = {}) {
    return {name, [&method, query](std::size_t source, const expmap::Patch& patch) {
              return method.compute_by_index(source, patch, query);
            }};
  }

  /// `method` queried from a point of a face next to each source vertex:
  /// half the weight at the vertex, the rest on the face's other corners.
  template <class Method>
  static Query_method point_query_method(const std::string& name, const Method& method,
                                         const Mesh& mesh,
                                         const typename Method::Query& query = {}) {
    return {name + "@point",
            [&method, &mesh, query](std::size_t source, const expmap::Patch& patch) {
              const Mesh::Vertex_index v(static_cast<Mesh::size_type>(source));
              auto h = mesh.halfedge(v);  // v is its target
              while (mesh.is_border(h)) h = mesh.opposite(mesh.next(h));
              expmap::Surface_point<Mesh::Face_index> at{mesh.face(h), {}};
              const auto g = mesh.halfedge(at.face);
              const Mesh::Vertex_index corner[3] = {mesh.source(g), mesh.target(g),
                                                    mesh.target(mesh.next(g))};
              for (int k = 0; k < 3; ++k) at.barycentric[k] = corner[k] == v ? 0.5 : 0.25;
              return method.compute(at, patch, query);
            }};
  }

  const Summary_row* find_row(const std::string& mesh, const std::string& method,
                              double fraction) const {
    for (const auto& r : m_rows)
      if (r.mesh == mesh && r.method == method && r.fraction == fraction) return &r;
    return nullptr;
  }

  void print_mesh_table(const std::vector<Summary_row>& rows) const {
    std::cout << pad("method", 10, true) << pad("fraction", 9) << pad("patch", 9)
              << pad("median ms", 12) << pad("p90 ms", 11) << pad("us/vertex", 11)
              << pad("floor ms", 11) << pad("ms/floor", 10) << pad("full/heat", 11)
              << pad("n", 4) << "\n";
    for (const auto& r : rows) {
      std::string speedup = "-";
      if (r.method == "heat")
        for (const auto& o : rows)
          if (o.method == "heat-full" && o.fraction == r.fraction && r.median_ms > 0 &&
              !std::isnan(o.median_ms))
            speedup = fixed(o.median_ms / r.median_ms, 1) + "x";
      std::cout << pad(r.method, 10, true) << pad(fmt(r.fraction, 3), 9)
                << pad(fixed(r.patch_vertices, 0), 9) << pad(fixed(r.median_ms, 3), 12)
                << pad(fixed(r.p90_ms, 3), 11) << pad(fixed(r.us_per_patch_vertex, 3), 11)
                << pad(fixed(r.floor_ms, 3), 11) << pad(fixed(r.floor_ratio, 2), 10)
                << pad(speedup, 11) << pad(std::to_string(r.queries), 4)
                << (r.failures ? "  (" + std::to_string(r.failures) + " failed)" : "") << "\n";
    }
    std::cout << std::flush;
  }

  void write_rows(const std::string& mesh, const std::vector<Summary_row>& rows,
                  const std::vector<Query_record>& records) {
    if (m_csv.is_open()) {
      for (const auto& r : rows)
        m_csv << r.mesh << "," << r.vertices << "," << r.method << "," << fmt(r.fraction) << ","
              << fmt(r.patch_vertices, 12) << "," << fmt(r.median_ms) << "," << fmt(r.p90_ms)
              << "," << fmt(r.us_per_patch_vertex) << "," << fmt(r.factor_entries, 12) << ","
              << fmt(r.floor_ms) << "," << fmt(r.floor_ratio) << "," << r.queries << ","
              << r.failures << "," << fmt(r.solve_floor_ratio) << ","
              << (r.method == "heat" ? std::to_string(r.retried) : std::string()) << "\n";
      m_csv << std::flush;
    }
    if (m_detail.is_open()) {
      for (const auto& q : records) {
        const bool heat = q.method == "heat" || q.method == "heat-full";
        m_detail << mesh << "," << q.method << "," << fmt(q.fraction) << "," << q.source << ","
                 << q.patch_vertices << "," << fmt(q.ms) << ",";
        if (heat)
          m_detail << q.statistics.forward_nodes << "," << q.statistics.backward_nodes << ","
                   << q.statistics.factor_entries << "," << fmt(q.floor_ms) << ","
                   << fmt(1e3 * q.statistics.solve_seconds) << ","
                   << q.statistics.region_retries;
        else
          m_detail << ",,,,,";
        m_detail << "\n";
      }
      m_detail << std::flush;
    }
  }

  void print_summary() const {
    std::vector<std::string> meshes;
    for (const auto& s : m_mesh_statistics) meshes.push_back(s.mesh);
    const auto& fractions = m_options.fractions;
    auto has = [&](const std::string& m) {
      return std::count(m_options.methods.begin(), m_options.methods.end(), m) > 0;
    };
    auto header = [&](const std::string& title) {
      std::cout << "\n" << title << "\n" << pad("mesh", 18, true);
      for (double f : fractions) std::cout << pad(fmt(f, 3), 10);
      std::cout << "\n";
    };

    std::cout << "\n==== summary ====\n";
    std::cout << pad("mesh", 18, true) << pad("vertices", 10) << pad("faces", 10)
              << pad("precompute s", 14) << pad("first map s", 13) << pad("peak RSS MiB", 14)
              << pad("query peak MiB", 16) << pad("tree h/P", 12) << pad("factor nnz", 13) << "\n";
    for (const auto& s : m_mesh_statistics)
      std::cout << pad(s.mesh, 18, true) << pad(std::to_string(s.vertices), 10)
                << pad(std::to_string(s.faces), 10) << pad(fixed(s.precompute_s, 2), 14)
                << pad(fixed(s.first_map_s, 2), 13)
                << pad(fixed(s.peak_rss_mb, 1) + (s.hwm_reset ? "" : "*"), 14)
                << pad(fixed(s.query_peak_rss_mb, 1), 16)
                << pad(fixed(s.heat_tree_height, 0) + "/" + fixed(s.poisson_tree_height, 0), 12)
                << pad(fixed(s.factor_nonzeros, 0), 13) << "\n";
    bool any_unreset = false;
    for (const auto& s : m_mesh_statistics) any_unreset = any_unreset || !s.hwm_reset;
    if (any_unreset)
      std::cout << "  * VmHWM could not be reset: the peak of the whole process so far\n";

    if (has("heat") && has("heat-full")) {
      header("speedup of the localized query over the whole-mesh query (heat-full / heat, "
             "medians):");
      double worst = std::numeric_limits<double>::infinity();
      for (const auto& m : meshes) {
        std::cout << pad(m, 18, true);
        for (double f : fractions) {
          const auto* a = find_row(m, "heat", f);
          const auto* b = find_row(m, "heat-full", f);
          double x = nan_value;
          if (a && b && a->median_ms > 0) x = b->median_ms / a->median_ms;
          if (!std::isnan(x)) worst = std::min(worst, x);
          std::cout << pad(std::isnan(x) ? "-" : fixed(x, 1) + "x", 10);
        }
        std::cout << "\n";
      }
      std::cout << "  (heat-full = Patch::fraction(1) on the same object: the map of the whole "
                   "component, which is what a non-localized solver computes anyway)\n";
      if (std::isfinite(worst)) std::cout << "  smallest speedup: " << fixed(worst, 1) << "x\n";
    }
    // One row per mesh of heat's median over another method's (the paper's
    // claim: below 1 from 5% patches on), and heat's p90 over its median
    // (retries make the tail).
    auto heat_table = [&](const std::string& title, auto value) {
      header(title);
      double worst = 0;
      for (const auto& m : meshes) {
        std::cout << pad(m, 18, true);
        for (double f : fractions) {
          const auto* a = find_row(m, "heat", f);
          const double x = a ? value(*a, m, f) : nan_value;
          if (!std::isnan(x)) worst = std::max(worst, x);
          std::cout << pad(std::isnan(x) ? "-" : fixed(x, 2), 10);
        }
        std::cout << "\n";
      }
      if (worst > 0) std::cout << "  largest ratio: " << fixed(worst, 2) << "\n";
    };
    for (const char* baseline : {"heat-paper", "dgpc", "dem"})
      if (has("heat") && has(baseline))
        heat_table(std::string("heat / ") + baseline +
                       " query time (medians over the same sources; below 1: heat is faster):",
                   [&](const Summary_row& heat, const std::string& m, double f) {
                     const auto* b = find_row(m, baseline, f);
                     return b && b->median_ms > 0 ? heat.median_ms / b->median_ms : nan_value;
                   });
    if (m_options.source_points) {
      for (const std::string& method : m_options.methods) {
        if (method == "heat-full") continue;
        header(method + ": query time from a point / from a vertex (medians over the same "
                        "sources):");
        for (const auto& m : meshes) {
          std::cout << pad(m, 18, true);
          for (double f : fractions) {
            const auto* a = find_row(m, method + "@point", f);
            const auto* b = find_row(m, method, f);
            std::cout << pad(a && b && b->median_ms > 0 ? fixed(a->median_ms / b->median_ms, 2)
                                                        : "-",
                             10);
          }
          std::cout << "\n";
        }
      }
    }
    if (has("heat"))
      heat_table("heat p90 / median query time:",
                 [](const Summary_row& heat, const std::string&, double) {
                   return heat.median_ms > 0 ? heat.p90_ms / heat.median_ms : nan_value;
                 });
    if (has("heat")) {
      // What makes the p90: a query that misses the safety margin pays for
      // a second distance step on a region twice as large.
      header("heat queries that doubled their region (of the sources timed):");
      for (const auto& m : meshes) {
        std::cout << pad(m, 18, true);
        for (double f : fractions) {
          const auto* a = find_row(m, "heat", f);
          std::cout << pad(a ? std::to_string(a->retried) + "/" + std::to_string(a->queries) : "-",
                           10);
        }
        std::cout << "\n";
      }
    }
    if (has("heat")) {
      heat_table("heat query time / stream floor (median over sources; whole query time, so an "
                 "upper bound on solve / floor):",
                 [](const Summary_row& heat, const std::string&, double) { return heat.floor_ratio; });
      heat_table("heat time inside the localized solves / stream floor (median over sources):",
                 [](const Summary_row& heat, const std::string&, double) {
                   return heat.solve_floor_ratio;
                 });
    }
    // Per patch vertex cost of every method, and relative to the reference
    // mesh (armadillo if benchmarked, else the first).
    std::string reference = meshes.empty() ? "" : meshes.front();
    for (const auto& m : meshes)
      if (m == "armadillo") reference = m;
    for (const std::string& method : m_options.methods) {
      if (method == "heat-full") continue;
      std::cout << "\n" << method << ": microseconds per patch vertex (median ms / patch; "
                << "(x): relative to " << reference << ")\n"
                << pad("mesh", 18, true);
      for (double f : fractions) std::cout << pad(fmt(f, 3), 16);
      std::cout << "\n";
      for (const auto& m : meshes) {
        std::cout << pad(m, 18, true);
        for (double f : fractions) {
          const auto* a = find_row(m, method, f);
          const auto* r = find_row(reference, method, f);
          std::string cell = a ? fixed(a->us_per_patch_vertex, 3) : "-";
          if (a && r && m != reference && r->us_per_patch_vertex > 0)
            cell += " (" + fixed(a->us_per_patch_vertex / r->us_per_patch_vertex, 2) + "x)";
          std::cout << pad(cell, 16);
        }
        std::cout << "\n";
      }
    }
    std::cout << std::flush;
  }

  const Bench_options& m_options;
  expmap::Heat_options m_heat_options;
  expmap::Heat_query_options m_heat_query;
  std::ofstream m_csv, m_stats, m_detail;
  std::vector<Mesh_statistics> m_mesh_statistics;
  std::vector<Summary_row> m_rows;
};

std::vector<Mesh_job> mesh_jobs(const Bench_options& o) {
  std::vector<Mesh_job> jobs;
  // Missing files fail now, not after the meshes before them were timed.
  for (const std::string& path : o.meshes) {
    if (!std::filesystem::is_regular_file(path))
      throw std::runtime_error("cannot open mesh file '" + path + "'");
    jobs.push_back({mesh_name(path), [path] { return read_triangle_mesh<Mesh>(path); }});
  }
  if (o.subdivide_elephant > 0) {
    std::string elephant = o.elephant;
    if (elephant.empty())
      for (const std::string& path : o.meshes)
        if (std::filesystem::path(path).filename() == "refined_elephant.off") elephant = path;
    if (elephant.empty()) elephant = "data/meshes/refined_elephant.off";
    if (!std::filesystem::is_regular_file(elephant))
      throw std::runtime_error("cannot open the mesh to subdivide '" + elephant +
                               "' (give --elephant FILE)");
    const unsigned levels = o.subdivide_elephant;
    const std::string name = loop_subdivided_name(elephant, levels);
    const std::filesystem::path dir =
        o.cache_dir.empty() ? std::filesystem::path(elephant).parent_path()
                            : std::filesystem::path(o.cache_dir);
    const std::string cache = (dir / (name + ".off")).string();
    jobs.push_back({name, [elephant, levels, cache] {
                      return loop_subdivided_mesh<Mesh>(elephant, levels, cache, std::cout);
                    }});
  }
  return jobs;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Bench_options options = parse_bench_options(argc, argv);
    if (options.help) {
      std::cout << usage_text();
      return 0;
    }
    std::cout << "expmap-bench: methods";
    for (const auto& m : options.methods) std::cout << " " << m;
    std::cout << "; fractions";
    for (double f : options.fractions) std::cout << " " << f;
    std::cout << "; " << options.sources << " sources (seed " << options.seed
              << "), each query the fastest of " << options.repeats << " runs, methods taking turns";
    if (options.full_sources > 0)
      std::cout << ", heat-full on the first " << options.full_sources;
    if (options.factor_precision == expmap::Factor_precision::single_precision) std::cout << "; single-precision factors";
    if (options.query_threads > 1)
      std::cout << "; heat queries on " << options.query_threads << " threads";
    std::cout << "\n";
    Benchmark benchmark(options);
    benchmark.run(mesh_jobs(options));
    return 0;
  } catch (const Usage_error& e) {
    std::cerr << "expmap-bench: " << e.what() << "\n\n" << usage_text();
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "expmap-bench: " << e.what() << "\n";
    return 1;
  }
}
