// The velocities after examples/in.collide's impacts (head-on pair, normal wall impact, oblique
// stick and Coulomb limits) against their analytic values, to round-off: the collision proofs an
// option of the impulse models must keep (test_impact_time.cpp, test_speculative.cpp).
#pragma once

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "run_driver.h"

namespace granlub::test {

inline void check_collide_velocities(const std::string& collide_deck, double e, const std::string& vars) {
    const auto r = results(run_driver(collide_deck, "-var e " + std::to_string(e) + " " + vars).output);
    BOOST_TEST_REQUIRE(r.count("vx1") == 1u);
    const auto close = [](double a, double b) { BOOST_TEST(std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b))); };
    close(r.at("vx1"), -e);
    close(r.at("vx2"), e);
    close(r.at("vz3"), e);
    close(r.at("vx4"), 5.0 / 7.0);
    close(r.at("vz4"), e);
    close(r.at("vx5"), 1.0 - 0.1 * (1.0 + e));
}

}  // namespace granlub::test
