// Sources at points of faces (expmap::Surface_point): a corner gives the
// vertex's map, a point on an edge the same map from both faces, the plane
// exactly, the sphere about as well as from a vertex.
#include <expmap/Geodesic_polar_coordinates.h>
#include <expmap/Heat_exponential_map.h>
#include <expmap/Locate_surface_point.h>
#include <expmap/Surface_point.h>

#include <boost/test/unit_test.hpp>

#include <map>

#include "baseline_fixtures.h"

using namespace expmap_test;

namespace {

using Face = Surface_mesh::Face_index;
using Point_source = expmap::Surface_point<Face>;

template <class Mesh>
using Dgpc = expmap::Geodesic_polar_coordinates<Mesh>;
template <class Mesh>
using Heat = expmap::Heat_exponential_map<Mesh>;

std::array<double, 3> position(const Surface_mesh& mesh, const Point_source& p) {
  const auto h = mesh.halfedge(p.face);
  const Point corners[3] = {mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                            mesh.point(mesh.target(mesh.next(h)))};
  std::array<double, 3> x{{0, 0, 0}};
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) x[d] += p.barycentric[k] * corners[k][d];
  return x;
}

// Mean |r error| and mean |theta error| (the best rotation removed) of a map
// from a point of the unit sphere, against the exact map from the point
// projected onto the sphere.
template <class Map>
Sphere_errors point_sphere_errors(const Map& map, const std::array<double, 3>& source,
                                  const expmap_analytic::Triangle_soup& soup) {
  Sphere_errors e;
  std::vector<double> differences;
  double c = 0, s = 0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const expmap_analytic::Polar exact = expmap_analytic::sphere_exponential_map(
        source, soup.points[map.indices[i]], 1.0, map.axis_u);
    e.distance += std::abs(map.distance[i] - exact.r);
    const double d = std::remainder(map.angle[i] - exact.theta_unrotated, 2 * M_PI);
    differences.push_back(d);
    c += std::cos(d);
    s += std::sin(d);
  }
  const double rotation = std::atan2(s, c);
  for (double d : differences) e.angle += angle_difference(d, rotation);
  e.vertices = differences.size();
  e.distance /= static_cast<double>(e.vertices);
  e.angle /= static_cast<double>(e.vertices);
  return e;
}

template <template <class> class Method>
void check_corner_is_the_vertex() {
  const auto& soup = icosphere(4);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 3, 5)) {
    const Face face(static_cast<Surface_mesh::size_type>(f));
    const auto h = mesh.halfedge(face);
    const Surface_mesh::Vertex_index corner[3] = {mesh.source(h), mesh.target(h),
                                                  mesh.target(mesh.next(h))};
    for (int k = 0; k < 3; ++k) {
      Point_source p{face, {{0, 0, 0}}};
      p.barycentric[k] = 1;
      for (const expmap::Patch& patch :
           {expmap::Patch::geodesic_radius(0.4), expmap::Patch::vertex_count(100)})
        check_same_map(method.compute(p, patch), method.compute(corner[k], patch), 1e-12);
    }
  }
}

// The same point on an edge, given from the edge's two faces.
template <template <class> class Method>
void check_edge_point_from_both_faces(double tolerance) {
  const auto& soup = icosphere(4);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 3, 11)) {
    const Face face(static_cast<Surface_mesh::size_type>(f));
    const auto h = mesh.halfedge(face);
    const Point_source p{face, {{0.35, 0.65, 0}}};
    std::map<Surface_mesh::Vertex_index, double> weight{{mesh.source(h), 0.35},
                                                       {mesh.target(h), 0.65}};
    const Face other = mesh.face(mesh.opposite(h));
    const auto g = mesh.halfedge(other);
    const Point_source q{other, {{weight[mesh.source(g)], weight[mesh.target(g)],
                                  weight[mesh.target(mesh.next(g))]}}};
    const auto a = method.compute(p, expmap::Patch::geodesic_radius(0.4));
    const auto b = method.compute(q, expmap::Patch::geodesic_radius(0.4));
    BOOST_TEST(a.size() > 100u);
    check_same_map(a, b, tolerance);
  }
}

