// impact_time on (model impulse / tangential impulse, single pass): each impact applied at its time
// within the step. Through the driver and tests/liggghts/in.impact_time (five grains, impacts that
// fall inside a step): the positions after a head-on pair (across the ranks' boundary on 2 ranks),
// a normal and two oblique wall impacts (stick and Coulomb limits) equal the analytic trajectories
// to round-off at every step, where Sawyer & Tichy's single pass is late by up to a step per impact
// (its position error, first order in dt); the velocities of examples/in.collide stay exact; the
// unsupported combination with iterate on stops with its message.
#define BOOST_TEST_MODULE liggghts_impact_time
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>
#include <string>

#include "collide_checks.h"
#include "run_driver.h"

namespace {

const std::string kDir = std::string(GRANLUB_SOURCE_DIR);
const std::string kDeck = kDir + "/tests/liggghts/in.impact_time";
const std::string kCollide = kDir + "/plugins/liggghts/examples/in.collide";

using granlub::test::results;

// The deck's geometry: every gap 0.1 mm closed at 1 m/s (the pair at 2 m/s): contact at 1e-4 s.
constexpr double kContact = 1e-4, kR = 0.005, kE = 0.5;

// The analytic positions at time t (after the impacts)
std::map<std::string, double> exact(double t) {
    const double after = t - kContact;
    return {{"x1", 0.0449 + kContact - kE * after},
            {"x2", 0.0551 - kContact + kE * after},
            {"z3", kR + kE * after},
            {"x4", 0.05 + kContact + 5.0 / 7.0 * after},  // stick: slip stopped, vx = 5/7
            {"z4", kR + kE * after},
            {"x5", 0.05 + kContact + (1.0 - 0.1 * (1.0 + kE)) * after},  // Coulomb: vx = 1 - mu (1 + e)
            {"z5", kR + kE * after}};
}

// The largest position error of a run, m
double worst_error(double dt, int steps, bool impact, int np = 1) {
    const std::string vars = "-var dt " + std::to_string(dt) + " -var nsteps " + std::to_string(steps) +
                             " -var impact " + (impact ? "on" : "off");
    const auto run = granlub::test::run_driver(kDeck, vars, np);
    const auto r = results(run.output);
    BOOST_TEST_REQUIRE(r.size() == 7u, run.output);
    double worst = 0.0;
    for (const auto& [key, value] : exact(dt * steps)) worst = std::max(worst, std::abs(r.at(key) - value));
    return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(impacts_inside_a_step_are_exact_in_position_single_pass_lags) {
    // dt = 3e-5 and 1.5e-5 s: the contact at 1e-4 s falls a third and two thirds into a step
    const double on_dt = worst_error(3e-5, 100, true), on_half = worst_error(1.5e-5, 200, true);
    const double off_dt = worst_error(3e-5, 100, false), off_half = worst_error(1.5e-5, 200, false);
    BOOST_TEST_MESSAGE("position error (m), dt / dt/2: impact_time on " << on_dt << " / " << on_half
                       << ", single pass " << off_dt << " / " << off_half);
    BOOST_TEST(on_dt <= 1e-12);
    BOOST_TEST(on_half <= 1e-12);
    // the single pass applies each impact at the end of the step it fell in, late by s = 2e-5 and
    // 5e-6 s, and `separate` puts the surfaces back in touch: every grain is e s short of where it
    // would be along the normal (2/7 s and 0.15 s tangentially): first order in dt
    BOOST_TEST(std::abs(off_dt - kE * 2e-5) <= 1e-9);
    BOOST_TEST(std::abs(off_half - kE * 5e-6) <= 1e-9);
}

BOOST_AUTO_TEST_CASE(two_ranks_give_the_exact_positions) {
    // the pair straddles the ranks' boundary at x = 0.05: each owner moves its own grain
    BOOST_TEST(worst_error(3e-5, 100, true, 2) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(collision_velocities_stay_exact) {
    for (const double e : {0.5, 0.9}) granlub::test::check_collide_velocities(kCollide, e, "-var impact on");
}

BOOST_AUTO_TEST_CASE(impact_time_with_iterate_on_is_refused) {
    const auto run = granlub::test::run_driver(kCollide, "-var iterate 1 -var impact on");
    BOOST_TEST(run.output.find("impact_time on is an option of the single pass") != std::string::npos, run.output);
    BOOST_TEST(run.output.find("RESULT") == std::string::npos);
}
