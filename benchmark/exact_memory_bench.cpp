// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// expmap-exact-memory: the memory one query of the exact method takes, by
// patch size. For each mesh, each patch size (vertex count) and a few
// random sources it prints one CSV row: the patch's vertices, the faces of
// the submesh the sequence tree is built on (region_faces()), the query's
// time and how far it raised the resident set above where it started
// (VmHWM after the query minus VmRSS before it, with the free heap returned
// to the system and the high-water mark reset before each query); the
// first query on a mesh also makes the method's workspace. doc/viewer.md
// fits the viewer's and the command line's limits to it.
//
// usage: expmap-exact-memory [--vertices K1,K2,...] [--sources S] [--seed X]
//                            [--source-vertices I,J,...]
//                            [--subdivide N --cache-dir DIR] MESH...

#include "Loop_subdivided_mesh.h"
#include "Mesh_loading.h"
#include "Peak_memory.h"
#include "Timing.h"

#include <expmap/Exact_exponential_map.h>

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
  std::vector<std::size_t> source_vertices;  // instead of random ones
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
    else if (a == "--source-vertices") o.source_vertices = parse_counts(value());
    else if (a == "--seed") o.seed = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--subdivide") o.subdivide = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--cache-dir") o.cache_dir = value();
    else if (!a.empty() && a[0] == '-') throw std::runtime_error("unknown option " + a);
    else o.meshes.push_back(a);
  }
  if (o.meshes.empty()) throw std::runtime_error("no mesh given");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    std::printf("mesh,mesh_vertices,source,patch_vertices,region_faces,seconds,query_mib\n");
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
      std::mt19937 random(o.seed);
      std::uniform_int_distribution<std::size_t> any_vertex(0, mesh.number_of_vertices() - 1);
      std::vector<std::size_t> sources = o.source_vertices;
      while (o.source_vertices.empty() && sources.size() < o.sources) {
        const std::size_t v = any_vertex(random);
        if (!mesh.is_isolated(Mesh::Vertex_index(static_cast<Mesh::size_type>(v)))) sources.push_back(v);
      }
      for (const std::size_t k : o.vertices)
        for (const std::size_t s : sources) {
          const Mesh::Vertex_index v(static_cast<Mesh::size_type>(s));
          const std::size_t region_faces = exact.region_faces(v, expmap::Patch::vertex_count(k));
          expmap_bench::release_free_memory();
          expmap_bench::reset_peak_rss();
          const double before = expmap_bench::current_rss_mib();
          expmap_bench::Stopwatch watch;
          const auto map = exact.compute_by_index(s, expmap::Patch::vertex_count(k));
          const double seconds = watch.seconds();
          const double peak = expmap_bench::peak_rss_mib();
          std::printf("%s,%zu,%zu,%zu,%zu,%.3f,%.1f\n", name.c_str(),
                      static_cast<std::size_t>(mesh.number_of_vertices()), s, map.size(),
                      region_faces, seconds, peak - before);
          std::fflush(stdout);
        }
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "expmap-exact-memory: " << e.what() << "\n";
    return 1;
  }
}
