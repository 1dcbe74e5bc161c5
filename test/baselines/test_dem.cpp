// The discrete exponential map (DEM): exact on planar meshes, close to the
// analytic map of the sphere, the same on every mesh representation.
#include <expmap/Discrete_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include "baseline_fixtures.h"

using namespace expmap_test;

namespace {
template <class Mesh>
using Dem = expmap::Discrete_exponential_map<Mesh>;
}

BOOST_AUTO_TEST_SUITE(dem)

// Paper, section 7.2: on planar meshes DEM is exact by construction.
BOOST_AUTO_TEST_CASE(exact_on_planar_grids) { check_exact_on_planar_grids<Dem>(1e-10, 1e-9); }

// Measured (5 sources): mean |r error| 1.1e-4 .. 1.6e-4, mean |theta error|
// 1.7e-3 .. 2.6e-3. DEM's angle error does not shrink with the mesh size
// (2.2e-3 on 40,962 vertices): it neglects the stretching of geodesic
// circles (sin r / r) when it adds up edge vectors.
BOOST_AUTO_TEST_CASE(close_to_the_analytic_sphere) { check_sphere_accuracy<Dem>("DEM", 2.5e-4, 4e-3); }

BOOST_AUTO_TEST_CASE(same_on_surface_mesh_and_polyhedron) { check_same_on_all_representations<Dem>(); }

// Count patches hold the vertices DEM freezes first (nearest in graph distance).
BOOST_AUTO_TEST_CASE(patch_kinds) { check_patch_kinds<Dem>(false); }

BOOST_AUTO_TEST_CASE(bad_input) { check_bad_input<Dem>(); }

BOOST_AUTO_TEST_CASE(concurrent_queries) { check_concurrent_queries<Dem>(); }

BOOST_AUTO_TEST_SUITE_END()
