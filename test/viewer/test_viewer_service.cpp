// The server side of `expmap view` without HTTP: requests are checked before
// any work, a map from a point of a plane is the plane's exact map, every
// method maps from points and unknown ones are refused by name,
// precomputations happen once, and queries per method are capped. (test/viewer/browser_test.mjs drives the
// server itself and the page in Chromium.)
#include "Map_service.h"
#include "Viewer_json.h"

#include <Analytic_surfaces.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using namespace expmap_view;

namespace {

using Params = std::multimap<std::string, std::string>;

// Whether `f()` throws an `E` whose message contains `text`.
template <class E, class F>
bool throws_with(F f, const std::string& text) {
  try {
    f();
  } catch (const E& e) {
    if (std::string(e.what()).find(text) != std::string::npos) return true;
    BOOST_TEST_MESSAGE("message was: " << e.what());
    return false;
  }
  return false;
}

// The numbers of the array `"name":[...]` in `json`, read back; an entry
// that is no number (such as null) reads as NaN.
std::vector<double> json_numbers(const std::string& json, const std::string& name) {
  const std::string head = "\"" + name + "\":[";
  const std::string::size_type start = json.find(head);
  BOOST_REQUIRE_MESSAGE(start != std::string::npos, "no array " << name);
  const std::string::size_type end = json.find(']', start);
  BOOST_REQUIRE(end != std::string::npos);
  std::vector<double> values;
  std::string::size_type i = start + head.size();
  while (i < end) {
    const std::string::size_type comma = std::min(json.find(',', i), end);
    const std::string item = json.substr(i, comma - i);
    char* stop = nullptr;
    const double x = std::strtod(item.c_str(), &stop);
    values.push_back(!item.empty() && stop == item.c_str() + item.size() ? x : std::nan(""));
    i = comma + 1;
  }
  return values;
}

// Whether the JSON of `r` holds its map's r, theta, u and v, every value
// finite and read back exactly.
bool json_holds_the_map(const Map_response& r) {
  const std::string json = map_json(r);
  const std::vector<double> distance = json_numbers(json, "r"), angle = json_numbers(json, "theta"),
                            u = json_numbers(json, "u"), v = json_numbers(json, "v");
  if (distance.size() != r.map.size() || angle.size() != r.map.size() || u.size() != r.map.size() ||
      v.size() != r.map.size())
    return false;
  for (std::size_t i = 0; i < r.map.size(); ++i) {
    const auto uv = r.map.uv(i);
    for (const double x : {distance[i], angle[i], u[i], v[i]})
      if (!std::isfinite(x)) return false;
    if (distance[i] != r.map.distance[i] || angle[i] != r.map.angle[i] || u[i] != uv[0] || v[i] != uv[1])
      return false;
  }
  return true;
}

Mesh planar_grid() {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(24, 24, 2.0, 2.0), mesh);
  return mesh;
}

}  // namespace

