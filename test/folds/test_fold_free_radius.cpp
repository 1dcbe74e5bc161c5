// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fold-free radius of a local map and the map cut to it: on a hand-built
// map with one deliberately flipped triangle (exact values), and on demo-mesh
// patches that fold, for every method, against a recomputation over all
// faces of the mesh.

#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Fold_free_radius.h>
#include <expmap/Fold_overs.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace expmap_test;

namespace {

using Vertex = Surface_mesh::Vertex_index;
using Map = expmap::Local_map<Vertex>;

/// A flat square fan around vertex 0 (ring 1-4 at distance 1) with two
/// outer triangles, (1, 5, 2) and (2, 6, 3), all counter-clockwise in z.
Surface_mesh fan_with_two_outer_triangles() {
  Surface_mesh mesh;
  const double xy[7][2] = {{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1.5, 1.5}, {-1.5, 1.5}};
  std::vector<Vertex> v;
  for (const auto& p : xy) v.push_back(mesh.add_vertex(Point(p[0], p[1], 0)));
  const int faces[6][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {1, 5, 2}, {2, 6, 3}};
  for (const auto& f : faces) mesh.add_face(v[f[0]], v[f[1]], v[f[2]]);
  return mesh;
}

/// A map of that fan by hand: vertices 0-6 nearest first, vertex 5 at
/// distance 2 and angle `angle5`, vertex 6 at 2.5 where it belongs.
Map hand_built_map(double angle5) {
  Map map;
  map.source = Vertex(0);
  const double pi = std::acos(-1.0);
  const double r[7] = {0, 1, 1, 1, 1, 2, 2.5};
  const double theta[7] = {0, 0, pi / 2, pi, -pi / 2, angle5, 3 * pi / 4};
  for (std::size_t i = 0; i < 7; ++i) {
    map.vertices.push_back(Vertex(static_cast<Surface_mesh::size_type>(i)));
    map.indices.push_back(i);
    map.distance.push_back(r[i]);
    map.angle.push_back(theta[i]);
  }
  return map;
}

/// The fold-free radius the slow way: every face of the mesh, its corners
/// looked up in an ordered map, the smallest farthest corner of a flipped one.
double fold_free_radius_over_all_faces(const Surface_mesh& mesh, const Map& map) {
  std::map<Vertex, std::size_t> position;
  for (std::size_t i = 0; i < map.size(); ++i) position[map.vertices[i]] = i;
  double radius = *std::max_element(map.distance.begin(), map.distance.end());
  for (auto f : mesh.faces()) {
    expmap::Patch_triangle<Surface_mesh::Face_index> t{f, {}};
    int k = 0;
    bool inside = true;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const auto it = position.find(v);
      if (it == position.end()) inside = false;
      else t.corner[k++] = it->second;
    }
    if (!inside || !expmap::is_flipped(map, t)) continue;
    double farthest = 0;
    for (std::size_t c : t.corner) farthest = std::max(farthest, map.distance[c]);
    radius = std::min(radius, farthest);
  }
  return radius;
}

}  // namespace

BOOST_AUTO_TEST_CASE(hand_built_map_with_one_flipped_triangle) {
  const Surface_mesh mesh = fan_with_two_outer_triangles();
  const double pi = std::acos(-1.0);
  const Map map = hand_built_map(-pi / 4);  // vertex 5 below the x axis: (1, 5, 2) turns over
  const auto folds = expmap::count_flipped_triangles(mesh, map);
  BOOST_TEST(folds.total == 6u);
  BOOST_TEST(folds.flipped == 1u);
  // The flipped triangle's farthest corner is vertex 5, at 2 (not the map's
  // largest distance, 2.5).
  BOOST_TEST(expmap::fold_free_radius(mesh, map) == 2.0);

  const Map trimmed = expmap::trim_to_fold_free_disk(mesh, map);
  BOOST_TEST(trimmed.size() == 5u);  // the source and the ring at distance 1
  for (std::size_t i = 0; i < trimmed.size(); ++i) {
    BOOST_TEST(trimmed.vertices[i] == map.vertices[i]);
    BOOST_TEST(trimmed.indices[i] == map.indices[i]);
    BOOST_TEST(trimmed.distance[i] == map.distance[i]);
    BOOST_TEST(trimmed.angle[i] == map.angle[i]);
  }
  BOOST_TEST(trimmed.fold_free_radius.value() == 1.0);  // its own: no fold left
  BOOST_TEST(expmap::count_flipped_triangles(mesh, trimmed).flipped == 0u);
  BOOST_TEST(expmap::count_flipped_triangles(mesh, trimmed).total == 4u);
}

BOOST_AUTO_TEST_CASE(hand_built_map_without_a_fold_stays_whole) {
  const Surface_mesh mesh = fan_with_two_outer_triangles();
  const Map map = hand_built_map(std::acos(-1.0) / 4);  // vertex 5 where it belongs
  BOOST_TEST(expmap::count_flipped_triangles(mesh, map).flipped == 0u);
  BOOST_TEST(expmap::fold_free_radius(mesh, map) == 2.5);  // the largest distance
  const Map trimmed = expmap::trim_to_fold_free_disk(mesh, map);
  BOOST_TEST(trimmed.size() == map.size());
  BOOST_TEST(trimmed.fold_free_radius.value() == 2.5);
}

