// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-batch-bench: throughput of compute_many(), in maps per second, for
// a patch around every vertex of a mesh, on 1, 2, ... threads. Through the
// public API only.
//
//   expmap-batch-bench [--mesh FILE] [--fraction F] [--methods heat,dgpc]
//                      [--threads 1,2] [--repeats R] [--csv OUT]
//
// Each (method, threads) batch maps every vertex with a face once per
// repeat; the best repeat is reported (the machine may be shared: the best
// is the one least disturbed), with the median beside it. Also reported:
// the CPU time the process used per map, which stays flat when threads scale
// and grows when they contend (memory bandwidth, cache), and the cores the
// batch kept busy (CPU time over wall time): on a machine shared with other
// work, 2 threads may get less than 2 cores, and then that, not the
// library, bounds the scaling.

#include <expmap/Batch.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "Bench_options.h"
#include "Mesh_loading.h"
#include "Timing.h"

namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

struct Options {
  std::string mesh = "data/meshes/armadillo.off";
  double fraction = 0.01;
  std::vector<std::string> methods{"heat", "dgpc"};
  std::vector<unsigned> threads{1, 2};
  unsigned repeats = 3;
  std::string csv;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    if (name == "--help" || name == "-h") {
      std::cout << "usage: expmap-batch-bench [--mesh FILE] [--fraction F] [--methods heat,dgpc]\n"
                   "                          [--threads 1,2] [--repeats R] [--csv OUT]\n";
      std::exit(0);
    }
    if (i + 1 >= argc) throw expmap_bench::Usage_error(name + " needs a value");
    const std::string value = argv[++i];
    if (name == "--mesh") {
      o.mesh = value;
    } else if (name == "--fraction") {
      o.fraction = expmap_bench::parse_double(name, value);
    } else if (name == "--methods") {
      o.methods = expmap_bench::split_list(value);
    } else if (name == "--threads") {
      o.threads.clear();
      for (const std::string& t : expmap_bench::split_list(value))
        o.threads.push_back(static_cast<unsigned>(expmap_bench::parse_double(name, t)));
    } else if (name == "--repeats") {
      o.repeats = std::max(1u, static_cast<unsigned>(expmap_bench::parse_double(name, value)));
    } else if (name == "--csv") {
      o.csv = value;
    } else {
      throw expmap_bench::Usage_error("unknown option " + name);
    }
  }
  return o;
}

double process_cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Row {
  std::string method;
  unsigned threads;
  std::size_t maps, failures;
  double best_seconds, median_seconds, cpu_seconds_per_map, cores_busy;
};

template <class Method>
void measure(const std::string& name, const Method& method, const std::vector<std::size_t>& sources,
             const expmap::Patch& patch, const Options& o, std::vector<Row>& rows) {
  for (unsigned threads : o.threads) {
    std::vector<double> seconds;
    double cpu = 0, wall = 0;
    std::size_t failures = 0;
    for (unsigned r = 0; r < o.repeats; ++r) {
      expmap::Batch_options batch;
      batch.threads = threads;
      const double cpu_start = process_cpu_seconds();
      expmap_bench::Stopwatch watch;
      const auto result = method.compute_many_by_index(sources, patch, batch);
      seconds.push_back(watch.seconds());
      cpu += process_cpu_seconds() - cpu_start;
      wall += seconds.back();
      failures = result.failures();
    }
    std::sort(seconds.begin(), seconds.end());
    rows.push_back({name, threads, sources.size(), failures, seconds.front(),
                    seconds[seconds.size() / 2],
                    cpu / (static_cast<double>(o.repeats) * static_cast<double>(sources.size())),
                    cpu / wall});
    const Row& row = rows.back();
    std::printf("%-5s %2u thread(s): %8.0f maps/s best, %8.0f median, %6.1f us CPU/map, "
                "%.2f cores busy%s\n",
                name.c_str(), threads, static_cast<double>(row.maps) / row.best_seconds,
                static_cast<double>(row.maps) / row.median_seconds, 1e6 * row.cpu_seconds_per_map,
                row.cores_busy, failures ? (", " + std::to_string(failures) + " failed").c_str() : "");
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    const Mesh mesh = expmap_bench::read_triangle_mesh<Mesh>(o.mesh);
    std::vector<std::size_t> sources;
    for (Mesh::Vertex_index v : vertices(mesh))
      if (!mesh.is_isolated(v)) sources.push_back(static_cast<std::size_t>(v));
    const expmap::Patch patch = expmap::Patch::fraction(o.fraction);
    std::printf("%s: %zu vertices, %zu sources, patches of %g of the mesh, %u hardware threads\n",
                o.mesh.c_str(), static_cast<std::size_t>(num_vertices(mesh)), sources.size(),
                o.fraction, std::thread::hardware_concurrency());
    std::vector<Row> rows;
    for (const std::string& name : o.methods) {
      expmap_bench::Stopwatch watch;
      if (name == "heat") {
        const expmap::Heat_exponential_map<Mesh> heat(mesh);
        std::printf("heat  precompute %.2f s\n", watch.seconds());
        measure(name, heat, sources, patch, o, rows);
      } else if (name == "dgpc") {
        const expmap::Geodesic_polar_coordinates<Mesh> dgpc(mesh);
        measure(name, dgpc, sources, patch, o, rows);
      } else {
        throw expmap_bench::Usage_error("unknown method '" + name + "' (heat, dgpc)");
      }
    }
    if (!o.csv.empty()) {
      std::ofstream out(o.csv);
      out << "mesh,vertices,fraction,method,threads,maps,failures,best_seconds,median_seconds,"
             "maps_per_second,cpu_us_per_map,cores_busy\n";
      for (const Row& r : rows)
        out << expmap_bench::mesh_name(o.mesh) << ',' << num_vertices(mesh) << ',' << o.fraction
            << ',' << r.method << ',' << r.threads << ',' << r.maps << ',' << r.failures << ','
            << r.best_seconds << ',' << r.median_seconds << ','
            << static_cast<double>(r.maps) / r.best_seconds << ',' << 1e6 * r.cpu_seconds_per_map
            << ',' << r.cores_busy << '\n';
      if (!out) throw std::runtime_error("could not write '" + o.csv + "'");
    }
    return 0;
  } catch (const expmap_bench::Usage_error& e) {
    std::cerr << "expmap-batch-bench: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "expmap-batch-bench: " << e.what() << "\n";
    return 1;
  }
}
