// Checks every method that maps from points of faces (expmap::Surface_point)
// must pass; each test file runs them on its method with the bounds measured
// for it.
#ifndef EXPMAP_TEST_SURFACE_POINT_FIXTURES_H
#define EXPMAP_TEST_SURFACE_POINT_FIXTURES_H

#include <expmap/Locate_surface_point.h>
#include <expmap/Surface_point.h>

#include <boost/test/unit_test.hpp>

#include <map>
#include <random>
#include <vector>

#include "baseline_fixtures.h"

namespace expmap_test {

using Face = Surface_mesh::Face_index;
using Point_source = expmap::Surface_point<Face>;

// Positions of surface points: the library's (checked against CGAL's
// construct_point in test_surface_points.cpp).
using expmap::surface_point_position;

inline double mean_edge_length(const Surface_mesh& mesh) {
  double sum = 0;
  for (auto e : mesh.edges())
    sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
  return sum / static_cast<double>(mesh.number_of_edges());
}

/// The 10,242-vertex unit icosphere with every vertex moved along the
/// sphere by up to `amount` of an edge length (reproducibly): irregular
/// triangles, still on the unit sphere, so the sphere's exact map still
/// applies.
inline const expmap_analytic::Triangle_soup& jittered_icosphere() {
  static const expmap_analytic::Triangle_soup soup = [] {
    expmap_analytic::Triangle_soup s = icosphere(5);
    const double amount = 0.25 * mean_edge_length(to_mesh<Surface_mesh>(s));
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (auto& p : s.points) {
      for (double& x : p) x += amount * unit(rng) / std::sqrt(3.0);
      const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (double& x : p) x /= n;
    }
    return s;
  }();
  return soup;
}

/// Mean |r error| and mean |theta error| (the best rotation removed) of a
/// map from a point of the unit sphere, against the exact map from the
/// point projected onto the sphere.
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

/// A point with a coordinate 1 gives its corner's map, bit for bit.
template <template <class> class Method>
void check_corner_is_the_vertex(const expmap_analytic::Triangle_soup& soup, double radius,
                                double tolerance) {
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
           {expmap::Patch::geodesic_radius(radius), expmap::Patch::vertex_count(100)})
        check_same_map(method.compute(p, patch), method.compute(corner[k], patch), tolerance);
    }
  }
}

/// The same point on an edge, given from the edge's two faces; on a unit
/// sphere, its errors against the sphere's exact map are within `factor`
/// of the mean of the edge's ends' as sources.
template <template <class> class Method>
void check_edge_point_from_both_faces(const expmap_analytic::Triangle_soup& soup, double radius,
                                      double tolerance, double factor) {
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
    const auto patch = expmap::Patch::geodesic_radius(radius);
    const auto a = method.compute(p, patch);
    const auto b = method.compute(q, patch);
    BOOST_TEST(a.size() > 100u);
    check_same_map(a, b, tolerance);
    const Sphere_errors e = point_sphere_errors(a, surface_point_position(mesh, p), soup);
    Sphere_errors ends;
    for (auto v : {mesh.source(h), mesh.target(h)}) {
      const Sphere_errors c = sphere_errors(method.compute(v, patch), soup);
      ends.distance += c.distance / 2;
      ends.angle += c.angle_rotation_removed / 2;
    }
    BOOST_TEST_MESSAGE("point on the edge of face " << face << ": mean |r error| " << e.distance
                                                    << ", mean |theta error| " << e.angle
                                                    << "; the edge's ends as sources: "
                                                    << ends.distance << ", " << ends.angle);
    BOOST_TEST(e.distance <= factor * ends.distance);
    BOOST_TEST(e.angle <= factor * ends.angle);
  }
}

