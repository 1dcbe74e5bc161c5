// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-tip-study: the heat method (with its geodesic-front fallback and
// without, as the paper computes it) and DGPC at the sources of closed
// meshes where the surface is least like a plane: the tips of thin parts,
// eyes, sharp creases (Tip_sources.h). Per mesh: each method's flipped
// triangles over all sources, the median over the sources of the
// fold-free fraction (the fold-free radius over the largest r of the map),
// and with --exact the median mean |dtheta| against the exact map after
// the best rotation (Map_agreement.h). The targets, per mesh: heat flips
// no more triangles than DGPC, and its median fold-free fraction is at
// least DGPC's.
//
//   --meshes DIR     the demo meshes (default: the project's data/meshes)
//   --mesh NAME      a mesh of DIR (repeatable; default: armadillo.off,
//                    elephant.off, man.off, bunny00.off, camel.off)
//   --sources N      tip sources per mesh (default 20)
//   --vertices LIST  these sources (comma-separated indices) instead, for
//                    every mesh named
//   --fraction F     patch size as a fraction of the mesh (default 0.05)
//   --exact          also the angle error against the exact map (slow)
//   --csv FILE       one row per (mesh, source, method) (default: none)

#include "Common.h"
#include "Map_agreement.h"
#include "Methods.h"
#include "Statistics.h"
#include "Tip_sources.h"

#include <expmap/Errors.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Fold_free_radius.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>
#include <expmap/Patch.h>

#include <algorithm>
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
  std::vector<std::string> names;
  std::size_t sources = 20;
  std::vector<std::size_t> vertices;
  double fraction = 0.05;
  bool exact = false;
  fs::path csv;
};

const char* usage_text() {
  return "usage: expmap-tip-study [--meshes DIR] [--mesh NAME ...] [--sources N]\n"
         "                        [--vertices I,J,...] [--fraction F] [--exact] [--csv FILE]\n";
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
    else if (a == "--mesh") o.names.push_back(value());
    else if (a == "--sources") o.sources = std::stoul(value());
    else if (a == "--vertices") {
      std::stringstream list(value());
      for (std::string item; std::getline(list, item, ',');) o.vertices.push_back(std::stoul(item));
    } else if (a == "--fraction") o.fraction = std::stod(value());
    else if (a == "--exact") o.exact = true;
    else if (a == "--csv") o.csv = value();
    else throw std::invalid_argument("unknown argument " + a);
  }
  if (o.names.empty())
    o.names = {"armadillo.off", "elephant.off", "man.off", "bunny00.off", "camel.off"};
  expmap::Patch::fraction(o.fraction);  // throws with a message if out of range
  return o;
}

/// One method's map of one source.
struct Measured {
  std::optional<Map_agreement> agreement;  // none if the query failed
  double fold_free_fraction = 0;
  std::size_t front_maps = 0;
};

/// The methods' medians and sums over one mesh's sources.
struct Summary {
  std::size_t flipped = 0, triangles = 0, failed = 0, front_maps = 0;
  std::vector<double> fold_free, angle_error;
};

const std::vector<std::string> method_keys = {"heat", "heat-paper", "dgpc"};

Method_set make_methods(const Mesh& mesh, bool exact) {
  Method_set set(mesh);
  if (exact) set.add<expmap::Exact_exponential_map>("exact", "exact");
  set.add_heat("heat", "heat", expmap::Heat_options(), expmap::Heat_query_options());
  expmap::Heat_query_options paper;
  paper.fallback = expmap::Heat_fallback::none;
  set.add_heat("heat-paper", "heat (paper)", expmap::Heat_options(), paper);
  set.add<expmap::Geodesic_polar_coordinates>("dgpc", "DGPC");
  return set;
}

double median_or_nan(std::vector<double> v) {
  return v.empty() ? std::nan("") : median(v);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "expmap-tip-study: " << e.what() << "\n" << usage_text();
    return 2;
  }
  std::ofstream csv;
  if (!options.csv.empty()) {
    csv.open(options.csv);
    csv << "mesh,source,method,flipped,triangles,fold_free_fraction,angle_error,front_map\n";
  }
  const expmap::Patch patch = expmap::Patch::fraction(options.fraction);
  bool all_pass = true;
  for (const std::string& name : options.names) {
    Mesh mesh;
    try {
      expmap::IO::read_triangle_mesh((options.meshes / name).string(), mesh);
    } catch (const std::exception& e) {
      std::cerr << "expmap-tip-study: " << name << ": " << e.what() << "\n";
      return 1;
    }
    const std::vector<std::size_t> sources =
        options.vertices.empty() ? tip_sources(mesh, options.sources) : options.vertices;
    const Method_set set = make_methods(mesh, options.exact);
    std::map<std::string, Summary> summary;
    for (std::size_t s : sources) {
      std::optional<Map> exact;
      for (const Method& method : set.methods) {
        Measured m;
        try {
          const Map map = method.compute(s, patch);
          if (method.key == "exact") {
            exact = map;
            continue;
          }
          m.agreement = exact ? map_agreement(mesh, map, *exact) : map_agreement(mesh, map);
          const double largest = map.distance.empty() ? 0.0 : map.distance.back();
          m.fold_free_fraction = largest > 0 ? expmap::fold_free_radius(mesh, map) / largest : 1.0;
          m.front_maps = map.statistics.front_maps;
        } catch (const std::exception& e) {
          if (method.key == "exact") continue;
          std::cerr << "  " << name << " source " << s << ", " << method.label << ": " << e.what()
                    << "\n";
        }
        if (method.key == "exact") continue;
        Summary& sum = summary[method.key];
        if (!m.agreement) {
          ++sum.failed;
          continue;
        }
        sum.flipped += m.agreement->flipped;
        sum.triangles += m.agreement->triangles;
        sum.front_maps += m.front_maps;
        sum.fold_free.push_back(m.fold_free_fraction);
        if (std::isfinite(m.agreement->angle_error)) sum.angle_error.push_back(m.agreement->angle_error);
        if (csv)
          csv << name << "," << s << "," << method.key << "," << m.agreement->flipped << ","
              << m.agreement->triangles << "," << m.fold_free_fraction << ","
              << m.agreement->angle_error << "," << m.front_maps << "\n";
      }
    }
    std::printf("%s: %zu sources, %.0f%% patches\n", name.c_str(), sources.size(),
                100 * options.fraction);
    std::printf("  %-13s %9s %10s %14s %12s %7s\n", "method", "flipped", "triangles",
                "fold-free frac", "mean|dtheta|", "failed");
    for (const std::string& key : method_keys) {
      const Summary& sum = summary[key];
      std::printf("  %-13s %9zu %10zu %14.3f %12.4f %7zu", key.c_str(), sum.flipped,
                  sum.triangles, median_or_nan(sum.fold_free), median_or_nan(sum.angle_error),
                  sum.failed);
      if (key == "heat") std::printf("   (%zu from the front)", sum.front_maps);
      std::printf("\n");
    }
    const Summary& heat = summary["heat"];
    const Summary& dgpc = summary["dgpc"];
    const bool pass = heat.failed == 0 && heat.flipped <= dgpc.flipped &&
                      median_or_nan(heat.fold_free) >= median_or_nan(dgpc.fold_free);
    all_pass = all_pass && pass;
    std::printf("  targets (heat flips <= DGPC's, median fold-free fraction >= DGPC's): %s\n\n",
                pass ? "PASS" : "FAIL");
  }
  return all_pass ? 0 : 3;
}
