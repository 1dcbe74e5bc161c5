#define BOOST_TEST_MODULE expmap_viewer
#include <boost/test/unit_test.hpp>