/// A point inside a face against the exact map of the unit sphere from
/// that point, and the face's corners as sources for comparison: the
/// point's mean errors are within `factor` of the corners' mean.
template <template <class> class Method>
void check_sphere_point_as_accurate_as_a_vertex(const char* name,
                                                const expmap_analytic::Triangle_soup& soup,
                                                double radius, double factor) {
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::geodesic_radius(radius);
  std::vector<Point_source> points;
  for (std::size_t f : random_sources(mesh.number_of_faces(), 5, 2018))
    points.push_back({Face(static_cast<Surface_mesh::size_type>(f)), {{0.2, 0.3, 0.5}}});
  expmap::Batch_options two_threads;
  two_threads.threads = 2;
  const auto batch = method.compute_many(points, patch, two_threads);
  BOOST_TEST(batch.failures() == 0u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Sphere_errors e = point_sphere_errors(batch.maps[i], surface_point_position(mesh, points[i]), soup);
    Sphere_errors corners;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(points[i].face), mesh)) {
      const Sphere_errors c = sphere_errors(method.compute(v, patch), soup);
      corners.distance += c.distance / 3;
      corners.angle += c.angle_rotation_removed / 3;
    }
    BOOST_TEST_MESSAGE(name << ", point in face " << points[i].face << ": mean |r error| "
                            << e.distance << ", mean |theta error| " << e.angle
                            << "; its corners as sources: " << corners.distance << ", "
                            << corners.angle << " (ratios " << e.distance / corners.distance
                            << ", " << e.angle / corners.angle << ")");
    BOOST_TEST(e.vertices > 200u);
    BOOST_TEST(e.distance <= factor * corners.distance);
    BOOST_TEST(e.angle <= factor * corners.angle);
  }
}

/// Every kind of patch from a point: a count patch holds that many
/// vertices (the nearest ones by reported distance, or for DEM the first
/// in Dijkstra's order), a vertex set its vertices (a corner included),
/// and the values of a vertex do not depend on the patch (to `tolerance`:
/// the exact map's submesh depends on the patch).
template <template <class> class Method>
void check_point_patch_kinds(bool nearest_by_reported_distance, double tolerance) {
  const auto mesh = to_mesh<Surface_mesh>(icosphere(5));
  const Method<Surface_mesh> method(mesh);
  const Point_source p{Face(1234), {{0.2, 0.3, 0.5}}};
  const auto by_radius = method.compute(p, expmap::Patch::geodesic_radius(0.3));
  BOOST_TEST_REQUIRE(by_radius.size() > 160u);
  BOOST_TEST(by_radius.distance.back() <= 0.3);
  std::map<std::size_t, std::size_t> in_radius;
  for (std::size_t i = 0; i < by_radius.size(); ++i) in_radius[by_radius.indices[i]] = i;
  auto same_values = [&](const auto& map) {
    double worst = 0;
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto found = in_radius.find(map.indices[i]);
      BOOST_TEST_REQUIRE((found != in_radius.end()));
      worst = std::max({worst, std::abs(map.distance[i] - by_radius.distance[found->second]),
                        angle_difference(map.angle[i], by_radius.angle[found->second])});
    }
    BOOST_TEST(worst <= tolerance);
  };
  const auto by_count = method.compute(p, expmap::Patch::vertex_count(60));
  BOOST_TEST(by_count.size() == 60u);
  same_values(by_count);
  if (nearest_by_reported_distance)
    BOOST_TEST(by_count.distance.back() <= by_radius.distance[60] * (1 + 1e-9));
  const auto h = mesh.halfedge(p.face);
  const std::size_t corner = mesh.target(h).idx();
  const std::vector<std::size_t> set{corner, by_radius.indices[100], by_radius.indices[150],
                                     by_radius.indices[100]};
  const auto by_set = method.compute(p, expmap::Patch::vertex_set(set));
  BOOST_TEST(by_set.size() == 3u);
  same_values(by_set);
  BOOST_TEST(method.compute(p, expmap::Patch::vertex_count(1)).size() == 1u);
}

