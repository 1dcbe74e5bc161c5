// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-patch-operator-bench: what the polar patch operator
// (expmap::polar_patch_operator) costs on top of the maps it is built from,
// how much memory it takes, and where each method places its grid points
// against the exact map. Through the public API only.
//
//   expmap-patch-operator-bench [--mesh FILE] [--subdivide K] [--cache-dir DIR]
//                               [--methods heat,dgpc,dem] [--patch-vertices 100,300]
//                               [--rings 5] [--rays 16] [--sources all|N]
//                               [--threads T] [--chunk N] [--accuracy-sources N]
//                               [--radius-sources N] [--seed S] [--csv OUT]
//
// Grid radius. For each patch size N the grid's radius R is the median, over
// --radius-sources random sources, of the DGPC distance of the N-th nearest
// vertex (the map of Patch::vertex_count(N) holds the N nearest, farthest
// last): a geodesic disk of radius R holds about N vertices. The estimate of
// a regular mesh of mean edge length h, R = h sqrt(N sqrt(3) / (2 pi)), is
// printed beside it.
//
// Timing. Per (method, N), the operator for every source (--sources all, the
// default: every vertex with a face; or N seeded random ones) on --threads
// threads, and the maps alone for the same sources: compute_many_by_index()
// with the patch the operator asks for, Patch::geodesic_radius(R + 2 h) with
// Query_options::find_fold_free_radius, on the same threads. The sources
// are cut into chunks of --chunk; per chunk every method runs both
// measurements, the methods in turn and the two measurements in alternating
// order, so that a change of load on a shared machine hits them alike. Each
// measurement is wall time and includes freeing its result (the operator's
// chunk, the batch's maps). "beyond maps" is (operator - maps) / maps.
//
// Memory. The operator's bytes are nonZeros * (8 + 8) + rows * (8 + 1):
// an entry's column index and weight, a row's start and its `sampled` flag;
// summed over the chunks, which is the operator of all the sources at once.
// "sampled" is the share of rows (grid points) that the maps hold.
//
// Placement. At --accuracy-sources random sources, the operator of one
// source is computed with the method and with expmap::Exact_exponential_map,
// both with the reference direction set to the exact map's axis_u at that
// source, so that grid point (i, j) is meant to be the same surface point.
// A grid point's surface position is sum_k weight_k * position(vertex_k);
// the table gives the mean and the 90th percentile (nearest rank) of the
// distance between the method's and the exact map's positions, divided by R,
// over the grid points that both sample.
//
// Random choices come from one std::mt19937(--seed), in this order: the
// radius sources, the accuracy sources, the timed subset (if not all).

#include <expmap/Batch.h>
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/Patch.h>
#include <expmap/Polar_patch_operator.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "Bench_options.h"
#include "Loop_subdivided_mesh.h"
#include "Mesh_loading.h"
#include "Sample_statistics.h"
#include "Timing.h"

namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

constexpr double pi = 3.14159265358979323846;

const char* usage_text() {
  return R"(usage: expmap-patch-operator-bench [options]

Times the polar patch operator against the maps it is built from, its
memory, and its grid placement against the exact map.

  --mesh FILE              a triangle mesh (default data/meshes/armadillo.off)
  --subdivide K            Loop-subdivide it K times first (default 0), cached
                           as OFF in --cache-dir
  --cache-dir DIR          where STEM_loopK.off is cached (default build/meshes)
  --methods LIST           comma-separated: heat, dgpc, dem (default all three)
  --patch-vertices LIST    vertices a geodesic disk of the grid's radius holds,
                           one grid radius each (default 100,300)
  --rings N, --rays N      the polar grid (default 5 x 16)
  --sources all|N          timed sources: every vertex with a face (default)
                           or N seeded random ones
  --threads T              threads of the operator and of the batches
                           (default 1)
  --chunk N                sources per timed batch; the measurements take
                           turns per chunk (default 4096)
  --accuracy-sources N     random sources of the placement study (default 50;
                           0 skips it)
  --radius-sources N       random sources the radius is measured at (default 20)
  --seed S                 std::mt19937 seed (default 1)
  --csv OUT                one row per method and patch size
  --help                   this text
)";
}

struct Options {
  std::string mesh = "data/meshes/armadillo.off";
  unsigned subdivide = 0;
  std::string cache_dir = "build/meshes";
  std::vector<std::string> methods{"heat", "dgpc", "dem"};
  std::vector<std::size_t> patch_vertices{100, 300};
  std::size_t rings = 5, rays = 16;
  std::size_t sources = 0;  // 0: all
  unsigned threads = 1;
  std::size_t chunk = 4096;
  std::size_t accuracy_sources = 50;
  std::size_t radius_sources = 20;
  unsigned seed = 1;
  std::string csv;
};

