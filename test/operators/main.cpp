#define BOOST_TEST_MODULE expmap_operators
#include <boost/test/unit_test.hpp>
