// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_MESH_LOADING_H
#define EXPMAP_BENCHMARK_MESH_LOADING_H

/// \file Mesh_loading.h
/// Reading a triangle mesh for the benchmark, and its name in the tables.

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace expmap_bench {

/// Reads any format CGAL reads (OFF, OBJ, PLY, STL) and triangulates
/// non-triangle faces. \throws std::runtime_error if the file cannot be read.
template <class Mesh>
Mesh read_triangle_mesh(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("cannot open mesh file '" + path + "'");
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh))
    throw std::runtime_error("cannot read a polygon mesh from '" + path + "'");
  if (!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  return mesh;
}

/// The name of a mesh in the tables: the file name without its extension.
inline std::string mesh_name(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_MESH_LOADING_H
