// Tests of the `expmap` command-line program, run as a user would run it:
// the built binary on small mesh files written here, judged by its exit
// status, its stderr and the files it writes.
// The program and the meshes come from Cli_fixture.h.

#include "Cli_fixture.h"

#include <expmap/version.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace expmap_test_cli;
namespace fs = std::filesystem;

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

BOOST_AUTO_TEST_CASE(every_angle_estimator_answers) {
  for (const char* angles : {"heat-gradient", "log-heat-gradient", "log-heat-quadratic-fit",
                             "heat-quadratic-fit"}) {
    BOOST_TEST_CONTEXT("--angles " << angles) {
      const int status = run("compute " + file("grid.off") + " --source 24 --vertices 10 --angles " +
                             angles + " -o " + file("map.csv"));
      BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
      BOOST_TEST(read_lines(dir / "map.csv").size() == 11u);
    }
  }
}

// Column `k` of every data row of a map CSV (vertex,r,theta,u,v).
std::vector<std::string> csv_column(const fs::path& path, int k) {
  std::vector<std::string> column;
  const std::vector<std::string> lines = read_lines(path);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream row(lines[i]);
    std::string field;
    for (int j = 0; j <= k; ++j) std::getline(row, field, ',');
    column.push_back(field);
  }
  return column;
}

// The number after `label` in the summary on stdout (NaN if missing).
double summary_number(const std::string& out, const std::string& label) {
  const std::string::size_type at = out.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::stod(out.substr(at + label.size()));
}

// A 5% patch of the camel that every method folds: the summary gives its
// fold-free radius, and --trim-folds keeps exactly the vertices inside it,
// none of whose triangles is flipped, in compute and in batch.
BOOST_AUTO_TEST_CASE(trim_folds_keeps_the_fold_free_disk) {
  const std::string mesh = "'" + std::string(EXPMAP_TEST_DATA_DIR) + "/camel.off'";
  for (const char* method : {"heat", "dem", "dgpc", "exact"}) {
    BOOST_TEST_CONTEXT("--method " << method) {
      const std::string command = "compute " + mesh + " --source 79 --fraction 0.05 --method " +
                                  method + " -o " + file("whole.csv");
      BOOST_TEST_REQUIRE(run(command) == 0, err());
      const std::string summary = out();
      const double radius = summary_number(summary, "fold-free:");
      const double max_r = summary_number(summary, "max r:");
      BOOST_TEST(summary_number(summary, "flipped:") > 0);
      BOOST_TEST((radius > 0 && radius < max_r), summary);
      BOOST_TEST(summary.find(" of max r)") != std::string::npos, summary);

      BOOST_TEST_REQUIRE(run("compute " + mesh + " --source 79 --fraction 0.05 --method " +
                             method + " --trim-folds -o " + file("trimmed.csv")) == 0,
                         err());
      BOOST_TEST(summary_number(out(), "flipped:") == 0, out());
      // The whole map's rows nearer than the radius, and only those: the
      // rows come nearest first, so they are its first rows, and the next
      // one is at the radius (the summary prints it to 6 digits).
      const std::vector<std::string> whole = read_lines(dir / "whole.csv");
      std::vector<std::string> trimmed = read_lines(dir / "trimmed.csv");
      trimmed.erase(trimmed.begin());
      BOOST_TEST_REQUIRE(trimmed.size() > 1u);
      BOOST_TEST_REQUIRE(trimmed.size() + 1 < whole.size());
      const std::vector<std::string> prefix(whole.begin() + 1, whole.begin() + 1 + trimmed.size());
      BOOST_TEST(trimmed == prefix, boost::test_tools::per_element());
      auto r_of = [](const std::string& row) { return std::stod(row.substr(row.find(',') + 1)); };
      BOOST_TEST(r_of(trimmed.back()) < radius * (1 + 1e-5));
      BOOST_TEST(r_of(whole[trimmed.size() + 1]) > radius * (1 - 1e-5));

      BOOST_TEST_REQUIRE(run("batch " + mesh + " --sources 79 --fraction 0.05 --method " + method +
                             " --trim-folds -o " + file("batch.csv")) == 0,
                         err());
      const std::vector<std::string> rows = read_lines(dir / "batch.csv");
      BOOST_TEST_REQUIRE(rows.size() == trimmed.size() + 1);
      for (std::size_t i = 0; i < trimmed.size(); ++i)
        BOOST_TEST(rows[i + 1].rfind("79," + trimmed[i] + ",", 0) == 0u, rows[i + 1]);
    }
  }
}

