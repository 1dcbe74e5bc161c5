// Point sources on the command line (--source-point, --source-face with
// --barycentric, batch --source-points), judged against the vertex source's
// output and, on a plane, the Euclidean distances.

#include "Cli_fixture.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace expmap_test_cli;
namespace fs = std::filesystem;

namespace {

// An n x n grid of unit squares in the plane z = 0, each split into two
// triangles; vertex j (n + 1) + i is at (i, j, 0).
void write_planar_grid(const fs::path& path, int n) {
  std::ofstream out(path);
  out << "OFF\n" << (n + 1) * (n + 1) << ' ' << 2 * n * n << " 0\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) out << i << ' ' << j << " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      out << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << d << '\n';
    }
}

// The distance column of a `compute` CSV by vertex.
std::map<long, double> distances(const fs::path& csv) {
  std::map<long, double> r;
  const std::vector<std::string> lines = read_lines(csv);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream row(lines[i]);
    long vertex = -1;
    char comma = 0;
    double distance = -1;
    row >> vertex >> comma >> distance;
    r[vertex] = distance;
  }
  return r;
}

const char* const point_methods[] = {"heat", "dem", "dgpc", "exact"};

}  // namespace

BOOST_FIXTURE_TEST_SUITE(point_sources, Cli_fixture)

// A point given at a vertex's position, or as a corner of a face, is that
// vertex: the same file, byte for byte.
BOOST_AUTO_TEST_CASE(a_point_at_a_vertex_gives_the_vertex_map) {
  const std::string grid = "compute " + file("grid.off") + " --method dgpc --vertices 12";
  BOOST_TEST_REQUIRE(run(grid + " --source 24 -o " + file("vertex.csv")) == 0, err());
  // Vertex 24 is at (3, 3, 0); faces 42 and 43 are the triangles 24 25 32
  // and 24 32 31 of the square to its upper right.
  BOOST_TEST_REQUIRE(run(grid + " --source-point 3,3,0 -o " + file("point.csv")) == 0, err());
  BOOST_TEST(err().empty(), err());  // on the surface: no note
  BOOST_TEST(read_text(dir / "point.csv") == read_text(dir / "vertex.csv"));
  BOOST_TEST_REQUIRE(run(grid + " --source-face 43 --barycentric 1,0,0 -o " + file("face.csv")) == 0,
                     err());
  BOOST_TEST(read_text(dir / "face.csv") == read_text(dir / "vertex.csv"));
  BOOST_TEST(out().find("in face 43, barycentric (1, 0, 0)") != std::string::npos, out());
  // Coordinates are rescaled to sum 1.
  BOOST_TEST_REQUIRE(run(grid + " --source-face 43 --barycentric 2,0,0 -o " + file("face.csv")) == 0,
                     err());
  BOOST_TEST(read_text(dir / "face.csv") == read_text(dir / "vertex.csv"));
  BOOST_TEST(out().find("source point (3, 3, 0) in face 43, barycentric (1, 0, 0)") !=
                 std::string::npos,
             out());
}