/// Bad points throw Invalid_input: coordinates negative, all zero or not
/// finite, a face out of range, a reference direction along the point's
/// normal (named by the point's face).
template <template <class> class Method>
void check_bad_points() {
  const auto mesh = to_mesh<Surface_mesh>(icosphere(5));
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::vertex_count(10);
  BOOST_CHECK_THROW(method.compute(Point_source{Face(0), {{-0.5, 1, 0.5}}}, patch),
                    expmap::Invalid_input);
  BOOST_CHECK_THROW(method.compute(Point_source{Face(0), {{0, 0, 0}}}, patch),
                    expmap::Invalid_input);
  BOOST_CHECK_THROW(method.compute(Point_source{Face(0), {{NAN, 0, 1}}}, patch),
                    expmap::Invalid_input);
  // Each finite, but their sum is not.
  BOOST_CHECK_THROW(method.compute(Point_source{Face(0), {{1e308, 1e308, 1e308}}}, patch),
                    expmap::Invalid_input);
  // A batch names a failed point by its position.
  const auto batch =
      method.compute_many(std::vector<Point_source>{{Face(0), {{0.2, 0.3, 0.5}}},
                                                    {Face(0), {{-1, 1, 1}}}},
                          patch);
  BOOST_TEST(batch.errors[0].empty());
  BOOST_TEST(batch.errors[1].find("source point 1") != std::string::npos);
  const Face beyond(static_cast<Surface_mesh::size_type>(mesh.number_of_faces() + 3));
  BOOST_CHECK_THROW(method.compute(Point_source{beyond, {{0.3, 0.3, 0.4}}}, patch),
                    expmap::Invalid_input);
  // A count patch from a point counts vertices only.
  const Point_source p{Face(7), {{0.3, 0.3, 0.4}}};
  const auto map = method.compute(p, patch);
  BOOST_TEST(map.size() == 10u);
  expmap::Query_options along_normal;
  along_normal.reference_direction = map.normal;
  try {
    method.compute(p, patch, along_normal);
    BOOST_ERROR("a reference direction along the normal was accepted");
  } catch (const expmap::Invalid_input& e) {
    BOOST_TEST(std::string(e.what()).find("source point in face 7") != std::string::npos);
  }
}

/// The largest move of a vertex's (u, v) between two maps, over the
/// vertices both hold.
template <class Map>
double largest_uv_move(const Map& a, const Map& b) {
  std::map<std::size_t, std::size_t> in_b;
  for (std::size_t j = 0; j < b.size(); ++j) in_b[b.indices[j]] = j;
  double largest = 0;
  std::size_t common = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto found = in_b.find(a.indices[i]);
    if (found == in_b.end()) continue;
    ++common;
    const auto x = a.uv(i), y = b.uv(found->second);
    largest = std::max(largest, std::hypot(x[0] - y[0], x[1] - y[1]));
  }
  BOOST_TEST(common > 100u);
  return largest;
}

/// The point moves by `delta` edge lengths inside a face, and across an
/// edge (from delta / 2 on one side to delta / 2 on the other): every
/// vertex's (u, v) moves by at most `bound` times the distance moved, as
/// the sphere's exact map does up to the turn of the frame (reported too).
template <template <class> class Method>
void check_no_jump(const char* name, const expmap_analytic::Triangle_soup& soup, double radius,
                   double delta, double bound) {
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const double step = delta * mean_edge_length(mesh);
  const auto patch = expmap::Patch::geodesic_radius(radius);
  // A point of `face` moved towards its corner k from `from` by `length`.
  auto toward = [&](Face face, std::array<double, 3> from, int k, double length) {
    Point_source p{face, from};
    Point_source corner{face, {{0, 0, 0}}};
    corner.barycentric[k] = 1;
    const auto x = surface_point_position(mesh, p), c = surface_point_position(mesh, corner);
    const double t = length / std::sqrt(CGAL::squared_distance(Point(x[0], x[1], x[2]),
                                                               Point(c[0], c[1], c[2])));
    for (int i = 0; i < 3; ++i) p.barycentric[i] = (1 - t) * from[i] + (i == k ? t : 0.0);
    return p;
  };
  // The sphere's exact map's move between the same points, in their frames.
  auto exact_move = [&](const auto& a, const Point_source& p, const auto& b,
                        const Point_source& q) {
    double largest = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto& x = soup.points[a.indices[i]];
      const auto s = expmap_analytic::sphere_exponential_map(surface_point_position(mesh, p), x, 1.0, a.axis_u);
      const auto t = expmap_analytic::sphere_exponential_map(surface_point_position(mesh, q), x, 1.0, b.axis_u);
      largest = std::max(largest, std::hypot(s.r * std::cos(s.theta_unrotated) -
                                                 t.r * std::cos(t.theta_unrotated),
                                             s.r * std::sin(s.theta_unrotated) -
                                                 t.r * std::sin(t.theta_unrotated)));
    }
    return largest;
  };
  double worst = 0;
  for (std::size_t f : random_sources(mesh.number_of_faces(), 3, 77)) {
    const Face face(static_cast<Surface_mesh::size_type>(f));
    // Inside the face.
    const Point_source p{face, {{0.3, 0.3, 0.4}}};
    const Point_source q = toward(face, p.barycentric, 0, step);
    const auto a = method.compute(p, patch), b = method.compute(q, patch);
    // Across the edge (source(h), target(h)), from its point at 0.4.
    const auto h = mesh.halfedge(face);
    const Face other = mesh.face(mesh.opposite(h));
    const auto g = mesh.halfedge(other);
    std::map<Surface_mesh::Vertex_index, double> weight{{mesh.source(h), 0.6},
                                                       {mesh.target(h), 0.4}};
    const Surface_mesh::Vertex_index other_corner[3] = {mesh.source(g), mesh.target(g),
                                                        mesh.target(mesh.next(g))};
    int apex = 0;
    while (weight.count(other_corner[apex])) ++apex;
    std::array<double, 3> on_edge_from_other{{0, 0, 0}};
    for (int k = 0; k < 3; ++k)
      if (k != apex) on_edge_from_other[k] = weight.at(other_corner[k]);
    const Point_source r = toward(face, {{0.6, 0.4, 0}}, 2, step / 2);
    const Point_source s = toward(other, on_edge_from_other, apex, step / 2);
    const auto c = method.compute(r, patch), d = method.compute(s, patch);
    const double inside = largest_uv_move(a, b) / step, across = largest_uv_move(c, d) / step;
    BOOST_TEST_MESSAGE(name << ", face " << face << ": largest (u, v) move / distance moved "
                            << inside << " inside the face, " << across
                            << " across an edge (the sphere's exact map: "
                            << exact_move(a, p, b, q) / step << ", "
                            << exact_move(c, r, d, s) / step << ")");
    worst = std::max({worst, inside, across});
  }
  BOOST_TEST(worst <= bound);
}

