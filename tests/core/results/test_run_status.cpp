// The regime status of a result (run_status.h) and the failure record (failure_record.h).
#include <filesystem>
#include <cmath>
#include <fstream>
#include <map>

#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/results/failure_record.h"
#include "granlub/results/run_status.h"

using namespace granlub;
using nlohmann::json;

namespace {
json refinement(double dnu, double rel_bottom, double z_bottom) {
    return {{"time_step_s", 5e-7},
            {"mean_solid_fraction", {{"change", dnu}}},
            {"shear_stress_bottom", {{"relative_change", rel_bottom}, {"z", z_bottom}}},
            {"shear_stress_top", {{"relative_change", 0.0}, {"z", 0.0}}}};
}
}  // namespace

BOOST_AUTO_TEST_SUITE(regime)

BOOST_AUTO_TEST_CASE(names_round_trip_and_missing_is_unknown) {
    for (auto s : {RegimeStatus::Steady, RegimeStatus::Transient, RegimeStatus::DtUnconverged, RegimeStatus::Ordered})
        BOOST_TEST((regime_status_from_string(to_string(s)) == s));
    BOOST_TEST(!regime_status_from_string("unknown").has_value());  // never written
    BOOST_TEST(!regime_status_from_string("Steady").has_value());
    json run = {{"steps", 10}};
    BOOST_TEST((read_regime(run).status == RegimeStatus::Unknown));  // an old summary: not invented
    set_regime(run, RegimeStatus::Transient, "no steady state detected");
    BOOST_TEST(run.at("status") == "transient");
    const Regime r = read_regime(run);
    BOOST_TEST((r.status == RegimeStatus::Transient));
    BOOST_TEST(r.reason == "no steady state detected");
    BOOST_TEST(!r.steady());
    run["status"] = "stedy";
    BOOST_TEST((read_regime(run).status == RegimeStatus::Unknown));
    BOOST_TEST(read_regime(run).reason.find("\"stedy\"") != std::string::npos);
    BOOST_CHECK_THROW(set_regime(run, RegimeStatus::Unknown), Error);
}

BOOST_AUTO_TEST_CASE(dt_refinement_thresholds) {
    json run;
    set_regime(run, RegimeStatus::Steady);
    run["dt_refinement"] = refinement(0.004, 0.05, 5.0);  // within 0.005 and 7 %
    BOOST_TEST(read_regime(run).steady());
    run["dt_refinement"] = refinement(-0.006, 0.0, 0.0);  // nu_bar moves by more than 0.005
    BOOST_TEST((read_regime(run).status == RegimeStatus::DtUnconverged));
    run["dt_refinement"] = refinement(0.0, 0.08, 1.5);  // 8 % but within the noise
    BOOST_TEST(read_regime(run).steady());
    run["dt_refinement"] = refinement(0.0, -0.08, -2.5);  // 8 % and 2.5 standard errors
    const Regime r = read_regime(run);
    BOOST_TEST((r.status == RegimeStatus::DtUnconverged));
    BOOST_TEST(r.reason.find("shear_stress_bottom by -8.0 %") != std::string::npos, r.reason);
    run["dt_refinement"].erase("shear_stress_top");  // malformed: unknown, naming the key
    BOOST_TEST((read_regime(run).status == RegimeStatus::Unknown));
    BOOST_TEST(read_regime(run).reason.find("shear_stress_top") != std::string::npos);
    // A transient stays transient whatever the refinement says.
    set_regime(run, RegimeStatus::Transient, "short");
    BOOST_TEST((read_regime(run).status == RegimeStatus::Transient));
    // A steady answer checked against a full-step run that was not steady is a transient too,
    // whether or not the two differ by more than the rule allows.
    set_regime(run, RegimeStatus::Steady);
    for (const auto& [dnu, dtau] : {std::pair{0.0, 0.0}, std::pair{-0.006, 0.0}}) {
        run["dt_refinement"] = refinement(dnu, dtau, 0.0);
        run["dt_refinement"]["full_step_run"] = {{"status", "transient"}};
        const Regime t = read_regime(run);
        BOOST_TEST((t.status == RegimeStatus::Transient));
        BOOST_TEST(t.reason.find("full-step run") != std::string::npos, t.reason);
        run["dt_refinement"]["full_step_run"]["status"] = "steady";
        BOOST_TEST((read_regime(run).status == (dnu == 0.0 ? RegimeStatus::Steady : RegimeStatus::DtUnconverged)));
    }
    // ... and says how to run that check longer in its own words (here: the cap that stopped it)
    run["dt_refinement"] = refinement(0.0, 0.0, 0.0);
    run["dt_refinement"]["full_step_run"] = {{"status", "transient"},
                                             {"status_reason", "no steady state in 2 s: raise [dem] time_max_full"}};
    const Regime capped = read_regime(run);
    BOOST_TEST((capped.status == RegimeStatus::Transient));
    BOOST_TEST(capped.reason.find("raise [dem] time_max_full") != std::string::npos, capped.reason);
}

