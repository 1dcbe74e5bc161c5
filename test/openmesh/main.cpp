#define BOOST_TEST_MODULE expmap_openmesh
#include <boost/test/unit_test.hpp>
