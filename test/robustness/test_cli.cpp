// Tests of the `expmap` command-line program, run as a user would run it:
// the built binary on small mesh files written here, judged by its exit
// status, its stderr and the files it writes.
//
// The binary's path comes from the build (test/CMakeLists.txt):
//   target_compile_definitions(test_robustness PRIVATE
//                              EXPMAP_CLI_PATH="$<TARGET_FILE:expmap_cli>")

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#ifndef EXPMAP_CLI_PATH
#error "EXPMAP_CLI_PATH must name the expmap program (test/CMakeLists.txt sets it)"
#else

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// A fresh folder with the meshes the tests use, removed afterwards.
struct Cli_fixture {
  fs::path dir;

  Cli_fixture() {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    dir = fs::temp_directory_path() / ("expmap_cli_test_" + std::to_string(::getpid()) + "_" +
                                       std::to_string(stamp) + "_" + std::to_string(counter++));
    fs::create_directories(dir);
    write_grid(dir / "grid.off", 6);
    // Two quads: a valid polygon mesh, triangulated unless --no-triangulate.
    std::ofstream(dir / "quads.off") << "OFF\n6 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n"
                                        "4 0 1 4 3\n4 1 2 5 4\n";
  }
  ~Cli_fixture() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }

  /// An n x n grid of unit squares split into triangles, counter-clockwise
  /// seen from +z, with the vertices perturbed a little in z so it is not
  /// exactly flat.
  static void write_grid(const fs::path& path, int n) {
    std::ofstream out(path);
    out << "OFF\n" << (n + 1) * (n + 1) << ' ' << 2 * n * n << " 0\n";
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        out << i << ' ' << j << ' ' << 0.05 * ((i * 7 + j * 3) % 5) << '\n';
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
        out << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << d << '\n';
      }
  }

  /// Runs `expmap ARGS` with stdout and stderr captured into the folder;
  /// returns the exit status (-1 if it did not exit normally, e.g. crashed).
  int run(const std::string& args) {
    const std::string command = "'" + std::string(EXPMAP_CLI_PATH) + "' " + args + " >'" +
                                (dir / "stdout.txt").string() + "' 2>'" +
                                (dir / "stderr.txt").string() + "'";
    const int status = std::system(command.c_str());
    if (status == -1 || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
  }

  std::string file(const std::string& name) const { return "'" + (dir / name).string() + "'"; }
  std::string err() const { return read_text(dir / "stderr.txt"); }
  std::string out() const { return read_text(dir / "stdout.txt"); }

  /// The command fails cleanly: status `expected`, and stderr is one
  /// message with the documented prefix.
  void check_error(const std::string& args, int expected) {
    BOOST_TEST_CONTEXT("expmap " << args) {
      const int status = run(args);
      BOOST_TEST(status == expected);
      const std::string message = err();
      BOOST_TEST(message.rfind("expmap: error: ", 0) == 0, "stderr: " << message);
    }
  }
};

}  // namespace

BOOST_FIXTURE_TEST_SUITE(command_line, Cli_fixture)