// When a check is repeated one halving finer: the pair fails the rule, or the coarser run never got
// steady while the finer one did; never when the finer run (the answer) is itself a transient.
BOOST_AUTO_TEST_CASE(a_check_is_refined_when_it_fails_or_has_no_steady_coarse_run) {
    nlohmann::json steady, transient;
    set_regime(steady, RegimeStatus::Steady);
    set_regime(transient, RegimeStatus::Transient, "the gap still drifts");
    const nlohmann::json pass = refinement(0.0, 0.0, 0.0), fail = refinement(-0.006, 0.0, 0.0);
    BOOST_TEST(dt_check_failure(steady, steady, pass).value() == "");
    BOOST_TEST(dt_check_failure(steady, steady, fail).value() == dt_unconverged_reason(fail));
    BOOST_TEST(!dt_check_failure(steady, steady, fail).value().empty());
    const auto no_coarse = dt_check_failure(transient, steady, pass);
    BOOST_TEST(no_coarse.value().find("did not reach a steady state (the gap still drifts)") != std::string::npos,
               no_coarse.value());
    BOOST_TEST(!dt_check_failure(steady, transient, fail).has_value());
    BOOST_TEST(!dt_check_failure(transient, transient, pass).has_value());
}

// After a second halving ([dem] refine_halvings = 2) the answer is checked against the half-step
// run: that run's steadiness decides, not the full-step run's, whose check already failed.
BOOST_AUTO_TEST_CASE(a_second_halving_is_judged_against_the_half_step_run) {
    nlohmann::json run;
    set_regime(run, RegimeStatus::Steady);
    run["dt_refinement"] = refinement(0.0, 0.0, 0.0);
    run["dt_refinement"]["full_step_run"] = {{"status", "steady"}};
    run["dt_refinement"]["half_step_run"] = {{"status", "transient"}};
    const Regime t = read_regime(run);
    BOOST_TEST((t.status == RegimeStatus::Transient));
    BOOST_TEST(t.reason.find("half-step run the quarter-step run checks against") != std::string::npos, t.reason);
    run["dt_refinement"]["half_step_run"]["status"] = "steady";
    run["dt_refinement"]["full_step_run"]["status"] = "transient";  // not the run the answer was compared with
    BOOST_TEST((read_regime(run).status == RegimeStatus::Steady));
    run["dt_refinement"] = refinement(-0.006, 0.0, 0.0);
    run["dt_refinement"]["half_step_run"] = {{"status", "steady"}};
    BOOST_TEST((read_regime(run).status == RegimeStatus::DtUnconverged));
}

BOOST_AUTO_TEST_CASE(failure_record_round_trip) {
    const auto dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / "core-tmp" / "failure";
    std::filesystem::remove_all(dir);
    BOOST_TEST(!read_failure(dir).has_value());
    write_failure(dir, "dem", "U2.0", "LIGGGHTS exited with status 1: see log.liggghts");
    const auto f = read_failure(dir);
    BOOST_TEST_REQUIRE(f.has_value());
    BOOST_TEST(f->solver == "dem");
    BOOST_TEST(f->point == "U2.0");
    BOOST_TEST(f->message == "LIGGGHTS exited with status 1: see log.liggghts");
    BOOST_TEST(f->utc_time.size() == 20u);  // 2026-01-01T00:00:00Z
    BOOST_TEST(!f->version.empty());
    BOOST_TEST(!f->no_answer);
    write_failure(dir, "yade", "U2.0", "point U2.0: granlub yade runs the slice only", true);
    BOOST_TEST(read_failure(dir)->no_answer);
    remove_failure(dir);
    BOOST_TEST(!read_failure(dir).has_value());
    std::ofstream(dir / kFailureFile) << "{\"format\": \"granlub-failure-1\"}";
    BOOST_CHECK_EXCEPTION(read_failure(dir), Error, [](const Error& e) {
        return std::string(e.what()).find("failure.json: malformed failure record") != std::string::npos;
    });
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(dt_refinement_record_is_what_read_regime_reads) {
    using granlub::Scalar;
    std::map<std::string, Scalar> o = {{"mean_solid_fraction", {0.50, std::nullopt, ""}},
                                       {"shear_stress_bottom", {100.0, 2.0, "Pa"}},
                                       {"shear_stress_top", {90.0, 2.0, "Pa"}},
                                       {"slip_bottom", {0.2, 0.01, "m/s"}}};
    auto r = o;
    r["shear_stress_bottom"].value = 103.0;  // 3 %: converged
    json run;
    set_regime(run, RegimeStatus::Steady);
    run["dt_refinement"] = dt_refinement_record(5e-6, o, r);
    BOOST_TEST(read_regime(run).steady());
    const json& rec = run["dt_refinement"];
    BOOST_TEST(rec.at("time_step_s").get<double>() == 5e-6);
    BOOST_TEST(std::abs(rec.at("shear_stress_bottom").at("relative_change").get<double>() - 0.03) < 1e-12);
    BOOST_TEST(std::abs(rec.at("shear_stress_bottom").at("z").get<double>() - 3.0 / std::sqrt(8.0)) < 1e-12);
    BOOST_TEST(rec.contains("slip_bottom"));
    BOOST_TEST(!rec.contains("slip_top"));  // only what both runs have
    r["shear_stress_top"].value = 80.0;  // -11 %, 3.5 standard errors
    run["dt_refinement"] = dt_refinement_record(5e-6, o, r);
    BOOST_TEST((read_regime(run).status == RegimeStatus::DtUnconverged));
    r["mean_solid_fraction"].value = 0.51;
    r["shear_stress_top"].value = 90.0;
    run["dt_refinement"] = dt_refinement_record(5e-6, o, r);
    BOOST_TEST((read_regime(run).status == RegimeStatus::DtUnconverged));
    r.erase("shear_stress_top");
    BOOST_CHECK_THROW(dt_refinement_record(5e-6, o, r), Error);
}
