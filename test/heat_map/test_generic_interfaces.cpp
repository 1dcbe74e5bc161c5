// The same map whatever the mesh data structure or the solver model: the
// package is generic over CGAL FaceGraphs and SparseCholeskySolver models.
#include <expmap/Eigen_simplicial_solver.h>
#include <expmap/Heat_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include <thread>

#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;

namespace {

template <class MapA, class MapB>
void check_identical(const MapA& a, const MapB& b, double tolerance) {
  BOOST_TEST_REQUIRE(a.size() == b.size());
  double worst_r = 0, worst_theta = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    BOOST_TEST(a.indices[i] == b.indices[i]);
    worst_r = std::max(worst_r, std::abs(a.distance[i] - b.distance[i]));
    worst_theta = std::max(worst_theta, std::abs(wrap_angle(a.angle[i] - b.angle[i])));
  }
  BOOST_TEST_MESSAGE("largest differences: r " << worst_r << ", theta " << worst_theta);
  BOOST_TEST(worst_r <= tolerance);
  BOOST_TEST(worst_theta <= tolerance);
}

// A solver model that factors the first matrix it is given (the heat
// system) with Eigen and fails on the next one (the Poisson system), as a
// model reports a numerically indefinite matrix: with an exception of its own.
struct Solver_failing_after_first_factor : expmap::Eigen_simplicial_solver {
  static inline int factored = 0;
  void factor(const Matrix& A) {
    if (factored++ > 0) throw std::runtime_error("model: the matrix is not positive definite");
    expmap::Eigen_simplicial_solver::factor(A);
  }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(generic_interfaces)

BOOST_AUTO_TEST_CASE(a_solver_models_failure_is_a_computation_error_naming_the_system) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_icosphere(2, 1.0), mesh);
  Solver_failing_after_first_factor::factored = 0;
  try {
    expmap::Heat_exponential_map<Surface_mesh, CGAL::Default, Solver_failing_after_first_factor>
        heat(mesh);
    BOOST_FAIL("the failing factorization was not reported");
  } catch (const expmap::Computation_error& e) {
    const std::string what = e.what();
    BOOST_TEST_MESSAGE(what);
    BOOST_TEST(what.find("Poisson matrix could not be factored") != std::string::npos);
    BOOST_TEST(what.find("not positive definite") != std::string::npos);
  }
  BOOST_TEST(Solver_failing_after_first_factor::factored == 2);
}

BOOST_AUTO_TEST_CASE(surface_mesh_and_polyhedron_give_identical_maps) {
  const Surface_mesh sm = load_mesh<Surface_mesh>("armadillo.off");
  const Polyhedron poly = load_mesh<Polyhedron>("armadillo.off");
  expmap::Heat_exponential_map<Surface_mesh> on_sm(sm);
  expmap::Heat_exponential_map<Polyhedron> on_poly(poly);
  for (std::size_t source : {17u, 12345u}) {
    const auto a = on_sm.compute_by_index(source, expmap::Patch::fraction(0.05));
    const auto b = on_poly.compute_by_index(source, expmap::Patch::fraction(0.05));
    check_identical(a, b, 1e-10);
  }
}

BOOST_AUTO_TEST_CASE(cholmod_and_eigen_models_give_identical_maps) {
  const Surface_mesh sm = load_mesh<Surface_mesh>("armadillo.off");
  expmap::Heat_exponential_map<Surface_mesh> cholmod(sm);
  expmap::Heat_exponential_map<Surface_mesh, CGAL::Default, expmap::Eigen_simplicial_solver>
      eigen(sm);
  for (std::size_t source : {17u, 12345u}) {
    const auto a = cholmod.compute_by_index(source, expmap::Patch::fraction(0.05));
    const auto b = eigen.compute_by_index(source, expmap::Patch::fraction(0.05));
    check_identical(a, b, 1e-10);
  }
}

BOOST_AUTO_TEST_CASE(class_and_free_function_agree) {
  const Surface_mesh sm = load_mesh<Surface_mesh>("armadillo.off");
  const auto source = *std::next(vertices(sm).begin(), 99);
  expmap::Heat_options options;
  options.laplacian = expmap::Laplacian_mode::intrinsic_delaunay;
  const auto a = expmap::Heat_exponential_map<Surface_mesh>(sm, options)
                     .compute(source, expmap::Patch::vertex_count(500));
  const auto b = expmap::estimate_exponential_map(sm, source, expmap::Patch::vertex_count(500),
                                                  options);
  check_identical(a, b, 0.0);
  BOOST_TEST(a.size() == 500u);
}

BOOST_AUTO_TEST_CASE(results_go_to_property_maps) {
  Surface_mesh sm = load_mesh<Surface_mesh>("armadillo.off");
  auto r = sm.add_property_map<Surface_mesh::Vertex_index, double>("v:r", -1.0).first;
  auto theta = sm.add_property_map<Surface_mesh::Vertex_index, double>("v:theta", -1.0).first;
  auto uv = sm.add_property_map<Surface_mesh::Vertex_index, std::array<double, 2>>(
                  "v:uv", std::array<double, 2>{{0, 0}})
                .first;
  expmap::Heat_exponential_map<Surface_mesh> heat(sm);
  const auto map = heat.compute_by_index(5, expmap::Patch::vertex_count(100));
  expmap::write_to_property_maps(map, r, theta, uv);
  std::size_t written = 0;
  for (auto v : vertices(sm))
    if (get(r, v) >= 0) ++written;
  BOOST_TEST(written == 100u);
  const auto last = map.vertices.back();
  BOOST_TEST(get(uv, last)[0] == map.uv(map.size() - 1)[0]);
  BOOST_TEST(std::hypot(get(uv, last)[0], get(uv, last)[1]) == get(r, last),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(concurrent_queries_match_sequential_ones) {
  const Surface_mesh sm = load_mesh<Surface_mesh>("armadillo.off");
  expmap::Heat_exponential_map<Surface_mesh> heat(sm);
  std::vector<std::size_t> sources{1, 2000, 4000, 8000, 16000, 24000};
  std::vector<expmap::Local_map<Surface_mesh::Vertex_index>> parallel(sources.size());
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < sources.size(); ++t)
    threads.emplace_back([&, t] {
      parallel[t] = heat.compute_by_index(sources[t], expmap::Patch::fraction(0.02));
    });
  for (auto& t : threads) t.join();
  for (std::size_t t = 0; t < sources.size(); ++t)
    check_identical(parallel[t], heat.compute_by_index(sources[t], expmap::Patch::fraction(0.02)),
                    0.0);
}

BOOST_AUTO_TEST_SUITE_END()
