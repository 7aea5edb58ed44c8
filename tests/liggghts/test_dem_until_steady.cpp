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
    fs::path dir;  // the point's results
};

Run run(const std::string& text, const std::string& name) {
    const Case c = parse_case(text, name + ".toml", test::dem_schema());
    RunOptions o;
    o.results_root = test::scratch("liggghts_dem_until_steady", name);
    Run r;
    r.code = dem::run(c, o);
    r.dir = result_dir(o.results_root, "dem", c.points.front().id);
    if (r.code == 0) r.summary = read_summary(r.dir / "summary.json");
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

// refine_halvings = 2: where the check at half the step fails the rule, the step is halved once
// more. At step_fraction 0.05 (the largest allowed) this cell's half-step run moves ν̄ by -0.0066
// and τ_top by -17 % (measured 2026-11-28), so the second halving runs; the half-step run moves to
// dt_half/ unchanged, and the answer is the quarter-step run, checked against it.
BOOST_AUTO_TEST_CASE(a_failed_dt_check_is_repeated_one_halving_finer) {
    const std::string longer = test::edit(with("refine_dt = true\nstep_fraction = 0.05\n"), "time = 0.1", "time = 0.2");
    const Run once = run(longer, "halved_once");
    BOOST_TEST_REQUIRE(once.code == 0);
    const auto& first = once.summary.run.at("dt_refinement");
    BOOST_TEST_REQUIRE(!dt_unconverged_reason(first).empty());  // the premise: the first check fails
    BOOST_TEST(first.at("halvings").get<int>() == 1);

    const Run twice = run(longer + "refine_halvings = 2\n", "halved_twice");
    BOOST_TEST_REQUIRE(twice.code == 0);
    const auto& run = twice.summary.run;
    const auto& rec = run.at("dt_refinement");
    BOOST_TEST(rec.at("halvings").get<int>() == 2);
    BOOST_TEST(rec.at("checked_against").get<std::string>() == "dt_half");
    const double dt = run.at("time_step_s").get<double>();
    BOOST_TEST(rec.at("time_step_s").get<double>() == dt);
    BOOST_TEST(rec.at("half_step_run").at("time_step_s").get<double>() == 2 * dt);
    BOOST_TEST(rec.at("full_step_run").at("time_step_s").get<double>() == 4 * dt);
    // the failed first pair is kept with its verdict, and it is the once-halved run's check
    BOOST_TEST(rec.at("first_check").at("verdict").get<std::string>() == dt_unconverged_reason(first));
    // the half-step run is the once-halved run's answer, moved: the same numbers
    for (const char* name : {"shear_stress_bottom", "shear_stress_top", "mean_solid_fraction"}) {
        BOOST_TEST(rec.at("half_step_run").at("outputs").at(name).at("value").get<double>() ==
                   once.summary.value(name), name);
        const Scalar& v = twice.summary.outputs.at(name);
        BOOST_TEST_REQUIRE(v.dt_error.has_value());
        BOOST_TEST(*v.dt_error == std::abs(once.summary.value(name) - v.value), name);
    }
    // the verdict is the last pair's, and every file of the point names one run
    BOOST_TEST((read_regime(run).status == (run.at("status") == "transient" ? RegimeStatus::Transient
                                            : dt_unconverged_reason(rec).empty() ? RegimeStatus::Steady
                                                                                 : RegimeStatus::DtUnconverged)));
    const fs::path& dir = twice.dir;
    for (const char* f : {"dt_half/profile.csv", "dt_half/in.granlub", "dt_half/final_state.csv",
                          "dt_full/profile.csv", "final_state.csv", "in.granlub"})
        BOOST_TEST(fs::exists(dir / f), f);
    const Case c = parse_case(longer + "refine_halvings = 2\n", "halved_twice.toml", test::dem_schema());
    BOOST_TEST((result_status(dir, c.inputs_hash("dem")).state == ResultState::Complete),
               result_status(dir, c.inputs_hash("dem")).reason);
}

BOOST_AUTO_TEST_CASE(a_second_halving_needs_a_cold_check) {
    for (const auto& [dem, why] : {std::pair{"refine_halvings = 2\n", "set refine_dt = true"},
                                   std::pair{"refine_dt = true\nrefine_time = 0.05\nrefine_halvings = 2\n",
                                             "repeat a cold check only"}}) {
        const Case c = parse_case(with(dem), "bad.toml", test::dem_schema());
        RunOptions o;
        o.results_root = test::scratch("liggghts_dem_until_steady", "bad_halvings");
        try {
            dem::check(c, o);
            BOOST_FAIL(std::string("accepted: ") + dem);
        } catch (const CaseError& e) {
            const std::string what = e.what();
            BOOST_TEST(what.find("refine_halvings") != std::string::npos, what);
            BOOST_TEST(what.find(why) != std::string::npos, what);
        }
    }
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