BOOST_AUTO_TEST_CASE(requests_are_checked) {
  Request_limits limits;
  limits.max_radius = 2;
  const auto bad = [&](Params p, const std::string& text) {
    return throws_with<Bad_request>([&] { parse_map_request(p, limits); }, text);
  };
  BOOST_TEST(bad({{"method", "dgpc"}, {"fraction", "0.1"}}, "point=X,Y,Z is required"));
  BOOST_TEST(bad({{"point", "1,2"}, {"method", "dgpc"}, {"fraction", "0.1"}}, "three comma-separated"));
  BOOST_TEST(bad({{"point", "1,2,inf"}, {"method", "dgpc"}, {"fraction", "0.1"}}, "finite number"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"fraction", "0.1"}}, "method is required"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}}, "exactly one of fraction"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"fraction", "0.1"}, {"radius", "1"}},
                 "exactly one of fraction"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"fraction", "0.5"}}, "fraction must be in (0, 0.25"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"radius", "3"}}, "radius must be in"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"radius", "-1"}}, "radius must be in"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"fraction", "0.1"}, {"m", "10"}}, "only to method=heat"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "heat"}, {"fraction", "0.1"}, {"m", "1e9"}}, "m must be in"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"fraction", "0.1"}, {"fraction", "0.2"}},
                 "'fraction' is given more than once"));
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"fraction", "0.1"}, {"colour\n", "1"}},
                 "unknown parameter 'colour?'"));

  // Values echoed into messages are cut short and shown in printable ASCII.
  BOOST_TEST(shown(std::string("a\xff\n") + std::string(100, 'b')) == "a??" + std::string(37, 'b') + "...");
  BOOST_TEST(shown("0.5") == "0.5");
  BOOST_TEST(bad({{"point", "1,2,3"}, {"method", "dgpc"}, {"fraction", "0.1\xc3" + std::string(200, '9')}},
                 "fraction must be a finite number (got '0.1?" + std::string(36, '9') + "...')"));
  BOOST_TEST(bad({{"point", "1,2,\x80" + std::string(200, '9')}, {"method", "dgpc"}, {"fraction", "0.1"}},
                 "(got '?" + std::string(39, '9') + "...')"));
  // JSON strings stay valid UTF-8: a valid sequence passes, stray bytes,
  // surrogates and overlong forms become '?'.
  BOOST_TEST(error_json("x\xe2\x82\xac\xff\xed\xa0\x80\xc0\xaf\"") ==
             "{\"error\":\"x\xe2\x82\xac??????\\\"\"}");

  const Map_request r = parse_map_request(
      {{"point", "0.5,-1e-3,2"}, {"method", "heat"}, {"radius", "0.25"}, {"m", "12.5"}}, limits);
  BOOST_TEST(r.point[0] == 0.5);
  BOOST_TEST(r.point[1] == -1e-3);
  BOOST_TEST(r.point[2] == 2.0);
  BOOST_TEST(r.method == "heat");
  BOOST_TEST(!r.fraction.has_value());
  BOOST_TEST(*r.radius == 0.25);
  BOOST_TEST(*r.time_factor == 12.5);
}

// On a plane the map from any point is exact: r is the distance in the
// plane, and the angle between two vertices seen from the point is the
// plane's.
BOOST_AUTO_TEST_CASE(map_from_a_point_of_a_plane_is_exact) {
  const Mesh mesh = planar_grid();
  Map_service service(mesh);
  const std::array<double, 3> p{{0.0123, -0.0456, 0.2}};  // above the plane: its foot is the source
  const Map_response r = service.compute(
      {{"point", "0.0123,-0.0456,0.2"}, {"method", "dgpc"}, {"radius", "0.5"}});
  BOOST_TEST(r.method == "dgpc");
  BOOST_TEST(std::abs(r.position[0] - p[0]) < 1e-12);
  BOOST_TEST(std::abs(r.position[1] - p[1]) < 1e-12);
  BOOST_TEST(std::abs(r.position[2]) < 1e-12);
  BOOST_TEST(r.map.size() > 100u);
  BOOST_TEST(r.flipped_faces.empty());
  BOOST_TEST(r.triangles > 100u);
  BOOST_TEST(r.map.fold_free_radius.has_value());
  double worst_r = 0, worst_angle = 0;
  const auto xy = [&](std::size_t i) {
    const auto& q = mesh.point(r.map.vertices[i]);
    return std::array<double, 2>{{q.x() - p[0], q.y() - p[1]}};
  };
  for (std::size_t i = 0; i < r.map.size(); ++i) {
    const auto d = xy(i);
    worst_r = std::max(worst_r, std::abs(r.map.distance[i] - std::hypot(d[0], d[1])));
    BOOST_TEST(r.map.distance[i] <= 0.5 + 1e-12);
    // The angle from the first vertex to this one, in the map and in the plane.
    const auto d0 = xy(0);
    const double plane = std::atan2(d0[0] * d[1] - d0[1] * d[0], d0[0] * d[0] + d0[1] * d[1]);
    double map = r.map.angle[i] - r.map.angle[0];
    map = std::atan2(std::sin(map - plane), std::cos(map - plane));
    worst_angle = std::max(worst_angle, std::abs(map));
  }
  BOOST_TEST(worst_r < 1e-12);
  BOOST_TEST(worst_angle < 1e-9);

  const std::string json = map_json(r);
  BOOST_TEST(json.find("\"fold_free_radius\":") != std::string::npos);
  BOOST_TEST(json.find("\"flipped\":0,") != std::string::npos);
  BOOST_TEST(json_holds_the_map(r));

  // The check above sees a null (the reading of a NaN that JSON cannot
  // carry) as not finite.
  const std::vector<double> read = json_numbers("{\"r\":[1.5,null,2]}", "r");
  BOOST_TEST((read.size() == 3u && read[0] == 1.5 && std::isnan(read[1]) && read[2] == 2));
  // A map with a value that is not finite is refused, not written as null.
  Map_response broken = r;
  broken.map.distance[3] = std::nan("");
  BOOST_TEST(throws_with<expmap::Computation_error>([&] { map_json(broken); },
                                                    "a value of \"r\" is not finite"));
  broken = r;
  broken.map.angle[0] = HUGE_VAL;
  BOOST_TEST(throws_with<expmap::Computation_error>([&] { map_json(broken); }, "\"theta\""));
}