// On a plane the map from a point inside a face is exact: its distances
// are the Euclidean ones, whether the point is given by a face and
// barycentric coordinates (of the file's corner order) or by its position.
BOOST_AUTO_TEST_CASE(a_point_in_a_face_of_a_plane_has_euclidean_distances) {
  write_planar_grid(dir / "plane.off", 8);
  // Face 2 (3 * 8 + 2) + 1 = 53 is the triangle 29 39 38: (2, 3), (3, 4), (2, 4).
  const std::array<double, 3> w{{0.2, 0.3, 0.5}};
  const double x = w[0] * 2 + w[1] * 3 + w[2] * 2, y = w[0] * 3 + w[1] * 4 + w[2] * 4;
  const std::string plane = "compute " + file("plane.off") + " --method dgpc --radius 3";
  BOOST_TEST_REQUIRE(run(plane + " --source-face 53 --barycentric 0.2,0.3,0.5 -o " +
                         file("face.csv") + " -o " + file("face.obj")) == 0,
                     err());
  char printed[96];  // the summary prints 6 significant digits, as %g does
  std::snprintf(printed, sizeof printed, "source point (%g, %g, 0) in face 53, barycentric (0.2, 0.3, 0.5)",
                x, y);
  BOOST_TEST(out().find(printed) != std::string::npos, out() << " lacks " << printed);
  const std::map<long, double> face = distances(dir / "face.csv");
  BOOST_TEST(face.size() > 20u);
  for (const auto& [vertex, r] : face) {
    const double vx = static_cast<double>(vertex % 9), vy = static_cast<double>(vertex / 9);
    BOOST_TEST(std::abs(r - std::hypot(vx - x, vy - y)) < 1e-12, "vertex " << vertex);
  }
  BOOST_TEST(read_text(dir / "face.obj").find("vt ") != std::string::npos);

  auto position = [&](double z) {
    std::ostringstream s;
    s.precision(17);
    s << x << ',' << y << ',' << z;
    return s.str();
  };
  // By its position, and above the plane: the nearest surface point, with
  // a note saying so.
  for (double z : {0.0, 0.5}) {
    BOOST_TEST_REQUIRE(
        run(plane + " --source-point " + position(z) + " -o " + file("point.csv")) == 0, err());
    BOOST_TEST(err().empty() == (z == 0), err());
    if (z > 0)
      BOOST_TEST(err().rfind("expmap: note: --source-point: the point is off the surface", 0) == 0,
                 err());
    const std::map<long, double> located = distances(dir / "point.csv");
    BOOST_TEST_REQUIRE(located.size() == face.size());
    for (const auto& [vertex, r] : located) BOOST_TEST(std::abs(r - face.at(vertex)) < 1e-12);
  }
}

// batch --source-points: a map per line, the same as compute's from that
// point, named by the point's position in the file.
BOOST_AUTO_TEST_CASE(batch_maps_a_file_of_points) {
  std::ofstream(dir / "points.txt") << "# x, y, z\n3, 3, 0\n\n2.5 3.25 0.1  # a comment\n";
  BOOST_TEST_REQUIRE(run("batch " + file("grid.off") + " --method dgpc --vertices 12 --threads 2" +
                         " --source-points " + file("points.txt") + " -o " + file("b.csv")) == 0,
                     err());
  const std::vector<std::string> rows = read_lines(dir / "b.csv");
  BOOST_TEST_REQUIRE(rows.size() == 25u);
  BOOST_TEST(rows[1].rfind("0,24,0,", 0) == 0, rows[1]);
  BOOST_TEST(rows[13].rfind("1,", 0) == 0, rows[13]);
  BOOST_TEST_REQUIRE(run("compute " + file("grid.off") + " --method dgpc --vertices 12" +
                         " --source-point 2.5,3.25,0.1 -o " + file("c.csv")) == 0,
                     err());
  const std::vector<std::string> single = read_lines(dir / "c.csv");
  BOOST_TEST_REQUIRE(single.size() == 13u);
  for (std::size_t i = 1; i < single.size(); ++i)  // vertex,r,theta,u,v against source,vertex,...
    BOOST_TEST(rows[12 + i].substr(2).rfind(single[i], 0) == 0, rows[12 + i] << " / " << single[i]);
}

