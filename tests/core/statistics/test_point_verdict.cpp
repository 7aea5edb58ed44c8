// One verdict per operating point (granlub/statistics/point_verdict.h): engines on either side of
// the threshold, one engine's Z within its errors of it, or within its time-step error (the Δt
// check's run at twice the step), read "at the transition" with the numbers.
#include <boost/test/unit_test.hpp>

#include <optional>

#include "granlub/statistics/flow_regime.h"
#include "granlub/statistics/point_verdict.h"

using namespace granlub;

namespace {
EngineRegime run(const std::string& engine, std::optional<double> z, std::optional<double> persistence,
                 std::optional<double> z_se = std::nullopt) {
    FlowDiagnostics d;
    d.coordination = z, d.persistence = persistence, d.coordination_stderr = z_se;
    return {engine, flow_regime_json(d), nullptr};
}
// the same engine with its Δt check's run at twice the step
EngineRegime checked(EngineRegime r, double z_coarse, double persistence_coarse = 0.85) {
    FlowDiagnostics d;
    d.coordination = z_coarse, d.persistence = persistence_coarse, d.coordination_stderr = 0.01;
    r.coarser = flow_regime_json(d);
    return r;
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

BOOST_AUTO_TEST_SUITE(point_verdicts)

// The main job's U = 2.8 m/s (issue 50): the DEM's Z = 4.17 says contact, YADE's 3.81 collision.
BOOST_AUTO_TEST_CASE(engines_on_either_side_read_at_the_transition) {
    const PointVerdict v = point_verdict({run("dem", 4.17, 0.87, 0.03), run("yade", 3.81, 0.8, 0.05)});
    BOOST_TEST((v.regime == PointRegime::Transition));
    BOOST_TEST(to_string(v.regime) == "at the transition");
    BOOST_TEST(has(v.criterion, "dem: Z = 4.17 ± 0.03"), v.criterion);
    BOOST_TEST(has(v.criterion, "yade: Z = 3.81"), v.criterion);
}

BOOST_AUTO_TEST_CASE(agreeing_engines_clear_of_the_threshold_give_their_verdict) {
    PointVerdict v = point_verdict({run("dem", 4.6, 0.87, 0.02), run("yade", 4.5, 0.9, 0.03)});
    BOOST_TEST((v.regime == PointRegime::Contact));
    v = point_verdict({run("dem", 3.2, 0.3, 0.05), run("yade", 3.5, std::nullopt, 0.05)});
    BOOST_TEST((v.regime == PointRegime::Collision));
    // an engine that could not decide does not overrule one that did
    v = point_verdict({run("dem", 4.6, 0.87, 0.02), run("yade", 4.5, std::nullopt)});
    BOOST_TEST((v.regime == PointRegime::Contact));
    BOOST_TEST(has(v.criterion, "persistence not measured"), v.criterion);
}

BOOST_AUTO_TEST_CASE(one_engine_within_its_errors_of_the_threshold) {
    // 4.05 +- 0.04: two errors reach below 4
    BOOST_TEST((point_verdict({run("dem", 4.05, 0.9, 0.04)}).regime == PointRegime::Transition));
    // 4.05 +- 0.02: clear of it
    BOOST_TEST((point_verdict({run("dem", 4.05, 0.9, 0.02)}).regime == PointRegime::Contact));
    // no error recorded (older summaries): the engine's own verdict
    BOOST_TEST((point_verdict({run("dem", 4.01, 0.9)}).regime == PointRegime::Contact));
    // the criterion names the error: one run's block error, or a pool's seeds' standard error
    // (seed_pool.h keeps the block errors beside it as coordination_number_block_stderr)
    BOOST_TEST(has(point_verdict({run("dem", 4.05, 0.9, 0.04)}).criterion, "Z within 2 block errors of 4"));
    EngineRegime pooled = run("dem", 4.05, 0.9, 0.04);
    pooled.flow_regime["coordination_number_block_stderr"] = 0.01;
    const PointVerdict v = point_verdict({pooled});
    BOOST_TEST((v.regime == PointRegime::Transition));
    BOOST_TEST(has(v.criterion, "Z within 2 standard errors (the seeds') of 4"), v.criterion);
}

// The rough regimes case: halving the step takes Z down by 0.1-0.4 at the dense points, tens of
// block errors; a verdict the step can turn is no verdict.
BOOST_AUTO_TEST_CASE(a_verdict_the_time_step_turns_is_at_the_transition) {
    // collision at the answer's step, contact at twice it
    PointVerdict v = point_verdict({checked(run("dem", 3.93, 0.82, 0.02), 4.12)});
    BOOST_TEST((v.regime == PointRegime::Transition));
    BOOST_TEST(v.step_moves);
    BOOST_TEST(!v.engines_disagree);
    BOOST_TEST(has(v.criterion, "within its time-step error of 4"), v.criterion);
    BOOST_TEST(has(v.criterion, "(collision lubrication; at twice the step Z = 4.12, contact)"), v.criterion);
    BOOST_TEST(has(v.brief, "dem Z = 3.93 (collision; 4.12 at twice the step)"), v.brief);
    // both contact, but the step moved Z by 0.25 and Z lies 0.15 from 4: its dt -> 0 value may not
    v = point_verdict({checked(run("dem", 4.15, 0.82, 0.01), 4.40)});
    BOOST_TEST((v.regime == PointRegime::Transition));
    BOOST_TEST(v.step_moves);
    // moved by 0.15, 0.6 from the threshold: the verdict stands, with the check's numbers beside it
    v = point_verdict({checked(run("dem", 4.6, 0.85, 0.01), 4.75)});
    BOOST_TEST((v.regime == PointRegime::Contact));
    BOOST_TEST(!v.step_moves);
    BOOST_TEST(has(v.criterion, "at twice the step Z = 4.75, contact"), v.criterion);
    // the persistence alone turns it at twice the step (Z clear of 4 at both)
    v = point_verdict({checked(run("dem", 4.6, 0.6, 0.01), 4.7, 0.4)});
    BOOST_TEST((v.regime == PointRegime::Transition));
}

// engine_regime reads the check that checked the answer: full_step_run, or half_step_run after a
// second halving; a run without a check has no coarser record
BOOST_AUTO_TEST_CASE(engine_regime_reads_the_answers_own_check) {
    FlowDiagnostics d;
    d.coordination = 4.5, d.persistence = 0.8;
    const nlohmann::json fr = flow_regime_json(d);
    d.coordination = 4.9;
    const nlohmann::json full = flow_regime_json(d);
    d.coordination = 4.7;
    const nlohmann::json half = flow_regime_json(d);
    nlohmann::json run = {{"flow_regime", fr}};
    BOOST_TEST(engine_regime("dem", run).coarser.is_null());
    run["dt_refinement"] = {{"full_step_run", {{"flow_regime", full}}}};
    BOOST_TEST(engine_regime("dem", run).coarser.at("coordination_number").get<double>() == 4.9);
    run["dt_refinement"]["half_step_run"] = {{"flow_regime", half}};
    BOOST_TEST(engine_regime("dem", run).coarser.at("coordination_number").get<double>() == 4.7);
    BOOST_TEST(engine_regime("dem", run).flow_regime.at("coordination_number").get<double>() == 4.5);
    BOOST_TEST(engine_regime("yade", nlohmann::json()).flow_regime.is_null());
}

BOOST_AUTO_TEST_CASE(nothing_decided_is_undetermined) {
    BOOST_TEST((point_verdict({run("yade", std::nullopt, std::nullopt)}).regime == PointRegime::Undetermined));
    BOOST_TEST((point_verdict({}).regime == PointRegime::Undetermined));
}

BOOST_AUTO_TEST_SUITE_END()
