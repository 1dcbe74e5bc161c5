// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TEST_CLI_FIXTURE_H
#define EXPMAP_TEST_CLI_FIXTURE_H

// The fixture of the tests of the `expmap` command-line program: a fresh
// folder with small meshes, and the program run in it as a user runs it.
// The binary's path comes from the build (test/CMakeLists.txt):
//   target_compile_definitions(test_robustness PRIVATE
//                              EXPMAP_CLI_PATH="$<TARGET_FILE:expmap_cli>")

#include <boost/test/unit_test.hpp>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#ifndef EXPMAP_CLI_PATH
#error "EXPMAP_CLI_PATH must name the expmap program (test/CMakeLists.txt sets it)"
#endif

namespace expmap_test_cli {

namespace fs = std::filesystem;

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::vector<std::string> read_lines(const fs::path& path) {
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

  /// Runs `expmap ARGS` with stdout and stderr captured into the folder,
  /// after the shell commands `setup` (e.g. "ulimit -v 2000000; ");
  /// returns the exit status (-1 if it did not exit normally, e.g. crashed).
  int run(const std::string& args, const std::string& setup = "") {
    const std::string command = setup + "'" + std::string(EXPMAP_CLI_PATH) + "' " + args + " >'" +
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

}  // namespace expmap_test_cli

#endif  // EXPMAP_TEST_CLI_FIXTURE_H
