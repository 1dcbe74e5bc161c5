// The server side of `expmap view` without HTTP: requests are checked before
// any work, a map from a point of a plane is the plane's exact map, every
// method maps from points and unknown ones are refused by name,
// precomputations happen once and report their steps, queries per method
// are capped and a few more wait their turn, and patches beyond a method's
// limit are refused. (test/viewer/browser_test.mjs drives the server itself
// and the page in Chromium; test/viewer/soak/soak_test.py loads it.)
#include "Map_service.h"
#include "Viewer_json.h"

#include <Analytic_surfaces.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
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

// The message of the `E` that `f` throws, "" if it throws none.
template <class E, class F>
std::string message_of(F f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
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

// A patch every method maps at once.
const expmap::Patch small_patch = expmap::Patch::fraction(0.01);

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

// The page offers the library's methods, by the library's names, in its order.
BOOST_AUTO_TEST_CASE(methods_are_the_librarys) {
  std::vector<std::string> names;
  for (const auto& m : expmap::Option_names<expmap::Map_method>::values) names.push_back(m.name);
  std::vector<std::string> offered;
  for (const Method_info& m : viewer_methods()) offered.push_back(m.name);
  BOOST_TEST(offered == names, boost::test_tools::per_element());
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
  Cache_limits limits;
  limits.queries_per_method = 2;
  limits.waiting_per_method = 0;
  limits.variants_kept = 2;
  Method_cache cache(mesh, limits);
  const Method_info& dgpc = *find_method("dgpc");
  {
    const auto a = cache.acquire(dgpc, 0, small_patch);
    const auto b = cache.acquire(dgpc, 0, small_patch);
    BOOST_TEST(throws_with<Busy>([&] { cache.acquire(dgpc, 0, small_patch); }, "2 queries of dgpc are running and 0 wait"));
  }
  const auto c = cache.acquire(dgpc, 0, small_patch);  // the leases above are returned
  const auto status = cache.status();
  BOOST_REQUIRE(status.size() == 1u);
  BOOST_TEST(status[0].method == "dgpc");
  BOOST_TEST((status[0].state == Precomputation_status::State::ready));

  // A heat method that cannot be built fails once, and is not tried again.
  const Method_info& heat = *find_method("heat");
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -1, small_patch); }, "precomputing heat (m = -1) failed"));
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -1, small_patch); }, "precomputing heat (m = -1) failed"));
  BOOST_TEST(cache.status().size() == 2u);
  // Two time factors are kept: a third makes room by dropping the oldest idle one.
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -2, small_patch); }, "failed"));
  BOOST_TEST(throws_with<Precomputation_failed>([&] { cache.acquire(heat, -3, small_patch); }, "failed"));
  std::size_t heat_entries = 0;
  for (const auto& s : cache.status()) heat_entries += s.method == "heat";
  BOOST_TEST(heat_entries == 2u);
}

// The vertices within a radius of a point of a plane, as the limits count
// them, are the grid points in that disk, counted one by one; counting
// stops just above the cap.
BOOST_AUTO_TEST_CASE(vertices_within_a_radius_are_counted) {
  const Mesh mesh = planar_grid();
  expmap::Surface_point_locator<Mesh> locator(mesh);
  const std::array<double, 3> center{{0.0123, -0.0456, 0}};
  const Point_on_surface p = locator.locate(center);
  for (const double radius : {0.01, 0.1, 0.33, 0.7, 1.5, 3.0}) {
    std::size_t inside = 0;
    for (const auto v : mesh.vertices()) {
      const auto& q = mesh.point(v);
      inside += std::hypot(q.x() - center[0], q.y() - center[1]) <= radius;
    }
    BOOST_TEST_CONTEXT("radius " << radius) {
      BOOST_TEST(expmap_cli::vertices_within(mesh, p.face, center, radius, 100000) == inside);
      BOOST_TEST(expmap_cli::vertices_within(mesh, p.face, center, radius, 50) == std::min<std::size_t>(inside, 51));
    }
  }
  BOOST_TEST(expmap_cli::estimated_patch_vertices(mesh, expmap::Patch::fraction(0.1), p.face, center, 10) ==
             static_cast<std::size_t>(std::ceil(0.1 * mesh.number_of_vertices())));
}