BOOST_AUTO_TEST_CASE(single_precision_factors_give_distances_to_float_round_off) {
  const std::string query = "compute " + file("grid.off") + " --source 24 --vertices 20";
  BOOST_TEST_REQUIRE(run(query + " -o " + file("double.csv")) == 0, "stderr: " << err());
  const std::string precision = " --factor-precision ";
  BOOST_TEST_REQUIRE(run(query + precision + "single -o " + file("single.csv")) == 0,
                     "stderr: " << err());
  BOOST_TEST(out().find("single-precision factors") != std::string::npos, out());
  BOOST_TEST_REQUIRE(run(query + precision + "double -o " + file("double2.csv")) == 0,
                     "stderr: " << err());
  const auto r_double = csv_column(dir / "double.csv", 1);
  BOOST_TEST(csv_column(dir / "double2.csv", 1) == r_double, boost::test_tools::per_element());
  const auto r_single = csv_column(dir / "single.csv", 1);
  BOOST_TEST_REQUIRE(r_single.size() == r_double.size());
  for (std::size_t i = 0; i < r_double.size(); ++i)
    BOOST_TEST(std::stod(r_single[i]) == std::stod(r_double[i]),
               boost::test_tools::tolerance(1e-5));
}

BOOST_AUTO_TEST_CASE(two_query_threads_give_the_same_map) {
  const std::string query = "compute " + file("grid.off") + " --source 24 --fraction 1";
  BOOST_TEST_REQUIRE(run(query + " -o " + file("one.csv")) == 0, "stderr: " << err());
  BOOST_TEST_REQUIRE(run(query + " --query-threads 2 -o " + file("two.csv")) == 0,
                     "stderr: " << err());
  BOOST_TEST(out().find("2 threads per query") != std::string::npos, out());
  BOOST_TEST(read_lines(dir / "two.csv") == read_lines(dir / "one.csv"),
             boost::test_tools::per_element());
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
        "--laplacian", "--vertex-area", "--factor-precision", "--angles",
        "--query-threads", "--near-source-blend",
        "--reference",
        "--no-triangulate", "--repair", "--trim-folds", "--force", "--output", "fold-free"})
    BOOST_TEST(help.find(option) != std::string::npos, option);
}

// The version the program prints is the header's, which is also the one
// CMake read for project(VERSION) (test/CMakeLists.txt passes it on).
BOOST_AUTO_TEST_CASE(version_is_the_headers) {
  BOOST_TEST_REQUIRE(run("--version") == 0);
  BOOST_TEST(out() == std::string("expmap ") + EXPMAP_VERSION_STRING + "\n");
  BOOST_TEST(err().empty());
  BOOST_TEST(std::string(EXPMAP_VERSION_STRING) == EXPMAP_TEST_PROJECT_VERSION);
  BOOST_TEST(std::to_string(EXPMAP_VERSION_MAJOR) + "." + std::to_string(EXPMAP_VERSION_MINOR) +
                 "." + std::to_string(EXPMAP_VERSION_PATCH) ==
             EXPMAP_VERSION_STRING);
  BOOST_TEST_REQUIRE(run("--help") == 0);
  BOOST_TEST(out().find("--version") != std::string::npos);
  check_error("--version extra", 2);
}

