// Maps solved on subdomains (geodesic balls with their own factors) against
// the same queries on the whole mesh's factors: over seeded random sources
// of a closed mesh and of a scan with holes, vertex and surface-point
// sources, count and radius patches, the distances and angles must agree to
// well below the heat's own error (issue targets: mean |dr| <= 2e-3 R,
// mean |dtheta| <= 2e-3 rad).
#include <expmap/Heat_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "test_support.h"

using namespace expmap_test;

namespace {

using Heat = expmap::Heat_exponential_map<Surface_mesh>;

expmap::Heat_options on_subdomains() {
  expmap::Heat_options options;
  options.subdomain_min_vertices = 0;
  return options;
}

struct Agreement {
  double mean_radial = 0;   // mean |dr| / R over the vertices both maps hold
  double mean_angular = 0;  // mean |dtheta| (rad) beyond a tenth of R
  double shared = 0;        // share of the whole-mesh map's vertices the other holds
};

template <class Map>
Agreement agreement(const Map& whole, const Map& sub) {
  std::unordered_map<std::size_t, std::size_t> at;
  for (std::size_t i = 0; i < sub.size(); ++i) at[sub.indices[i]] = i;
  const double radius = whole.distance.back();
  Agreement a;
  std::size_t shared = 0, angular = 0;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const auto it = at.find(whole.indices[i]);
    if (it == at.end()) continue;
    ++shared;
    a.mean_radial += std::abs(whole.distance[i] - sub.distance[it->second]) / radius;
    if (whole.distance[i] > 0.1 * radius) {
      a.mean_angular += std::abs(wrap_angle(whole.angle[i] - sub.angle[it->second]));
      ++angular;
    }
  }
  a.mean_radial /= static_cast<double>(std::max<std::size_t>(1, shared));
  a.mean_angular /= static_cast<double>(std::max<std::size_t>(1, angular));
  a.shared = static_cast<double>(shared) / static_cast<double>(whole.size());
  return a;
}

void check_mesh_agrees(const std::string& name) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>(name);
  const Heat whole(mesh);
  const Heat sub(mesh, on_subdomains());
  BOOST_TEST(!whole.uses_subdomains());
  BOOST_TEST(sub.uses_subdomains());
  BOOST_TEST(sub.time_step() == whole.time_step());

  std::mt19937 random(46);
  std::uniform_int_distribution<std::size_t> vertex(0, num_vertices(mesh) - 1);
  std::uniform_int_distribution<std::size_t> face(0, num_faces(mesh) - 1);
  std::vector<double> radial, angular, shared;
  const double h = whole.mean_edge_length();
  // Small patches: on these meshes of 26k-37k vertices the balls of larger
  // ones would hold more than a quarter of the mesh (answered on the whole).
  const expmap::Patch patches[] = {expmap::Patch::vertex_count(100),
                                   expmap::Patch::vertex_count(300),
                                   expmap::Patch::geodesic_radius(6 * h)};
  for (int k = 0; k < 12; ++k) {
    const std::size_t s = vertex(random);
    for (const expmap::Patch& patch : patches) {
      const Agreement a = agreement(whole.compute_by_index(s, patch), sub.compute_by_index(s, patch));
      radial.push_back(a.mean_radial);
      angular.push_back(a.mean_angular);
      shared.push_back(a.shared);
    }
    // A point inside a face.
    const expmap::Surface_point<Surface_mesh::Face_index> point{
        Surface_mesh::Face_index(static_cast<Surface_mesh::size_type>(face(random))),
        {{0.2, 0.3, 0.5}}};
    const expmap::Patch patch = expmap::Patch::vertex_count(200);
    const Agreement a = agreement(whole.compute(point, patch), sub.compute(point, patch));
    radial.push_back(a.mean_radial);
    angular.push_back(a.mean_angular);
    shared.push_back(a.shared);
  }
  BOOST_TEST_MESSAGE(name << ": mean |dr|/R " << mean(radial) << ", mean |dtheta| "
                          << mean(angular) << ", shared " << mean(shared) << ", "
                          << sub.subdomain_bytes() << " bytes of subdomains");
  BOOST_TEST(sub.subdomain_bytes() > 0u);
  BOOST_TEST(mean(radial) <= 2e-3);
  BOOST_TEST(mean(angular) <= 2e-3);
  BOOST_TEST(mean(shared) >= 0.99);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(subdomains)

BOOST_AUTO_TEST_CASE(maps_on_a_closed_mesh_agree_with_the_whole_mesh) {
  check_mesh_agrees("armadillo.off");
}

BOOST_AUTO_TEST_CASE(maps_on_a_scan_with_holes_agree_with_the_whole_mesh) {
  check_mesh_agrees("bunny00.off");
}

