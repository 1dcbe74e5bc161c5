// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_LOOP_SUBDIVIDED_MESH_H
#define EXPMAP_BENCHMARK_LOOP_SUBDIVIDED_MESH_H

/// \file Loop_subdivided_mesh.h
/// A large test mesh made by Loop-subdividing a smaller one (the paper's
/// largest meshes are subdivided models), cached as an OFF file.
///
/// Each Loop step (CGAL::Subdivision_method_3::Loop_subdivision) splits
/// every triangle into four: V' = V + E, E' = 2E + 3F, F' = 4F. Two steps
/// on refined_elephant (44,460 vertices) give 711,420 vertices.
///
/// The cache file is written with 17 significant digits (so reading it back
/// gives the same doubles), to a temporary name first and then renamed, so
/// an interrupted run never leaves a truncated cache. A cache whose vertex
/// and face counts are not those the input predicts is rebuilt.

#include "Mesh_loading.h"
#include "Timing.h"

#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/OFF.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace expmap_bench {

/// The name of `input` subdivided `levels` times: "elephant_loop2" for
/// refined_elephant.off and 2 ("refined_" is dropped), else STEM_loopN.
inline std::string loop_subdivided_name(const std::string& input, unsigned levels) {
  std::string stem = mesh_name(input);
  const std::string refined = "refined_";
  if (stem.compare(0, refined.size(), refined) == 0 && stem.size() > refined.size())
    stem = stem.substr(refined.size());
  return stem + "_loop" + std::to_string(levels);
}

/// `input` Loop-subdivided `levels` times, read from `cache_path` if that
/// file holds it, else computed and written there. Says what it did on `log`.
template <class Mesh>
Mesh loop_subdivided_mesh(const std::string& input, unsigned levels,
                          const std::string& cache_path, std::ostream& log) {
  const Mesh coarse = read_triangle_mesh<Mesh>(input);
  std::size_t v = num_vertices(coarse), e = num_edges(coarse), f = num_faces(coarse);
  for (unsigned i = 0; i < levels; ++i) {
    const std::size_t v2 = v + e, e2 = 2 * e + 3 * f, f2 = 4 * f;
    v = v2;
    e = e2;
    f = f2;
  }

  if (std::filesystem::is_regular_file(cache_path)) {
    Stopwatch watch;
    try {
      Mesh cached = read_triangle_mesh<Mesh>(cache_path);
      if (num_vertices(cached) == v && num_faces(cached) == f) {
        log << "read " << cache_path << " (" << v << " vertices) in " << watch.seconds()
            << " s\n";
        return cached;
      }
      log << "cache " << cache_path << " has " << num_vertices(cached)
          << " vertices, expected " << v << ": rebuilding it\n";
    } catch (const std::exception& e) {
      log << "cache " << cache_path << " unreadable (" << e.what() << "): rebuilding it\n";
    }
  }

  Stopwatch watch;
  Mesh fine = coarse;
  CGAL::Subdivision_method_3::Loop_subdivision(
      fine, CGAL::parameters::number_of_iterations(static_cast<int>(levels)));
  log << "Loop-subdivided " << input << " " << levels << " times: " << num_vertices(fine)
      << " vertices, " << num_faces(fine) << " faces in " << watch.seconds() << " s\n";

  const std::filesystem::path target(cache_path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const std::string temporary = cache_path + ".tmp";
  {
    std::ofstream out(temporary);
    if (!out || !CGAL::IO::write_OFF(out, fine, CGAL::parameters::stream_precision(17)))
      throw std::runtime_error("cannot write the subdivided mesh to '" + temporary + "'");
  }
  std::filesystem::rename(temporary, target);
  log << "cached it as " << cache_path << "\n";
  return fine;
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_LOOP_SUBDIVIDED_MESH_H
