// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_COMMON_H
#define EXPMAP_BENCHMARK_EVALUATION_COMMON_H

/// \file Common.h
/// The types, constants and the clock that all of expmap-evaluate's studies
/// share: CGAL's Surface_mesh over the EPICK kernel, its local maps, 3-vectors.

#include <expmap/Local_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <chrono>
#include <filesystem>

namespace expmap_evaluation {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Map = expmap::Local_map<Vertex>;
using Vec3 = std::array<double, 3>;
namespace fs = std::filesystem;

constexpr double pi = 3.14159265358979323846;

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_COMMON_H
