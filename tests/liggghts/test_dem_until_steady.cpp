// `granlub dem` with [dem] time_max (until steady, with a cap): a loaded cell whose plate is still
// settling at the end of its run is continued from where it ended, and the continued run is
// steady; without the cap the same run is a transient; the Δt check's full-step run is continued
// too; and a cap that leaves no room stops with the key named.
#define BOOST_TEST_MODULE liggghts_dem_until_steady
#include <boost/test/unit_test.hpp>

#include <filesystem>

#include "granlub/case/case.h"
#include "granlub/dem/command.h"
#include "granlub/error.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "granlub/run/sweep.h"
#include "tiny_cell.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

// 275 grains (inserted at 0.5) under 5.5 kPa at 2 m/s, the plate starting at the 6 mm gap: it
// settles to ~5.1 mm in about 0.1 s (measured 2026-11-26: a 0.1 s run is a transient; continued
// by 0.1 s it is steady from 0.024 s of the second piece, every drift check resolved and passed).
const std::string kCase = test::tiny_cell("tiny_until_steady",
                                          "control = \"load\"\nnormal_stress = [5500.0]\n",
                                          "time = 0.1\nsample_every = 20\nservo_every = 100\nservo_gain = 0.05\n"
                                          "snapshots = 20\nstations = 6\n");

std::string with(const std::string& dem) {
    std::string text = test::edit(kCase, "speed = \\[1.0\\]", "speed = [2.0]");
    return test::edit(text, "solid_fraction = 0.4", "solid_fraction = 0.5") + dem;
}

struct Run {
    int code = 1;
    Summary summary;
};

Run run(const std::string& text, const std::string& name) {
    const Case c = parse_case(text, name + ".toml", test::dem_schema());
    RunOptions o;
    o.results_root = test::scratch("liggghts_dem_until_steady", name);
    Run r;
    r.code = dem::run(c, o);
    if (r.code == 0) r.summary = read_summary(result_dir(o.results_root, "dem", c.points.front().id) / "summary.json");
    return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_run_still_settling_is_continued_until_steady) {
    const Run one = run(with(""), "one_run");
    BOOST_TEST_REQUIRE(one.code == 0);
    BOOST_TEST(one.summary.run.at("status").get<std::string>() == "transient");  // the plate still settling
    BOOST_TEST(!one.summary.run.contains("continuation"));

    const Run r = run(with("time_max = 0.8\n"), "continued");
    BOOST_TEST_REQUIRE(r.code == 0);
    const auto& run = r.summary.run;
    BOOST_TEST(run.at("status").get<std::string>() == "steady");
    const auto& k = run.at("continuation");
    const int pieces = k.at("pieces").get<int>();
    BOOST_TEST(pieces >= 2);
    BOOST_TEST(pieces <= 4);  // 0.1, 0.1, 0.2, 0.4 s: at most 0.8 s in all
    const double earlier = k.at("earlier_s").get<double>(), last = k.at("last_piece_s").get<double>();
    BOOST_TEST(last == earlier, boost::test_tools::tolerance(1e-9));  // the run doubles
    BOOST_TEST(run.at("simulated_time_s").get<double>() == earlier + last, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(k.at("simulated_s").get<double>() <= 0.8 * 1.01);
    // the window lies in the last piece, and its start is counted from the run's start
    BOOST_TEST(run.at("steady_state_start_s").get<double>() >= earlier);
    BOOST_TEST(run.at("steady_state_start_s").get<double>() < earlier + 0.5 * last);
    // the plate carries the load in the steady piece
    BOOST_TEST(r.summary.value("normal_stress_top") == 5500.0, boost::test_tools::tolerance(0.1));
}

// The Δt check's full-step run is continued until steady as well, so its check is a check.
BOOST_AUTO_TEST_CASE(the_dt_check_runs_until_steady_too) {
    const Run r = run(with("time_max = 0.8\nrefine_dt = true\nrefine_time = 0.05\n"), "refined");
    BOOST_TEST_REQUIRE(r.code == 0);
    const auto& full = r.summary.run.at("dt_refinement").at("full_step_run");
    BOOST_TEST(full.at("status").get<std::string>() == "steady");
    BOOST_TEST(full.at("continuation").at("pieces").get<int>() >= 2);
    // the point is a result (steady, or dt-unconverged with its reason), not a transient
    BOOST_TEST((read_regime(r.summary.run).status != RegimeStatus::Transient), read_regime(r.summary.run).reason);
}

BOOST_AUTO_TEST_CASE(a_cap_without_room_names_the_key) {
    const Case c = parse_case(with("time_max = 0.15\n"), "bad.toml", test::dem_schema());
    RunOptions o;
    o.results_root = test::scratch("liggghts_dem_until_steady", "bad");
    try {
        dem::check(c, o);
        BOOST_FAIL("time_max = 0.15 with time = 0.1 was accepted");
    } catch (const CaseError& e) {
        const std::string what = e.what();
        BOOST_TEST(what.find("time_max") != std::string::npos, what);
        BOOST_TEST(what.find("twice") != std::string::npos, what);
    }
}
