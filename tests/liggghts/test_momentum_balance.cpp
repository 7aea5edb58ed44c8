// The wall forces `granlub dem` records balance the grains' momentum in steady state: per floor
// area, P_bot - P_top = weight - side_wall_support (vertical) and tau_top = tau_bot + the side
// walls' drag (streamwise; side walls move with the floor). Before the impulse model resolved
// contacts across a periodic boundary from the start-of-step state, the two owners of such a pair
// gave it different impulses: a bed riding on its floor kept its velocity while the walls
// recorded a net streamwise force of 4.4 Pa and 16 % more than its weight (measured 2026-11-23).
#define BOOST_TEST_MODULE liggghts_momentum_balance
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "granlub/case/case.h"
#include "granlub/dem/command.h"
#include "granlub/results/results.h"
#include "granlub/run/sweep.h"
#include "tiny_cell.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

struct Balance {
    double vertical = 0;    // P_bot - P_top - (weight - side support), Pa
    double streamwise = 0;  // tau_top - tau_bot - side drag, Pa
    double vertical_se = 0, streamwise_se = 0;
    double weight = 0;      // Pa
    double p_top = 0, p_top_se = 0;  // the top wall's normal stress, Pa
};

// The tiny cell (220 grains of 1 mm, 8 x 6 x 6 mm, side walls) at its inserted fill, 0.4 s.
std::string tiny(const std::string& name, bool centripetal) {
    std::string text = test::tiny_cell(name, "", "time = 0.4\n");
    if (!centripetal) text = test::edit(text, "annulus_radius = 0.05", "annulus_radius = 0.0");
    return text;
}

Balance run(const std::string& name, const std::string& text, int np = 1) {
    Schema schema = test::dem_schema();
    const Case c = parse_case(text, name + ".toml", schema);
    RunOptions o;
    o.results_root = test::scratch("liggghts_momentum_balance", name);
    o.np = np;
    BOOST_TEST_REQUIRE(dem::run(c, o) == 0);
    const Summary s = read_summary(result_dir(o.results_root, "dem", c.points.front().id) / "summary.json");
    auto v = [&](const char* k) { return s.outputs.at(k).value; };
    auto e = [&](const char* k) { return s.outputs.at(k).stderr_.value_or(0.0); };
    const double grains = s.run.at("atoms").get<double>();  // the grains LIGGGHTS ran
    const double area = c.cell.length * c.cell.width;
    Balance b;
    b.weight = grains * std::numbers::pi / 6.0 * std::pow(c.grains.diameter, 3) * c.grains.density * c.gravity / area;
    b.p_top = v("normal_stress_top");
    b.p_top_se = e("normal_stress_top");
    b.vertical = v("normal_stress_bottom") - v("normal_stress_top") - (b.weight - v("side_wall_support"));
    b.vertical_se = std::hypot(e("normal_stress_bottom"), e("normal_stress_top"), e("side_wall_support"));
    // side drag per floor area: both walls' force (2 x stress x L H) over L W
    const double side = 2.0 * v("shear_stress_side") * c.cell.gap / c.cell.width;
    b.streamwise = v("shear_stress_top") - v("shear_stress_bottom") - side;
    b.streamwise_se = std::hypot(e("shear_stress_top"), e("shear_stress_bottom"),
                                 2.0 * e("shear_stress_side") * c.cell.gap / c.cell.width);
    BOOST_TEST_MESSAGE(name << ": weight " << b.weight << " Pa; vertical imbalance " << b.vertical << " +- "
                            << b.vertical_se << " Pa, streamwise " << b.streamwise << " +- " << b.streamwise_se);
    return b;
}

}  // namespace

// Without the centripetal force the bed settles and rides with the floor and the side walls: no
// shear, and the forces are steady enough for a tight check.
BOOST_AUTO_TEST_CASE(a_bed_riding_on_its_floor_balances) {
    const Balance b = run("riding", tiny("riding", false));
    BOOST_TEST(std::abs(b.vertical) < 0.01 * b.weight);  // was +16 %
    BOOST_TEST(std::abs(b.streamwise) < 0.5);            // Pa; was -4.4
}

