// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every mesh of Debian's libcgal-demo (scripts/fetch-cgal-meshes.sh puts
// them in data/meshes), read as the `expmap` program reads it, through every
// method from three sources: a map whose numbers are all finite, or an
// expmap exception with a message. Small patches keep the exact method fast.

#include <expmap/Discrete_exponential_map.h>
#include <expmap/Errors.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace expmap_test;

namespace {

namespace fs = std::filesystem;

struct Tally {
  std::size_t maps = 0, errors = 0;
};

/// Runs `query` for each source; a map must be finite, a failure an expmap
/// exception with a message. Anything else fails the test.
template <class Method>
void check_sources(const std::string& context, const Method& method,
                   const std::vector<std::size_t>& sources, Tally& tally) {
  for (std::size_t s : sources) {
    BOOST_TEST_CONTEXT(context << ", source " << s) {
      try {
        const auto map = method.compute_by_index(s, expmap::Patch::vertex_count(30));
        BOOST_TEST(map.size() > 0u);
        bool finite = true;
        for (std::size_t i = 0; i < map.size(); ++i)
          finite = finite && std::isfinite(map.distance[i]) && std::isfinite(map.angle[i]);
        BOOST_TEST(finite);
        ++tally.maps;
      } catch (const expmap::Invalid_input& e) {
        BOOST_TEST_MESSAGE(context << ", source " << s << ": " << e.what());
        BOOST_TEST(std::string(e.what()).size() > 0u);
        ++tally.errors;
      } catch (const expmap::Computation_error& e) {
        BOOST_TEST_MESSAGE(context << ", source " << s << ": " << e.what());
        BOOST_TEST(std::string(e.what()).size() > 0u);
        ++tally.errors;
      }
    }
  }
}

/// Builds a method (its own validation may refuse the mesh) and queries it.
template <class Method>
void check_method(const std::string& context, const Surface_mesh& mesh,
                  const std::vector<std::size_t>& sources, Tally& tally) {
  try {
    const Method method(mesh);
    check_sources(context, method, sources, tally);
  } catch (const expmap::Invalid_input& e) {
    BOOST_TEST_MESSAGE(context << ": " << e.what());
    BOOST_TEST(std::string(e.what()).size() > 0u, context);
    tally.errors += sources.size();
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_demo_mesh_gives_a_map_or_a_clear_error_with_every_method) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(EXPMAP_TEST_DATA_DIR))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  // libcgal-demo brings 143 meshes; fewer means the fetch went wrong.
  BOOST_TEST_REQUIRE(files.size() >= 143u, "run scripts/fetch-cgal-meshes.sh");

  std::map<std::string, Tally> tallies;
  std::size_t unreadable = 0;
  for (const fs::path& file : files) {
    Surface_mesh mesh;
    try {
      expmap::IO::read_triangle_mesh(file.string(), mesh);
    } catch (const expmap::Invalid_input& e) {
      BOOST_TEST_MESSAGE(file.filename().string() << ": " << e.what());
      ++unreadable;
      continue;
    }
    const std::size_t n = num_vertices(mesh);
    const std::vector<std::size_t> sources = {0, n / 2, n - 1};
    const std::string name = file.filename().string();
    check_method<expmap::Heat_exponential_map<Surface_mesh>>(name + " heat", mesh, sources,
                                                             tallies["heat"]);
    check_method<expmap::Discrete_exponential_map<Surface_mesh>>(name + " dem", mesh, sources,
                                                                 tallies["dem"]);
    check_method<expmap::Geodesic_polar_coordinates<Surface_mesh>>(name + " dgpc", mesh, sources,
                                                                   tallies["dgpc"]);
    check_method<expmap::Exact_exponential_map<Surface_mesh>>(name + " exact", mesh, sources,
                                                              tallies["exact"]);
  }
  BOOST_TEST_MESSAGE(unreadable << " of " << files.size() << " files unreadable");
  for (const auto& [method, t] : tallies)
    BOOST_TEST_MESSAGE(method << ": " << t.maps << " maps, " << t.errors << " errors");
  // Most of the demo meshes are clean triangle meshes: a method that
  // refused them all would pass the loop above.
  for (const auto& [method, t] : tallies) BOOST_TEST(t.maps > 2 * t.errors, method);
}
