// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Breadth-first candidate search: a search continued from where it reached
// a smaller budget must find the vertices of a fresh search with the larger
// budget, in the same order, and that order must be by edge hops (checked
// against a plain std::queue search).

#include <expmap/Analytic_surfaces.h>
#include <expmap/internal/Indexed_mesh.h>
#include <expmap/internal/Region_growing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/test/unit_test.hpp>

#include <queue>
#include <vector>

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

}  // namespace

BOOST_AUTO_TEST_SUITE(region_growing)

BOOST_AUTO_TEST_CASE(a_continued_breadth_first_search_equals_a_fresh_one) {
  Surface_mesh mesh;
  expmap::soup_to_mesh(expmap::make_icosphere(4, 1.0), mesh);
  const expmap::internal::Indexed_mesh<Surface_mesh, CGAL::Default> indexed(
      mesh, get(CGAL::vertex_point, mesh));
  const auto& m = indexed.arrays;
  expmap::internal::Vertex_marks marks, fresh_marks;
  marks.resize(m.point.size());
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

BOOST_AUTO_TEST_SUITE_END()