// The largest move of a patch vertex's (u, v) between two maps, over the
// vertices both hold within `radius`.
template <class Map>
double largest_uv_move(const Map& a, const Map& b, double radius) {
  std::map<std::size_t, std::array<double, 2>> uv;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.distance[i] <= radius) uv[a.indices[i]] = a.uv(i);
  double largest = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const auto it = uv.find(b.indices[i]);
    if (it == uv.end() || b.distance[i] > radius) continue;
    const auto q = b.uv(i);
    largest = std::max(largest, std::hypot(q[0] - it->second[0], q[1] - it->second[1]));
  }
  return largest;
}

// A point moved in steps of `step` (a fraction of the face's coordinates)
// from inside a face, across its edge into the next face and up to a corner
// moves every (u, v) by a bounded multiple of the distance it moved: no
// jump where the nearest corner changes, at the edge or at the vertex.
template <template <class> class Method>
void check_continuous_motion(double bound) {
  const auto& soup = icosphere(4);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::geodesic_radius(0.4);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 3, 29)) {
    const Face face(static_cast<Surface_mesh::size_type>(f));
    const auto h = mesh.halfedge(face);
    const Face other = mesh.face(mesh.opposite(h));
    const auto g = mesh.halfedge(other);
    // The edge (a, b) = (source(h), target(h)) is shared; c and d are the
    // apexes. A path from near c through the edge's middle to d, then to a.
    const auto a = mesh.source(h), b = mesh.target(h);
    auto in_other = [&](double wa, double wb, double wd) {
      std::map<Surface_mesh::Vertex_index, double> w{{a, wa}, {b, wb}};
      Point_source q{other, {{0, 0, 0}}};
      const Surface_mesh::Vertex_index corner[3] = {mesh.source(g), mesh.target(g),
                                                    mesh.target(mesh.next(g))};
      for (int k = 0; k < 3; ++k) q.barycentric[k] = w.count(corner[k]) ? w[corner[k]] : wd;
      return q;
    };
    std::vector<Point_source> path;
    const int steps = 20;
    for (int i = 0; i <= steps; ++i) {  // from the face's middle to the edge's
      const double t = static_cast<double>(i) / steps;
      const double wc = (1 - t) / 3;
      path.push_back({face, {{(1 - wc) / 2, (1 - wc) / 2, wc}}});
    }
    for (int i = 1; i <= steps; ++i) {  // on into the other face
      const double wd = static_cast<double>(i) / steps / 3;
      path.push_back(in_other((1 - wd) / 2, (1 - wd) / 2, wd));
    }
    for (int i = 1; i <= steps; ++i) {  // then to corner a (a vertex at the end)
      const double t = static_cast<double>(i) / steps;
      const double wa = 1.0 / 3 + t * 2.0 / 3;
      path.push_back(in_other(wa, (1 - wa) / 2, (1 - wa) / 2));
    }
    auto previous = method.compute(path[0], patch);
    auto x0 = position(mesh, path[0]);
    double worst = 0;
    for (std::size_t i = 1; i < path.size(); ++i) {
      const auto map = method.compute(path[i], patch);
      const auto x = position(mesh, path[i]);
      const double moved = std::hypot(std::hypot(x[0] - x0[0], x[1] - x0[1]), x[2] - x0[2]);
      worst = std::max(worst, largest_uv_move(previous, map, 0.3) / moved);
      previous = map;
      x0 = x;
    }
    BOOST_TEST_MESSAGE("face " << f << ": largest (u, v) move per distance moved " << worst);
    BOOST_TEST(worst < bound);
  }
}

// A point inside a face against the exact map of the unit sphere from that
// point; the face's corners as sources for comparison.
template <template <class> class Method>
void check_sphere_point_as_accurate_as_a_vertex(const char* name,
                                                const expmap_analytic::Triangle_soup& soup) {
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::geodesic_radius(0.5);
  std::vector<Point_source> points;
  for (std::size_t f : random_sources(mesh.number_of_faces(), 5, 2018))
    points.push_back({Face(static_cast<Surface_mesh::size_type>(f)), {{0.2, 0.3, 0.5}}});
  expmap::Batch_options two_threads;
  two_threads.threads = 2;
  const auto batch = method.compute_many(points, patch, two_threads);
  BOOST_TEST(batch.failures() == 0u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Sphere_errors e = point_sphere_errors(batch.maps[i], position(mesh, points[i]), soup);
    Sphere_errors corners;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(points[i].face), mesh)) {
      const Sphere_errors c = sphere_errors(method.compute(v, patch), soup);
      corners.distance += c.distance / 3;
      corners.angle += c.angle_rotation_removed / 3;
    }
    BOOST_TEST_MESSAGE(name << ", point in face " << points[i].face << ": mean |r error| "
                            << e.distance << ", mean |theta error| " << e.angle
                            << "; its corners as sources: " << corners.distance << ", "
                            << corners.angle);
    BOOST_TEST(e.vertices > 500u);
    BOOST_TEST(e.distance <= 1.5 * corners.distance);
    BOOST_TEST(e.angle <= 1.5 * corners.angle);
  }
}

