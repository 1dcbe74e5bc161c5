// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_POINT_SOURCES_H
#define EXPMAP_TOOLS_POINT_SOURCES_H

/// \file Point_sources.h
/// The point sources of `expmap compute` and `expmap batch`: positions
/// located on the surface, faces of the file with barycentric coordinates,
/// a file of positions, and the words that name a point in the summary.

#include "Command_line.h"

#include <expmap/Errors.h>
#include <expmap/IO/Input_faces.h>
#include <expmap/Locate_surface_point.h>
#include <expmap/Surface_point.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace expmap_cli {

/// The positions in a file of source points: one point a line, its three
/// coordinates separated by commas or white space; '#' to the end of a
/// line is a comment, and blank lines are skipped.
/// \throws Runtime_error naming the file and line of a malformed point.
inline std::vector<std::array<double, 3>> read_point_file(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw Runtime_error("cannot open source point file '" + path + "' (missing or not readable)");
  std::vector<std::array<double, 3>> points;
  std::size_t line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    std::vector<std::string> numbers;
    for (std::string word; words >> word;) numbers.push_back(word);
    if (numbers.empty()) continue;
    const std::string where =
        "source point file '" + path + "', line " + std::to_string(line_number);
    if (numbers.size() != 3)
      throw Runtime_error(where + ": expected three coordinates X,Y,Z (got " +
                          std::to_string(numbers.size()) + " numbers)");
    std::array<double, 3> p{};
    for (int k = 0; k < 3; ++k) {
      try {
        p[k] = parse_real("a coordinate", numbers[k]);
      } catch (const Usage_error&) {
        throw Runtime_error(where + ": '" + numbers[k] + "' is not a finite number");
      }
    }
    points.push_back(p);
  }
  if (points.empty()) throw Runtime_error("source point file '" + path + "' lists no point");
  return points;
}

/// Finds the surface points a command line names, on the mesh read from
/// the file `mesh_path`; the locator's tree and the file's faces are made
/// on first use.
template <class Mesh>
class Point_sources {
 public:
  using Surface_point = expmap::Surface_point<typename Mesh::Face_index>;

  /// `file_index` as in `expmap::IO::Mesh_reading_report`.
  Point_sources(const Mesh& mesh, const std::vector<std::size_t>& file_index,
                std::string mesh_path)
      : m_mesh(mesh), m_file_index(file_index), m_path(std::move(mesh_path)) {}

  /// The surface points nearest to `positions`. Positions farther from the
  /// surface than 1e-6 of the bounding box's diagonal get one note on
  /// stderr (`what` names them) saying how far the farthest is.
  /// \throws expmap::Invalid_input, naming `what` and the point, for a
  ///         point too far from the mesh to locate.
  std::vector<Surface_point> locate(const std::vector<std::array<double, 3>>& positions,
                                    const std::string& what) {
    if (!m_locator) m_locator = std::make_unique<expmap::Surface_point_locator<Mesh>>(m_mesh);
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(m_mesh);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                      CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    std::vector<Surface_point> points;
    std::size_t off = 0;
    double farthest = 0;
    for (const auto& x : positions) {
      try {
        points.push_back(m_locator->locate(x));
      } catch (const expmap::Invalid_input& e) {
        const std::string which =
            positions.size() == 1 ? std::string()
                                  : "source " + std::to_string(points.size()) + ": ";
        throw expmap::Invalid_input(what + ": " + which + e.what());
      }
      const std::array<double, 3> y = expmap::surface_point_position(m_mesh, points.back());
      const double d = std::sqrt(CGAL::square(x[0] - y[0]) + CGAL::square(x[1] - y[1]) +
                                 CGAL::square(x[2] - y[2]));
      if (d > 1e-6 * diagonal) {
        ++off;
        farthest = std::max(farthest, d);
      }
    }
    if (off > 0) {
      std::fflush(stdout);
      std::cerr << "expmap: note: " << what << ": "
                << (positions.size() == 1 ? std::string("the point is")
                                          : std::to_string(off) + " of " +
                                                std::to_string(positions.size()) +
                                                " points are")
                << " off the surface (by " << (off > 1 ? "up to " : "") << farthest << ", "
                << farthest / diagonal
                << " of the bounding box's diagonal); mapping from the nearest surface point"
                << (off > 1 ? "s" : "") << "\n";
    }
    return points;
  }

  /// The point of face `face` of the file with barycentric coordinates
  /// `barycentric` of its corners in the file's order.
  /// \throws Usage_error for a face out of range, Runtime_error for a face
  ///         that is no triangle of the mesh.
  Surface_point from_file_face(std::size_t face, const std::array<double, 3>& barycentric) {
    const expmap::IO::Input_faces<Mesh>& faces = file_faces();
    if (face >= faces.size())
      throw Usage_error("--source-face " + std::to_string(face) + " is out of range: '" + m_path +
                        "' has " + std::to_string(faces.size()) + " faces" +
                        (faces.size() ? " (0 to " + std::to_string(faces.size() - 1) + ")" : ""));
    try {
      return faces.surface_point({face, barycentric});
    } catch (const expmap::Invalid_input& e) {
      throw Runtime_error(e.what());
    }
  }

  /// The point in words for the summary: the file's face and coordinates
  /// (its corners in the file's order) and the position.
  std::string describe(const Surface_point& p) {
    std::ostringstream s;
    s.precision(6);
    const auto in_file = file_faces().input_point(p);
    const std::array<double, 3> x = expmap::surface_point_position(m_mesh, p);
    s << "point (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
    if (in_file) {
      const auto& w = in_file->barycentric;
      s << " in face " << in_file->face << ", barycentric (" << w[0] << ", " << w[1] << ", "
        << w[2] << ")";
    } else {
      s << " in a triangle of a polygon of the file";
    }
    return s.str();
  }

 private:
  // The file's faces as it lists them, read again (the mesh's may be
  // reordered, split or repaired).
  const expmap::IO::Input_faces<Mesh>& file_faces() {
    if (m_faces) return *m_faces;
    std::vector<typename Mesh::Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(m_path, points, polygons, CGAL::parameters::verbose(false)))
      throw Runtime_error("cannot read the faces of '" + m_path + "'");
    m_faces = std::make_unique<expmap::IO::Input_faces<Mesh>>(m_mesh, m_file_index,
                                                               std::move(polygons));
    return *m_faces;
  }

  const Mesh& m_mesh;
  const std::vector<std::size_t>& m_file_index;
  std::string m_path;
  std::unique_ptr<expmap::Surface_point_locator<Mesh>> m_locator;
  std::unique_ptr<expmap::IO::Input_faces<Mesh>> m_faces;
};

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_POINT_SOURCES_H
