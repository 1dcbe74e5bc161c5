#define BOOST_TEST_MODULE expmap_batch
#include <boost/test/unit_test.hpp>
