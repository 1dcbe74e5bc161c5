#define BOOST_TEST_MODULE expmap_demo_meshes
#include <boost/test/unit_test.hpp>