// The icosphere with every vertex moved along the sphere by up to a fifth
// of an edge in a random direction.
expmap_analytic::Triangle_soup jittered_icosphere(int subdivisions, unsigned seed) {
  expmap_analytic::Triangle_soup soup = expmap_analytic::make_icosphere(subdivisions, 1.0);
  const double edge = 1.1 * 2 * M_PI / (5 * std::pow(2.0, subdivisions));
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (auto& p : soup.points) {
    std::array<double, 3> q;
    for (int d = 0; d < 3; ++d) q[d] = p[d] + 0.2 / std::sqrt(3.0) * edge * normal(rng);
    const double length = std::hypot(std::hypot(q[0], q[1]), q[2]);
    for (int d = 0; d < 3; ++d) p[d] = q[d] / length;
  }
  return soup;
}

// Points in faces with an edge on a planar grid's boundary, against the
// exact planar map: the largest distance error and angle error (weighted by
// the distance, so a length too) of the patch as small, up to 1.5 times
// (and 1e-9), as those of the face's corners as sources, and no fold.
template <template <class> class Method>
void check_boundary_face_points(const char* name) {
  const auto soup = planar_grid(24, true);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::geodesic_radius(0.5);
  expmap::Query_options query;
  query.find_fold_free_radius = true;
  auto errors = [&](const auto& map, const std::array<double, 3>& source) {
    std::array<double, 2> e{{0, 0}};
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto exact =
          expmap_analytic::plane_exponential_map(source, soup.points[map.indices[i]], map.axis_u);
      e[0] = std::max(e[0], std::abs(map.distance[i] - exact.r));
      e[1] = std::max(e[1], exact.r * angle_difference(map.angle[i], exact.theta_unrotated));
    }
    return e;
  };
  std::size_t checked = 0;
  for (auto f : mesh.faces()) {
    bool on_boundary = false;
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      on_boundary = on_boundary || mesh.is_border(mesh.opposite(h));
    if (!on_boundary || f.idx() % 7 != 0) continue;
    const Point_source p{f, {{0.2, 0.3, 0.5}}};
    const auto map = method.compute(p, patch, query);
    const auto e = errors(map, position(mesh, p));
    std::array<double, 2> corners{{0, 0}};
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const auto x = mesh.point(v);
      const auto c = errors(method.compute(v, patch), {{x.x(), x.y(), x.z()}});
      for (int k = 0; k < 2; ++k) corners[k] = std::max(corners[k], c[k]);
    }
    BOOST_TEST_MESSAGE(name << ", point in boundary face " << f << ": largest |r error| " << e[0]
                            << ", largest r |theta error| " << e[1] << "; its corners': "
                            << corners[0] << ", " << corners[1]);
    BOOST_TEST(map.size() > 25u);  // a quarter disk at the grid's corners
    BOOST_TEST(e[0] <= std::max(1.5 * corners[0], 1e-9));
    BOOST_TEST(e[1] <= std::max(1.5 * corners[1], 1e-9));
    // No fold: the fold-free disk is the whole patch.
    BOOST_TEST(*map.fold_free_radius == *std::max_element(map.distance.begin(), map.distance.end()));
    ++checked;
  }
  BOOST_TEST(checked >= 5u);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(surface_points)

