// The same map on a CGAL::Polyhedron_3, with Eigen's SimplicialLDLT instead
// of CHOLMOD: any FaceGraph and any SparseCholeskySolver model plug in.
//
//   example_polyhedron_with_eigen_solver [mesh.off] [source] [radius]
#include <expmap/Eigen_simplicial_solver.h>
#include <expmap/Heat_exponential_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;

int main(int argc, char** argv) {
  const char* file = argc > 1 ? argv[1] : "data/meshes/armadillo.off";
  Polyhedron mesh;
  if (!CGAL::IO::read_polygon_mesh(file, mesh)) {
    std::cerr << "cannot read " << file << "\n";
    return 1;
  }
  const std::size_t source = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 2000;
  const double radius = argc > 3 ? std::atof(argv[3]) : 10.0;
  try {
    expmap::Heat_options options;
    options.time_factor = 1.0;  // closer to exact geodesics, less smoothing
    options.laplacian = expmap::Laplacian_mode::intrinsic_delaunay;
    expmap::Heat_exponential_map<Polyhedron, CGAL::Default, expmap::Eigen_simplicial_solver>
        heat(mesh, options);
    const auto map = heat.compute_by_index(source, expmap::Patch::geodesic_radius(radius));
    std::cout << map.size() << " vertices within geodesic distance " << radius << "\n";
    for (std::size_t i = 0; i < map.size() && i < 5; ++i)
      std::cout << "  vertex " << map.indices[i] << ": r = " << map.distance[i]
                << ", theta = " << map.angle[i] << "\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
