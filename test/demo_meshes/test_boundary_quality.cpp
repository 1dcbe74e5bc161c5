// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The heat method at sources on and near a mesh boundary, against DGPC and
// the exact map, with the targets of Boundary_quality_targets.h (those of
// expmap-boundary-study): heat's flipped triangles within twice DGPC's (or
// DGPC's + 2% of the patch), no source where heat flips > 30% and DGPC < 5%,
// heat's median mean |dtheta| (best rotation, no reflection) within
// max(0.05 rad, 3 x DGPC's).
//
// The meshes: lion-head.off (one boundary loop of long edges at the neck),
// head.off (three loops: the neck and two eyes), mushroom.off (open at the
// foot of its stem), cylinder_locally_refined.off (an open tube, two loops,
// a mesh refined in one band), blade.off (a thin plate: two sheets meeting
// at a rim), holes.off (a sheet with round holes), and the CAD parts
// ALSTOM_TEST4.off (a strip where the heat is not positive at some sources)
// and boeing.off (holes shorter than the heat's reach; no vertex is two
// rings from its boundary). The paper's map misses the targets on all but
// lion-head in expmap-boundary-study (doc/results.md, section 4); the
// geodesic front's fallback is what meets them. The sources, per mesh,
// from Boundary_sources.h: 4 boundary vertices spread along the loops, the
// nearest vertex one and two rings in from each, and as a control the
// nearest vertex 6 rings in (an interior source whose 5% patch may still
// reach the boundary). Patches are 5% of the mesh, as in
// the study; the exact maps take a few seconds in all.

#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/read_triangle_mesh.h>
#include <expmap/Patch.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>

#include "Boundary_quality_targets.h"
#include "Boundary_sources.h"
#include "Map_agreement.h"
#include "test_support.h"

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace {

namespace ev = expmap_evaluation;
using Mesh = expmap_test::Surface_mesh;
using Map = expmap::Local_map<Mesh::Vertex_index>;

const std::vector<std::string> boundary_meshes = {
    "lion-head.off", "head.off",         "mushroom.off", "cylinder_locally_refined.off",
    "blade.off",     "holes.off",        "ALSTOM_TEST4.off", "boeing.off"};
constexpr std::size_t boundary_sources_per_mesh = 4;
constexpr int interior_ring = 6;
constexpr double patch_fraction = 0.05;

/// Where a source lies: which targets it is checked against.
enum class Source_kind { boundary, one_ring_in, two_rings_in, interior };

std::string to_string(Source_kind kind) {
  switch (kind) {
    case Source_kind::boundary: return "boundary";
    case Source_kind::one_ring_in: return "one ring in";
    case Source_kind::two_rings_in: return "two rings in";
    case Source_kind::interior: return "interior";
  }
  return "";
}

/// The measured maps of one source.
struct Source_maps {
  std::size_t vertex = 0;
  Source_kind kind = Source_kind::boundary;
  ev::Heat_and_dgpc agreement;  // against the exact map
};

struct Mesh_maps {
  std::string name;
  std::vector<Source_maps> sources;
};

/// The test's sources of `mesh` (see the file comment).
std::vector<std::pair<std::size_t, Source_kind>> test_sources(const Mesh& mesh) {
  const ev::Vertex_graph graph = ev::vertex_graph(mesh);
  const std::vector<int> hops = ev::hops_from_boundary(graph);
  std::vector<std::pair<std::size_t, Source_kind>> sources;
  for (std::size_t b : ev::spread_along_boundary(graph, boundary_sources_per_mesh)) {
    sources.push_back({b, Source_kind::boundary});
    if (const auto v = ev::nearest_at_ring(graph, hops, b, 1))
      sources.push_back({*v, Source_kind::one_ring_in});
    if (const auto v = ev::nearest_at_ring(graph, hops, b, 2))
      sources.push_back({*v, Source_kind::two_rings_in});
    if (const auto v = ev::nearest_at_ring(graph, hops, b, interior_ring))
      sources.push_back({*v, Source_kind::interior});
  }
  return sources;
}

/// Heat's, DGPC's and the exact maps of the test's sources, computed once
/// for all the test cases of this file.
const std::vector<Mesh_maps>& measured_meshes() {
  static const std::vector<Mesh_maps> measured = [] {
    std::vector<Mesh_maps> all;
    const expmap::Patch patch = expmap::Patch::fraction(patch_fraction);
    for (const std::string& name : boundary_meshes) {
      Mesh mesh;
      expmap::IO::read_triangle_mesh(expmap_test::data_mesh(name), mesh);
      const expmap::Heat_exponential_map<Mesh> heat(mesh);
      const expmap::Geodesic_polar_coordinates<Mesh> dgpc(mesh);
      const expmap::Exact_exponential_map<Mesh> exact(mesh);
      Mesh_maps maps{name, {}};
      for (const auto& [vertex, kind] : test_sources(mesh)) {
        const Map reference = exact.compute_by_index(vertex, patch);
        Source_maps s;
        s.vertex = vertex;
        s.kind = kind;
        s.agreement.heat = ev::map_agreement(mesh, heat.compute_by_index(vertex, patch), reference);
        s.agreement.dgpc = ev::map_agreement(mesh, dgpc.compute_by_index(vertex, patch), reference);
        maps.sources.push_back(s);
      }
      all.push_back(std::move(maps));
    }
    return all;
  }();
  return measured;
}

std::string describe(const ev::Map_agreement& a) {
  return std::to_string(a.flipped) + " of " + std::to_string(a.triangles) +
         " triangles flipped, mean |dtheta| " + std::to_string(a.angle_error) + " rad";
}

}  // namespace

