#define BOOST_TEST_MODULE expmap_heat_map
#include <boost/test/unit_test.hpp>
