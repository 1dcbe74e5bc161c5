#define BOOST_TEST_MODULE expmap_patches
#include <boost/test/unit_test.hpp>