/// On a planar grid with half its edges flipped, the map from a point of a
/// face on the boundary, of its boundary edge (and of faces anywhere) is
/// the plane's exact map.
template <template <class> class Method>
void check_exact_on_a_plane_from_boundary_faces(double distance_tolerance,
                                                double angle_tolerance) {
  const auto soup = planar_grid(24, true);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  std::vector<Point_source> points;
  std::size_t on_boundary = 0;
  for (Face f : mesh.faces()) {
    if (f.idx() % 7 != 0 || on_boundary == 8) continue;
    const auto h = mesh.halfedge(f);
    const Surface_mesh::Halfedge_index edge[3] = {h, mesh.next(h), mesh.prev(h)};
    for (int k = 0; k < 3; ++k) {
      if (!mesh.is_border(mesh.opposite(edge[k]))) continue;
      points.push_back({f, {{0.2, 0.5, 0.3}}});
      Point_source on_edge{f, {{0, 0, 0}}};  // edge k joins corners k and k + 1
      on_edge.barycentric[k] = 0.3;
      on_edge.barycentric[(k + 1) % 3] = 0.7;
      points.push_back(on_edge);
      ++on_boundary;
      break;
    }
  }
  BOOST_TEST_REQUIRE(on_boundary == 8u);
  for (std::size_t f : random_sources(mesh.number_of_faces(), 4, 17))
    points.push_back({Face(static_cast<Surface_mesh::size_type>(f)), {{0.2, 0.5, 0.3}}});
  double distance = 0, angle = 0;
  for (const Point_source& p : points) {
    const auto source = surface_point_position(mesh, p);
    const auto map = method.compute(p, expmap::Patch::geodesic_radius(0.3));
    BOOST_TEST(map.size() > 10u);  // 17 in a corner of the grid
    for (std::size_t i = 0; i < map.size(); ++i) {
      const auto exact =
          expmap_analytic::plane_exponential_map(source, soup.points[map.indices[i]], map.axis_u);
      distance = std::max(distance, std::abs(map.distance[i] - exact.r));
      angle = std::max(angle, angle_difference(map.angle[i], exact.theta_unrotated));
    }
  }
  BOOST_TEST_MESSAGE("largest errors on the plane: r " << distance << ", theta " << angle);
  BOOST_TEST(distance <= distance_tolerance);
  BOOST_TEST(angle <= angle_tolerance);
}

