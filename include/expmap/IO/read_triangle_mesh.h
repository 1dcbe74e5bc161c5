// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_READ_TRIANGLE_MESH_H
#define EXPMAP_IO_READ_TRIANGLE_MESH_H

/// \file read_triangle_mesh.h
/// Reading a mesh file into a triangle mesh the methods accept, repairing
/// what can be repaired without renumbering the file's vertices, and saying
/// what was repaired.

#include <expmap/Degenerate_face_repair.h>
#include <expmap/Errors.h>
#include <expmap/IO/check_declared_sizes.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// What `read_triangle_mesh()` may change.
struct Mesh_reading_options {
  /// Split faces with more than three vertices into triangles (no vertex is
  /// added). If false, such faces are kept and the methods refuse the mesh.
  bool triangulate = true;
  /// Remove degenerate faces, needles and caps (`repair_degenerate_faces()`);
  /// this removes vertices, so the mesh's vertex indices no longer follow
  /// the file (see `Mesh_reading_report::file_index`).
  bool repair = false;
};

/// \ingroup PkgExpmapIO
/// What `read_triangle_mesh()` did to the file's mesh.
struct Mesh_reading_report {
  /// One sentence per repair, e.g. "reversed 412 faces to orient the polygon
  /// soup consistently"; empty if the file was used as it is.
  std::vector<std::string> notes;
  /// `file_index[i]` is the position in the file of vertex `i` of the mesh.
  /// The identity unless `repair` removed vertices; vertices that orienting
  /// a soup had to split get indices from the file's vertex count upwards.
  std::vector<std::size_t> file_index;
  std::size_t file_vertices = 0;  ///< vertices the file lists
};

namespace internal {

/// Counts what `orient_polygon_soup` changes, for the report.
struct Soup_orientation_counter : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  std::size_t* reversed;
  std::size_t* split;
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
  void duplicated_vertex(std::size_t, std::size_t) { ++*split; }
};

/// Drops polygons that cannot be faces (fewer than three vertices, or a
/// vertex twice) and duplicates; never renumbers points. Returns notes.
template <class Point>
std::vector<std::string> clean_polygons(const std::vector<Point>& points,
                                        std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::string> notes;
  const std::size_t point_count = points.size();
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (std::size_t v : polygons[f])
      if (v >= point_count)
        throw Invalid_input("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                            ", but the file has " + std::to_string(point_count) + " vertices");
  const std::size_t before = polygons.size();
  polygons.erase(std::remove_if(polygons.begin(), polygons.end(),
                                [](std::vector<std::size_t> p) {
                                  std::sort(p.begin(), p.end());
                                  return p.size() < 3 ||
                                         std::adjacent_find(p.begin(), p.end()) != p.end();
                                }),
                 polygons.end());
  if (polygons.size() < before)
    notes.push_back("dropped " + std::to_string(before - polygons.size()) +
                    " faces with fewer than three distinct vertices");
  const std::size_t duplicates =
      CGAL::Polygon_mesh_processing::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  if (duplicates) notes.push_back("dropped " + std::to_string(duplicates) + " duplicate faces");
  return notes;
}

/// The file as a polygon soup, oriented and turned into a mesh: the path for
/// files whose faces do not form an oriented 2-manifold as they stand.
template <class Point>
std::vector<std::string> read_as_oriented_soup(const std::string& path,
                                               CGAL::Surface_mesh<Point>& mesh,
                                               std::size_t& file_vertices) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    throw Invalid_input("cannot read '" + path +
                        "': the format is not .off, .obj, .ply or .stl, or the file is malformed "
                        "(truncated, a count or index out of range, or a non-number)");
  file_vertices = points.size();
  std::vector<std::string> notes = clean_polygons(points, polygons);
  if (polygons.empty()) throw Invalid_input("'" + path + "' has no usable face");
  std::size_t reversed = 0, split = 0;
  Soup_orientation_counter counter;
  counter.reversed = &reversed;
  counter.split = &split;
  PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(counter));
  if (reversed) notes.push_back("reversed " + std::to_string(reversed) + " faces to orient it");
  if (split)
    notes.push_back("split " + std::to_string(split) +
                    " non-manifold vertices into copies (numbered from " +
                    std::to_string(file_vertices) + " on)");
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return notes;
}

}  // namespace internal

