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

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
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
#include <iterator>
#include <numeric>
#include <utility>
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
  /// The identity, except that the copies made of a non-manifold vertex
  /// (added after the file's vertices) have the index of the vertex they
  /// copy, and that `repair` removes vertices.
  std::vector<std::size_t> file_index;
  std::size_t file_vertices = 0;  ///< vertices the file lists
};

namespace internal {

/// Counts what `orient_polygon_soup` changes, for the report, and which
/// point each new point copies.
struct Soup_orientation_counter : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  std::size_t* reversed;
  std::vector<std::pair<std::size_t, std::size_t>>* copies;  // (original, copy)
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
  void duplicated_vertex(std::size_t original, std::size_t copy) {
    copies->emplace_back(original, copy);
  }
};

/// The note on split non-manifold vertices, naming the first few of them
/// by `original_index` (the caller's numbering of the mesh's vertices).
inline std::string split_note(const std::vector<std::pair<std::size_t, std::size_t>>& copies,
                              const std::vector<std::size_t>& original_index) {
  std::vector<std::size_t> split;
  for (const auto& copy : copies) split.push_back(original_index[copy.first]);
  std::sort(split.begin(), split.end());
  split.erase(std::unique(split.begin(), split.end()), split.end());
  constexpr std::size_t named = 10;
  std::string list;
  for (std::size_t i = 0; i < std::min(split.size(), named); ++i)
    list += (i ? ", " : "") + std::to_string(split[i]);
  if (split.size() > named) list += " and " + std::to_string(split.size() - named) + " more";
  return "split non-manifold " + std::string(split.size() == 1 ? "vertex " : "vertices ") + list +
         " into " + std::to_string(copies.size()) + " extra cop" +
         (copies.size() == 1 ? "y" : "ies") + ", one per sheet meeting there";
}

/// Splits every vertex of `mesh` where several sheets meet (a bow tie) into
/// one copy per sheet, added after the other vertices, and appends
/// (original, copy) to `copies`: a Surface_mesh holds such a vertex, but a
/// map through it would fold one sheet onto a single direction.
template <class Point>
void split_non_manifold_vertices(CGAL::Surface_mesh<Point>& mesh,
                                 std::vector<std::pair<std::size_t, std::size_t>>& copies) {
  using Vertex = typename CGAL::Surface_mesh<Point>::Vertex_index;
  std::vector<std::vector<Vertex>> split;
  CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(
      mesh, CGAL::parameters::output_iterator(std::back_inserter(split)));
  for (const auto& group : split)
    for (std::size_t k = 1; k < group.size(); ++k) copies.emplace_back(group[0], group[k]);
}

/// Drops polygons that cannot be faces (fewer than three vertices, or a
/// vertex twice) and duplicates; never renumbers points. Returns notes.
/// \pre every index is a point's.
template <class Point>
std::vector<std::string> clean_polygons(const std::vector<Point>& points,
                                        std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::string> notes;
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

/// `polygons` over `points` oriented and turned into `mesh`: the path for
/// faces that do not form an oriented 2-manifold as they stand. Appends
/// (original, copy) to `copies` for every point duplicated to separate the
/// sheets at a non-manifold edge or vertex. Returns notes; `name` names
/// the faces' origin in errors.
template <class Point>
std::vector<std::string> mesh_from_oriented_soup(
    const std::string& name, std::vector<Point>& points,
    std::vector<std::vector<std::size_t>>& polygons, CGAL::Surface_mesh<Point>& mesh,
    std::vector<std::pair<std::size_t, std::size_t>>& copies) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::string> notes = clean_polygons(points, polygons);
  if (polygons.empty()) throw Invalid_input(name + " has no usable face");
  std::size_t reversed = 0;
  Soup_orientation_counter counter;
  counter.reversed = &reversed;
  counter.copies = &copies;
  PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(counter));
  if (reversed) notes.push_back("reversed " + std::to_string(reversed) + " faces to orient it");
  // orient_polygon_soup separates every non-manifold edge and vertex; the
  // check stands in for CGAL's precondition, off in Release builds.
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Invalid_input("the faces could not be oriented into a 2-manifold mesh, even after "
                        "splitting non-manifold edges and vertices");
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return notes;
}

/// The report's `file_index` and split note from the copies made.
inline void record_copies(const std::vector<std::pair<std::size_t, std::size_t>>& copies,
                          std::size_t mesh_vertices, Mesh_reading_report& report) {
  report.file_index.resize(mesh_vertices);
  std::iota(report.file_index.begin(), report.file_index.end(), std::size_t(0));
  // In the order made: a copy of a copy gets the index of the first.
  for (const auto& [original, copy] : copies)
    report.file_index[copy] = report.file_index[original];
  if (!copies.empty()) report.notes.push_back(split_note(copies, report.file_index));
}

/// `mesh` made of the polygons face by face, as CGAL's readers make a
/// Surface_mesh of a file's faces: true unless a polygon cannot be a face
/// (fewer than three distinct vertices) or cannot be added (a non-manifold
/// edge, or an edge two faces share in the same direction); then `mesh` is
/// left empty. Where sheets touch at a vertex only, the faces are added.
template <class Point>
bool add_polygons_as_faces(const std::vector<Point>& points,
                           const std::vector<std::vector<std::size_t>>& polygons,
                           CGAL::Surface_mesh<Point>& mesh) {
  using Vertex = typename CGAL::Surface_mesh<Point>::Vertex_index;
  using Size = typename CGAL::Surface_mesh<Point>::size_type;
  for (std::vector<std::size_t> p : polygons) {
    std::sort(p.begin(), p.end());
    if (p.size() < 3 || std::adjacent_find(p.begin(), p.end()) != p.end()) return false;
  }
  mesh.clear();
  for (const Point& p : points) mesh.add_vertex(p);
  std::vector<Vertex> face;
  for (const auto& polygon : polygons) {
    face.clear();
    for (std::size_t v : polygon) face.push_back(Vertex(static_cast<Size>(v)));
    if (mesh.add_face(face) == CGAL::Surface_mesh<Point>::null_face()) {
      mesh.clear();
      return false;
    }
  }
  return true;
}