std::size_t positive_count(const std::string& option, const std::string& value) {
  const std::size_t n = expmap_bench::parse_count(option, value);
  if (n == 0) throw expmap_bench::Usage_error(option + " must be at least 1");
  return n;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    if (name == "--help" || name == "-h") {
      std::cout << usage_text();
      std::exit(0);
    }
    if (i + 1 >= argc) throw expmap_bench::Usage_error(name + " needs a value");
    const std::string value = argv[++i];
    if (name == "--mesh") {
      o.mesh = value;
    } else if (name == "--subdivide") {
      o.subdivide = static_cast<unsigned>(expmap_bench::parse_count(name, value));
      if (o.subdivide > 4)
        throw expmap_bench::Usage_error("--subdivide: at most 4 levels (each is 4x larger)");
    } else if (name == "--cache-dir") {
      o.cache_dir = value;
    } else if (name == "--methods") {
      o.methods = expmap_bench::split_list(value);
      if (o.methods.empty()) throw expmap_bench::Usage_error("--methods is empty");
      for (const std::string& m : o.methods)
        if (m != "heat" && m != "dgpc" && m != "dem")
          throw expmap_bench::Usage_error("unknown method '" + m + "' (heat, dgpc, dem)");
    } else if (name == "--patch-vertices") {
      o.patch_vertices.clear();
      for (const std::string& n : expmap_bench::split_list(value))
        o.patch_vertices.push_back(positive_count(name, n));
      if (o.patch_vertices.empty()) throw expmap_bench::Usage_error("--patch-vertices is empty");
    } else if (name == "--rings") {
      o.rings = positive_count(name, value);
    } else if (name == "--rays") {
      o.rays = positive_count(name, value);
    } else if (name == "--sources") {
      o.sources = value == "all" ? 0 : positive_count(name, value);
    } else if (name == "--threads") {
      o.threads = static_cast<unsigned>(positive_count(name, value));
    } else if (name == "--chunk") {
      o.chunk = positive_count(name, value);
    } else if (name == "--accuracy-sources") {
      o.accuracy_sources = expmap_bench::parse_count(name, value);
    } else if (name == "--radius-sources") {
      o.radius_sources = positive_count(name, value);
    } else if (name == "--seed") {
      o.seed = static_cast<unsigned>(expmap_bench::parse_count(name, value));
    } else if (name == "--csv") {
      o.csv = value;
    } else {
      throw expmap_bench::Usage_error("unknown option " + name);
    }
  }
  return o;
}

/// The mean edge length, summed as the operator sums it (so that the maps
/// alone get the very patch the operator asks for).
double mean_edge_length(const Mesh& mesh) {
  double total = 0;
  std::size_t count = 0;
  for (auto e : edges(mesh)) {
    const auto& a = mesh.point(source(e, mesh));
    const auto& b = mesh.point(target(e, mesh));
    const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
    total += std::sqrt(dx * dx + dy * dy + dz * dz);
    ++count;
  }
  return count > 0 ? total / double(count) : 0;
}

/// `count` distinct random vertices with a face (fewer if the mesh has
/// fewer), drawn from `rng`.
std::vector<std::size_t> pick_sources(const std::vector<std::size_t>& usable, std::size_t count,
                                      std::mt19937& rng) {
  count = std::min(count, usable.size());
  std::uniform_int_distribution<std::size_t> pick(0, usable.size() - 1);
  std::set<std::size_t> taken;
  std::vector<std::size_t> out;
  while (out.size() < count) {
    const std::size_t v = usable[pick(rng)];
    if (taken.insert(v).second) out.push_back(v);
  }
  return out;
}

/// A method behind one interface: its operator and its maps alone.
struct Bench_method {
  std::string name;
  std::function<expmap::Polar_patch_operator(const std::vector<std::size_t>&,
                                             const expmap::Polar_grid&, const expmap::Batch_options&,
                                             const expmap::Query_options&)>
      patch_operator;
  /// The maps of the sources, computed and freed; returns the failures.
  std::function<std::size_t(const std::vector<std::size_t>&, const expmap::Patch&,
                            const expmap::Batch_options&, const expmap::Query_options&)>
      maps;
};

