#define BOOST_TEST_MODULE expmap_hostile_input
#include <boost/test/unit_test.hpp>