/// `mesh_from_polygon_soup()`, with `name` naming the polygons' origin in
/// errors.
template <class Point>
Mesh_reading_report mesh_from_soup(const std::string& name, std::vector<Point>& points,
                                   std::vector<std::vector<std::size_t>>& polygons,
                                   CGAL::Surface_mesh<Point>& mesh) {
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (std::size_t v : polygons[f])
      if (v >= points.size())
        throw Invalid_input("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                            ", but " + name + " has " + std::to_string(points.size()) +
                            " vertices");
  Mesh_reading_report report;
  report.file_vertices = points.size();
  std::vector<std::pair<std::size_t, std::size_t>> copies;  // (original, copy)
  mesh.clear();
  if (add_polygons_as_faces(points, polygons, mesh)) {
    split_non_manifold_vertices(mesh, copies);
  } else {
    std::string note = "its faces are not an oriented 2-manifold mesh; oriented as a polygon soup";
    for (const std::string& s : mesh_from_oriented_soup(name, points, polygons, mesh, copies))
      note += ", " + s;
    report.notes.push_back(note);
  }
  record_copies(copies, mesh.number_of_vertices(), report);
  return report;
}

}  // namespace internal

/// \ingroup PkgExpmapIO
/// Makes `mesh` from the polygons `polygons` over `points` (each polygon
/// the indices of its points, in order) as `read_triangle_mesh()` makes it
/// from a file's (step 2 there): face by face as they stand if they can be
/// added so (an oriented mesh, possibly with sheets touching at vertices),
/// oriented as a polygon soup otherwise (faces with fewer than
/// three distinct points and duplicate faces dropped, faces reversed and,
/// at non-manifold edges, points duplicated); either way a vertex where
/// several sheets meet is split into one copy per sheet. Vertex i of `mesh`
/// is point i for every i below `points.size()`; the copies follow, and
/// `file_index` of the report names the point each vertex copies. Polygons
/// are not triangulated.
/// \throws Invalid_input if a polygon names a point out of range, no polygon
/// has three distinct points, or (not expected: `orient_polygon_soup`
/// separates every non-manifold edge and vertex) the soup cannot be made a
/// 2-manifold.
template <class Point>
Mesh_reading_report mesh_from_polygon_soup(std::vector<Point> points,
                                           std::vector<std::vector<std::size_t>> polygons,
                                           CGAL::Surface_mesh<Point>& mesh) {
  return internal::mesh_from_soup("the polygon soup", points, polygons, mesh);
}

/// \ingroup PkgExpmapIO
/// Reads the mesh file at `path` (.off, .obj, .ply or .stl) into `mesh`,
/// keeping the file's vertex order, and makes it a triangle mesh:
///
/// 1. `check_declared_sizes()` first, so a lying header costs no memory;
/// 2. as a polygon mesh; if its faces are not an oriented 2-manifold (faces
///    in random orientation, non-manifold edges or vertices, faces repeating
///    a vertex, duplicate faces), as a polygon soup instead: such faces are
///    dropped, the rest is oriented with
///    `CGAL::Polygon_mesh_processing::orient_polygon_soup` and converted with
///    `polygon_soup_to_polygon_mesh`; either way a vertex where several
///    sheets meet is split into one copy per sheet (added after the file's
///    vertices), so that no map passes from one sheet to another through it;
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
  if (CGAL::IO::read_polygon_mesh(path, mesh, CGAL::parameters::verbose(false)) &&
      !mesh.is_empty()) {
    report.file_vertices = mesh.number_of_vertices();
    std::vector<std::pair<std::size_t, std::size_t>> copies;  // (original, copy)
    internal::split_non_manifold_vertices(mesh, copies);
    internal::record_copies(copies, mesh.number_of_vertices(), report);
  } else {
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
      throw Invalid_input("cannot read '" + path +
                          "': the format is not .off, .obj, .ply or .stl, or the file is "
                          "malformed (truncated, a count or index out of range, or a "
                          "non-number)");
    report = internal::mesh_from_soup("'" + path + "'", points, polygons, mesh);
  }

  if (options.triangulate && !CGAL::is_triangle_mesh(mesh)) {
    std::size_t polygons = 0;
    for (auto f : mesh.faces()) polygons += mesh.degree(f) > 3;
    if (!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw Invalid_input("cannot split every face of '" + path + "' into triangles");
    report.notes.push_back("triangulated " + std::to_string(polygons) +
                           " faces with more than three vertices (no vertex added)");
  }

  if (options.repair && CGAL::is_triangle_mesh(mesh)) {
    auto file_index =
        mesh.template add_property_map<typename CGAL::Surface_mesh<Point>::Vertex_index,
                                       std::size_t>("v:expmap_file_index")
            .first;
    for (auto v : mesh.vertices()) file_index[v] = report.file_index[v];
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
