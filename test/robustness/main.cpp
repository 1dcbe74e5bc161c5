#define BOOST_TEST_MODULE expmap_robustness
#include <boost/test/unit_test.hpp>