/// \ingroup PkgExpmapIO
/// Reads the mesh file at `path` (.off, .obj, .ply or .stl) into `mesh`,
/// keeping the file's vertex order, and makes it a triangle mesh:
///
/// 1. `check_declared_sizes()` first, so a lying header costs no memory;
/// 2. as a polygon mesh; if its faces are not an oriented 2-manifold (faces
///    in random orientation, non-manifold edges or vertices, faces repeating
///    a vertex, duplicate faces), as a polygon soup instead: such faces are
///    dropped, the rest is oriented with
///    `CGAL::Polygon_mesh_processing::orient_polygon_soup` (which may split
///    non-manifold vertices into copies, added after the file's vertices)
///    and converted with `polygon_soup_to_polygon_mesh`;
/// 3. faces with more than three vertices are triangulated
///    (`options.triangulate`);
/// 4. degenerate faces are removed (`options.repair`).
///
/// \code
/// CGAL::Surface_mesh<Point> mesh;
/// const auto report = expmap::IO::read_triangle_mesh(path, mesh);
/// for (const auto& note : report.notes) std::cerr << note << "\n";
/// \endcode
/// \throws Invalid_input if the file cannot be opened or read, or declares
/// more than it holds; the message names the file and the problem.
template <class Point>
Mesh_reading_report read_triangle_mesh(const std::string& path, CGAL::Surface_mesh<Point>& mesh,
                                       const Mesh_reading_options& options = {}) {
  check_declared_sizes(path);
  Mesh_reading_report report;
  mesh.clear();
  std::vector<std::string> soup_notes;
  if (CGAL::IO::read_polygon_mesh(path, mesh, CGAL::parameters::verbose(false)) &&
      !mesh.is_empty()) {
    report.file_vertices = mesh.number_of_vertices();
  } else {
    soup_notes = internal::read_as_oriented_soup(path, mesh, report.file_vertices);
  }
  if (!soup_notes.empty()) {
    std::string note = "its faces are not an oriented 2-manifold mesh; read as a polygon soup";
    for (const std::string& s : soup_notes) note += ", " + s;
    report.notes.push_back(note);
  }

  if (options.triangulate && !CGAL::is_triangle_mesh(mesh)) {
    std::size_t polygons = 0;
    for (auto f : mesh.faces()) polygons += mesh.degree(f) > 3;
    if (!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw Invalid_input("cannot split every face of '" + path + "' into triangles");
    report.notes.push_back("triangulated " + std::to_string(polygons) +
                           " faces with more than three vertices (no vertex added)");
  }

  report.file_index.resize(mesh.number_of_vertices());
  std::iota(report.file_index.begin(), report.file_index.end(), std::size_t(0));
  if (options.repair && CGAL::is_triangle_mesh(mesh)) {
    auto file_index =
        mesh.template add_property_map<typename CGAL::Surface_mesh<Point>::Vertex_index,
                                       std::size_t>("v:expmap_file_index")
            .first;
    for (auto v : mesh.vertices()) file_index[v] = static_cast<std::size_t>(v);
    const Degenerate_face_repair repair = repair_degenerate_faces(mesh);
    report.file_index.clear();
    for (auto v : mesh.vertices()) report.file_index.push_back(file_index[v]);
    mesh.remove_property_map(file_index);
    if (repair.faces_after != repair.faces_before || !repair.complete)
      report.notes.push_back(
          "removed " + std::to_string(repair.faces_before - repair.faces_after) +
          " degenerate faces and needles and " +
          std::to_string(repair.vertices_before - repair.vertices_after) + " vertices" +
          (repair.complete ? "" : " (some degenerate faces could not be removed)"));
  }
  return report;
}

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_READ_TRIANGLE_MESH_H
