// One verdict per operating point (granlub/statistics/point_verdict.h): engines on either side of
// the threshold, or one engine's Z within its errors of it, read "at the transition" with the numbers.
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
    return {engine, flow_regime_json(d)};
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
}

BOOST_AUTO_TEST_CASE(nothing_decided_is_undetermined) {
    BOOST_TEST((point_verdict({run("yade", std::nullopt, std::nullopt)}).regime == PointRegime::Undetermined));
    BOOST_TEST((point_verdict({}).regime == PointRegime::Undetermined));
}

BOOST_AUTO_TEST_SUITE_END()
