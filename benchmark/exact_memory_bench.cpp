// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-exact-memory: the memory one query of the exact method takes, by
// patch size. For each mesh, each patch size (vertex count) and a few
// random sources it prints one CSV row: the patch's vertices, the region
// the sequence tree is built on (the submesh of Exact_exponential_map), the
// query's time and how far it raised the resident set above where it
// started (VmHWM after the query minus VmRSS before it, with the free heap
// returned to the system and the high-water mark reset before each query).
// doc/viewer.md fits the viewer's and the command line's limits to it.
//
// usage: expmap-exact-memory [--vertices K1,K2,...] [--sources S] [--seed X]
//                            [--subdivide N --cache-dir DIR] MESH...

#include "Loop_subdivided_mesh.h"
#include "Mesh_loading.h"
#include "Peak_memory.h"
#include "Timing.h"

#include <expmap/Exact_exponential_map.h>
#include <expmap/internal/Geodesic_ball_submesh.h>
#include <expmap/internal/Indexed_mesh.h>
#include <expmap/internal/Region_growing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

struct Options {
  std::vector<std::size_t> vertices{1000, 2000, 4000, 8000};
  std::size_t sources = 3;
  unsigned seed = 1;
  unsigned subdivide = 0;
  std::string cache_dir = "build/meshes";
  std::vector<std::string> meshes;
};

std::vector<std::size_t> parse_counts(const std::string& text) {
  std::vector<std::size_t> counts;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) counts.push_back(std::stoul(item));
  return counts;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--vertices") o.vertices = parse_counts(value());
    else if (a == "--sources") o.sources = std::stoul(value());
    else if (a == "--seed") o.seed = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--subdivide") o.subdivide = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--cache-dir") o.cache_dir = value();
    else if (!a.empty() && a[0] == '-') throw std::runtime_error("unknown option " + a);
    else o.meshes.push_back(a);
  }
  if (o.meshes.empty()) throw std::runtime_error("no mesh given");
  return o;
}

// The number of vertices and faces of the submesh an exact query from `s`
// with a patch of `k` vertices builds its sequence tree on: the faces
// within the graph distance that reaches k vertices, as
// Exact_exponential_map::ball_radius() and extract_ball_submesh() find them.
struct Region {
  std::size_t vertices = 0, faces = 0;
};
Region exact_region(const expmap::internal::Mesh_arrays& m, int s, std::size_t k) {
  namespace in = expmap::internal;
  in::Vertex_marks in_region, seen, face_marks, vertex_marks;
  in_region.resize(m.number_of_vertices());
  seen.resize(m.number_of_vertices());
  vertex_marks.resize(m.number_of_vertices());
  face_marks.resize(m.face.size());
  std::vector<double> tentative(m.number_of_vertices());
  std::vector<int> region, queue;
  double reach = 0;
  in::grow_region(m, s, in_region, seen, tentative, region, [&](int, double d, std::size_t size) {
    if (size >= k) return false;
    reach = d;
    return true;
  });
  in::Ball_submesh ball;
  in::extract_ball_submesh(m, s, reach * (1 + 1e-9), face_marks, vertex_marks, queue, ball);
  return {ball.point.size(), ball.face.size()};
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    std::printf("mesh,mesh_vertices,source,patch_vertices,region_vertices,region_faces,seconds,"
                "query_mib\n");
    for (const std::string& path : o.meshes) {
      const Mesh mesh =
          o.subdivide ? expmap_bench::loop_subdivided_mesh<Mesh>(
                            path, o.subdivide,
                            o.cache_dir + "/" + expmap_bench::loop_subdivided_name(path, o.subdivide) +
                                ".off",
                            std::cerr)
                      : expmap_bench::read_triangle_mesh<Mesh>(path);
      const std::string name = o.subdivide ? expmap_bench::loop_subdivided_name(path, o.subdivide)
                                           : expmap_bench::mesh_name(path);
      const expmap::Exact_exponential_map<Mesh> exact(mesh);
      const expmap::internal::Indexed_mesh<Mesh, CGAL::Default> indexed(
          mesh, get(CGAL::vertex_point, mesh));
      std::mt19937 random(o.seed);
      std::uniform_int_distribution<std::size_t> any_vertex(0, mesh.number_of_vertices() - 1);
      std::vector<std::size_t> sources;
      while (sources.size() < o.sources) {
        const std::size_t v = any_vertex(random);
        if (!mesh.is_isolated(Mesh::Vertex_index(static_cast<Mesh::size_type>(v)))) sources.push_back(v);
      }
      for (const std::size_t k : o.vertices)
        for (const std::size_t s : sources) {
          const Region region = exact_region(indexed.arrays, static_cast<int>(s), k);
          expmap_bench::release_free_memory();
          expmap_bench::reset_peak_rss();
          const double before = expmap_bench::current_rss_mib();
          expmap_bench::Stopwatch watch;
          const auto map = exact.compute_by_index(s, expmap::Patch::vertex_count(k));
          const double seconds = watch.seconds();
          const double peak = expmap_bench::peak_rss_mib();
          std::printf("%s,%zu,%zu,%zu,%zu,%zu,%.3f,%.1f\n", name.c_str(),
                      static_cast<std::size_t>(mesh.number_of_vertices()), s, map.size(),
                      region.vertices, region.faces, seconds, peak - before);
          std::fflush(stdout);
        }
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "expmap-exact-memory: " << e.what() << "\n";
    return 1;
  }
}