BOOST_AUTO_TEST_CASE(hand_built_map_folding_at_the_source_keeps_the_source_alone) {
  const Surface_mesh mesh = fan_with_two_outer_triangles();
  Map map = hand_built_map(std::acos(-1.0) / 4);
  // A collapsed distance field: vertices 1 and 2 at the source, so the
  // triangle (0, 1, 2) has zero area and all its corners at distance 0.
  map.distance[1] = map.distance[2] = 0;
  BOOST_TEST(expmap::fold_free_radius(mesh, map) == 0.0);
  const Map trimmed = expmap::trim_to_fold_free_disk(mesh, map);
  BOOST_TEST(trimmed.size() == 1u);
  BOOST_TEST(trimmed.vertices[0] == map.source);
  BOOST_TEST(trimmed.fold_free_radius.value() == 0.0);
}

namespace {

/// A source and its 5% patch that every method folds.
struct Folding_patch {
  const char* mesh;
  std::size_t source;
};
const Folding_patch folding_patches[] = {{"camel.off", 79}, {"armadillo.off", 4530}};

template <class Method>
void check_fold_free_disk(const std::string& name) {
  for (const Folding_patch& p : folding_patches) {
    BOOST_TEST_CONTEXT(name << " on " << p.mesh << ", source " << p.source) {
      const Surface_mesh mesh = load_mesh<Surface_mesh>(p.mesh);
      const Method method(mesh);
      const expmap::Patch patch = expmap::Patch::fraction(0.05);
      // Found only when asked: the pass costs about a tenth of a query.
      BOOST_TEST(!method.compute_by_index(p.source, patch).fold_free_radius.has_value());
      expmap::Query_options find;
      find.find_fold_free_radius = true;
      const Map map = method.compute_by_index(p.source, patch, find);
      BOOST_TEST_REQUIRE(map.fold_free_radius.has_value());
      const double radius = *map.fold_free_radius;
      const double largest = *std::max_element(map.distance.begin(), map.distance.end());
      BOOST_TEST(expmap::count_flipped_triangles(mesh, map).flipped > 0u);
      BOOST_TEST(radius == fold_free_radius_over_all_faces(mesh, map));
      BOOST_TEST(radius == expmap::fold_free_radius(mesh, map));
      BOOST_TEST(radius > 0.0);
      BOOST_TEST(radius <= largest);
      BOOST_TEST_MESSAGE(name << " on " << p.mesh << ", source " << p.source
                              << ": fold-free radius " << radius << " of " << largest);

      expmap::Query_options trim;
      trim.trim_folds = true;
      const Map trimmed = method.compute_by_index(p.source, patch, trim);
      BOOST_TEST(expmap::count_flipped_triangles(mesh, trimmed).flipped == 0u);
      // Exactly the vertices strictly inside the disk, the source first, as
      // in the whole map.
      std::size_t inside = 0;
      for (double r : map.distance) inside += r < radius ? 1 : 0;
      BOOST_TEST(trimmed.size() == inside);
      BOOST_TEST(trimmed.vertices[0] == map.source);
      bool same = trimmed.size() <= map.size();
      for (std::size_t i = 0; same && i < trimmed.size(); ++i)
        same = trimmed.vertices[i] == map.vertices[i] && trimmed.indices[i] == map.indices[i] &&
               trimmed.distance[i] == map.distance[i] && trimmed.angle[i] == map.angle[i] &&
               trimmed.distance[i] < radius;
      BOOST_TEST(same);
      BOOST_TEST(trimmed.fold_free_radius.value() ==
                 *std::max_element(trimmed.distance.begin(), trimmed.distance.end()));
      BOOST_TEST(trimmed.fold_free_radius.value() == expmap::fold_free_radius(mesh, trimmed));

      // The free function cuts the same map.
      const Map cut = expmap::trim_to_fold_free_disk(mesh, map);
      BOOST_TEST(cut.indices == trimmed.indices, boost::test_tools::per_element());
      BOOST_TEST(cut.fold_free_radius.value() == trimmed.fold_free_radius.value());

      // compute_many passes the option to every query.
      const auto batch = method.compute_many_by_index({p.source}, patch, {1, {}}, trim);
      BOOST_TEST(batch.maps[0].indices == trimmed.indices, boost::test_tools::per_element());
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(heat_fold_free_disk) {
  check_fold_free_disk<expmap::Heat_exponential_map<Surface_mesh>>("heat");
}
BOOST_AUTO_TEST_CASE(dem_fold_free_disk) {
  check_fold_free_disk<expmap::Discrete_exponential_map<Surface_mesh>>("DEM");
}
BOOST_AUTO_TEST_CASE(dgpc_fold_free_disk) {
  check_fold_free_disk<expmap::Geodesic_polar_coordinates<Surface_mesh>>("DGPC");
}
BOOST_AUTO_TEST_CASE(exact_fold_free_disk) {
  check_fold_free_disk<expmap::Exact_exponential_map<Surface_mesh>>("exact");
}
