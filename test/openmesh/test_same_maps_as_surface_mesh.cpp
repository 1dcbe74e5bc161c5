// Every method gives the same map on an OpenMesh TriMesh (through CGAL's
// graph traits for OpenMesh) as on a CGAL::Surface_mesh of the same mesh:
// the package is generic over face graphs, not written for CGAL's own.
#include <expmap/Discrete_exponential_map.h>
#include <expmap/Exact_exponential_map.h>
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>

#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_support.h"

using namespace expmap_test;

namespace {

// OpenMesh's default mesh: float coordinates.
using Open_mesh = OpenMesh::TriMesh_ArrayKernelT<>;

// A real mesh read by OpenMesh's own reader, as an OpenMesh user would.
Open_mesh read_open_mesh(const std::string& name) {
  Open_mesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, data_mesh(name)))
    throw std::runtime_error("OpenMesh cannot read " + data_mesh(name));
  return mesh;
}

// The same mesh as a Surface_mesh, built vertex by vertex and face by face
// so that vertex i is vertex i in both and both hold the same (float)
// coordinates. (CGAL::copy_face_graph() would renumber the vertices.)
Surface_mesh copy_to_surface_mesh(const Open_mesh& om) {
  Surface_mesh sm;
  for (auto v : om.vertices()) {
    const auto& p = om.point(v);
    sm.add_vertex(Point(p[0], p[1], p[2]));
  }
  for (auto f : om.faces()) {
    std::vector<Surface_mesh::Vertex_index> corners;
    for (auto v : om.fv_range(f)) corners.emplace_back(static_cast<unsigned>(v.idx()));
    if (sm.add_face(corners) == Surface_mesh::null_face())
      throw std::runtime_error("Surface_mesh refuses a face OpenMesh accepted");
  }
  return sm;
}

// The two maps hold the same vertices in the same order, with distances
// and angles equal up to rounding.
template <class OpenMap, class SurfaceMap>
void check_same_map(const OpenMap& on_open_mesh, const SurfaceMap& on_surface_mesh) {
  BOOST_TEST_REQUIRE(on_open_mesh.size() == on_surface_mesh.size());
  BOOST_TEST_REQUIRE(on_open_mesh.size() > 1u);
  double worst_r = 0, worst_theta = 0;
  for (std::size_t i = 0; i < on_open_mesh.size(); ++i) {
    BOOST_TEST(on_open_mesh.indices[i] == on_surface_mesh.indices[i]);
    // The descriptors of the OpenMesh result are that mesh's own handles.
    BOOST_TEST(static_cast<std::size_t>(on_open_mesh.vertices[i].idx()) ==
               on_open_mesh.indices[i]);
    worst_r = std::max(worst_r, std::abs(on_open_mesh.distance[i] - on_surface_mesh.distance[i]));
    worst_theta = std::max(worst_theta,
                           std::abs(wrap_angle(on_open_mesh.angle[i] - on_surface_mesh.angle[i])));
  }
  const double radius = on_surface_mesh.distance.back();
  BOOST_TEST_MESSAGE(on_open_mesh.size() << " vertices; largest differences: r " << worst_r
                                         << " (patch radius " << radius << "), theta "
                                         << worst_theta);
  BOOST_TEST(worst_r <= 1e-9 * radius);
  BOOST_TEST(worst_theta <= 1e-9);
}

// Queries both objects from a few sources spread over the mesh, each by its
// own descriptor type.
template <class Method_on_open_mesh, class Method_on_surface_mesh>
void check_same_maps(const Open_mesh& om, const Method_on_open_mesh& on_open_mesh,
                     const Method_on_surface_mesh& on_surface_mesh, const expmap::Patch& patch) {
  const std::size_t n = om.n_vertices();
  for (std::size_t source : {std::size_t(0), n / 3, (2 * n) / 3}) {
    const auto a = on_open_mesh.compute(om.vertex_handle(static_cast<unsigned>(source)), patch);
    const auto b = on_surface_mesh.compute_by_index(source, patch);
    BOOST_TEST(a.source == om.vertex_handle(static_cast<unsigned>(source)));
    check_same_map(a, b);
  }
}

struct Elephant {
  Open_mesh om = read_open_mesh("elephant.off");
  Surface_mesh sm = copy_to_surface_mesh(om);
};

}  // namespace

BOOST_FIXTURE_TEST_SUITE(openmesh_trimesh, Elephant)

BOOST_AUTO_TEST_CASE(the_copy_is_the_same_mesh) {
  BOOST_TEST(om.n_vertices() == num_vertices(sm));
  BOOST_TEST(om.n_faces() == num_faces(sm));
  BOOST_TEST(om.n_vertices() > 2000u);
  for (auto v : om.vertices()) {
    const auto& p = om.point(v);
    const Point& q = sm.point(Surface_mesh::Vertex_index(v.idx()));
    BOOST_TEST(p[0] == q.x());
    BOOST_TEST(p[1] == q.y());
    BOOST_TEST(p[2] == q.z());
  }
}

BOOST_AUTO_TEST_CASE(heat_exponential_map) {
  check_same_maps(om, expmap::Heat_exponential_map<Open_mesh>(om),
                  expmap::Heat_exponential_map<Surface_mesh>(sm), expmap::Patch::fraction(0.05));
}

BOOST_AUTO_TEST_CASE(discrete_exponential_map) {
  check_same_maps(om, expmap::Discrete_exponential_map<Open_mesh>(om),
                  expmap::Discrete_exponential_map<Surface_mesh>(sm),
                  expmap::Patch::fraction(0.05));
}

BOOST_AUTO_TEST_CASE(geodesic_polar_coordinates) {
  check_same_maps(om, expmap::Geodesic_polar_coordinates<Open_mesh>(om),
                  expmap::Geodesic_polar_coordinates<Surface_mesh>(sm),
                  expmap::Patch::fraction(0.05));
}

BOOST_AUTO_TEST_CASE(exact_exponential_map) {
  check_same_maps(om, expmap::Exact_exponential_map<Open_mesh>(om),
                  expmap::Exact_exponential_map<Surface_mesh>(sm), expmap::Patch::fraction(0.02));
}

BOOST_AUTO_TEST_SUITE_END()
