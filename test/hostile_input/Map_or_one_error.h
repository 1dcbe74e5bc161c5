// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TEST_MAP_OR_ONE_ERROR_H
#define EXPMAP_TEST_MAP_OR_ONE_ERROR_H

// The rule every run of the `expmap` program on any input must obey: either
// it succeeds and writes a map without NaN or infinity, or it fails with
// status 1 or 2 and exactly one `expmap: error:` line on stderr (notes about
// repairs may come before it). Never a crash, a hang or runaway memory.

#include "Bounded_process.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#ifndef EXPMAP_CLI_PATH
#error "EXPMAP_CLI_PATH must name the expmap program (test/CMakeLists.txt sets it)"
#endif

namespace expmap_test {

inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

enum class Outcome { map, error, broken };

struct Judged_run {
  Outcome outcome = Outcome::broken;
  std::string problem;  // what broke the rule, if it did
  std::string stderr_text;
};

/// Runs `expmap compute MESH ARGS -o CSV` within 60 s and 2 GB of address
/// space, and judges it by the rule above.
inline Judged_run run_expmap(const std::string& mesh, const std::vector<std::string>& args,
                             const std::string& work_dir) {
  const std::string csv = work_dir + "/map.csv", out = work_dir + "/stdout.txt",
                    err = work_dir + "/stderr.txt";
  std::remove(csv.c_str());
  std::vector<std::string> all = {"compute", mesh};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("-o");
  all.push_back(csv);
  const Process_result p = run_bounded(EXPMAP_CLI_PATH, all, out, err, 60.0, 2ull << 30);
  Judged_run j;
  j.stderr_text = file_text(err);
  if (p.timed_out) {
    j.problem = "did not finish within 60 s";
    return j;
  }
  if (!p.exited) {
    j.problem = "ended by signal " + std::to_string(p.signal);
    return j;
  }
  std::vector<std::string> lines;
  std::istringstream stream(j.stderr_text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  std::size_t errors = 0, others = 0;
  for (const std::string& line : lines) {
    if (line.rfind("expmap: error: ", 0) == 0)
      ++errors;
    else if (line.rfind("expmap: note: ", 0) != 0)
      ++others;
  }
  if (others) {
    j.problem = "stderr has lines other than notes and errors";
    return j;
  }
  if (p.status == 0) {
    if (errors) {
      j.problem = "succeeded but printed an error";
      return j;
    }
    std::ifstream table(csv);
    std::string header;
    if (!std::getline(table, header) || header != "vertex,r,theta,u,v") {
      j.problem = "succeeded without a CSV header";
      return j;
    }
    std::size_t rows = 0;
    for (std::string row; std::getline(table, row); ++rows) {
      std::istringstream cells(row);
      std::string cell;
      while (std::getline(cells, cell, ',')) {
        const double value = std::strtod(cell.c_str(), nullptr);
        if (!std::isfinite(value) || cell.find("nan") != std::string::npos) {
          j.problem = "CSV row '" + row + "' is not finite";
          return j;
        }
      }
    }
    if (rows == 0) {
      j.problem = "succeeded with an empty map";
      return j;
    }
    j.outcome = Outcome::map;
    return j;
  }
  if ((p.status == 1 || p.status == 2) && errors == 1) {
    j.outcome = Outcome::error;
    return j;
  }
  j.problem = "exit status " + std::to_string(p.status) + " with " + std::to_string(errors) +
              " error lines";
  return j;
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_MAP_OR_ONE_ERROR_H