template <class Method>
Bench_method bench_method(const std::string& name, const Mesh& mesh, const Method& method) {
  using Query = typename Method::Query;
  Bench_method b;
  b.name = name;
  b.patch_operator = [&mesh, &method](const std::vector<std::size_t>& sources,
                                      const expmap::Polar_grid& grid,
                                      const expmap::Batch_options& batch,
                                      const expmap::Query_options& query) {
    return expmap::polar_patch_operator(mesh, method, sources, grid, batch, Query(query));
  };
  b.maps = [&method](const std::vector<std::size_t>& sources, const expmap::Patch& patch,
                     const expmap::Batch_options& batch, const expmap::Query_options& query) {
    return method.compute_many_by_index(sources, patch, batch, Query(query)).failures();
  };
  return b;
}

/// The surface positions of the grid points of a one-source operator;
/// `sampled[r]` says which exist.
std::vector<std::array<double, 3>> grid_positions(const expmap::Polar_patch_operator& op,
                                                  const std::vector<std::array<double, 3>>& point) {
  using Weights = decltype(op.weights);
  std::vector<std::array<double, 3>> out(static_cast<std::size_t>(op.weights.rows()),
                                         std::array<double, 3>{{0, 0, 0}});
  for (std::ptrdiff_t r = 0; r < op.weights.rows(); ++r)
    for (Weights::InnerIterator it(op.weights, r); it; ++it)
      for (int c = 0; c < 3; ++c)
        out[static_cast<std::size_t>(r)][c] +=
            it.value() * point[static_cast<std::size_t>(it.col())][c];
  return out;
}

/// The mean; NaN for an empty sample.
double mean(const std::vector<double>& xs) {
  double sum = 0;
  for (double x : xs) sum += x;
  return xs.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / double(xs.size());
}