BOOST_AUTO_TEST_CASE(methods_are_checked_by_name) {
  const Mesh mesh = planar_grid();
  Map_service service(mesh);
  BOOST_TEST(throws_with<Bad_request>(
      [&] { service.compute({{"point", "0,0,0"}, {"method", "nope"}, {"fraction", "0.1"}}); },
      "unknown method 'nope' (known: heat, dem, dgpc, exact)"));
  BOOST_TEST(throws_with<Bad_request>(
      [&] { service.compute({{"point", "-1e308,0,1e308"}, {"method", "dgpc"}, {"fraction", "0.1"}}); },
      "point must be near the mesh"));
  BOOST_TEST(throws_with<Bad_request>(
      [&] { service.compute({{"point", "0,0,3"}, {"method", "dgpc"}, {"fraction", "0.1"}}); },
      "point must be near the mesh"));
  // Nothing was precomputed for the refused requests.
  BOOST_TEST(service.cache().status().empty());
}

// Every method maps from a point inside a face: the located point is the
// one asked for, no vertex is at it, and the distances are the plane's.
BOOST_AUTO_TEST_CASE(every_method_maps_from_a_point) {
  const Mesh mesh = planar_grid();
  Map_service service(mesh);
  const std::array<double, 3> p{{0.0123, -0.0456, 0}};
  for (const Method_info& m : viewer_methods()) {
    BOOST_TEST_CONTEXT(m.name) {
      const Map_response r =
          service.compute({{"point", "0.0123,-0.0456,0"}, {"method", m.name}, {"radius", "0.3"}});
      BOOST_TEST(r.method == m.name);
      for (int d = 0; d < 3; ++d) BOOST_TEST(std::abs(r.position[d] - p[d]) < 1e-12);
      BOOST_TEST(r.map.size() > 20u);
      double worst = 0;
      for (std::size_t i = 0; i < r.map.size(); ++i) {
        const auto& q = mesh.point(r.map.vertices[i]);
        const double plane = std::hypot(q.x() - p[0], q.y() - p[1]);
        BOOST_TEST((r.map.distance[i] > 0 && std::isfinite(r.map.angle[i])));
        worst = std::max(worst, std::abs(r.map.distance[i] - plane) / plane);
      }
      BOOST_TEST_MESSAGE(m.name << ": largest relative distance error " << worst);
      // DEM, DGPC and exact are exact on a plane; heat is smoothed (its
      // largest relative error here is 0.14).
      BOOST_TEST(worst < (std::string(m.name) == "heat" ? 0.2 : 1e-12));
      BOOST_TEST(json_holds_the_map(r));
    }
  }
}

BOOST_AUTO_TEST_CASE(precomputed_once_and_queries_capped) {
  const Mesh mesh = planar_grid();
  Method_cache cache(mesh, 2, 2);
  const Method_info& dgpc = *find_method("dgpc");
  {
    const auto a = cache.acquire(dgpc, 0);
    const auto b = cache.acquire(dgpc, 0);
    BOOST_TEST(throws_with<Busy>([&] { cache.acquire(dgpc, 0); }, "2 queries of dgpc are running"));
  }
  const auto c = cache.acquire(dgpc, 0);  // the leases above are returned
  const auto status = cache.status();
  BOOST_REQUIRE(status.size() == 1u);
  BOOST_TEST(status[0].method == "dgpc");
  BOOST_TEST((status[0].state == Precomputation_status::State::ready));

  // A heat method that cannot be built fails once, and is not tried again.
  const Method_info& heat = *find_method("heat");
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -1); }, "precomputing heat (m = -1) failed"));
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -1); }, "precomputing heat (m = -1) failed"));
  BOOST_TEST(cache.status().size() == 2u);
  // Two time factors are kept: a third makes room by dropping the oldest idle one.
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -2); }, "failed"));
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -3); }, "failed"));
  std::size_t heat_entries = 0;
  for (const auto& s : cache.status()) heat_entries += s.method == "heat";
  BOOST_TEST(heat_entries == 2u);
}
