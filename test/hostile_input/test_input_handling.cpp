// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the `expmap` program does with messy input (doc/manual.md, section
// "Input files"): headers that claim more than the file holds, polygon
// soups, polygonal faces, degenerate faces, several connected components,
// boundaries and non-manifold vertices.

#include <boost/test/unit_test.hpp>

#include "Map_or_one_error.h"

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using expmap_test::Outcome;

std::string data_mesh(const std::string& name) {
  return std::string(EXPMAP_TEST_DATA_DIR) + "/" + name;
}

struct Work_dir {
  fs::path dir;
  Work_dir() {
    static int counter = 0;
    dir = fs::temp_directory_path() /
          ("expmap_input_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir);
  }
  ~Work_dir() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  expmap_test::Judged_run run(const std::string& mesh, const std::vector<std::string>& args) const {
    return expmap_test::run_expmap(mesh, args, dir.string());
  }
  /// The CSV's vertex column.
  std::vector<long> csv_vertices() const {
    std::ifstream in(dir / "map.csv");
    std::string line;
    std::getline(in, line);
    std::vector<long> v;
    while (std::getline(in, line)) v.push_back(std::stol(line.substr(0, line.find(','))));
    return v;
  }
};

/// An n x n grid of unit squares in the plane z = 0 shifted by `x0`,
/// triangulated, counter-clockwise; vertex indices start at `first`.
void append_grid(std::ostringstream& vertices, std::ostringstream& faces, int n, double x0,
                 int first) {
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) vertices << x0 + i << ' ' << j << " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = first + j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      faces << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << d << '\n';
    }
}

/// The vertices of a bow-tie map, sorted, without the pinch vertex 0 (or
/// its copy, which the CSV names 0 too); empty unless 0 is there once.
std::vector<long> square_without_pinch(std::vector<long> v) {
  if (std::count(v.begin(), v.end(), 0) != 1) return {};
  v.erase(std::remove(v.begin(), v.end(), 0), v.end());
  std::sort(v.begin(), v.end());
  return v;
}

/// An ASCII PLY file with `vertices` points and the face count `faces`
/// (as written in the header, right or wrong), then `body`.
std::string ascii_ply(int vertices, const std::string& faces, const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
         "\nproperty list uchar int vertex_indices\nend_header\n" + body;
}

/// Each file fails with one error line that contains `needle`.
void check_refused(const Work_dir& w, const std::vector<std::string>& files,
                   const std::string& needle) {
  for (const std::string& file : files) {
    const auto run = w.run(file, {"--source", "0", "--vertices", "3"});
    BOOST_TEST((run.outcome == Outcome::error), file << ": " << run.problem);
    BOOST_TEST(run.stderr_text.find(needle) != std::string::npos, run.stderr_text);
  }
}

const char* const methods[] = {"heat", "dem", "dgpc", "exact"};

}  // namespace

BOOST_AUTO_TEST_SUITE(input_handling)

