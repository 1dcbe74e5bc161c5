// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Breadth-first candidate search: a search continued from where it reached
// a smaller budget must find the vertices of a fresh search with the larger
// budget, in the same order, and that order must be by edge hops (checked
// against a plain std::queue search); rings grown around some of a region's
// edge vertices must be those of a multi-source search.

#include <expmap/internal/Indexed_mesh.h>
#include <expmap/internal/Region_growing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <queue>
#include <vector>

#include "Analytic_surfaces.h"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;

std::vector<int> hops_from(const expmap::internal::Mesh_arrays& m, int source) {
  std::vector<int> hops(m.point.size(), -1);
  std::queue<int> queue;
  hops[source] = 0;
  queue.push(source);
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p)
      if (hops[m.neighbor[p]] < 0) {
        hops[m.neighbor[p]] = hops[v] + 1;
        queue.push(m.neighbor[p]);
      }
  }
  return hops;
}

// An icosphere of 2,562 vertices, its arrays and a set of marks for them.
struct Icosphere {
  Surface_mesh mesh = [] {
    Surface_mesh sphere;
    expmap_analytic::soup_to_mesh(expmap_analytic::make_icosphere(4, 1.0), sphere);
    return sphere;
  }();
  const expmap::internal::Indexed_mesh<Surface_mesh, CGAL::Default> indexed{
      mesh, get(CGAL::vertex_point, mesh)};
  const expmap::internal::Mesh_arrays& m = indexed.arrays;
  expmap::internal::Vertex_marks marks;
  Icosphere() { marks.resize(m.point.size()); }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(region_growing)

BOOST_FIXTURE_TEST_CASE(a_continued_breadth_first_search_equals_a_fresh_one, Icosphere) {
  expmap::internal::Vertex_marks fresh_marks;
  fresh_marks.resize(m.point.size());
  for (int source : {0, 17, 1500}) {
    const std::vector<int> hops = hops_from(m, source);
    for (std::size_t first_budget : {20u, 97u, 400u}) {
      std::vector<int> continued;
      std::size_t head =
          expmap::internal::grow_region_by_hops(m, source, marks, first_budget, continued);
      BOOST_TEST(continued.size() == first_budget);
      for (std::size_t budget : {first_budget + 1, 2 * first_budget + 5, 3 * first_budget}) {
        head = expmap::internal::continue_region_by_hops(m, marks, budget, continued, head);
        std::vector<int> fresh;
        expmap::internal::grow_region_by_hops(m, source, fresh_marks, budget, fresh);
        BOOST_TEST(continued == fresh);
        for (std::size_t i = 0; i < continued.size(); ++i) {
          BOOST_TEST(marks.is_marked(continued[i]));
          BOOST_TEST(marks.value(continued[i]) == static_cast<int>(i));
          if (i > 0) BOOST_TEST(hops[continued[i - 1]] <= hops[continued[i]]);
        }
      }
    }
  }
}

// Rings grown around some vertices of a region's edge: every vertex outside
// the region within k hops of those seeds through vertices outside the
// region (checked against a plain std::queue search), each appended once and
// marked with its position.
BOOST_FIXTURE_TEST_CASE(rings_around_seeds_equal_a_multi_source_search, Icosphere) {
  std::vector<int> frontier, next;
  for (int source : {0, 17, 1500})
    for (int rings : {1, 2, 5}) {
      std::vector<int> region;
      expmap::internal::grow_region_by_hops(m, source, marks, 300, region);
      const std::vector<int> inside = region;
      std::vector<char> in_region(m.point.size(), 0);
      for (int v : inside) in_region[v] = 1;
      // Seeds: every third vertex of the region's edge (one side grows more).
      std::vector<int> seeds;
      int edge_count = 0;
      for (int v : inside)
        for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p)
          if (!in_region[m.neighbor[p]]) {
            if (edge_count++ % 3 == 0) seeds.push_back(v);
            break;
          }
      expmap::internal::grow_rings_around(m, marks, seeds, rings, region, frontier, next);
      // Reference: hops from the seeds through vertices outside the region.
      std::vector<int> hops(m.point.size(), -1);
      std::queue<int> queue;
      for (int v : seeds) {
        hops[v] = 0;
        queue.push(v);
      }
      while (!queue.empty()) {
        const int v = queue.front();
        queue.pop();
        if (hops[v] == rings) continue;
        for (int p = m.neighbor_start[v]; p < m.neighbor_start[v + 1]; ++p) {
          const int w = m.neighbor[p];
          if (hops[w] < 0 && !in_region[w]) {
            hops[w] = hops[v] + 1;
            queue.push(w);
          }
        }
      }
      std::vector<int> expected;
      for (int v = 0; v < static_cast<int>(m.point.size()); ++v)
        if (hops[v] > 0) expected.push_back(v);
      std::vector<int> added(region.begin() + static_cast<std::ptrdiff_t>(inside.size()), region.end());
      std::sort(added.begin(), added.end());
      BOOST_TEST_CONTEXT("source " << source << ", rings " << rings) {
        BOOST_TEST(!added.empty());
        BOOST_TEST(added == expected, boost::test_tools::per_element());
        for (std::size_t i = 0; i < region.size(); ++i)
          BOOST_TEST(marks.value(region[i]) == static_cast<int>(i));
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()
