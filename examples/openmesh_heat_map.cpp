// The heat exponential map on an OpenMesh TriMesh: CGAL's graph traits for
// OpenMesh make it a face graph, so the class takes it as it is. The result
// holds OpenMesh vertex handles; here (u, v) go into OpenMesh's own texture
// coordinates and OpenMesh writes them out.
//
//   example_openmesh_heat_map [mesh.off] [source] [fraction] [out.obj]
#include <expmap/Heat_exponential_map.h>

// Before any use of the mesh type: makes it a CGAL face graph.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstdlib>
#include <iostream>

using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;

int main(int argc, char** argv) {
  const char* file = argc > 1 ? argv[1] : "data/meshes/armadillo.off";
  Mesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, file)) {
    std::cerr << "cannot read " << file << "\n";
    return 1;
  }
  const std::size_t source = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 2000;
  const double fraction = argc > 3 ? std::atof(argv[3]) : 0.05;
  const char* out = argc > 4 ? argv[4] : "openmesh_heat_map.obj";
  try {
    expmap::Heat_exponential_map<Mesh> heat(mesh);  // t = 10 h^2, CHOLMOD
    const auto map = heat.compute_by_index(source, expmap::Patch::fraction(fraction));

    // Vertices outside the patch keep the texture coordinate (0, 0).
    mesh.request_vertex_texcoords2D();
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto uv = map.uv(i);
      mesh.set_texcoord2D(map.vertices[i], Mesh::TexCoord2D(float(uv[0]), float(uv[1])));
    }
    if (!OpenMesh::IO::write_mesh(mesh, out, OpenMesh::IO::Options::VertexTexCoord)) {
      std::cerr << "cannot write " << out << "\n";
      return 1;
    }
    std::cout << map.size() << " vertices mapped around vertex " << map.source.idx()
              << ", farthest at r = " << map.distance.back() << "; wrote " << out << "\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
