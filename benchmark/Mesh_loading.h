// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_MESH_LOADING_H
#define EXPMAP_BENCHMARK_MESH_LOADING_H

/// \file Mesh_loading.h
/// Reading a triangle mesh for the benchmark, and its name in the tables.

#include <expmap/IO/read_triangle_mesh.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace expmap_bench {

/// Reads any format CGAL reads (OFF, OBJ, PLY, STL) as the `expmap` program
/// does (`expmap::IO::read_triangle_mesh`: sizes checked, soups oriented,
/// polygons triangulated). \throws std::runtime_error if the file cannot be
/// read.
template <class Mesh>
Mesh read_triangle_mesh(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("cannot open mesh file '" + path + "'");
  Mesh mesh;
  try {
    expmap::IO::read_triangle_mesh(path, mesh);
  } catch (const expmap::Invalid_input& e) {
    throw std::runtime_error(e.what());
  }
  return mesh;
}

/// The name of a mesh in the tables: the file name without its extension.
inline std::string mesh_name(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_MESH_LOADING_H
