// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_MESH_FILE_H
#define EXPMAP_TOOLS_MESH_FILE_H

/// \file Mesh_file.h
/// Reading a mesh file into the `CGAL::Surface_mesh` the command-line
/// program and the Python module work on. One reader for both, so a file one
/// of them accepts the other accepts too, with the same error messages.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace expmap_cli {

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

/// A mesh file that cannot be opened or read: a runtime error of the run,
/// not of its arguments.
class Mesh_file_error : public std::runtime_error {
 public:
  explicit Mesh_file_error(const std::string& message) : std::runtime_error(message) {}
};

/// Reads `path` (.off, .obj, .ply or .stl). With `triangulate`, polygonal
/// faces are split into triangles (no vertex is added, so indices keep file
/// order); without it they are kept, and the methods reject them.
/// \throws Mesh_file_error if the file is missing, unreadable or malformed.
inline Mesh read_mesh_file(const std::string& path, bool triangulate) {
  if (!std::ifstream(path))
    throw Mesh_file_error("cannot open mesh file '" + path + "' (missing or not readable)");
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh))
    throw Mesh_file_error("cannot read '" + path +
                          "' as a polygon mesh: the format is not .off, .obj, .ply or .stl, the "
                          "file is malformed, or its faces do not form a consistently oriented "
                          "2-manifold mesh");
  if (triangulate && !CGAL::is_triangle_mesh(mesh) &&
      !CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
    throw Mesh_file_error("--triangulate could not split every face of '" + path +
                          "' into triangles");
  return mesh;
}

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_MESH_FILE_H