// Vertex-set patches and balls larger than a quarter of the mesh are
// answered on the whole mesh's factors, built on first use.
BOOST_AUTO_TEST_CASE(large_and_vertex_set_patches_use_the_whole_mesh) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  const Heat whole(mesh);
  const Heat sub(mesh, on_subdomains());
  BOOST_TEST(sub.factor_bytes() == 0u);
  const auto a = whole.compute_by_index(17, expmap::Patch::fraction(0.5));
  const auto b = sub.compute_by_index(17, expmap::Patch::fraction(0.5));
  // The same maps up to rounding: the whole mesh is stored in another
  // vertex order where queries use subdomains.
  BOOST_TEST(a.indices == b.indices);
  const Agreement same = agreement(a, b);
  BOOST_TEST(same.mean_radial <= 1e-9);
  BOOST_TEST(same.mean_angular <= 1e-9);
  const auto c = sub.compute_by_index(17, expmap::Patch::vertex_set({1, 2, 3, 4000}));
  BOOST_TEST(c.size() == 5u);
}

// Which subdomain answers a query depends on its source and patch alone:
// the same map bit for bit after other queries or none, as on any number
// of threads.
BOOST_AUTO_TEST_CASE(a_map_does_not_depend_on_the_queries_before_it) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  const Heat fresh(mesh, on_subdomains());
  const Heat used(mesh, on_subdomains());
  const expmap::Patch patch = expmap::Patch::vertex_count(150);
  for (std::size_t s : {100u, 101u, 102u, 7000u, 7001u}) used.compute_by_index(s, patch);
  for (std::size_t s : {103u, 7002u}) {
    const auto a = fresh.compute_by_index(s, patch);
    const auto b = used.compute_by_index(s, patch);
    BOOST_TEST(a.indices == b.indices);
    BOOST_TEST(a.distance == b.distance);
    BOOST_TEST(a.angle == b.angle);
  }
}

// A batch answers neighbouring sources one after another, and two threads
// that need the same ball share one build: a batch of the sources of one
// region, given in a shuffled order, on two threads, keeps the same balls
// as answering them one by one in order, and gives the same maps; two
// threads asking for the same balls at once keep one copy of each.
BOOST_AUTO_TEST_CASE(a_batch_factors_each_ball_once) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  const Heat whole(mesh);
  std::vector<std::size_t> sources = whole.compute_by_index(100, expmap::Patch::vertex_count(400)).indices;
  std::shuffle(sources.begin(), sources.end(), std::mt19937(48));
  const expmap::Patch patch = expmap::Patch::vertex_count(120);

  const Heat one_by_one(mesh, on_subdomains());
  std::vector<std::size_t> in_order = sources;
  std::sort(in_order.begin(), in_order.end());
  for (std::size_t s : in_order) one_by_one.compute_by_index(s, patch);
  const Heat batched(mesh, on_subdomains());
  expmap::Batch_options two;
  two.threads = 2;
  const auto batch = batched.compute_many_by_index(sources, patch, two);
  BOOST_TEST_MESSAGE("one by one: " << one_by_one.subdomain_bytes() << " bytes, batch: "
                                    << batched.subdomain_bytes());
  // Equal up to the Poisson factor's compression, which round-off can move
  // by a few entries; one ball more would be several percent.
  const double ratio = static_cast<double>(batched.subdomain_bytes()) /
                       static_cast<double>(one_by_one.subdomain_bytes());
  BOOST_TEST(std::abs(ratio - 1) <= 0.01);
  BOOST_REQUIRE(batch.failures() == 0u);

  // Two threads asking for the same balls at the same time.
  const Heat shared(mesh, on_subdomains());
  const std::vector<std::size_t> far_apart = {0, 5000, 10000, 15000, 20000, 25000};
  const auto ask = [&] {
    for (std::size_t s : far_apart) shared.compute_by_index(s, patch);
  };
  std::thread other(ask);
  ask();
  other.join();
  const Heat alone(mesh, on_subdomains());
  for (std::size_t s : far_apart) alone.compute_by_index(s, patch);
  BOOST_TEST(std::abs(static_cast<double>(shared.subdomain_bytes()) /
                          static_cast<double>(alone.subdomain_bytes()) -
                      1) <= 0.01);

  for (std::size_t i = 0; i < sources.size(); i += 37) {
    const auto expected = one_by_one.compute_by_index(sources[i], patch);
    BOOST_TEST(batch.maps[i].indices == expected.indices);
    // Up to the round-off of factorizations run on other threads.
    const Agreement same = agreement(expected, batch.maps[i]);
    BOOST_TEST(same.mean_radial <= 1e-12);
    BOOST_TEST(same.mean_angular <= 1e-12);
  }
}

// The cache keeps its bound: with room for one subdomain, queries far
// apart leave only the latest.
BOOST_AUTO_TEST_CASE(the_cache_keeps_its_bound) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  expmap::Heat_options options = on_subdomains();
  options.subdomain_cache_bytes = 1;
  const Heat sub(mesh, options);
  std::size_t largest = 0;
  for (std::size_t s : {0u, 5000u, 10000u, 15000u, 20000u, 25000u}) {
    sub.compute_by_index(s, expmap::Patch::vertex_count(100));
    largest = std::max(largest, sub.subdomain_bytes());
  }
  expmap::Heat_options unbounded = on_subdomains();
  const Heat kept(mesh, unbounded);
  for (std::size_t s : {0u, 5000u, 10000u, 15000u, 20000u, 25000u})
    kept.compute_by_index(s, expmap::Patch::vertex_count(100));
  BOOST_TEST(largest > 0u);
  BOOST_TEST(kept.subdomain_bytes() > 2 * largest);
}

BOOST_AUTO_TEST_SUITE_END()
