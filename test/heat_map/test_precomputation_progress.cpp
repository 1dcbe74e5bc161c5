// The heat method's precomputation reports its steps through
// Heat_options::progress: in order, with growing fractions, "done" last;
// an exception from the callback ends the precomputation; the object keeps
// no copy of the callback; and reporting changes no map.
#include <expmap/Heat_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;

namespace {

struct Report {
  std::string step;
  double fraction;
};

}  // namespace

BOOST_AUTO_TEST_CASE(steps_are_reported_in_order_and_end_with_done) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(30, 30, 2.0, 2.0), mesh);  // a boundary
  std::vector<Report> reports;
  expmap::Heat_options options;
  options.progress = [&](const char* step, double fraction) { reports.push_back({step, fraction}); };
  const expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options);

  const std::vector<std::string> expected{"locality order",
                                          "intrinsic Delaunay triangulation",
                                          "cotan operators",
                                          "heat factorization",
                                          "boundary heat factorization",
                                          "Poisson factorization",
                                          "Poisson compression",
                                          "query workspace",
                                          "done"};
  BOOST_REQUIRE_EQUAL(reports.size(), expected.size());
  for (std::size_t i = 0; i < reports.size(); ++i) {
    BOOST_TEST(reports[i].step == expected[i]);
    BOOST_TEST((reports[i].fraction >= 0 && reports[i].fraction <= 1));
    if (i > 0) BOOST_TEST(reports[i].fraction > reports[i - 1].fraction, reports[i].step);
  }
  BOOST_TEST(reports.back().fraction == 1.0);
  BOOST_TEST(reports[reports.size() - 2].fraction < 1.0);
  // The object keeps no callback that could outlive what it refers to.
  BOOST_TEST(!heat.options().progress);

  // A closed mesh has no boundary to factor: that step is not reported.
  Surface_mesh sphere;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_icosphere(3), sphere);
  reports.clear();
  const expmap::Heat_exponential_map<Surface_mesh> closed(sphere, options);
  BOOST_TEST(reports.size() == expected.size() - 1);
  for (const Report& r : reports) BOOST_TEST(r.step != "boundary heat factorization");

  // Reporting changes nothing: the same map with and without a callback.
  const auto a = heat.compute_by_index(40, expmap::Patch::fraction(0.2));
  const auto b = expmap::Heat_exponential_map<Surface_mesh>(mesh).compute_by_index(
      40, expmap::Patch::fraction(0.2));
  BOOST_TEST_REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    BOOST_TEST(a.distance[i] == b.distance[i]);
    BOOST_TEST(a.angle[i] == b.angle[i]);
  }
}

BOOST_AUTO_TEST_CASE(an_exception_from_the_callback_cancels_the_precomputation) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(20, 20, 2.0, 2.0), mesh);
  struct Cancelled : std::runtime_error {
    Cancelled() : std::runtime_error("cancelled") {}
  };
  std::vector<std::string> steps;
  expmap::Heat_options options;
  options.progress = [&](const char* step, double) {
    steps.push_back(step);
    if (steps.back() == "Poisson factorization") throw Cancelled();
  };
  BOOST_CHECK_THROW(expmap::Heat_exponential_map<Surface_mesh>(mesh, options), Cancelled);
  BOOST_TEST(steps.back() == "Poisson factorization");
}
