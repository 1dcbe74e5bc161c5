#define BOOST_TEST_MODULE expmap_folds
#include <boost/test/unit_test.hpp>
