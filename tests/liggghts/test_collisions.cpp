// The impulse operator against its analytic answers, through the driver and the example deck
// plugins/liggghts/examples/in.collide: exact restitution grain-grain and grain-wall, the
// stick limit (5/7), the Coulomb limit, Walton's beta0, and 1 vs 2 MPI ranks; plus the errors
// for an unknown model and a missing restitution. Each answer holds for both operators: Sawyer
// & Tichy's single pass and the contacts solved to convergence (fix impulse/solve, iterate 1),
// which resolves an isolated contact in its first sweep.
#define BOOST_TEST_MODULE liggghts_collisions
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "run_driver.h"

namespace fs = std::filesystem;

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/plugins/liggghts/examples/in.collide";

std::string run_driver(const std::string& deck, const std::string& vars, int np = 1) {
    return granlub::test::run_driver(deck, vars, np).output;
}

using granlub::test::results;

void close(double a, double b) { BOOST_TEST(std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b))); }

// the deck's operator: single pass, then solved to convergence
const char* const kOperators[] = {" -var iterate 0", " -var iterate 1"};

}  // namespace

BOOST_AUTO_TEST_CASE(restitution_is_exact_grain_grain_and_grain_wall) {
    for (const char* op : kOperators)
    for (double e : {0.3, 0.65, 0.9, 1.0}) {
        for (double ew : {0.5, 0.85}) {
            const auto r =
                results(run_driver(kDeck, "-var e " + std::to_string(e) + " -var ew " + std::to_string(ew) + op));
            BOOST_TEST_REQUIRE(r.count("vx1") == 1u);
            close(r.at("vx1"), -e);
            close(r.at("vx2"), e);
            close(r.at("vz3"), ew);
            close(r.at("vz4"), ew);  // the oblique impacts keep the normal restitution
            close(r.at("vz5"), ew);
        }
    }
}

BOOST_AUTO_TEST_CASE(oblique_impact_stick_limit_and_coulomb_limit) {
    // grain with vx = 1, vz = -1, no spin on the wall; I = 2/5 m r^2, r = 5 mm
    for (const char* op : kOperators) {
    const auto r = results(run_driver(kDeck, std::string("-var e 0.8 -var mu 0.9 -var mulow 0.1") + op));
    BOOST_TEST_REQUIRE(r.count("vx4") == 1u);
    close(r.at("vx4"), 5.0 / 7.0);                      // stick: slip stopped
    close(r.at("omegay4"), 5.0 / 7.0 / 0.005);          // rolling without slip: w r = vx
    close(r.at("vx5"), 1.0 - 0.1 * (1.0 + 0.8));       // Coulomb: mu (1 + e) |v_n|
    }
}

BOOST_AUTO_TEST_CASE(walton_beta0_sets_the_tangential_restitution) {
    for (const char* op : kOperators)
    for (double b : {-0.5, 0.0, 0.4, 1.0}) {
        const auto r = results(run_driver(kDeck, "-var beta0 " + std::to_string(b) + op));
        BOOST_TEST_REQUIRE(r.count("vx4") == 1u);
        const double vx = r.at("vx4"), w = r.at("omegay4");
        close(vx, 1.0 - 2.0 / 7.0 * (1.0 + b));
        // contact-point slip after = -beta0 * slip before (slip before = 1 m/s)
        close(vx - w * 0.005, -b);
    }
    // out of range: a clear LIGGGHTS error
    const std::string out = run_driver(kDeck, "-var beta0 1.5");
    BOOST_TEST(out.find("beta0 must lie in [-1, 1]") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(one_and_two_mpi_ranks_give_identical_results) {
    // processors * 1 1 splits x at 0.05: the head-on pair sits on different ranks
    for (const char* op : kOperators) {
        const std::string vars = std::string("-var e 0.7 -var beta0 0.3") + op;
        const auto one = results(run_driver(kDeck, vars, 1));
        const auto two = results(run_driver(kDeck, vars, 2));
        BOOST_TEST_REQUIRE(one.size() == 9u);  // 8 velocities and beta0
        BOOST_TEST(one == two);
    }
}

BOOST_AUTO_TEST_CASE(separate_on_removes_overlaps_exactly) {
    // the single pass; the solver's version (the default) leaves its slop: test_impulse_solve.cpp
    const auto r = results(run_driver(std::string(GRANLUB_SOURCE_DIR) + "/tests/liggghts/in.separate",
                                      " -var settings 'iterate off'"));
    BOOST_TEST_REQUIRE(r.count("z1") == 1u);
    close(r.at("z1"), 0.005);    // touching the wall
    close(r.at("x2"), 0.0495);   // equal masses: each moves half of the 1 mm overlap
    close(r.at("x3"), 0.0595);
}

BOOST_AUTO_TEST_CASE(bad_decks_give_clear_errors) {
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / "liggghts_collide";
    fs::create_directories(dir);
    const std::string deck = granlub::test::read_text(kDeck);
    {  // unknown normal model
        std::ofstream(dir / "in.unknown") << std::regex_replace(deck, std::regex("model impulse"), "model impulsive");
        const std::string out = run_driver((dir / "in.unknown").string(), "");
        BOOST_TEST(out.find("ERROR") != std::string::npos);
        BOOST_TEST(out.find("RESULT") == std::string::npos);
    }
    {  // no coefficientRestitution
        std::ofstream(dir / "in.norest") << std::regex_replace(deck, std::regex("fix m3 [^\n]*\n"), "");
        const std::string out = run_driver((dir / "in.norest").string(), "");
        BOOST_TEST(out.find("coefficientRestitution") != std::string::npos);
        BOOST_TEST(out.find("RESULT") == std::string::npos);
    }
}
