// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzzing the `expmap` program with OFF files mutated from a small real mesh
// (eight.off of libcgal-demo, 315 vertices, genus 2), with a fixed seed so
// that a failure can be reproduced: every input, through every method, gives
// a map without NaN or exactly one `expmap: error:` line
// (Map_or_one_error.h), within bounded time and memory.

#include <boost/test/unit_test.hpp>

#include "Map_or_one_error.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

/// An OFF mesh as text fields, so that mutations can put anything anywhere.
struct Off_text {
  std::string vertex_count, face_count;
  std::vector<std::vector<std::string>> vertices;  // coordinates
  std::vector<std::vector<std::string>> faces;     // count, then indices

  static Off_text read(const std::string& path) {
    std::ifstream in(path);
    std::string keyword;
    Off_text m;
    std::string edges;
    in >> keyword >> m.vertex_count >> m.face_count >> edges;
    const int nv = std::stoi(m.vertex_count), nf = std::stoi(m.face_count);
    m.vertices.assign(nv, std::vector<std::string>(3));
    for (auto& v : m.vertices) in >> v[0] >> v[1] >> v[2];
    for (int f = 0; f < nf; ++f) {
      std::string count;
      in >> count;
      std::vector<std::string> face = {count};
      for (int k = 0; k < std::stoi(count); ++k) {
        std::string index;
        in >> index;
        face.push_back(index);
      }
      m.faces.push_back(face);
    }
    return m;
  }

  std::string write() const {
    std::ostringstream out;
    out << "OFF\n" << vertex_count << ' ' << face_count << " 0\n";
    for (const auto& v : vertices) out << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    for (const auto& f : faces) {
      for (std::size_t k = 0; k < f.size(); ++k) out << (k ? " " : "") << f[k];
      out << '\n';
    }
    return out.str();
  }
};

std::string scaled(const std::string& coordinate, double factor) {
  std::ostringstream s;
  s.precision(17);
  s << std::stod(coordinate) * factor;
  return s.str();
}

/// One mutation of the base mesh, chosen by `kind`, its details by `random`.
/// Returns the file's text and a short name for failure messages.
std::pair<std::string, std::string> mutate(const Off_text& base, int kind, std::mt19937& random) {
  Off_text m = base;
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
  auto& vertex = m.vertices[pick(m.vertices.size())];
  auto& face = m.faces[pick(m.faces.size())];
  const std::string nv = std::to_string(m.vertices.size());
  switch (kind) {
    case 0: {
      const std::string text = m.write();
      return {text.substr(0, pick(text.size())), "truncated"};
    }
    case 1: vertex[pick(3)] = "nan"; return {m.write(), "NaN coordinate"};
    case 2: vertex[pick(3)] = random() % 2 ? "inf" : "-inf"; return {m.write(), "infinite coordinate"};
    case 3: vertex[pick(3)] = random() % 2 ? "1e308" : "-1.7e308"; return {m.write(), "1e308 coordinate"};
    case 4: vertex[pick(3)] = "4.9e-324"; return {m.write(), "denormal coordinate"};
    case 5: face[1 + pick(3)] = nv; return {m.write(), "index out of range"};
    case 6: face[1 + pick(3)] = "-" + std::to_string(1 + pick(5)); return {m.write(), "negative index"};
    case 7:
      face[1 + pick(3)] = random() % 2 ? "4294967296" : "99999999999999999999";
      return {m.write(), "huge index"};
    case 8: m.vertex_count = std::to_string(m.vertices.size() + 1 + pick(1000)); return {m.write(), "vertex count too large"};
    case 9: m.face_count = random() % 2 ? "999999999" : std::to_string(m.faces.size() + 1 + pick(50)); return {m.write(), "face count too large"};
    case 10: m.vertex_count = std::to_string(pick(m.vertices.size())); return {m.write(), "vertex count too small"};
    case 11: m.face_count = std::to_string(pick(m.faces.size())); return {m.write(), "face count too small"};
    case 12:
      (random() % 2 ? m.vertex_count : m.face_count) = "-" + std::to_string(1 + pick(100));
      return {m.write(), "negative count"};
    case 13: m.faces.push_back(face); return {m.write(), "duplicated face"};
    case 14:
      std::swap(face[1], face[2]);
      return {m.write(), "flipped face"};
    case 15: {
      const auto other = m.vertices[pick(m.vertices.size())];
      vertex = other;
      return {m.write(), "coincident vertices"};
    }
    case 16: face[2] = face[1]; return {m.write(), "face repeating a vertex"};
    case 17: {
      std::string text = m.write();
      const std::size_t at = pick(text.size()), n = 1 + pick(16);
      for (std::size_t k = 0; k < n && at + k < text.size(); ++k) text[at + k] = static_cast<char>(random());
      return {text, "random bytes"};
    }
    case 18:
      for (auto& v : m.vertices)
        for (auto& c : v) c = scaled(c, 1e-12);
      return {m.write(), "scaled by 1e-12"};
    case 19:
      for (auto& v : m.vertices)
        for (auto& c : v) c = scaled(c, 1e12);
      return {m.write(), "scaled by 1e12"};
    case 20: face[0] = random() % 2 ? "999999999" : "-1"; return {m.write(), "face vertex count wrong"};
    default: {
      // Two faces flipped and one face duplicated at once: a soup to orient.
      std::swap(m.faces[pick(m.faces.size())][1], m.faces[pick(m.faces.size())][2]);
      m.faces.push_back(m.faces[pick(m.faces.size())]);
      return {m.write(), "flipped and duplicated faces"};
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(mutated_off_files_give_a_map_or_one_error) {
  const Off_text base = Off_text::read(std::string(EXPMAP_TEST_DATA_DIR) + "/eight.off");
  BOOST_TEST_REQUIRE(base.vertices.size() == 315u);
  const fs::path dir = fs::temp_directory_path() / ("expmap_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::mt19937 random(20261122);
  const int kinds = 22, inputs = 330;
  std::map<std::string, int> maps, errors;
  for (int i = 0; i < inputs; ++i) {
    const auto [text, name] = mutate(base, i % kinds, random);
    const std::string path = (dir / "mutated.off").string();
    std::ofstream(path, std::ios::binary) << text;
    const std::string source = std::to_string(random() % 315);
    for (const char* method : {"heat", "dem", "dgpc", "exact"}) {
      const auto run = expmap_test::run_expmap(
          path, {"--source", source, "--vertices", "30", "--method", method}, dir.string());
      BOOST_TEST((run.outcome != expmap_test::Outcome::broken),
                 "input " << i << " (" << name << "), --method " << method << ": " << run.problem
                          << "; stderr: " << run.stderr_text);
      if (run.outcome == expmap_test::Outcome::broken) {
        // Keep the input for whoever reproduces it.
        std::ofstream(dir.string() + "_failed_input_" + std::to_string(i) + ".off") << text;
      }
      (run.outcome == expmap_test::Outcome::map ? maps : errors)[name]++;
    }
  }
  for (const auto& [name, count] : maps) BOOST_TEST_MESSAGE(name << ": " << count << " maps");
  for (const auto& [name, count] : errors) BOOST_TEST_MESSAGE(name << ": " << count << " errors");
  // The mutations that leave a valid mesh must give maps, not only errors:
  // a program that refused everything would otherwise pass.
  BOOST_TEST(maps["flipped face"] > 0);
  BOOST_TEST(maps["scaled by 1e12"] > 0);
  BOOST_TEST(maps["flipped and duplicated faces"] > 0);
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}
