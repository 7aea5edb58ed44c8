// Boost.Test precondition for suites that need YADE itself: skip, with the install hint, when
// neither $GRANLUB_YADE nor `yade` on PATH is found.
#pragma once
#include <cstdlib>

#include <boost/test/unit_test.hpp>

#include "granlub/run/process.h"

namespace granlub::yade::test {

struct YadeInstalled {
    boost::test_tools::assertion_result operator()(boost::unit_test::test_unit_id) const {
        const char* env = std::getenv("GRANLUB_YADE");
        if (find_executable(env && *env ? env : "yade")) return true;
        boost::test_tools::assertion_result r(false);
        r.message() << "YADE is not installed (apt-get install -y --no-install-recommends yade): skipped";
        return r;
    }
};

}  // namespace granlub::yade::test
