#define BOOST_TEST_MODULE expmap_solvers
#include <boost/test/unit_test.hpp>