BOOST_AUTO_TEST_CASE(headers_claiming_more_than_the_file_holds_are_refused_by_name) {
  // Within the runner's 2 GB of address space: reading the file as CGAL
  // does would ask for 24 GB and end as "out of memory" instead.
  Work_dir w;
  std::ifstream in(data_mesh("eight.off"));
  std::string keyword, nv, nf, ne;
  in >> keyword >> nv >> nf >> ne;
  std::string body((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string lying_off = w.write("faces.off", "OFF\n" + nv + " 999999999 0" + body);
  const std::string lying_face =
      w.write("face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n999999999 0 1 2\n");
  const std::string lying_ply =
      w.write("faces.ply", ascii_ply(3, "999999999", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  check_refused(w, {lying_off, lying_face, lying_ply}, "999999999");
}

BOOST_AUTO_TEST_CASE(indices_outside_the_file_are_refused_by_name) {
  // CGAL 5.5 casts OFF indices from doubles (1e20 wraps to a vertex) and
  // does not check PLY indices (its Surface_mesh reader crashes).
  Work_dir w;
  const std::string off =
      w.write("index.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 1e20\n");
  const std::string ply = w.write(
      "index.ply", ascii_ply(4, "2", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 99999\n"));
  check_refused(w, {off, ply}, "refers to vertex");
}

BOOST_AUTO_TEST_CASE(polygon_soups_are_oriented_with_a_note) {
  Work_dir w;
  for (const char* name : {"cube-shuffled.off", "blobby-shuffled.off"}) {
    const auto run = w.run(data_mesh(name), {"--source", "0", "--vertices", "10"});
    BOOST_TEST((run.outcome == Outcome::map), name << ": " << run.problem << run.stderr_text);
    BOOST_TEST(run.stderr_text.find("expmap: note:") != std::string::npos, run.stderr_text);
    BOOST_TEST(run.stderr_text.find("reversed") != std::string::npos, run.stderr_text);
  }
}

BOOST_AUTO_TEST_CASE(polygonal_faces_are_triangulated_unless_refused) {
  Work_dir w;
  const std::string quads = data_mesh("cube_quad.off");
  auto run = w.run(quads, {"--source", "0", "--fraction", "1"});
  BOOST_TEST_REQUIRE((run.outcome == Outcome::map), run.problem << run.stderr_text);
  BOOST_TEST(run.stderr_text.find("triangulated") != std::string::npos, run.stderr_text);
  BOOST_TEST(w.csv_vertices().size() == 8u);  // no vertex added
  run = w.run(quads, {"--source", "0", "--fraction", "1", "--triangulate"});
  BOOST_TEST((run.outcome == Outcome::map), run.problem);
  run = w.run(quads, {"--source", "0", "--fraction", "1", "--no-triangulate"});
  BOOST_TEST((run.outcome == Outcome::error), run.problem);
  BOOST_TEST(run.stderr_text.find("--no-triangulate") != std::string::npos, run.stderr_text);
}

BOOST_AUTO_TEST_CASE(degenerate_faces_name_repair_which_removes_them) {
  Work_dir w;
  const std::string degenerate = data_mesh("degtri_sliding.off");
  auto run = w.run(degenerate, {"--source", "0", "--vertices", "4"});
  BOOST_TEST((run.outcome == Outcome::error), run.problem);
  BOOST_TEST(run.stderr_text.find("--repair") != std::string::npos, run.stderr_text);
  run = w.run(degenerate, {"--source", "0", "--vertices", "4", "--repair"});
  BOOST_TEST_REQUIRE((run.outcome == Outcome::map), run.problem << run.stderr_text);
  BOOST_TEST(run.stderr_text.find("removed") != std::string::npos, run.stderr_text);
  for (long v : w.csv_vertices()) BOOST_TEST((v >= 0 && v < 8), v);  // the file's indices
}

BOOST_AUTO_TEST_CASE(every_method_stays_in_the_source_component) {
  Work_dir w;
  std::ostringstream vertices, faces;
  append_grid(vertices, faces, 4, 0.0, 0);   // 25 vertices, 32 faces
  append_grid(vertices, faces, 3, 10.0, 25);  // 16 vertices, 18 faces
  const std::string two =
      w.write("two.off", "OFF\n41 50 0\n" + vertices.str() + faces.str());
  for (const char* method : methods) {
    auto run = w.run(two, {"--source", "12", "--fraction", "1", "--method", method});
    BOOST_TEST_REQUIRE((run.outcome == Outcome::map), method << ": " << run.problem);
    BOOST_TEST(w.csv_vertices().size() == 25u, method);
    run = w.run(two, {"--source", "30", "--fraction", "1", "--method", method});
    BOOST_TEST_REQUIRE((run.outcome == Outcome::map), method << ": " << run.problem);
    const auto v = w.csv_vertices();
    BOOST_TEST(v.size() == 16u, method);
    for (long i : v) BOOST_TEST(i >= 25, method);
  }
}

BOOST_AUTO_TEST_CASE(every_method_maps_from_a_boundary_corner) {
  Work_dir w;
  std::ostringstream vertices, faces;
  append_grid(vertices, faces, 6, 0.0, 0);
  const std::string grid = w.write("grid.off", "OFF\n49 72 0\n" + vertices.str() + faces.str());
  for (const char* method : methods) {
    // The corner's three nearest neighbours are (1,0), (0,1) and (1,1).
    const auto run = w.run(grid, {"--source", "0", "--vertices", "4", "--method", method});
    BOOST_TEST_REQUIRE((run.outcome == Outcome::map), method << ": " << run.problem);
    auto v = w.csv_vertices();
    std::sort(v.begin(), v.end());
    BOOST_TEST((v == std::vector<long>{0, 1, 7, 8}), method);
  }
}

BOOST_AUTO_TEST_CASE(non_manifold_vertices_are_split_and_each_side_mapped_alone) {
  // Two squares touching at vertex 0 only (a bow tie). Reading splits
  // vertex 0 into one copy per square and says so; a map never crosses
  // over, and the CSV names either copy by the file's index 0.
  Work_dir w;
  const std::string bowtie = w.write(
      "bowtie.off",
      "OFF\n7 4 0\n0 0 0\n1 0 0\n1 1 0.1\n0 1 0\n-1 0 0\n-1 -1 0.1\n0 -1 0\n"
      "3 0 1 2\n3 0 2 3\n3 0 4 5\n3 0 5 6\n");
  for (const char* method : methods) {
    auto run = w.run(bowtie, {"--source", "2", "--fraction", "1", "--method", method});
    BOOST_TEST_REQUIRE((run.outcome == Outcome::map), method << ": " << run.problem);
    BOOST_TEST(run.stderr_text.find("non-manifold") != std::string::npos, run.stderr_text);
    BOOST_TEST((square_without_pinch(w.csv_vertices()) == std::vector<long>{1, 2, 3}), method);
    run = w.run(bowtie, {"--source", "5", "--fraction", "1", "--method", method});
    BOOST_TEST_REQUIRE((run.outcome == Outcome::map), method << ": " << run.problem);
    BOOST_TEST((square_without_pinch(w.csv_vertices()) == std::vector<long>{4, 5, 6}), method);
  }
}

BOOST_AUTO_TEST_SUITE_END()
