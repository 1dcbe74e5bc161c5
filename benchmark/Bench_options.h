// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_BENCH_OPTIONS_H
#define EXPMAP_BENCHMARK_BENCH_OPTIONS_H

/// \file Bench_options.h
/// The command line of expmap-bench.

#include <expmap/Heat_options.h>
#include <expmap/Option_names.h>
#include <expmap/Setting_ranges.h>

#include <cstddef>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace expmap_bench {

inline const char* usage_text() {
  return R"(usage: expmap-bench --mesh FILE [--mesh FILE ...] [options]

Times exponential-map queries from random source vertices (the paper's
Figs. 7 and 8): query time against patch fraction and against mesh size.

  --mesh FILE              a triangle mesh (OFF, OBJ, PLY, STL); repeatable
  --subdivide-elephant N   also benchmark refined_elephant Loop-subdivided N
                           times ("elephant_loopN", 711,420 vertices for N=2),
                           cached as OFF in --cache-dir; runs after the --mesh
                           meshes
  --elephant FILE          the mesh to subdivide (default: the --mesh named
                           refined_elephant.off, else
                           data/meshes/refined_elephant.off)
  --cache-dir DIR          where elephant_loopN.off is cached (default: the
                           directory of the mesh to subdivide)
  --methods LIST           comma-separated: heat, heat-paper (heat without its
                           geodesic-front fallback, on the same object),
                           heat-full, dem, dgpc, exact
                           (default: heat,heat-full)
  --fractions LIST         patch fractions in (0,1] (default:
                           0.01,0.02,0.05,0.1,0.25)
  --sources N              random source vertices per mesh (default 20)
  --source-points          also time each method from a point of a face next
                           to each source vertex (weight 0.5 at the vertex,
                           0.25 at the face's other corners), as
                           "METHOD@point" taking turns with the rest, and
                           print the point / vertex time ratios
  --full-sources N         heat-full uses only the first N of them (default:
                           all); its time does not depend on the fraction
  --seed S                 std::mt19937 seed of the sources (default 1)
  --repeats K              each query is run K times and its fastest run
                           kept (default 3); the methods take turns per
                           source, so a change of load hits them alike
  --time-factor M          Heat_options::time_factor (default: the library's)
  --factor-precision P     double-precision | single-precision (or double |
                           single): Heat_options::factor_precision (default:
                           the library's; the stream floor counts every
                           factor entry as a double)
  --query-threads N        1 | 2: Heat_query_options::query_threads, the threads
                           one heat query runs on (default 1; the speed
                           targets are for one)
  --poisson-compression T  Heat_options::poisson_compression_tolerance
                           (default: the library's; 0 keeps the Poisson
                           factor dense)
  --subdomain-min-vertices N
                           Heat_options::subdomain_min_vertices (default: the
                           library's; a number above the mesh's size factors
                           the whole mesh)
  --csv OUT                one row per mesh, method and fraction
  --stats CSV2             one row per mesh: precompute time, peak memory,
                           factor sizes
  --detail CSV3            one row per query
  --help                   this text
)";
}

/// A command-line mistake (the program prints the usage after it).
struct Usage_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct Bench_options {
  std::vector<std::string> meshes;
  unsigned subdivide_elephant = 0;  // 0: none
  std::string elephant;             // empty: find it
  std::string cache_dir;            // empty: next to the elephant
  std::vector<std::string> methods{"heat", "heat-full"};
  std::vector<double> fractions{0.01, 0.02, 0.05, 0.1, 0.25};
  std::size_t sources = 20;
  bool source_points = false;  // also time each method from a point next to each source
  std::size_t full_sources = 0;  // 0: all
  unsigned seed = 1;
  std::size_t repeats = 3;
  double time_factor = 0;  // 0: the library's default
  expmap::Factor_precision factor_precision = expmap::Heat_options().factor_precision;
  int query_threads = 1;
  double poisson_compression = -1;  // negative: the library's default
  std::size_t subdomain_min_vertices = expmap::Heat_options().subdomain_min_vertices;
  std::string csv, stats, detail;
  bool help = false;
};

inline std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

inline double parse_double(const std::string& option, const std::string& text) {
  try {
    std::size_t used = 0;
    const double x = std::stod(text, &used);
    if (used == text.size()) return x;
  } catch (...) {
  }
  throw Usage_error(option + " expects a number (got '" + text + "')");
}

inline std::size_t parse_count(const std::string& option, const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error(option + " expects a non-negative integer (got '" + text + "')");
  return static_cast<std::size_t>(std::stoull(text));
}

/// `value` if `range` holds it.
inline double in_range(const std::string& option, const expmap::Setting_range& range,
                       double value) {
  if (!range.contains(value))
    throw Usage_error(option + " must be " + range.range + " (got " +
                      expmap::setting_value_text(value) + ")");
  return value;
}

/// \throws Usage_error with a message for the user.
inline Bench_options parse_bench_options(int argc, char** argv) {
  Bench_options o;
  const std::vector<std::string> known_methods{"heat",  "heat-paper", "heat-full",
                                               "dem",   "dgpc",       "exact"};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      o.help = true;
      return o;
    }
    if (arg == "--source-points") {
      o.source_points = true;
      continue;
    }
    if (i + 1 >= argc) throw Usage_error("unknown option or missing value: " + arg);
    const std::string value = argv[++i];
    if (arg == "--mesh") {
      o.meshes.push_back(value);
    } else if (arg == "--subdivide-elephant") {
      o.subdivide_elephant = static_cast<unsigned>(parse_count(arg, value));
      if (o.subdivide_elephant > 4)
        throw Usage_error("--subdivide-elephant: at most 4 levels (each is 4x larger)");
    } else if (arg == "--elephant") {
      o.elephant = value;
    } else if (arg == "--cache-dir") {
      o.cache_dir = value;
    } else if (arg == "--methods") {
      o.methods = split_list(value);
      for (const auto& m : o.methods) {
        bool ok = false;
        for (const auto& k : known_methods) ok = ok || m == k;
        if (!ok)
          throw Usage_error("unknown method '" + m +
                                      "' (choose from heat, heat-full, dem, dgpc, exact)");
      }
      if (o.methods.empty()) throw Usage_error("--methods is empty");
    } else if (arg == "--fractions") {
      o.fractions.clear();
      for (const auto& f : split_list(value)) {
        const double x = parse_double(arg, f);
        if (!(x > 0 && x <= 1)) throw Usage_error("fractions must be in (0, 1]");
        o.fractions.push_back(x);
      }
      if (o.fractions.empty()) throw Usage_error("--fractions is empty");
    } else if (arg == "--sources") {
      o.sources = parse_count(arg, value);
      if (o.sources == 0) throw Usage_error("--sources must be at least 1");
    } else if (arg == "--full-sources") {
      o.full_sources = parse_count(arg, value);
    } else if (arg == "--repeats") {
      o.repeats = parse_count(arg, value);
      if (o.repeats == 0) throw Usage_error("--repeats must be at least 1");
    } else if (arg == "--seed") {
      o.seed = static_cast<unsigned>(parse_count(arg, value));
    } else if (arg == "--time-factor") {
      o.time_factor = in_range(arg, expmap::setting_ranges::time_factor, parse_double(arg, value));
    } else if (arg == "--factor-precision") {
      try {
        o.factor_precision = expmap::from_string<expmap::Factor_precision>(value);
      } catch (const expmap::Invalid_input& e) {
        throw Usage_error(e.what());
      }
    } else if (arg == "--query-threads") {
      o.query_threads = static_cast<int>(in_range(arg, expmap::setting_ranges::query_threads,
                                                  static_cast<double>(parse_count(arg, value))));
    } else if (arg == "--poisson-compression") {
      o.poisson_compression =
          in_range(arg, expmap::setting_ranges::poisson_compression_tolerance,
                   parse_double(arg, value));
    } else if (arg == "--subdomain-min-vertices") {
      o.subdomain_min_vertices = parse_count(arg, value);
    } else if (arg == "--csv") {
      o.csv = value;
    } else if (arg == "--stats") {
      o.stats = value;
    } else if (arg == "--detail") {
      o.detail = value;
    } else {
      throw Usage_error("unknown option: " + arg);
    }
  }
  if (o.meshes.empty() && o.subdivide_elephant == 0)
    throw Usage_error("give at least one --mesh (or --subdivide-elephant N)");
  return o;
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_BENCH_OPTIONS_H
