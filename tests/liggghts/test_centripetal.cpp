// fix centripetal/annulus (plugins/liggghts/doc/fix_centripetal_annulus.txt) through the driver
// and tests/liggghts/in.centripetal: the force at the first step is -m v_x^2 / (R - z) per grain;
// 200 steps of 216 colliding grains give the same positions, velocities and forces, to the last
// bit, as the atom-style variable + fix addforce it replaces, on 1 and on 2 ranks; bad input stops.
#define BOOST_TEST_MODULE liggghts_centripetal
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "run_driver.h"

namespace fs = std::filesystem;

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/tests/liggghts/in.centripetal";
const std::string kFolder = "liggghts_centripetal";

// Runs the deck and returns the text of its per-atom dump (id x y z vx vy vz fx fy fz per line).
std::string run(const std::string& body, const std::string& vars, int np = 1) {
    const fs::path file = fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder / ("forces." + body + ".txt");
    fs::remove(file);
    const auto r = granlub::test::run_driver(kDeck, "-var body " + body + " " + vars, np, kFolder);
    BOOST_TEST_REQUIRE(r.exit_code == 0, r.output);
    const std::string text = granlub::test::read_text(file);
    BOOST_TEST_REQUIRE(text.find("ITEM: ATOMS") != std::string::npos);
    return text;
}

std::vector<std::vector<double>> atoms(const std::string& dump) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(dump.substr(dump.find('\n', dump.find("ITEM: ATOMS")) + 1));
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        std::vector<double> row;
        for (double v; l >> v;) row.push_back(v);
        if (row.size() == 10) rows.push_back(row);
    }
    return rows;
}

}  // namespace

BOOST_AUTO_TEST_CASE(force_is_m_vx2_over_R_minus_z_toward_minus_z) {
    // step 0: grains on a lattice of 1.05 d touch nothing, so f_z is the centripetal force alone
    const double R = 0.05;
    const double mass = 2500.0 * std::numbers::pi / 6.0 * 1e-9;  // density 2500, d = 1 mm
    const auto rows = atoms(run("fix", "-var steps 0 -var R 0.05"));
    BOOST_TEST_REQUIRE(rows.size() == 216u);
    for (const auto& a : rows) {
        const double expect = -mass * a[4] * a[4] / (R - a[3]);
        BOOST_TEST(expect < 0.0);
        BOOST_TEST(std::abs(a[9] - expect) <= 1e-12 * std::abs(expect));
        BOOST_TEST(a[7] == 0.0);
    }
}

BOOST_AUTO_TEST_CASE(same_bits_as_the_variable_form_on_1_and_2_ranks) {
    for (int np : {1, 2}) {
        const std::string fix = run("fix", "", np);
        const std::string variable = run("variable", "", np);
        BOOST_TEST(atoms(fix).size() == 216u);
        BOOST_TEST((fix == variable), "np " << np << ": per-atom x, v, f after 200 steps differ");
    }
    // and the comparison can fail: another radius gives other trajectories
    BOOST_TEST((run("fix", "-var R 0.06") != run("variable", "")));
}

BOOST_AUTO_TEST_CASE(bad_radius_and_grains_beyond_the_axis_stop) {
    auto r = granlub::test::run_driver(kDeck, "-var body fix -var R 0", 1, kFolder);
    BOOST_TEST(r.exit_code != 0);
    BOOST_TEST(r.output.find("R must be > 0") != std::string::npos, r.output);
    r = granlub::test::run_driver(kDeck, "-var body fix -var R 0.001", 1, kFolder);  // grains up to z = 3 mm
    BOOST_TEST(r.exit_code != 0);
    BOOST_TEST(r.output.find("a grain at z >= R") != std::string::npos, r.output);
}
