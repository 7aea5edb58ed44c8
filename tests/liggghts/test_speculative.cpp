// speculative on (model impulse / tangential impulse, single pass or iterated): contacts activated on their
// predicted gap (plugins/liggghts/models/impulse_speculative.h). Through the driver: the velocities
// of examples/in.collide (head-on pair, normal wall impact, oblique stick and Coulomb) stay exact;
// on tests/liggghts/in.impact_time the grains turn at the start of the step in which the surfaces
// would meet, never overlapping, so each is (1 + e) s' short of the analytic trajectory along the
// normal, s' the time left to contact (1e-5 s at both steps; 1 and 2 ranks), in the single pass and
// in the iterated solve (speculative contacts inside fix impulse/solve); impact_time with speculative
// stops with the model's message.
#define BOOST_TEST_MODULE liggghts_speculative
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "collide_checks.h"
#include "run_driver.h"

namespace {

const std::string kDir = std::string(GRANLUB_SOURCE_DIR);
const std::string kDeck = kDir + "/tests/liggghts/in.impact_time";
const std::string kCollide = kDir + "/plugins/liggghts/examples/in.collide";

using granlub::test::results;

constexpr double kContact = 1e-4, kR = 0.005, kE = 0.5;  // in.impact_time: contact at 1e-4 s, e = 0.5

}  // namespace

BOOST_AUTO_TEST_CASE(collision_velocities_stay_exact) {
    for (const double e : {0.5, 0.9}) {
        granlub::test::check_collide_velocities(kCollide, e, "-var spec on");
        granlub::test::check_collide_velocities(kCollide, e, "-var spec on -var iterate 1");  // in the iterated solve
    }
}

BOOST_AUTO_TEST_CASE(grains_turn_before_they_touch) {
    // the pair straddles the ranks' boundary at x = 0.05 on 2 ranks: each owner turns its own grain
    // the single pass and the iterated solve (fix impulse/solve made by the pair style) alike
    for (const auto& [dt, np, iter] : {std::tuple{3e-5, 1, "off"}, std::tuple{1.5e-5, 1, "off"}, std::tuple{3e-5, 2, "off"},
                                       std::tuple{3e-5, 1, "on"}, std::tuple{1.5e-5, 1, "on"}, std::tuple{3e-5, 2, "on"}}) {
        BOOST_TEST_CONTEXT("dt " << dt << ", " << np << " ranks, iterate " << iter) {
        const int steps = static_cast<int>(std::lround(3e-3 / dt));
        const auto r = results(granlub::test::run_driver(
                                   kDeck, "-var dt " + std::to_string(dt) + " -var nsteps " + std::to_string(steps) +
                                              " -var impact off -var spec on -var iter " + iter, np)
                                   .output);
        BOOST_TEST_REQUIRE(r.count("z3") == 1u);
        // the last step before contact starts 1e-5 s before it (at 9e-5 s for both steps): turned there
        const double t = dt * steps, early = 1e-5, after = t - (kContact - early);
        const auto close = [](double a, double b) { BOOST_TEST(std::abs(a - b) <= 1e-12, a << " vs " << b); };
        close(r.at("x1"), 0.0449 + kContact - early - kE * after);
        close(r.at("x2"), 0.0551 - kContact + early + kE * after);
        close(r.at("z3"), kR + early + kE * after);  // above the wall by e s' more than at contact
        close(r.at("z4"), kR + early + kE * after);
        close(r.at("z5"), kR + early + kE * after);
        }
    }
}

BOOST_AUTO_TEST_CASE(unsupported_combinations_are_refused) {
    const auto both = granlub::test::run_driver(kCollide, "-var impact on -var spec on");
    BOOST_TEST(both.output.find("at most one of them on") != std::string::npos, both.output);
    BOOST_TEST(both.output.find("RESULT") == std::string::npos);
}
