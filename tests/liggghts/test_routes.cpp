// The routes into LIGGGHTS the plugin README documents: the stock Debian `liggghts` with the plugin
// in LD_PRELOAD runs a deck with the models' defaults (the fix impulse/solve the pair style makes
// is registered in that route too); the solver's state can be named in thermo_style before the
// first run, whether the pair style made the fix or the deck wrote its own; `granlub-liggghts -h`
// lists the plugin's styles. Deck: tests/liggghts/tutorials/in.pour (LIGGGHTS' cohesion tutorial).
#define BOOST_TEST_MODULE liggghts_routes
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <sstream>
#include <string>

#include "run_driver.h"

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/tests/liggghts/tutorials/in.pour";
const std::string kFolder = "liggghts_routes";
const std::string kShort = "-var model 'impulse tangential impulse' -var steps 200 -var rest 10 ";
const std::string kStock = "/usr/bin/liggghts";

granlub::test::DriverRun stock(const std::string& vars) {
    const std::filesystem::path dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / kFolder;
    std::filesystem::create_directories(dir);
    const std::string cmd = "cd '" + dir.string() + "' && LD_PRELOAD='" + GRANLUB_LIGGGHTS_PLUGIN_PATH + "' " + kStock +
                            " -in '" + kDeck + "' -log none -echo none " + vars + " 2>&1";
    return granlub::test::run_command(cmd);
}

bool has(const std::string& out, const std::string& what) { return out.find(what) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_CASE(ld_preload_into_the_stock_binary_runs_the_defaults) {
    if (!std::filesystem::exists(kStock)) {
        BOOST_TEST_MESSAGE("no " << kStock << ": skipped");
        return;
    }
    const auto made = stock(kShort + "-var cols 'f_granlub_impulse_solve[1] f_granlub_impulse_solve[7]'");
    BOOST_TEST(made.exit_code == 0, made.output);
    BOOST_TEST(!has(made.output, "Invalid fix style"), made.output);
    BOOST_TEST(has(made.output, "made 'fix granlub_impulse_solve all impulse/solve'"));
    BOOST_TEST(has(made.output, "RESULT rest atoms2=250"), made.output);
    // the deck's own solver, written after the pair style, in the same route
    const auto written = stock(kShort + "-var solver 1 -var solve 'tolerance 1e-5' -var cols f_solver[1]");
    BOOST_TEST(written.exit_code == 0, written.output);
    BOOST_TEST(has(written.output, "RESULT rest atoms2=250"), written.output);
}

// thermo_style names the solver before the first run; the made fix reports the deck's when it has one
BOOST_AUTO_TEST_CASE(the_solver_state_is_in_thermo_from_the_first_step) {
    const auto made = granlub::test::run_driver(
        kDeck, kShort + "-var cols 'f_granlub_impulse_solve[1] f_granlub_impulse_solve[7] f_granlub_impulse_solve[9]'", 1,
        kFolder);
    BOOST_TEST_REQUIRE(made.exit_code == 0, made.output);
    BOOST_TEST(has(made.output, "granlub_ "));  // the column (LIGGGHTS cuts its name)
    const auto both = granlub::test::run_driver(
        kDeck, kShort + "-var solver 1 -var cols 'f_solver[3] f_granlub_impulse_solve[3]'", 1, kFolder);
    BOOST_TEST_REQUIRE(both.exit_code == 0, both.output);
    // the last thermo line before the RESULT: both columns are the deck's solver's mean sweeps per step
    const std::size_t end = both.output.find("RESULT rest");
    BOOST_TEST_REQUIRE(end != std::string::npos);
    const std::size_t loop = both.output.rfind("Loop time", end);
    const std::size_t line = both.output.rfind('\n', both.output.rfind('\n', loop) - 1);
    std::istringstream in(both.output.substr(line + 1, loop - line - 1));
    double step, atoms, ke, zc, a, b;
    BOOST_TEST_REQUIRE(static_cast<bool>(in >> step >> atoms >> ke >> zc >> a >> b), both.output.substr(line, loop - line));
    BOOST_TEST(a > 0.0);
    BOOST_TEST(a == b);
}

BOOST_AUTO_TEST_CASE(help_lists_the_plugin_styles) {
    const auto help = granlub::test::run_driver(kDeck, "-h", 1, kFolder);
    for (const char* s : {"'model impulse tangential impulse'", "impulse/solve", "wall/gran/moving", "centripetal/annulus",
                          "check/timestep/gran", "wall/gran/force"})
        BOOST_TEST(has(help.output, s), s);
}