// A patch beyond a method's limit is refused before any precomputation,
// by a fraction or by a radius, with the limit and the way to the map
// anyway; so is an exact map whose submesh is too large; a map within the
// limits is answered.
BOOST_AUTO_TEST_CASE(requests_beyond_a_methods_limit_are_too_large) {
  // 90,601 vertices: a quarter of them is more than the exact limit.
  Mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(300, 300, 2.0, 2.0), mesh);
  const double n = static_cast<double>(mesh.number_of_vertices());
  BOOST_REQUIRE(0.25 * n > max_exact_patch_vertices);
  Map_service service(mesh, {}, "grid.off");
  const auto too_large = [&](Params p, const std::string& quantity, std::size_t maximum,
                             const std::string& text) {
    try {
      service.compute(p);
    } catch (const Too_large& e) {
      BOOST_TEST_MESSAGE(e.what());
      BOOST_TEST(e.method == "exact");
      BOOST_TEST(e.quantity == quantity);
      BOOST_TEST(e.maximum == maximum);
      BOOST_TEST(e.asked > maximum);
      return std::string(e.what()).find(text) != std::string::npos;
    }
    return false;
  };
  const std::string command = "compute the map with 'expmap compute grid.off --method exact --source-point "
                              "0.01,0.02,0 --fraction ";
  BOOST_TEST(too_large({{"point", "0.01,0.02,0"}, {"method", "exact"}, {"fraction", "0.25"}}, "patch_vertices",
                       max_exact_patch_vertices,
                       "fraction 0.25 is 22,651 patch vertices; this server maps at most 20,000 patch "
                       "vertices with exact: ask for a smaller patch (a fraction of at most 0.2207), or " +
                           command + "0.25 -o map.csv'"));
  BOOST_TEST(too_large({{"point", "0.01,0.02,0"}, {"method", "exact"}, {"radius", "2"}}, "patch_vertices",
                       max_exact_patch_vertices,
                       "radius 2 takes in more than 20,000 vertices (counted within that distance in space)"));
  BOOST_TEST(service.cache().status().empty());  // nothing was precomputed for them
  // 19,027 patch vertices, within that limit; their submesh has more than
  // 40,000 faces (the graph distance that reaches them overshoots).
  BOOST_TEST(too_large({{"point", "0.01,0.02,0"}, {"method", "exact"}, {"fraction", "0.21"}}, "region_faces",
                       max_exact_region_faces,
                       "this exact map's submesh (the faces within reach of its geodesics) has more than "
                       "40,000 faces, the most this server maps (up to 1.1 GB; the surface may fold back "
                       "within its reach): ask for a smaller patch, or " + command + "0.21 -o map.csv'"));

  // Other methods map a quarter of it; a radius inside a disk of about
  // 15,000 vertices (the grid's spacing is 2/300) passes the count.
  const Map_response r = service.compute({{"point", "0.01,0.02,0"}, {"method", "dgpc"}, {"fraction", "0.25"}});
  BOOST_TEST(r.map.size() == static_cast<std::size_t>(std::ceil(0.25 * n)));
  const double radius = std::sqrt(15000 / 3.14159265) * 2.0 / 300;
  const Map_response inside =
      service.compute({{"point", "0.01,0.02,0"}, {"method", "dgpc"}, {"radius", std::to_string(radius)}});
  BOOST_TEST(inside.map.size() < max_exact_patch_vertices);
  BOOST_TEST(expmap_cli::vertices_within(mesh, inside.source.face, inside.position, radius,
                                         max_exact_patch_vertices) <= max_exact_patch_vertices);
}

