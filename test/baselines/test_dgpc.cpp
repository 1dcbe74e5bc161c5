// The discrete geodesic polar coordinates (DGPC): exact on planar meshes, close to the
// analytic map of the sphere, the same on every mesh representation.
#include <expmap/Geodesic_polar_coordinates.h>

#include <boost/test/unit_test.hpp>

#include "baseline_fixtures.h"

using namespace expmap_test;

namespace {
template <class Mesh>
using Dgpc = expmap::Geodesic_polar_coordinates<Mesh>;
}

BOOST_AUTO_TEST_SUITE(dgpc)

// Paper, section 7.2: on planar meshes DGPC is exact by construction.
BOOST_AUTO_TEST_CASE(exact_on_planar_grids) { check_exact_on_planar_grids<Dgpc>(1e-10, 1e-9); }

// The apex's angle sum is rescaled to 2 pi; the boundary ring is never reached.
BOOST_AUTO_TEST_CASE(cone_from_its_apex) { check_cone_from_apex<Dgpc>(1e-10, 1e-9); }

// Measured (5 sources): mean |r error| 9.0e-5 .. 9.4e-5, mean |theta error|
// 4.8e-4 .. 6.1e-4; both shrink on finer spheres (4.2e-5 and 2.5e-4 on
// 40,962 vertices).
BOOST_AUTO_TEST_CASE(close_to_the_analytic_sphere) { check_sphere_accuracy<Dgpc>("DGPC", 1.5e-4, 1e-3); }

BOOST_AUTO_TEST_CASE(same_on_surface_mesh_and_polyhedron) { check_same_on_all_representations<Dgpc>(); }

BOOST_AUTO_TEST_CASE(patch_kinds) { check_patch_kinds<Dgpc>(true); }

BOOST_AUTO_TEST_CASE(bad_input) { check_bad_input<Dgpc>(); }

BOOST_AUTO_TEST_CASE(concurrent_queries) { check_concurrent_queries<Dgpc>(); }

BOOST_AUTO_TEST_SUITE_END()
