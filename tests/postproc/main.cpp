#define BOOST_TEST_MODULE granlub postproc
#include <boost/test/unit_test.hpp>