// With its queries all running, a request waits its turn behind those
// before it, up to the queue's length and for at most the longest wait.
BOOST_AUTO_TEST_CASE(waiting_requests_are_served_in_turn) {
  const Mesh mesh = planar_grid();
  Cache_limits limits;
  limits.queries_per_method = 1;
  limits.waiting_per_method = 2;
  limits.max_wait_seconds = 20;
  Method_cache cache(mesh, limits);
  const Method_info& dem = *find_method("dem");
  std::optional<Method_cache::Lease> held(cache.acquire(dem, 0, small_patch));
  std::mutex order_mutex;
  std::vector<int> order;
  const auto waits = [&](int id) {
    return std::thread([&, id] {
      const auto lease = cache.acquire(dem, 0, small_patch);
      std::lock_guard<std::mutex> lock(order_mutex);
      order.push_back(id);
    });
  };
  const auto queued = [&](unsigned count) {
    for (int i = 0; i < 2000; ++i) {
      const auto s = cache.status();
      if (s.size() == 1 && s[0].waiting == count) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  };
  std::thread first = waits(1);
  BOOST_TEST(queued(1));
  std::thread second = waits(2);
  BOOST_TEST(queued(2));
  BOOST_TEST(throws_with<Busy>([&] { cache.acquire(dem, 0, small_patch); }, "1 queries of dem are running and 2 wait"));
  held.reset();
  first.join();
  second.join();
  BOOST_TEST((order == std::vector<int>{1, 2}));

  // A wait that lasts too long ends in Busy.
  limits.max_wait_seconds = 0.2;
  Method_cache impatient(mesh, limits);
  const auto lease = impatient.acquire(dem, 0, small_patch);
  const auto start = std::chrono::steady_clock::now();
  BOOST_TEST(throws_with<Busy>([&] { impatient.acquire(dem, 0, small_patch); }, "waited 0.2 s for one of the 1 queries"));
  BOOST_TEST(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= 0.2);
  BOOST_TEST(impatient.status()[0].waiting == 0u);
}

// While the heat method is precomputed, its status names the step it is in
// and the fraction done; a request for it meanwhile says the same.
BOOST_AUTO_TEST_CASE(precomputation_progress_is_reported) {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(200, 200, 2.0, 2.0), mesh);
  Method_cache cache(mesh, {});
  const Method_info& heat = *find_method("heat");
  std::thread precomputing([&] { cache.acquire(heat, 10, small_patch); });
  std::vector<std::string> steps;
  std::vector<double> fractions;
  std::string busy;
  for (;;) {
    const auto s = cache.status();
    if (!s.empty() && s[0].state != Precomputation_status::State::running) break;
    if (!s.empty() && !s[0].step.empty() && (steps.empty() || steps.back() != s[0].step)) {
      steps.push_back(s[0].step);
      fractions.push_back(s[0].fraction);
      if (busy.empty()) busy = message_of<Busy>([&] { cache.acquire(heat, 10, small_patch); });
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  precomputing.join();
  BOOST_TEST_MESSAGE("steps seen: " << steps.size() << ", busy: " << busy);
  BOOST_TEST(steps.size() >= 3u);
  BOOST_TEST(std::is_sorted(fractions.begin(), fractions.end()));
  BOOST_TEST(busy.find("heat (m = 10) is being precomputed: ") == 0u);
  BOOST_TEST((cache.status()[0].state == Precomputation_status::State::ready));
  BOOST_TEST(cache.status()[0].step == "done");
}

// The viewer's heat method with its queries on subdomains on any mesh (the
// library does so from 200,000 vertices), their cache bound at 1 MiB.
std::unique_ptr<Viewer_method> make_heat_on_subdomains(const Mesh& mesh, double time_factor,
                                                       const expmap::Precomputation_callback& progress) {
  expmap::Heat_options options;
  options.time_factor = time_factor;
  options.progress = progress;
  options.subdomain_min_vertices = 0;
  options.subdomain_cache_bytes = std::size_t(1) << 20;
  return std::make_unique<Viewer_method_model<expmap::Heat_exponential_map<Mesh>>>(mesh, options);
}

// A heat method on subdomains answers small patches at once; the first
// patch too large for them factors the whole mesh first, as a
// precomputation the status reports, and only after dropping other idle
// variants while their bytes and the factors' would exceed the budget. Its
// maps are then the whole mesh's.
BOOST_AUTO_TEST_CASE(heat_factors_the_whole_mesh_for_a_large_patch) {
  Mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(200, 200, 2.0, 2.0), mesh);
  Cache_limits limits;
  limits.variant_bytes_kept = std::size_t(4) << 20;
  Method_cache cache(mesh, limits);
  const Method_info heat{"heat", "heat method", true, max_fast_patch_vertices, 0,
                         make_heat_on_subdomains};
  const expmap::Patch small = expmap::Patch::vertex_count(30), large = expmap::Patch::fraction(0.3);
  const Point_on_surface source{Mesh::Face_index(mesh.number_of_faces() / 2 + 200), {{0.2, 0.3, 0.5}}};
  {
    const auto one = cache.acquire(heat, 1, small);
    BOOST_TEST(!one.method().may_factor_whole_mesh(small));
    BOOST_TEST(one.method().may_factor_whole_mesh(large));
    const auto two = cache.acquire(heat, 2, small);
  }
  BOOST_REQUIRE(cache.status().size() == 2u);  // 1 MiB each: both fit in 4 MiB

  std::atomic<bool> factored{false};
  std::thread factoring([&] {
    const auto lease = cache.acquire(heat, 2, large);
    BOOST_TEST(!lease.method().may_factor_whole_mesh(large));
    factored = true;
  });
  std::string busy, step;
  while (!factored) {
    const auto s = cache.status();
    const auto running = std::find_if(s.begin(), s.end(), [](const Precomputation_status& p) {
      return p.state == Precomputation_status::State::running;
    });
    if (running != s.end() && !running->step.empty() && busy.empty()) {
      step = running->step;
      busy = message_of<Busy>([&] { cache.acquire(heat, 2, small); });
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  factoring.join();
  BOOST_TEST_MESSAGE("step seen: " << step << "; busy: " << busy);
  BOOST_TEST(busy.find("heat (m = 2) is being precomputed: ") == 0u);
  // The first whole-mesh factorization may take the whole budget: the
  // idle variant m = 1 made room for it.
  const auto status = cache.status();
  BOOST_REQUIRE(status.size() == 1u);
  BOOST_TEST(status[0].time_factor == 2.0);
  BOOST_TEST((status[0].state == Precomputation_status::State::ready));
  BOOST_TEST(status[0].step == "done");

  // Its large maps are those of a heat method on the whole mesh's factors.
  const auto lease = cache.acquire(heat, 2, large);
  const Map on_subdomains = lease.method().compute(source, large);
  expmap::Heat_options whole_options;
  whole_options.time_factor = 2;
  const expmap::Heat_exponential_map<Mesh> whole(mesh, whole_options);
  BOOST_REQUIRE(!whole.uses_subdomains());
  const Map reference = whole.compute(source, large);
  BOOST_REQUIRE(on_subdomains.size() == reference.size());
  std::map<std::size_t, double> distance;
  for (std::size_t i = 0; i < reference.size(); ++i)
    distance[reference.indices[i]] = reference.distance[i];
  // The factors order the vertices differently: round-off may swap
  // vertices at equal distance on the patch's rim.
  double largest = 0;
  std::size_t shared = 0;
  for (std::size_t i = 0; i < on_subdomains.size(); ++i) {
    const auto d = distance.find(on_subdomains.indices[i]);
    if (d == distance.end()) continue;
    ++shared;
    largest = std::max(largest, std::abs(on_subdomains.distance[i] - d->second));
  }
  BOOST_TEST_MESSAGE("shared " << shared << " of " << reference.size() << ", largest |dr| " << largest);
  BOOST_TEST(shared >= reference.size() * 99 / 100);
  BOOST_TEST(largest < 1e-9);
}
