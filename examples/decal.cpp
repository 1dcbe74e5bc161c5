// A decal: texture coordinates from the exponential map, written as an OBJ
// that any viewer can show with a checkerboard texture. The reference
// direction fixes the decal's rotation on the surface.
//
//   example_decal [mesh.off] [source] [radius] [out.obj]
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/write_textured_obj.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <fstream>
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
  const double radius = argc > 3 ? std::atof(argv[3]) : 15.0;
  const char* out = argc > 4 ? argv[4] : "decal.obj";
  try {
    expmap::Heat_exponential_map<Mesh> heat(mesh);
    expmap::Query_options query;
    query.reference_direction = std::array<double, 3>{{0, 1, 0}};  // decal "up" = world y
    const auto map = heat.compute_by_index(source, expmap::Patch::geodesic_radius(radius), query);
    std::ofstream obj(out);
    expmap::IO::write_textured_obj(obj, mesh, map);
    std::cout << "wrote " << out << " (" << map.size() << " vertices)\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
