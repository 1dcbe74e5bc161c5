// expmap::IO::Input_faces: a point of an input face, given in the input's
// corner order, is the same point of the mesh whatever reading did to the
// face (reordered, reversed, duplicated, split into triangles).

#include <expmap/Errors.h>
#include <expmap/IO/Input_faces.h>
#include <expmap/IO/read_triangle_mesh.h>
#include <expmap/Locate_surface_point.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Faces = expmap::IO::Input_faces<Mesh>;

}  // namespace

BOOST_AUTO_TEST_SUITE(input_faces)

BOOST_AUTO_TEST_CASE(points_of_input_faces_survive_reading) {
  // A 3 x 2 grid of unit squares in z = x y / 10 (not planar): triangles,
  // face 1 reversed, face 4 a repeat of face 0 in another rotation, and
  // the last square a quad.
  std::vector<Point> points;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) points.emplace_back(i, j, 0.1 * i * j);
  const std::vector<std::vector<std::size_t>> faces = {
      {0, 1, 5}, {0, 4, 5}, {1, 2, 6}, {1, 6, 5}, {5, 0, 1}, {2, 3, 7}, {2, 7, 6},
      {4, 5, 9}, {4, 9, 8}, {5, 6, 10}, {5, 10, 9}, {6, 7, 11, 10}};
  Mesh mesh;
  const auto report = expmap::IO::mesh_from_polygon_soup(points, faces, mesh);
  BOOST_TEST(!report.notes.empty());  // reversed and repeated faces: oriented as a soup
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  const Faces input(mesh, report.file_index, faces);
  BOOST_TEST(input.size() == faces.size());

  const std::array<double, 3> w{{0.2, 0.3, 0.5}};
  for (std::size_t j = 0; j + 1 < faces.size(); ++j) {
    BOOST_TEST_CONTEXT("face " << j) {
      const auto p = input.surface_point({j, w});
      const std::array<double, 3> x = expmap::surface_point_position(mesh, p);
      for (int d = 0; d < 3; ++d) {
        double expected = 0;
        for (int k = 0; k < 3; ++k) expected += w[k] * points[faces[j][k]][d];
        BOOST_TEST(std::abs(x[d] - expected) < 1e-15);
      }
      const auto back = input.input_point(p);
      BOOST_TEST_REQUIRE(back.has_value());
      BOOST_TEST(back->face == (j == 4 ? 0u : j));  // a repeat names the first
      for (int k = 0; k < 3; ++k)
        BOOST_TEST(back->barycentric[k] == (j == 4 ? w[(k + 1) % 3] : w[k]));
    }
  }
  // The quad is no face of the mesh; its triangles are no face of the input.
  BOOST_CHECK_THROW(input.surface_point({faces.size() - 1, w}), expmap::Invalid_input);
  BOOST_CHECK_THROW(input.surface_point({faces.size(), w}), expmap::Invalid_input);
  std::size_t unnamed = 0;
  for (Mesh::Face_index f : mesh.faces())
    unnamed += !input.input_point({f, w}).has_value();
  BOOST_TEST(unnamed == 2u);
}

// An input vertex list of another length than the mesh's vertices is
// refused by name, before any lookup.
BOOST_AUTO_TEST_CASE(a_vertex_list_of_the_wrong_length_is_refused) {
  Mesh mesh;
  const auto a = mesh.add_vertex(Point(0, 0, 0)), b = mesh.add_vertex(Point(1, 0, 0)),
             c = mesh.add_vertex(Point(0, 1, 0));
  mesh.add_face(a, b, c);
  const std::vector<std::vector<std::size_t>> faces = {{0, 1, 2}};
  for (const std::vector<std::size_t>& rows : {std::vector<std::size_t>{0, 1}, std::vector<std::size_t>{0, 1, 2, 3}}) {
    try {
      const Faces input(mesh, rows, faces);
      BOOST_ERROR("a list of " << rows.size() << " input vertices was taken for 3 vertices");
    } catch (const expmap::Invalid_input& e) {
      BOOST_TEST(std::string(e.what()).find("has " + std::to_string(rows.size()) +
                                            " entries but the mesh has 3 vertices") != std::string::npos,
                 e.what());
    }
  }
  const Faces input(mesh, {0, 1, 2}, faces);
  BOOST_TEST(input.surface_point({0, {{0.2, 0.3, 0.5}}}).face == *mesh.faces().begin());
}

BOOST_AUTO_TEST_SUITE_END()
