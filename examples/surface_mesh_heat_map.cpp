// The heat exponential map on a CGAL::Surface_mesh: precompute once, query
// a patch, and store (u, v) in a vertex property map.
//
//   example_surface_mesh_heat_map [mesh.off] [source] [fraction]
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <cstdlib>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv) {
  const char* file = argc > 1 ? argv[1] : "data/meshes/armadillo.off";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(file, mesh)) {
    std::cerr << "cannot read " << file << "\n";
    return 1;
  }
  const std::size_t source = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 2000;
  const double fraction = argc > 3 ? std::atof(argv[3]) : 0.05;
  try {
    expmap::Heat_exponential_map<Mesh> heat(mesh);  // t = 10 h^2, CHOLMOD
    const auto map = heat.compute_by_index(source, expmap::Patch::fraction(fraction));

    auto uv = mesh.add_property_map<Mesh::Vertex_index, std::array<double, 2>>("v:uv").first;
    auto r = mesh.add_property_map<Mesh::Vertex_index, double>("v:r").first;
    auto theta = mesh.add_property_map<Mesh::Vertex_index, double>("v:theta").first;
    expmap::write_to_property_maps(map, r, theta, uv);

    std::cout << map.size() << " vertices mapped, farthest at r = " << map.distance.back()
              << "; its (u, v) = (" << get(uv, map.vertices.back())[0] << ", "
              << get(uv, map.vertices.back())[1] << ")\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