BOOST_AUTO_TEST_CASE(locator_finds_the_face_and_coordinates) {
  const auto mesh = to_mesh<Surface_mesh>(icosphere(3));
  const expmap::Surface_point_locator<Surface_mesh> locator(mesh);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 5, 3)) {
    const Point_source p{Face(static_cast<Surface_mesh::size_type>(f)), {{0.2, 0.3, 0.5}}};
    const Point_source found = locator.locate(position(mesh, p));
    BOOST_TEST(found.face == p.face);
    for (int k = 0; k < 3; ++k) BOOST_TEST(std::abs(found.barycentric[k] - p.barycentric[k]) < 1e-12);
  }
  const Point_source once = expmap::locate_surface_point(mesh, {{0, 0, 2}});
  const auto x = position(mesh, once);
  BOOST_TEST(x[2] > 0.99);  // nearest the north pole
}

BOOST_AUTO_TEST_CASE(dgpc_corner_is_the_vertex) { check_corner_is_the_vertex<Dgpc>(); }

BOOST_AUTO_TEST_CASE(dgpc_edge_point_from_both_faces) { check_edge_point_from_both_faces<Dgpc>(1e-9); }

// DGPC is exact on a plane from a vertex, and from a point: the front
// starts with the face's unfolding, exact on a plane.
BOOST_AUTO_TEST_CASE(dgpc_exact_on_a_planar_grid) {
  const auto soup = planar_grid(24, true);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Dgpc<Surface_mesh> dgpc(mesh);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 5, 17)) {
    const Point_source p{Face(static_cast<Surface_mesh::size_type>(f)), {{0.2, 0.5, 0.3}}};
    const auto source = position(mesh, p);
    const auto map = dgpc.compute(p, expmap::Patch::geodesic_radius(0.3));
    BOOST_TEST(map.size() > 30u);
    double distance = 0, angle = 0;
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto exact =
          expmap_analytic::plane_exponential_map(source, soup.points[map.indices[i]], map.axis_u);
      distance = std::max(distance, std::abs(map.distance[i] - exact.r));
      angle = std::max(angle, angle_difference(map.angle[i], exact.theta_unrotated));
    }
    BOOST_TEST(distance < 1e-12);
    BOOST_TEST(angle < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(dgpc_sphere_point_as_accurate_as_a_vertex) {
  check_sphere_point_as_accurate_as_a_vertex<Dgpc>("DGPC", icosphere(5));
  check_sphere_point_as_accurate_as_a_vertex<Dgpc>("DGPC, jittered", jittered_icosphere(5, 3));
}

BOOST_AUTO_TEST_CASE(dgpc_boundary_face_points) { check_boundary_face_points<Dgpc>("DGPC"); }

BOOST_AUTO_TEST_CASE(dgpc_continuous_motion) { check_continuous_motion<Dgpc>(3.0); }

BOOST_AUTO_TEST_CASE(heat_corner_is_the_vertex) { check_corner_is_the_vertex<Heat>(); }

BOOST_AUTO_TEST_CASE(heat_edge_point_from_both_faces) { check_edge_point_from_both_faces<Heat>(1e-9); }

BOOST_AUTO_TEST_CASE(heat_sphere_point_as_accurate_as_a_vertex) {
  check_sphere_point_as_accurate_as_a_vertex<Heat>("heat", icosphere(5));
  check_sphere_point_as_accurate_as_a_vertex<Heat>("heat, jittered", jittered_icosphere(5, 3));
}

BOOST_AUTO_TEST_CASE(heat_boundary_face_points) { check_boundary_face_points<Heat>("heat"); }

BOOST_AUTO_TEST_CASE(heat_continuous_motion) { check_continuous_motion<Heat>(3.0); }

BOOST_AUTO_TEST_CASE(bad_points) {
  const auto mesh = to_mesh<Surface_mesh>(icosphere(2));
  const Dgpc<Surface_mesh> dgpc(mesh);
  const auto patch = expmap::Patch::vertex_count(10);
  BOOST_CHECK_THROW(dgpc.compute(Point_source{Face(0), {{-0.5, 1, 0.5}}}, patch), expmap::Invalid_input);
  BOOST_CHECK_THROW(dgpc.compute(Point_source{Face(0), {{0, 0, 0}}}, patch), expmap::Invalid_input);
  BOOST_CHECK_THROW(dgpc.compute(Point_source{Face(0), {{NAN, 0, 1}}}, patch), expmap::Invalid_input);
  // A count patch from a point counts vertices only.
  BOOST_TEST(dgpc.compute(Point_source{Face(0), {{0.3, 0.3, 0.4}}}, patch).size() == 10u);
}

BOOST_AUTO_TEST_SUITE_END()
