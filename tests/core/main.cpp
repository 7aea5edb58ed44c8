#define BOOST_TEST_MODULE granlub core
#include <boost/test/unit_test.hpp>
