#define BOOST_TEST_MODULE expmap_baselines
#include <boost/test/unit_test.hpp>