struct Row {
  std::string method;
  std::size_t patch_vertices = 0;
  double radius = 0;
  std::size_t sources = 0, failures = 0, map_failures = 0;
  double operator_seconds = 0, maps_seconds = 0;
  std::size_t rows = 0, entries = 0, sampled = 0;
  std::size_t accuracy_sources = 0;  // at which both operators were computed
  std::vector<double> placement;     // distance / R per grid point both sample
  double beyond_maps() const { return (operator_seconds - maps_seconds) / maps_seconds; }
  double operator_bytes() const { return double(entries) * (8 + 8) + double(rows) * (8 + 1); }
  double sampled_share() const { return rows ? double(sampled) / double(rows) : 0; }
};

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    const Mesh mesh =
        o.subdivide
            ? expmap_bench::loop_subdivided_mesh<Mesh>(
                  o.mesh, o.subdivide,
                  o.cache_dir + "/" + expmap_bench::loop_subdivided_name(o.mesh, o.subdivide) +
                      ".off",
                  std::cout)
            : expmap_bench::read_triangle_mesh<Mesh>(o.mesh);
    const std::string mesh_name = o.subdivide
                                      ? expmap_bench::loop_subdivided_name(o.mesh, o.subdivide)
                                      : expmap_bench::mesh_name(o.mesh);
    std::vector<std::size_t> usable;
    for (Mesh::Vertex_index v : vertices(mesh))
      if (!mesh.is_isolated(v)) usable.push_back(static_cast<std::size_t>(v));
    if (usable.empty()) throw std::runtime_error("the mesh has no face");
    std::vector<std::array<double, 3>> point(num_vertices(mesh));
    for (Mesh::Vertex_index v : vertices(mesh)) {
      const auto& p = mesh.point(v);
      point[static_cast<std::size_t>(v)] = {{p.x(), p.y(), p.z()}};
    }
    const double h = mean_edge_length(mesh);

    std::mt19937 rng(o.seed);
    const std::vector<std::size_t> radius_sources = pick_sources(usable, o.radius_sources, rng);
    const std::vector<std::size_t> accuracy_sources =
        pick_sources(usable, o.accuracy_sources, rng);
    std::vector<std::size_t> sources = usable;
    if (o.sources != 0 && o.sources < usable.size()) {
      sources = pick_sources(usable, o.sources, rng);
      std::sort(sources.begin(), sources.end());
    }
    std::printf("%s: %zu vertices, %zu faces, mean edge length h = %.6g; %zu timed sources, "
                "%u thread(s) (%u hardware threads), %zu x %zu grid\n",
                mesh_name.c_str(), static_cast<std::size_t>(num_vertices(mesh)),
                static_cast<std::size_t>(num_faces(mesh)), h, sources.size(), o.threads,
                std::thread::hardware_concurrency(), o.rings, o.rays);

    // The methods, built once (DGPC also measures the radii).
    expmap_bench::Stopwatch watch;
    const expmap::Geodesic_polar_coordinates<Mesh> dgpc(mesh);
    std::unique_ptr<expmap::Heat_exponential_map<Mesh>> heat;
    std::unique_ptr<expmap::Discrete_exponential_map<Mesh>> dem;
    std::vector<Bench_method> methods;
    for (const std::string& name : o.methods) {
      if (name == "heat") {
        watch.restart();
        heat = std::make_unique<expmap::Heat_exponential_map<Mesh>>(mesh);
        std::printf("heat  precompute %.2f s\n", watch.seconds());
        methods.push_back(bench_method(name, mesh, *heat));
      } else if (name == "dgpc") {
        methods.push_back(bench_method(name, mesh, dgpc));
      } else {
        dem = std::make_unique<expmap::Discrete_exponential_map<Mesh>>(mesh);
        methods.push_back(bench_method(name, mesh, *dem));
      }
    }

    // The grid radii.
    std::vector<double> radii;
    for (std::size_t n : o.patch_vertices) {
      std::vector<double> far;
      for (std::size_t s : radius_sources) {
        const auto map = dgpc.compute_by_index(s, expmap::Patch::vertex_count(n));
        far.push_back(map.distance.back());
      }
      radii.push_back(expmap_bench::median(far));
      std::printf("%4zu vertices: R = %.6g = %.2f h (median of %zu DGPC disks; a regular mesh: "
                  "%.2f h)\n",
                  n, radii.back(), radii.back() / h, far.size(),
                  std::sqrt(double(n) * std::sqrt(3.0) / (2 * pi)));
    }
    std::fflush(stdout);

    std::vector<Row> rows;
    expmap::Batch_options batch;
    batch.threads = o.threads;
    for (std::size_t k = 0; k < o.patch_vertices.size(); ++k) {
      const expmap::Polar_grid grid{radii[k], o.rings, o.rays};
      const expmap::Patch patch = expmap::Patch::geodesic_radius(radii[k] + 2 * h);
      expmap::Query_options query;
      query.find_fold_free_radius = true;
      const std::size_t first = rows.size();
      for (const Bench_method& m : methods) {
        rows.emplace_back();
        rows.back().method = m.name;
        rows.back().patch_vertices = o.patch_vertices[k];
        rows.back().radius = radii[k];
      }
      // Untimed warm-up: each method's workspaces on every thread.
      {
        const std::vector<std::size_t> warm(
            sources.begin(), sources.begin() + std::min<std::size_t>(sources.size(), 4 * o.threads));
        for (const Bench_method& m : methods) {
          m.patch_operator(warm, grid, batch, query);
          m.maps(warm, patch, batch, query);
        }
      }
      const std::size_t chunks = (sources.size() + o.chunk - 1) / o.chunk;
      expmap_bench::Stopwatch total;
      for (std::size_t c = 0; c < chunks; ++c) {
        const std::vector<std::size_t> part(
            sources.begin() + c * o.chunk,
            sources.begin() + std::min(sources.size(), (c + 1) * o.chunk));
        // The methods in turn, starting one further each chunk; each
        // method's two measurements swap places from chunk to chunk.
        for (std::size_t i = 0; i < methods.size(); ++i) {
          const std::size_t j = (c + i) % methods.size();
          const Bench_method& m = methods[j];
          Row& row = rows[first + j];
          const auto run_operator = [&] {
            expmap_bench::Stopwatch w;
            {
              const expmap::Polar_patch_operator op = m.patch_operator(part, grid, batch, query);
              row.rows += static_cast<std::size_t>(op.weights.rows());
              row.entries += static_cast<std::size_t>(op.weights.nonZeros());
              for (unsigned char s : op.sampled) row.sampled += s;
              for (const std::string& e : op.errors) row.failures += e.empty() ? 0 : 1;
            }
            row.operator_seconds += w.seconds();
          };
          const auto run_maps = [&] {
            expmap_bench::Stopwatch w;
            row.map_failures += m.maps(part, patch, batch, query);
            row.maps_seconds += w.seconds();
          };
          if ((c + j) % 2 == 0) {
            run_operator();
            run_maps();
          } else {
            run_maps();
            run_operator();
          }
          row.sources += part.size();
        }
        if (chunks > 1 && ((c + 1) * 10 / chunks != c * 10 / chunks))
          std::fprintf(stderr, "%zu vertices: %zu / %zu sources timed, %.0f s\n",
                       o.patch_vertices[k], std::min(sources.size(), (c + 1) * o.chunk),
                       sources.size(), total.seconds());
      }
    }

    // Placement against the exact map.
    if (!accuracy_sources.empty()) {
      const expmap::Exact_exponential_map<Mesh> exact(mesh);
      expmap::Batch_options one;
      one.threads = 1;
      expmap_bench::Stopwatch w;
      for (std::size_t s : accuracy_sources) {
        expmap::Query_options query;
        try {
          query.reference_direction = exact.compute_by_index(s, expmap::Patch::vertex_count(1)).axis_u;
        } catch (const std::exception& e) {
          std::fprintf(stderr, "exact map at source %zu failed: %s\n", s, e.what());
          continue;
        }
        for (std::size_t k = 0; k < o.patch_vertices.size(); ++k) {
          const expmap::Polar_grid grid{radii[k], o.rings, o.rays};
          const expmap::Polar_patch_operator reference =
              expmap::polar_patch_operator(mesh, exact, {s}, grid, one, query);
          if (!reference.errors[0].empty()) {
            std::fprintf(stderr, "%s\n", reference.errors[0].c_str());
            continue;
          }
          const auto where = grid_positions(reference, point);
          for (std::size_t i = 0; i < methods.size(); ++i) {
            Row& row = rows[k * methods.size() + i];
            const expmap::Polar_patch_operator op =
                methods[i].patch_operator({s}, grid, one, query);
            if (!op.errors[0].empty()) continue;
            ++row.accuracy_sources;
            const auto placed = grid_positions(op, point);
            for (std::size_t r = 0; r < placed.size(); ++r) {
              if (!op.sampled[r] || !reference.sampled[r]) continue;
              double d2 = 0;
              for (int c = 0; c < 3; ++c) d2 += std::pow(placed[r][c] - where[r][c], 2);
              row.placement.push_back(std::sqrt(d2) / radii[k]);
            }
          }
        }
      }
      std::fprintf(stderr, "placement study: %zu sources in %.0f s\n", accuracy_sources.size(),
                   w.seconds());
    }

    std::printf("\n%-5s %5s %8s %7s %9s %9s %7s %8s %8s %7s %9s %9s\n", "", "patch", "R/h",
                "sources", "operator", "maps", "beyond", "ms per", "operator", "sampled",
                "placement", "placement");
    std::printf("%-5s %5s %8s %7s %9s %9s %7s %8s %8s %7s %9s %9s\n", "", "verts", "", "", "s",
                "alone s", "maps", "source", "MB", "", "mean/R", "p90/R");
    for (const Row& r : rows) {
      std::printf("%-5s %5zu %8.2f %7zu %9.1f %9.1f %6.1f%% %8.3f %8.1f %6.1f%% %9.4f %9.4f%s\n",
                  r.method.c_str(), r.patch_vertices, r.radius / h, r.sources, r.operator_seconds,
                  r.maps_seconds, 100 * r.beyond_maps(),
                  1e3 * r.operator_seconds / double(r.sources), r.operator_bytes() / 1e6,
                  100 * r.sampled_share(), mean(r.placement), expmap_bench::percentile(r.placement, 90),
                  r.failures || r.map_failures
                      ? (" (" + std::to_string(r.failures) + " operator / " +
                         std::to_string(r.map_failures) + " map failures)")
                            .c_str()
                      : "");
    }

    if (!o.csv.empty()) {
      std::ofstream out(o.csv);
      out << "mesh,vertices,method,patch_vertices,radius,radius_over_h,rings,rays,threads,sources,"
             "failures,operator_seconds,maps_seconds,beyond_maps,ms_per_source,operator_bytes,"
             "sampled_share,accuracy_sources,placement_points,placement_mean_over_r,"
             "placement_p90_over_r\n";
      for (const Row& r : rows) {
        out << mesh_name << ',' << num_vertices(mesh) << ',' << r.method << ','
            << r.patch_vertices << ',' << r.radius << ',' << r.radius / h << ',' << o.rings << ','
            << o.rays << ',' << o.threads << ',' << r.sources << ','
            << r.failures << ',' << r.operator_seconds << ',' << r.maps_seconds << ','
            << r.beyond_maps() << ',' << 1e3 * r.operator_seconds / double(r.sources) << ','
            << r.operator_bytes() << ',' << r.sampled_share() << ',' << r.accuracy_sources << ','
            << r.placement.size() << ',' << mean(r.placement) << ','
            << expmap_bench::percentile(r.placement, 90) << '\n';
      }
      if (!out) throw std::runtime_error("could not write '" + o.csv + "'");
    }
    return 0;
  } catch (const expmap_bench::Usage_error& e) {
    std::cerr << "expmap-patch-operator-bench: " << e.what() << "\n" << usage_text();
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "expmap-patch-operator-bench: " << e.what() << "\n";
    return 1;
  }
}
