// Uses the installed headers: an exponential map on a small generated grid.
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <iostream>
#include <vector>

int main() {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  using Mesh = CGAL::Surface_mesh<Point>;
  // The unit square cut into n x n cells, each split along a diagonal; the
  // source is the vertex at the centre.
  const int n = 20;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      grid.push_back(mesh.add_vertex(Point(double(i) / n - 0.5, double(j) / n - 0.5, 0.0)));
  auto at = [&](int i, int j) { return grid[std::size_t(j * (n + 1) + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  expmap::Heat_exponential_map<Mesh> heat(mesh);
  const auto map = heat.compute(at(n / 2, n / 2), expmap::Patch::vertex_count(50));
  std::cout << "consumer: " << map.size() << " vertices, farthest at r = " << map.distance.back()
            << "\n";
  return map.size() == 50 ? 0 : 1;
}
