// compute_many: the same maps as one compute() per source, in source order,
// on one thread or several, with failures kept to their own source.
#include <expmap/Batch.h>
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;

namespace {

using Mesh = Surface_mesh;
using Vertex = Mesh::Vertex_index;

const Mesh& elephant() {
  static const Mesh mesh = load_mesh<Mesh>("elephant.off");  // 2,775 vertices
  return mesh;
}

// Sources spread over the mesh, some repeated and out of order, so that
// "source order" is not the order a sorted or deduplicated batch would give.
std::vector<std::size_t> spread_sources(std::size_t count) {
  const std::size_t n = num_vertices(elephant());
  std::vector<std::size_t> sources;
  for (std::size_t i = 0; i < count; ++i) sources.push_back((i * 977 + 13) % n);
  sources.push_back(sources.front());
  return sources;
}

void check_same_map(const expmap::Local_map<Vertex>& batch, const expmap::Local_map<Vertex>& single) {
  BOOST_REQUIRE_EQUAL(batch.size(), single.size());
  BOOST_CHECK_EQUAL(batch.source, single.source);
  for (std::size_t i = 0; i < single.size(); ++i) {
    BOOST_REQUIRE_EQUAL(batch.indices[i], single.indices[i]);
    BOOST_CHECK_EQUAL(batch.vertices[i], single.vertices[i]);
    BOOST_CHECK_EQUAL(batch.distance[i], single.distance[i]);
    BOOST_CHECK_EQUAL(batch.angle[i], single.angle[i]);
  }
}

// compute_many (by descriptor and by index) against compute() per source.
template <class Method>
void check_equals_single_queries(const Method& method, const expmap::Patch& patch,
                                 std::size_t count) {
  const std::vector<std::size_t> sources = spread_sources(count);
  std::vector<Vertex> descriptors;
  for (std::size_t s : sources) descriptors.push_back(Vertex(static_cast<Mesh::size_type>(s)));
  std::vector<expmap::Local_map<Vertex>> single;
  for (Vertex v : descriptors) single.push_back(method.compute(v, patch));
  for (unsigned threads : {1u, 2u}) {
    BOOST_TEST_CONTEXT("threads " << threads) {
      expmap::Batch_options options;
      options.threads = threads;
      const auto by_index = method.compute_many_by_index(sources, patch, options);
      const auto by_descriptor = method.compute_many(descriptors, patch, options);
      BOOST_REQUIRE_EQUAL(by_index.maps.size(), sources.size());
      BOOST_REQUIRE_EQUAL(by_descriptor.maps.size(), sources.size());
      BOOST_CHECK_EQUAL(by_index.failures(), 0u);
      BOOST_CHECK_EQUAL(by_descriptor.failures(), 0u);
      for (std::size_t i = 0; i < sources.size(); ++i) {
        BOOST_TEST_CONTEXT("source " << sources[i] << " at position " << i) {
          BOOST_CHECK_EQUAL(by_index.errors[i], "");
          BOOST_CHECK_EQUAL(by_index.maps[i].source, descriptors[i]);
          check_same_map(by_index.maps[i], single[i]);
          check_same_map(by_descriptor.maps[i], single[i]);
        }
      }
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(compute_many)

// Heat_query_options::query_threads = 2 gives a query a second thread; a batch on
// more than one thread runs each query on one (it keeps the cores busy
// already), a batch on one thread lets its queries take the second. The
// second thread's star solve reads more factor entries (it solves the whole
// region), so the counts tell which ran; the maps are the same either way.
BOOST_AUTO_TEST_CASE(a_parallel_batch_runs_each_heat_query_on_one_thread) {
  Mesh sphere;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_icosphere(5), sphere);
  expmap::Heat_query_options two_threads;
  two_threads.query_threads = 2;
  const expmap::Heat_exponential_map<Mesh> heat(sphere);
  const expmap::Patch patch = expmap::Patch::fraction(0.3);  // a region of 6,000 vertices
  const std::vector<std::size_t> sources{17, 4000, 9000};
  for (unsigned threads : {1u, 2u}) {
    expmap::Batch_options options;
    options.threads = threads;
    const auto batch = heat.compute_many_by_index(sources, patch, options, two_threads);
    BOOST_REQUIRE_EQUAL(batch.failures(), 0u);
    for (std::size_t i = 0; i < sources.size(); ++i) {
      const auto on_one = heat.compute_by_index(sources[i], patch);
      const auto on_two = heat.compute_by_index(sources[i], patch, two_threads);
      BOOST_TEST(on_two.statistics.factor_entries > on_one.statistics.factor_entries);
      BOOST_TEST(batch.maps[i].statistics.factor_entries ==
                 (threads == 1 ? on_two : on_one).statistics.factor_entries);
      BOOST_TEST(batch.maps[i].indices == on_one.indices);
    }
  }
}

// The exact map is slow: fewer sources and smaller patches for it.
BOOST_AUTO_TEST_CASE(every_method_equals_single_queries) {
  const Mesh& mesh = elephant();
  const auto fraction = expmap::Patch::fraction(0.02);
  check_equals_single_queries(expmap::Heat_exponential_map<Mesh>(mesh), fraction, 40);
  check_equals_single_queries(expmap::Discrete_exponential_map<Mesh>(mesh), fraction, 40);
  check_equals_single_queries(expmap::Geodesic_polar_coordinates<Mesh>(mesh),
                              expmap::Patch::geodesic_radius(0.05), 40);
  check_equals_single_queries(expmap::Exact_exponential_map<Mesh>(mesh),
                              expmap::Patch::vertex_count(30), 6);
}

// An index out of range and a patch vertex out of range fail their own
// source only, with a message naming it, and the others' maps are kept.
BOOST_AUTO_TEST_CASE(invalid_sources_fail_alone) {
  const expmap::Geodesic_polar_coordinates<Mesh> dgpc(elephant());
  const std::size_t n = num_vertices(elephant());
  const std::vector<std::size_t> sources{5, n + 7, 100, n, 2000};
  for (unsigned threads : {1u, 2u}) {
    expmap::Batch_options options;
    options.threads = threads;
    const auto batch = dgpc.compute_many_by_index(sources, expmap::Patch::vertex_count(20), options);
    BOOST_REQUIRE_EQUAL(batch.errors.size(), sources.size());
    BOOST_CHECK_EQUAL(batch.failures(), 2u);
    for (std::size_t i : {1u, 3u}) {
      BOOST_CHECK(batch.maps[i].size() == 0);
      BOOST_CHECK_MESSAGE(batch.errors[i].find("source vertex " + std::to_string(sources[i])) !=
                              std::string::npos,
                          batch.errors[i]);
      BOOST_CHECK_MESSAGE(batch.errors[i].find("out of range") != std::string::npos,
                          batch.errors[i]);
    }
    for (std::size_t i : {0u, 2u, 4u}) {
      BOOST_CHECK_EQUAL(batch.errors[i], "");
      BOOST_CHECK_EQUAL(batch.maps[i].size(), 20u);
      BOOST_CHECK_EQUAL(batch.maps[i].indices.front(), sources[i]);
    }
  }

  // A bad patch fails every source, each with its own message.
  const auto all_bad = dgpc.compute_many_by_index(
      {1, 2}, expmap::Patch::vertex_set({0, n + 1}), expmap::Batch_options{});
  BOOST_CHECK_EQUAL(all_bad.failures(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    BOOST_CHECK_MESSAGE(all_bad.errors[i].rfind("source vertex " + std::to_string(i + 1) + ": ", 0) == 0,
                        all_bad.errors[i]);
    BOOST_CHECK_MESSAGE(all_bad.errors[i].find("patch vertex " + std::to_string(n + 1)) !=
                            std::string::npos,
                        all_bad.errors[i]);
  }
}

// The callback sees every map once, (1, total) to (total, total), and never
// two calls at once.
BOOST_AUTO_TEST_CASE(progress_is_called_once_per_map) {
  const expmap::Discrete_exponential_map<Mesh> dem(elephant());
  std::vector<std::size_t> sources = spread_sources(50);
  sources.push_back(num_vertices(elephant()) + 1);  // failures count as done too
  for (unsigned threads : {1u, 2u}) {
    std::vector<std::size_t> seen;
    std::atomic<int> inside{0};
    bool overlapped = false, wrong_total = false;
    expmap::Batch_options options;
    options.threads = threads;
    options.progress = [&](std::size_t done, std::size_t total) {
      if (inside.fetch_add(1) != 0) overlapped = true;
      if (total != sources.size()) wrong_total = true;
      seen.push_back(done);
      inside.fetch_sub(1);
    };
    dem.compute_many_by_index(sources, expmap::Patch::fraction(0.01), options);
    BOOST_CHECK(!overlapped);
    BOOST_CHECK(!wrong_total);
    BOOST_REQUIRE_EQUAL(seen.size(), sources.size());
    for (std::size_t i = 0; i < seen.size(); ++i) BOOST_CHECK_EQUAL(seen[i], i + 1);
  }
}

// A throwing callback cancels the batch: the exception reaches the caller.
BOOST_AUTO_TEST_CASE(throwing_progress_cancels) {
  const expmap::Discrete_exponential_map<Mesh> dem(elephant());
  const std::vector<std::size_t> sources = spread_sources(200);
  for (unsigned threads : {1u, 2u}) {
    std::size_t calls = 0;
    expmap::Batch_options options;
    options.threads = threads;
    options.progress = [&](std::size_t done, std::size_t) {
      ++calls;
      if (done == 3) throw std::runtime_error("cancelled");
    };
    BOOST_CHECK_THROW(dem.compute_many_by_index(sources, expmap::Patch::fraction(0.01), options),
                      std::runtime_error);
    BOOST_CHECK_LT(calls, sources.size());
  }
}

BOOST_AUTO_TEST_CASE(empty_batch) {
  const expmap::Discrete_exponential_map<Mesh> dem(elephant());
  const auto batch = dem.compute_many_by_index({}, expmap::Patch::fraction(0.01));
  BOOST_CHECK(batch.maps.empty());
  BOOST_CHECK(batch.errors.empty());
  BOOST_CHECK_EQUAL(batch.failures(), 0u);
}

BOOST_AUTO_TEST_SUITE_END()