// The same bed with its contacts solved by fix impulse/solve (contact_solve = "iterated"), on 1
// and 2 ranks: a pair across the periodic boundary, or across the ranks' boundary, is solved by
// both of its owners from the same state in every sweep, so they give it equal and opposite
// impulses whether or not the sweeps have converged; the cap of 50 sweeps keeps the test short.
// Measured 2026-11-25 (cap 200): vertical imbalance 5e-5 / 2e-5 Pa on 1 / 2 ranks (single pass 0.21).
BOOST_AUTO_TEST_CASE(a_bed_riding_on_its_floor_balances_when_its_contacts_are_solved) {
    const std::string text = test::edit(tiny("riding_iterated", false), "time = 0.4",
                                        "time = 0.4\ncontact_solve = \"iterated\"\nsolve_iterations = 50");
    for (const int np : {1, 2}) {
        const Balance b = run("riding_iterated_np" + std::to_string(np), text, np);
        BOOST_TEST(std::abs(b.vertical) < 0.01 * b.weight, np << " ranks");
        BOOST_TEST(std::abs(b.streamwise) < 0.5, np << " ranks");  // Pa
    }
}

// Sheared, with the centripetal force pressing the grains onto a side wall.
BOOST_AUTO_TEST_CASE(a_sheared_layer_on_its_side_wall_balances) {
    const Balance b = run("sheared", tiny("sheared", true));
    BOOST_TEST(std::abs(b.vertical) < 0.1 * b.weight);  // was +30 % (17 Pa)
    BOOST_TEST(std::abs(b.vertical) < 3.0 * b.vertical_se + 0.01 * b.weight);
    BOOST_TEST(std::abs(b.streamwise) < 3.0 * b.streamwise_se + 0.05 * b.weight);  // was -20 Pa
}

// Hertz contacts (1 GPa) under load control: the deck moves the plate in jumps, and with the
// servo's rigid-grain gain (0.05 d per unit error, ~300 contact overlaps at this load) each jump
// hammered the loaded contacts, and the walls recorded 116 Pa (twice the weight) more upward
// force than the grains' weight (measured 2026-11-24; on sawyer2001's cell it also dilated the
// bed, nu 0.55 instead of 0.58). The gain is now capped at one contact overlap per unit error.
BOOST_AUTO_TEST_CASE(hertz_grains_under_a_servo_plate_balance) {
    std::string text = test::tiny_cell("hertz_load", "control = \"load\"\nnormal_stress = 1000.0\n",
                                       "model = \"hertz\"\ntime = 0.3\nservo_plate = \"window\"\n");
    text = test::edit(text, "gap = 6.0e-3", "gap = 4.4e-3");  // the inserted grains' gap under the load
    text = test::edit(text, "solid_fraction = 0.4", "solid_fraction = 0.545");
    text = test::edit(text, "friction = 0.5\n\\[walls\\]", "friction = 0.5\nyoungs_modulus = 1e9\n[walls]");
    const Balance b = run("hertz_load", text);
    // (the block errors of the spiky plate force, ~170 Pa, are no yardstick here; the run is deterministic)
    BOOST_TEST(std::abs(b.vertical) < 0.1 * b.weight);  // was +2.0 weights
}

// Rigid grains sheared under a weighted plate (servo_plate = "weight", the default): the plate's
// own Newton's law holds its mean force on the grains at P A, so P_top is the load within its
// error bar, and the walls carry the grains' weight plus the load, nothing more. (The window
// servo's jumps into rigid grains made its window forces spike to 6x the load, and its clamp then
// held P_top above P at small steps: docs/measurements/liggghts.md.)
BOOST_AUTO_TEST_CASE(rigid_grains_under_a_weighted_plate_balance) {
    std::string text = test::tiny_cell("weight_load", "control = \"load\"\nnormal_stress = 300.0\n", "time = 0.4\n");
    text = test::edit(text, "solid_fraction = 0.4", "solid_fraction = 0.5");
    const Balance b = run("weight_load", text);
    BOOST_TEST_MESSAGE("P_top " << b.p_top << " +- " << b.p_top_se << " Pa");
    BOOST_TEST(std::abs(b.p_top - 300.0) < 3.0 * b.p_top_se + 0.01 * 300.0);
    BOOST_TEST(std::abs(b.vertical) < 3.0 * b.vertical_se + 0.05 * b.weight);
}