BOOST_AUTO_TEST_CASE(writes_a_csv_row_per_patch_vertex) {
  const int status =
      run("compute " + file("grid.off") + " --source 24 --vertices 10 -o " + file("map.csv"));
  BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
  const auto lines = read_lines(dir / "map.csv");
  BOOST_TEST_REQUIRE(lines.size() == 11u);
  BOOST_TEST(lines[0] == "vertex,r,theta,u,v");
  // The source first, at the origin, then nine distinct vertices with
  // coordinates that agree with r and theta.
  BOOST_TEST(lines[1].rfind("24,0,", 0) == 0, lines[1]);
  std::vector<long> seen;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream row(lines[i]);
    long vertex = -1;
    double r = -1, theta = 0, u = 0, v = 0;
    char c1 = 0, c2 = 0, c3 = 0, c4 = 0;
    row >> vertex >> c1 >> r >> c2 >> theta >> c3 >> u >> c4 >> v;
    BOOST_TEST_REQUIRE(!row.fail(), lines[i]);
    BOOST_TEST((c1 == ',' && c2 == ',' && c3 == ',' && c4 == ','));
    BOOST_TEST((vertex >= 0 && vertex < 49));
    BOOST_TEST(r >= 0);
    BOOST_TEST(r < 3.0);  // ten vertices around (3, 3) on a unit grid
    BOOST_TEST((theta > -M_PI - 1e-12 && theta <= M_PI + 1e-12));
    BOOST_TEST(std::abs(u - r * std::cos(theta)) < 1e-9);
    BOOST_TEST(std::abs(v - r * std::sin(theta)) < 1e-9);
    seen.push_back(vertex);
  }
  std::sort(seen.begin(), seen.end());
  BOOST_TEST((std::unique(seen.begin(), seen.end()) == seen.end()));
  BOOST_TEST(out().find("flipped:") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(writes_obj_and_svg_together) {
  const int status = run("compute " + file("grid.off") + " --source 24 --fraction 1 -o " +
                         file("patch.obj") + " --output=" + file("patch.svg"));
  BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
  std::size_t v = 0, vt = 0, f = 0;
  for (const auto& line : read_lines(dir / "patch.obj")) {
    v += line.rfind("v ", 0) == 0;
    vt += line.rfind("vt ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  BOOST_TEST(v == 49u);  // the whole grid
  BOOST_TEST(vt == 49u);
  BOOST_TEST(f == 72u);
  const std::string svg = read_text(dir / "patch.svg");
  BOOST_TEST(svg.find("<svg") != std::string::npos);
  BOOST_TEST(svg.find("72 triangles") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(every_method_answers_the_same_patch_size) {
  for (const char* method : {"heat", "dem", "dgpc", "exact"}) {
    BOOST_TEST_CONTEXT("--method " << method) {
      const int status =
          run("compute " + file("grid.off") + " --source 24 --vertices 10 --method " + method +
              " -o " + file("map.csv"));
      BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
      const auto lines = read_lines(dir / "map.csv");
      BOOST_TEST(lines.size() == 11u);
    }
  }
}

BOOST_AUTO_TEST_CASE(both_angle_estimators_answer) {
  for (const char* angles : {"area-weighted", "quadratic-fit"}) {
    BOOST_TEST_CONTEXT("--angles " << angles) {
      const int status = run("compute " + file("grid.off") + " --source 24 --vertices 10 --angles " +
                             angles + " -o " + file("map.csv"));
      BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
      BOOST_TEST(read_lines(dir / "map.csv").size() == 11u);
    }
  }
}

BOOST_AUTO_TEST_CASE(polygon_meshes_are_triangulated_by_default) {
  for (const char* flag : {"", " --triangulate"}) {
    const int status = run("compute " + file("quads.off") + flag + " --source 1 --fraction 1 -o " +
                           file("map.csv"));
    BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
    BOOST_TEST(read_lines(dir / "map.csv").size() == 7u);  // all six vertices, none added
    BOOST_TEST(err().rfind("expmap: note: ", 0) == 0, err());
  }
}

BOOST_AUTO_TEST_CASE(help_documents_every_option) {
  BOOST_TEST_REQUIRE(run("compute --help") == 0);
  const std::string help = out();
  for (const char* option :
       {"--source", "--radius", "--fraction", "--vertices", "--method", "--time-factor",
        "--laplacian", "--angles", "--reference", "--no-triangulate", "--repair", "--output"})
    BOOST_TEST(help.find(option) != std::string::npos, option);
}

BOOST_AUTO_TEST_CASE(runtime_errors_exit_with_status_1) {
  check_error("compute " + file("missing.off") + " --source 0 --vertices 10 -o " + file("a.csv"),
              1);
  check_error("compute " + file("quads.off") + " --no-triangulate --source 0 --vertices 3 -o " +
                  file("a.csv"),
              1);
  BOOST_TEST(err().find("more than three vertices") != std::string::npos, err());
  BOOST_TEST(!std::filesystem::exists(dir / "a.csv"));
}

BOOST_AUTO_TEST_CASE(usage_errors_exit_with_status_2) {
  const std::string grid = "compute " + file("grid.off");
  const std::string csv = " -o " + file("a.csv");
  check_error(grid + " --source 0 --radius -1" + csv, 2);
  check_error(grid + " --source 0 --fraction 1.5" + csv, 2);
  check_error(grid + " --source 999999 --vertices 10" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 -o " + file("a.txt"), 2);
  check_error(grid + " --source 0 --vertices 10 --no-such-option" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --method no-such-method" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --angles sideways" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --method dem --angles quadratic-fit" + csv, 2);
  check_error(grid + " --source 0 --radius", 2);
  check_error(grid + " --source 0 --vertices 10", 2);
  check_error("", 2);
  BOOST_TEST(!std::filesystem::exists(dir / "a.csv"));
}

BOOST_AUTO_TEST_SUITE_END()

#endif  // EXPMAP_CLI_PATH