// An exact run estimated beyond the memory available stops before its
// first map unless forced. Under an address-space limit of 2 GB, 48 exact
// maps at once (one per thread) are estimated at 40 MiB each, 2.0 GB,
// though these are tiny.
BOOST_AUTO_TEST_CASE(exact_maps_beyond_the_memory_available_need_force) {
  const std::string limited = "ulimit -v 2000000; ";
  const std::string batch = "batch " + file("grid.off") +
                            " --sources all --method exact --vertices 3 --threads 48 -o " + file("b.csv");
  BOOST_TEST(run(batch, limited) == 1);
  BOOST_TEST(err().rfind("expmap: error: an exact map of this patch builds its sequence tree on ", 0) == 0, err());
  BOOST_TEST(err().find(", 48 at once (one per thread) 2.0 GB, by the measured estimate") != std::string::npos);
  BOOST_TEST(err().find("choose a smaller patch or fewer --threads, or give --force") != std::string::npos);
  BOOST_TEST(!std::filesystem::exists(dir / "b.csv"));
  BOOST_TEST(run(batch + " --force", limited) == 0);
  BOOST_TEST(err().rfind("expmap: warning: an exact map of this patch", 0) == 0, err());
  BOOST_TEST(err().find("trying anyway (--force)") != std::string::npos);
  BOOST_TEST(read_lines(dir / "b.csv").size() == 1 + 49 * 3u);
  // --force is only for the exact method.
  check_error("compute " + file("grid.off") + " --source 0 --vertices 3 --force -o " + file("a.csv"), 2);
  BOOST_TEST(err().find("--force applies only to --method exact") != std::string::npos);
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
  check_error(grid + " --source 0 --vertices 10 --time-factor 0" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --method dgpc --time-factor 1" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --method dem --near-source-blend 1,2" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --factor-precision half" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --method dgpc --factor-precision single" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --query-threads 3" + csv, 2);
  check_error(grid + " --source 0 --vertices 10 --method dem --query-threads 2" + csv, 2);
  check_error(grid + " --source 0 --radius", 2);
  check_error(grid + " --source 0 --vertices 10", 2);
  check_error("", 2);
  BOOST_TEST(!std::filesystem::exists(dir / "a.csv"));
}

BOOST_AUTO_TEST_SUITE_END()

// `expmap batch`: many sources in one run, judged against `expmap compute`
// run once per source.
BOOST_FIXTURE_TEST_SUITE(batch_command, Cli_fixture)

// The rows of a CSV file without its header.
std::vector<std::string> csv_rows(const fs::path& path) {
  std::vector<std::string> lines = read_lines(path);
  if (!lines.empty()) lines.erase(lines.begin());
  return lines;
}

BOOST_AUTO_TEST_CASE(rows_equal_one_compute_per_source) {
  for (const char* method : {"heat", "dem", "dgpc", "exact"}) {
    BOOST_TEST_CONTEXT("--method " << method) {
      const int status = run("batch " + file("grid.off") + " --sources 24,0,24,48 --vertices 10" +
                             " --method " + method + " --threads 2 -o " + file("batch.csv"));
      BOOST_TEST_REQUIRE(status == 0, "stderr: " << err());
      BOOST_TEST(err().empty(), err());  // no progress bar when stderr is not a terminal
      const auto lines = read_lines(dir / "batch.csv");
      BOOST_TEST_REQUIRE(lines.size() == 41u);
      BOOST_TEST(lines[0] == "source,vertex,r,theta,u,v,fold_free_radius");
      std::size_t row = 1;
      for (const char* source : {"24", "0", "24", "48"}) {
        BOOST_TEST_REQUIRE(run("compute " + file("grid.off") + " --source " + source +
                               " --vertices 10 --method " + method + " -o " + file("one.csv")) == 0);
        // The map's fold-free radius ends each of its rows; a flat grid
        // does not fold, so it is the map's largest r.
        const std::vector<std::string> expected_rows = csv_rows(dir / "one.csv");
        double largest = 0;
        for (const std::string& expected : expected_rows)
          largest = std::max(largest, std::stod(expected.substr(expected.find(',') + 1)));
        for (const std::string& expected : expected_rows) {
          const std::string& line = lines[row++];
          const std::string prefix = std::string(source) + "," + expected + ",";
          BOOST_TEST(line.rfind(prefix, 0) == 0u, line);
          BOOST_TEST(std::stod(line.substr(prefix.size())) == largest, line);
        }
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(threads_do_not_change_the_output) {
  const std::string command = "batch " + file("grid.off") + " --sources all --fraction 0.3";
  BOOST_TEST_REQUIRE(run(command + " --threads 1 -o " + file("one.csv")) == 0, err());
  BOOST_TEST_REQUIRE(run(command + " --threads 2 -o " + file("two.csv")) == 0, err());
  BOOST_TEST(read_text(dir / "one.csv") == read_text(dir / "two.csv"));
  BOOST_TEST(read_lines(dir / "one.csv").size() == 1u + 49u * 15u);  // ceil(0.3 * 49) each
}

BOOST_AUTO_TEST_CASE(sources_from_a_file) {
  std::ofstream(dir / "sources.txt") << "# centre and corners\n24, 0\n6 48  # last\n\n";
  BOOST_TEST_REQUIRE(run("batch " + file("grid.off") + " --sources @" + file("sources.txt") +
                         " --vertices 3 -o " + file("b.csv")) == 0,
                     err());
  std::vector<std::string> sources;
  for (const std::string& row : csv_rows(dir / "b.csv")) sources.push_back(row.substr(0, row.find(',')));
  BOOST_TEST((sources == std::vector<std::string>{"24", "24", "24", "0", "0", "0", "6", "6", "6",
                                                  "48", "48", "48"}));
}

// An isolated vertex has no map: a warning names it, the other maps are
// written, and the exit status says that something failed.
BOOST_AUTO_TEST_CASE(a_failed_source_costs_only_its_map) {
  {
    std::ofstream out(dir / "lonely.off");
    out << "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n9 9 9\n3 0 1 3\n3 0 3 2\n";
  }
  const int status = run("batch " + file("lonely.off") + " --sources 0,4,3 --vertices 4 -o " +
                         file("b.csv") + " -o " + file("b.npz"));
  BOOST_TEST(status == 1);
  const std::vector<std::string> errors = read_lines(dir / "stderr.txt");
  BOOST_TEST_REQUIRE(errors.size() == 2u, err());
  BOOST_TEST(errors[0].rfind("expmap: warning: source vertex 4 ", 0) == 0, errors[0]);
  BOOST_TEST(errors[1].rfind("expmap: error: 1 of 3 sources failed", 0) == 0, errors[1]);
  std::vector<std::string> sources;
  for (const std::string& row : csv_rows(dir / "b.csv")) sources.push_back(row.substr(0, row.find(',')));
  BOOST_TEST((sources == std::vector<std::string>{"0", "0", "0", "0", "3", "3", "3", "3"}));
  BOOST_TEST(fs::exists(dir / "b.npz"));

  // "all" means every vertex with a face.
  BOOST_TEST(run("batch " + file("lonely.off") + " --sources all --vertices 2 -o " + file("a.csv")) == 0,
             err());
  BOOST_TEST(csv_rows(dir / "a.csv").size() == 8u);
}

// A stored zip: local header first, end-of-directory record last.
BOOST_AUTO_TEST_CASE(writes_npz) {
  BOOST_TEST_REQUIRE(run("batch " + file("grid.off") + " --sources 1,2 --radius 1.5 -o " +
                         file("b.npz")) == 0,
                     err());
  const std::string npz = read_text(dir / "b.npz");
  BOOST_TEST_REQUIRE(npz.size() > 22u);
  BOOST_TEST(npz.substr(0, 4) == std::string("PK\x03\x04", 4));
  BOOST_TEST(npz.substr(npz.size() - 22, 4) == std::string("PK\x05\x06", 4));
  for (const char* name : {"sources.npy", "offsets.npy", "vertex.npy", "r.npy", "theta.npy", "u.npy",
                           "v.npy", "fold_free_radius.npy"})
    BOOST_TEST(npz.find(name) != std::string::npos, name);
}

// Reading may renumber the mesh (a non-manifold vertex split into copies
// added at the end, --repair removing vertices); `batch`, like `compute`,
// speaks of the file's vertices in --sources and in both columns.
BOOST_AUTO_TEST_CASE(indices_are_the_files_when_reading_renumbers) {
  std::ofstream(dir / "bowtie.off") << "OFF\n7 4 0\n0 0 0\n1 0 0\n1 1 0.1\n0 1 0\n-1 0 0\n"
                                       "-1 -1 0.1\n0 -1 0\n3 0 1 2\n3 0 2 3\n3 0 4 5\n3 0 5 6\n";
  // Vertex 1 sits 1e-7 from vertex 0: --repair collapses the needles and
  // removes it, so mesh vertex 1 is file vertex 2.
  std::ofstream(dir / "needle.off") << "OFF\n6 5 0\n0 0 0\n1e-7 0 0\n2 0 0\n2 2 0\n0 2 0\n"
                                       "1 3 0\n3 0 1 3\n3 1 2 3\n3 0 3 4\n3 4 3 5\n3 0 4 1\n";
  const std::string bowtie = file("bowtie.off"), needle = file("needle.off") + " --repair";
  for (const std::string& mesh_and_flags : {bowtie, needle}) {
    BOOST_TEST_CONTEXT(mesh_and_flags) {
      const std::string patch = " --vertices 3 " + mesh_and_flags;
      BOOST_TEST_REQUIRE(run("batch " + patch + " --sources all -o " + file("b.csv")) == 0, err());
      BOOST_TEST(err().rfind("expmap: note: ", 0) == 0, err());  // reading did change the mesh
      const auto rows = csv_rows(dir / "b.csv");
      std::vector<std::string> sources;
      for (const std::string& row : rows) {
        const std::string source = row.substr(0, row.find(','));
        if (sources.empty() || sources.back() != source) sources.push_back(source);
      }
      // "all" is every file vertex once: the bow tie's pinch vertex 0 and its
      // copy are both file vertex 0; the removed needle vertex is left out.
      const auto expected = mesh_and_flags == bowtie
                                ? std::vector<std::string>{"0", "1", "2", "3", "4", "5", "6"}
                                : std::vector<std::string>{"0", "2", "3", "4", "5"};
      BOOST_TEST(sources == expected);
      std::size_t row = 0;
      for (const std::string& source : sources) {
        BOOST_TEST_REQUIRE(
            run("compute " + patch + " --source " + source + " -o " + file("one.csv")) == 0, err());
        for (const std::string& one : csv_rows(dir / "one.csv"))  // then the fold-free radius
          BOOST_TEST(rows.at(row++).rfind(source + "," + one + ",", 0) == 0u);
      }
      BOOST_TEST(row == rows.size());
      // After the note on reading, the error (so not check_error).
      BOOST_TEST(run("batch " + patch + " --sources 2,8 -o " + file("a.csv")) == 2);
      BOOST_TEST(err().find("expmap: error: --sources: vertex 8 is out of range") != std::string::npos,
                 err());  // 7 and 6 vertices in the files
    }
  }
  BOOST_TEST(run("batch " + needle + " --vertices 3 --sources 0,1 -o " + file("a.csv")) == 1);
  BOOST_TEST(err().find("expmap: error: --sources: vertex 1 was removed by --repair") !=
                 std::string::npos,
             err());
  BOOST_TEST(!fs::exists(dir / "a.csv"));
}

BOOST_AUTO_TEST_CASE(help_documents_every_option) {
  BOOST_TEST_REQUIRE(run("batch --help") == 0);
  const std::string help = out();
  for (const char* option :
       {"--sources", "--threads", "--radius", "--fraction", "--vertices", "--method",
        "--time-factor", "--laplacian", "--vertex-area", "--factor-precision",
        "--query-threads", "--angles",
        "--near-source-blend", "--reference",
        "--no-triangulate", "--repair", "--trim-folds", "--output", ".npz", "fold_free_radius",
        "expmap: warning:"})
    BOOST_TEST(help.find(option) != std::string::npos, option);
  BOOST_TEST_REQUIRE(run("--help") == 0);
  BOOST_TEST(out().find("batch") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(errors_leave_no_output) {
  const std::string grid = "batch " + file("grid.off");
  const std::string csv = " -o " + file("a.csv");
  check_error(grid + " --vertices 10" + csv, 2);                      // no --sources
  check_error(grid + " --sources 1,,2 --vertices 10" + csv, 2);
  check_error(grid + " --sources -1 --vertices 10" + csv, 2);
  check_error(grid + " --sources 3,49 --vertices 10" + csv, 2);       // out of range
  check_error(grid + " --sources all --vertices 10 --threads many" + csv, 2);
  check_error(grid + " --sources all --vertices 10 -o " + file("a.obj"), 2);
  check_error(grid + " --sources all --vertices 10 --source 3" + csv, 2);
  check_error(grid + " --sources @ --vertices 10" + csv, 2);
  check_error(grid + " --sources @" + file("missing.txt") + " --vertices 10" + csv, 1);
  std::ofstream(dir / "bad.txt") << "1 2\nthree\n";
  check_error(grid + " --sources @" + file("bad.txt") + " --vertices 10" + csv, 1);
  BOOST_TEST(err().find("line 2") != std::string::npos, err());
  check_error("batch " + file("quads.off") + " --sources all --vertices 3 --no-triangulate" + csv, 1);
  BOOST_TEST(err().find("more than three vertices") != std::string::npos, err());
  check_error("compute " + file("grid.off") + " --source 0 --vertices 3 -o " + file("a.npz"), 2);
  BOOST_TEST(!fs::exists(dir / "a.csv"));
  BOOST_TEST(!fs::exists(dir / "a.npz"));
}

BOOST_AUTO_TEST_SUITE_END()
