// Uses the installed headers: an exponential map on a small generated grid.
#include <expmap/Analytic_surfaces.h>
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

int main() {
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  Mesh mesh;
  expmap::soup_to_mesh(expmap::make_grid(20, 20, 1.0, 1.0), mesh);
  expmap::Heat_exponential_map<Mesh> heat(mesh);
  const auto map = heat.compute_by_index(expmap::grid_origin_vertex(20, 20),
                                         expmap::Patch::vertex_count(50));
  std::cout << "consumer: " << map.size() << " vertices, farthest at r = " << map.distance.back()
            << "\n";
  return map.size() == 50 ? 0 : 1;
}
