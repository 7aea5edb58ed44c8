// Momentum in a box periodic in x, y and z (tests/liggghts/in.periodic_momentum: 512 touching
// grains sheared, no wall, no gravity): no external force acts, so the grains' total momentum is
// conserved to rounding. Every pair near a face is a boundary pair, resolved by both owners
// (newton off), on one rank as periodic images and on two across the ranks too; the two sides must
// give equal and opposite impulses. With model impulse's boundary_start on the single pass takes such
// a pair's geometry from the positions as the pass began (plugins/liggghts/models/impulse_boundary.h);
// off (the default, every earlier result), `separate` moves the owned grain but not its image, and
// the box gains momentum (measured 2026-12-06, below).
#define BOOST_TEST_MODULE liggghts_periodic_momentum
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "run_driver.h"

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/tests/liggghts/in.periodic_momentum";

// The largest change of a momentum component over the run, relative to the grains' summed
// |m v| at the start.
double drift(const std::string& vars, int np) {
    const auto run = granlub::test::run_driver(kDeck, vars, np, "liggghts_periodic_momentum");
    const auto r = granlub::test::results(run.output);
    BOOST_TEST_REQUIRE(r.size() == 8u, run.output);
    double worst = 0.0;
    for (const char* k : {"px", "py", "pz"})
        worst = std::max(worst, std::abs(r.at(std::string(k) + "1") - r.at(std::string(k) + "0")));
    const double d = worst / r.at("pa0");
    BOOST_TEST_MESSAGE(vars << " on " << np << " rank(s): momentum drift " << d << " of sum |m v|");
    return d;
}

// Rounding: the two sides compute each impulse from the same numbers up to the rounding of the
// periodic shift (1e-16 of the box), so each pair leaves ~1e-16 of its impulse; a random walk over
// ~1000 contacts and 1000 steps stays near 1e-13, and the printed sums resolve 1e-15 of them.
// Measured 2026-12-06 (on 0d893b8): at most 1e-16 of sum |m v| on 1 and 2 ranks, single pass with
// boundary_start on (also speculative on) and iterated solve alike; with boundary_start off, 2.2e-3
// (1 rank), 2.1e-3 (2 ranks), 1.1e-3 (speculative on), and 0 with separate off (nothing moved in
// the pass).
constexpr double kTolerance = 1e-12;
// boundary_start off leaks: well above rounding, well below the measured 2.2e-3
constexpr double kLeak = 1e-5;

}  // namespace

BOOST_AUTO_TEST_CASE(the_single_pass_with_boundary_start_conserves_momentum_across_periodic_boundaries) {
    for (const int np : {1, 2}) BOOST_TEST(drift("", np) < kTolerance, np << " rank(s)");
}

// the default, the sequential geometry of every earlier result: the switch is what conserves
BOOST_AUTO_TEST_CASE(without_boundary_start_the_single_pass_leaks_momentum) {
    BOOST_TEST(drift("-var bstart off", 1) > kLeak);
}

// the iterated solve refuses boundary_start on: it resolves boundary pairs from one state already
BOOST_AUTO_TEST_CASE(boundary_start_with_the_iterated_solve_is_refused) {
    const auto run = granlub::test::run_driver(kDeck, "-var iterate 1", 1, "liggghts_periodic_momentum");
    BOOST_TEST(run.output.find("boundary_start on is an option of the single pass") != std::string::npos, run.output);
}

BOOST_AUTO_TEST_CASE(the_single_pass_with_speculative_contacts_conserves_momentum) {
    BOOST_TEST(drift("-var spec on", 1) < kTolerance);
}

BOOST_AUTO_TEST_CASE(the_iterated_solve_conserves_momentum_across_periodic_boundaries) {
    for (const int np : {1, 2}) BOOST_TEST(drift("-var iterate 1 -var bstart off", np) < kTolerance, np << " rank(s)");
}