BOOST_AUTO_TEST_CASE(bad_point_sources_are_one_error) {
  const std::string grid = "compute " + file("grid.off") + " --method dgpc --vertices 5 -o " +
                           file("a.csv");
  check_error(grid + " --source-point 1,2", 2);
  check_error(grid + " --source-point 1,2,nan", 2);
  // Too far to locate (CGAL's search overflows there): one error line.
  BOOST_TEST(run(grid + " --source-point -1e308,0,1e308") == 1);
  const std::string far = err();
  BOOST_TEST(far.rfind("expmap: error: --source-point: the point (-1e+308, 0, 1e+308) is too far "
                       "from the mesh", 0) == 0, far);
  BOOST_TEST(std::count(far.begin(), far.end(), '\n') == 1, far);
  check_error(grid + " --source 3 --source-point 1,2,3", 2);
  check_error(grid + " --source-face 3", 2);
  check_error(grid + " --barycentric 1,0,0 --source 3", 2);
  check_error(grid + " --source-face 3 --barycentric 1,-1,1", 2);
  check_error(grid + " --source-face 3 --barycentric 0,0,0", 2);
  check_error(grid + " --source-face 72 --barycentric 1,1,1", 2);  // 72 faces: 0 to 71
  // A quad, split into triangles when read (which a note says first).
  BOOST_TEST(run("compute " + file("quads.off") + " --method dgpc --vertices 3 --source-face 0" +
                 " --barycentric 1,1,1 -o " + file("a.csv")) == 1);
  BOOST_TEST(err().find("\nexpmap: error: source face 0 has 4 corners, not 3") != std::string::npos,
             err());
  const std::string batch = "batch " + file("grid.off") + " --method dgpc --vertices 5 -o " +
                            file("b.csv");
  std::ofstream(dir / "two.txt") << "1 2\n";
  check_error(batch + " --source-points " + file("two.txt"), 1);
  BOOST_TEST(err().find("line 1") != std::string::npos, err());
  std::ofstream(dir / "none.txt") << "# nothing\n";
  check_error(batch + " --source-points " + file("none.txt"), 1);
  check_error(batch + " --source-points " + file("missing.txt"), 1);
  std::ofstream(dir / "far.txt") << "1 2 0\n3 3 1e300\n";
  check_error(batch + " --source-points " + file("far.txt"), 1);
  BOOST_TEST(err().find("far.txt': source 1: the point (3, 3, 1e+300) is too far") != std::string::npos,
             err());
  check_error(batch + " --source-points " + file("two.txt") + " --sources all", 2);
  BOOST_TEST(!fs::exists(dir / "a.csv"));
  BOOST_TEST(!fs::exists(dir / "b.csv"));
}

// Every method maps from a point inside a face of a plane: no vertex is at
// the point, so no row has r = 0, every number is finite, and the distances
// are the plane's.
BOOST_AUTO_TEST_CASE(every_method_maps_from_points) {
  write_planar_grid(dir / "plane.off", 8);
  const double x = 2.3, y = 3.8;  // in face 53, the triangle (2, 3), (3, 4), (2, 4)
  for (const char* method : point_methods) {
    BOOST_TEST_CONTEXT(method) {
      BOOST_TEST_REQUIRE(run("compute " + file("plane.off") + " --vertices 12 --source-point 2.3,3.8,0" +
                             " --method " + method + " -o " + file("m.csv")) == 0,
                         err());
      BOOST_TEST(err().empty(), err());
      const std::vector<std::string> lines = read_lines(dir / "m.csv");
      BOOST_TEST_REQUIRE(lines.size() == 13u);
      double worst = 0;
      for (std::size_t i = 1; i < lines.size(); ++i) {
        std::istringstream row(lines[i]);
        long vertex = -1;
        double r = 0, theta = 0, u = 0, v = 0;
        char c1 = 0, c2 = 0, c3 = 0, c4 = 0;
        BOOST_TEST_REQUIRE(bool(row >> vertex >> c1 >> r >> c2 >> theta >> c3 >> u >> c4 >> v), lines[i]);
        BOOST_TEST((std::isfinite(r) && std::isfinite(theta) && std::isfinite(u) && std::isfinite(v)),
                   lines[i]);
        BOOST_TEST(r > 0, lines[i]);
        const double euclidean = std::hypot(static_cast<double>(vertex % 9) - x,
                                            static_cast<double>(vertex / 9) - y);
        worst = std::max(worst, std::abs(r - euclidean) / euclidean);
      }
      BOOST_TEST_MESSAGE(method << ": largest relative distance error " << worst);
      // DEM, DGPC and exact are exact on a plane; heat is smoothed (its
      // largest relative error here is 0.12).
      BOOST_TEST(worst < (std::string(method) == "heat" ? 0.2 : 1e-12));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