/// A point walked in steps of 1/60 of a face's coordinates from the face's
/// middle to the middle of an edge, on into the next face's middle, and
/// from there onto a corner, the last step landing on the vertex itself
/// (whose map is the vertex query's): every (u, v) within 0.75 of the
/// radius moves by at most `bound` times the distance moved, so the map
/// comes to the vertex's continuously.
template <template <class> class Method>
void check_path_onto_a_vertex(const char* name, const expmap_analytic::Triangle_soup& soup,
                              double radius, double bound) {
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::geodesic_radius(radius);
  auto within = [&](auto map) {  // the map cut to 0.75 of the radius
    std::size_t kept = 0;
    while (kept < map.size() && map.distance[kept] <= 0.75 * radius) ++kept;
    for (auto* column : {&map.distance, &map.angle}) column->resize(kept);
    map.indices.resize(kept);
    map.vertices.resize(kept);
    return map;
  };
  for (std::size_t f : random_sources(mesh.number_of_faces(), 3, 29)) {
    const Face face(static_cast<Surface_mesh::size_type>(f));
    const auto h = mesh.halfedge(face);
    const Face other = mesh.face(mesh.opposite(h));
    const auto g = mesh.halfedge(other);
    const auto a = mesh.source(h), b = mesh.target(h);
    const Surface_mesh::Vertex_index other_corner[3] = {mesh.source(g), mesh.target(g),
                                                        mesh.target(mesh.next(g))};
    auto in_other = [&](double wa, double wb, double apex) {
      Point_source q{other, {{0, 0, 0}}};
      for (int k = 0; k < 3; ++k)
        q.barycentric[k] = other_corner[k] == a ? wa : other_corner[k] == b ? wb : apex;
      return q;
    };
    const int steps = 20;
    std::vector<Point_source> path;
    for (int i = 0; i <= steps; ++i) {
      const double apex = (1 - static_cast<double>(i) / steps) / 3;
      path.push_back({face, {{(1 - apex) / 2, (1 - apex) / 2, apex}}});
    }
    for (int i = 1; i <= steps; ++i) {
      const double apex = static_cast<double>(i) / steps / 3;
      path.push_back(in_other((1 - apex) / 2, (1 - apex) / 2, apex));
    }
    for (int i = 1; i <= steps; ++i) {
      const double wa = 1.0 / 3 + static_cast<double>(i) / steps * 2.0 / 3;
      path.push_back(in_other(wa, (1 - wa) / 2, (1 - wa) / 2));
    }
    auto previous = within(method.compute(path[0], patch));
    double worst = 0;
    for (std::size_t i = 1; i < path.size(); ++i) {
      const auto map = within(method.compute(path[i], patch));
      const auto x = surface_point_position(mesh, path[i - 1]), y = surface_point_position(mesh, path[i]);
      const double moved = std::hypot(std::hypot(x[0] - y[0], x[1] - y[1]), x[2] - y[2]);
      worst = std::max(worst, largest_uv_move(previous, map) / moved);
      previous = map;
    }
    BOOST_TEST_MESSAGE(name << ", face " << face << " onto a vertex: largest (u, v) move / "
                                                    "distance moved "
                            << worst);
    BOOST_TEST(worst <= bound);
  }
}

/// For a method that is not exact on a plane: points of faces on a planar
/// grid's boundary (half its edges flipped) have largest distance and
/// angle errors (the angle's times r, a length too) against the plane's
/// exact map at most 1.5 times those of the face's corners as sources, and
/// nothing folds.
template <template <class> class Method>
void check_boundary_faces_as_accurate_as_their_corners(const char* name) {
  const auto soup = planar_grid(24, true);
  const auto mesh = to_mesh<Surface_mesh>(soup);
  const Method<Surface_mesh> method(mesh);
  const auto patch = expmap::Patch::geodesic_radius(0.5);
  typename Method<Surface_mesh>::Query query;
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
  for (Face f : mesh.faces()) {
    bool on_boundary = false;
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      on_boundary = on_boundary || mesh.is_border(mesh.opposite(h));
    if (!on_boundary || f.idx() % 7 != 0) continue;
    const Point_source p{f, {{0.2, 0.3, 0.5}}};
    const auto map = method.compute(p, patch, query);
    const auto e = errors(map, surface_point_position(mesh, p));
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
    // Round-off aside: maps exact on the plane (DGPC's, the heat's fallback
    // next to a boundary) are within 1e-15 of it from the point and the
    // corners alike.
    BOOST_TEST(e[0] <= std::max(1.5 * corners[0], 1e-12));
    BOOST_TEST(e[1] <= std::max(1.5 * corners[1], 1e-12));
    // No fold: the fold-free disk is the whole patch.
    BOOST_TEST(*map.fold_free_radius ==
               *std::max_element(map.distance.begin(), map.distance.end()));
    ++checked;
  }
  BOOST_TEST(checked >= 5u);
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_SURFACE_POINT_FIXTURES_H
