// A decal centred at any point of the surface, not only at a vertex: the
// point nearest to a given position is located (an AABB tree of the faces),
// mapped from, and the map written as a textured OBJ that any viewer can
// show with a checkerboard texture, the point at the texture's centre.
//
//   example_decal_at_point [mesh.off] [x y z] [radius] [out.obj]
//
// Without a position, the centre of the mesh's bounding box is taken: the
// decal goes where the surface is nearest to it.
#include <expmap/Heat_exponential_map.h>
#include <expmap/IO/write_textured_obj.h>
#include <expmap/Locate_surface_point.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
// Any of the four methods maps from a Surface_point, e.g.
// expmap::Geodesic_polar_coordinates<Mesh> (DGPC).
using Method = expmap::Heat_exponential_map<Mesh>;

int main(int argc, char** argv) {
  const char* file = argc > 1 ? argv[1] : "data/meshes/armadillo.off";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "cannot read " << file << " as a triangle mesh\n";
    return 1;
  }
  std::array<double, 3> position;
  if (argc > 4) {
    position = {{std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4])}};
  } else {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    position = {{(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                 (box.zmin() + box.zmax()) / 2}};
  }
  const double radius = argc > 5 ? std::atof(argv[5]) : 15.0;
  const char* out = argc > 6 ? argv[6] : "decal_at_point.obj";
  try {
    const Method method(mesh);
    const expmap::Surface_point_locator<Mesh> locator(mesh);
    const auto point = locator.locate(position);
    Method::Query query;
    query.reference_direction = std::array<double, 3>{{0, 1, 0}};  // decal "up" = world y
    const auto map = method.compute(point, expmap::Patch::geodesic_radius(radius), query);
    std::ofstream obj(out);
    expmap::IO::write_textured_obj(obj, mesh, map);
    std::cout << "decal at face " << point.face << " (barycentric " << point.barycentric[0] << ", "
              << point.barycentric[1] << ", " << point.barycentric[2] << "): wrote " << out << " ("
              << map.size() << " vertices)\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