// The instrument first: a map that is the exact one turned by a constant
// has no angle error, the exact map mirrored has a large one. Otherwise the
// targets below could pass a mirrored heat map.
BOOST_AUTO_TEST_CASE(best_rotation_angle_error_forgives_rotations_not_reflections) {
  Mesh mesh;
  expmap::IO::read_triangle_mesh(expmap_test::data_mesh("lion-head.off"), mesh);
  const expmap::Exact_exponential_map<Mesh> exact(mesh);
  const std::size_t source = ev::spread_along_boundary(ev::vertex_graph(mesh), 1).front();
  const Map reference = exact.compute_by_index(source, expmap::Patch::fraction(0.02));
  Map rotated = reference, mirrored = reference;
  for (double& a : rotated.angle) a = expmap_test::wrap_angle(a + 2.0);
  for (double& a : mirrored.angle) a = -a;
  const auto itself = ev::map_agreement(mesh, reference);
  const auto turned = ev::map_agreement(mesh, rotated, reference);
  const auto flipped = ev::map_agreement(mesh, mirrored, reference);
  BOOST_TEST(turned.angle_error < 1e-12);
  BOOST_TEST(std::abs(expmap_test::wrap_angle(turned.rotation - 2.0)) < 1e-12);
  BOOST_TEST(turned.flipped == itself.flipped);
  // A source on the boundary sees a half disk of directions; mirrored, the
  // differences c - 2 theta go round the circle and no rotation undoes them.
  BOOST_TEST(flipped.angle_error > 0.5);
  // Mirroring negates every signed area: what the exact map keeps turns over.
  BOOST_TEST(itself.triangles > 0u);
  BOOST_TEST(flipped.flipped >= itself.triangles - itself.flipped);
}

// The reference checked against an independent method: DGPC handles
// boundaries, so it must agree with the exact map at these very sources.
// If this fails, the exact map or the source choice is wrong, not heat.
// (On the other meshes DGPC folds where the exact map does too: behind
// holes, around a plate's rim.)
const std::vector<std::string> smooth_boundary_meshes = {"lion-head.off", "head.off",
                                                         "mushroom.off",
                                                         "cylinder_locally_refined.off"};

BOOST_AUTO_TEST_CASE(dgpc_agrees_with_the_exact_map_at_boundary_sources) {
  for (const Mesh_maps& mesh : measured_meshes()) {
    BOOST_TEST(mesh.sources.size() >= boundary_sources_per_mesh, mesh.name);
    if (std::find(smooth_boundary_meshes.begin(), smooth_boundary_meshes.end(), mesh.name) ==
        smooth_boundary_meshes.end())
      continue;
    for (const Source_maps& s : mesh.sources) {
      BOOST_TEST_CONTEXT(mesh.name << ", " << to_string(s.kind) << " source " << s.vertex
                                   << ", dgpc: " << describe(s.agreement.dgpc)) {
        BOOST_TEST(s.agreement.dgpc.triangles > 0u);
        BOOST_TEST(s.agreement.dgpc.flipped_fraction() < 0.05);
        BOOST_TEST(s.agreement.dgpc.angle_error < 0.05);
      }
    }
  }
}

// Every kind of source meets the flip, mirror and angle targets on every
// mesh. The paper's map alone misses them on the boundary of seven of these
// meshes (blade: 548 triangles flipped against DGPC's 91, holes: median
// 0.11 rad against 0.011; doc/results.md, section 4) and fails on some
// sources of ALSTOM_TEST4 and boeing; the geodesic front's fallback
// (Heat_fallback) is what meets them.
BOOST_AUTO_TEST_CASE(heat_meets_the_boundary_targets_against_dgpc_and_the_exact_map) {
  for (const Mesh_maps& mesh : measured_meshes()) {
    for (Source_kind kind : {Source_kind::boundary, Source_kind::one_ring_in,
                             Source_kind::two_rings_in, Source_kind::interior}) {
      std::vector<ev::Heat_and_dgpc> sources;
      for (const Source_maps& s : mesh.sources) {
        if (s.kind != kind) continue;
        sources.push_back(s.agreement);
        BOOST_TEST_CONTEXT(mesh.name << ", " << to_string(kind) << " source " << s.vertex
                                     << ", heat: " << describe(s.agreement.heat)
                                     << "; dgpc: " << describe(s.agreement.dgpc)) {
          BOOST_TEST(!ev::collapsed(s.agreement), "heat > 30% flipped where DGPC < 5%");
        }
      }
      if (sources.empty()) continue;  // no vertex that many rings in
      const ev::Boundary_quality q = ev::boundary_quality(sources);
      BOOST_TEST_CONTEXT(mesh.name << ", " << q.sources << " " << to_string(kind) << " sources") {
        BOOST_TEST(q.heat_flipped <= q.flip_limit,
                   "heat flips " << q.heat_flipped << " triangles, DGPC " << q.dgpc_flipped
                                 << ", limit " << q.flip_limit);
        BOOST_TEST(q.heat_angle_error <= q.angle_limit,
                   "heat's median mean |dtheta| " << q.heat_angle_error << " rad, DGPC's "
                                                  << q.dgpc_angle_error << ", limit "
                                                  << q.angle_limit);
      }
    }
  }
}
