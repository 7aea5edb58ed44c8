// compute wall/gran/force (plugins/liggghts/doc/compute_wall_gran_force.txt) through the driver and
// tests/liggghts/in.wallforce: every step, each wall's summed force equals, to the last bit, the
// compute reduce sums it replaces, on 1 and 2 ranks and after a wall is unfixed and made again as a
// loaded plate (fix wall/gran/moving, whose sums run over the grains its own pass evaluated);
// the forces are not zero (the comparison means something); bad input stops with a message.
#define BOOST_TEST_MODULE liggghts_wall_force
#include <boost/test/unit_test.hpp>

#include <regex>
#include <string>
#include <vector>

#include "run_driver.h"

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/tests/liggghts/in.wallforce";
const std::string kFolder = "liggghts_wall_force";

struct Half {
    double mismatches, fy, fx_side;
};

std::vector<Half> halves(const std::string& out) {
    static const std::regex line(R"(RESULT half \d mismatches (\S+) fy (\S+) fx_side (\S+))");
    std::vector<Half> h;
    for (auto it = std::sregex_iterator(out.begin(), out.end(), line); it != std::sregex_iterator(); ++it)
        h.push_back({std::stod((*it)[1].str()), std::stod((*it)[2].str()), std::stod((*it)[3].str())});
    return h;
}

// The loaded plate's mean f_y over the second half (it presses on the bed: negative).
double plate_fy(const std::string& out) {
    static const std::regex line(R"(RESULT plate fy (\S+))");
    std::smatch m;
    return std::regex_search(out, m, line) ? std::stod(m[1].str()) : 0.0;
}

}  // namespace

BOOST_AUTO_TEST_CASE(same_bits_as_compute_reduce_every_step_on_1_and_2_ranks) {
    for (int np : {1, 2}) {
        const auto r = granlub::test::run_driver(kDeck, "", np, kFolder);
        BOOST_TEST_REQUIRE(r.exit_code == 0, r.output);
        const auto h = halves(r.output);
        BOOST_TEST_REQUIRE(h.size() == 2u, r.output);
        for (const Half& x : h) {
            BOOST_TEST(x.mismatches == 0.0, "np " << np << ": components differing per step " << x.mismatches);
            // the floor carries the grains (g = 1000 m/s^2 here) and the moving side walls drag them:
            // non-zero sums, so equal sums are a real check
            BOOST_TEST(x.fy > 0.0, "np " << np);
            BOOST_TEST(x.fx_side != 0.0, "np " << np);
        }
        // the second half's top wall is a loaded plate (1 N) resting on the bed: its sums, taken
        // over the grains its own pass evaluated, are compared with grains under it
        BOOST_TEST(plate_fy(r.output) < -0.5, "np " << np);
    }
}

BOOST_AUTO_TEST_CASE(the_comparison_can_fail) {
    // the walls listed in another order: the sums land in other components and differ
    const auto r = granlub::test::run_driver(kDeck, "-var walls \"wtop wbot ws1 ws2\"", 1, kFolder);
    BOOST_TEST_REQUIRE(r.exit_code == 0, r.output);
    const auto h = halves(r.output);
    BOOST_TEST_REQUIRE(h.size() == 2u);
    BOOST_TEST(h[0].mismatches > 0.0);
}

BOOST_AUTO_TEST_CASE(bad_input_stops_with_a_message) {
    struct Case {
        std::string vars, message;
    };
    const std::vector<Case> cases = {
        {"-var walls nosuch", "no fix with ID nosuch"},
        {"-var walls grav", "fix grav is not a wall/gran fix"},
        {"-var store no", "wall wbot does not store its forces (add store_force yes)"},
        {"-var walls \"\"", "expected compute ID group wall/gran/force wallID1"},
    };
    for (const Case& c : cases) {
        const auto r = granlub::test::run_driver(kDeck, c.vars, 1, kFolder);
        BOOST_TEST(r.exit_code != 0, c.vars);
        BOOST_TEST(r.output.find(c.message) != std::string::npos, c.vars << "\n" << r.output);
    }
}
