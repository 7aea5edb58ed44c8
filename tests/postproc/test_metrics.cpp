// Golden metrics on synthetic result sets (see synthetic.h): every expected value follows from
// the definitions in metrics.h and the analytic profiles and power laws written.
#include <cmath>

#include <boost/test/unit_test.hpp>

#include "granlub/results/results.h"
#include "results/collect.h"
#include "statistics/metrics.h"
#include "synthetic.h"

using namespace granlub;
using namespace granlub::postproc;
namespace tt = boost::test_tools;

namespace {
const MetricRow& find(const std::vector<MetricRow>& rows, const std::string& kind, const std::string& point,
                      const std::string& q, const std::string& a, const std::string& b) {
    for (const auto& r : rows)
        if (r.kind == kind && r.point == point && r.quantity == q && r.solver_a == a && r.solver_b == b) return r;
    BOOST_FAIL("no metric row " + kind + " " + point + " " + q + " " + a + " " + b);
    throw;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(metrics)

BOOST_AUTO_TEST_CASE(golden_metrics_three_solvers) {
    auto s = test::make_case("golden");
    for (const char* solver : {"continuum", "automaton", "dem"}) test::write_solver(s, solver);
    const Collection col = collect(s.c, s.o);
    BOOST_TEST(col.count(ResultState::Complete) == 9u);
    BOOST_TEST((col.missing_solvers == std::vector<std::string>{"yade"}));
    const auto rows = compute_metrics(col);
    const std::string p2 = s.c.points[1].id;  // U = 2 m/s

    // Profiles: u/U differs by a constant 0.05 (dem - continuum offset), noise = 0.01 (dem only).
    const auto& u = find(rows, "profile", p2, "u_over_U", "continuum", "dem");
    BOOST_TEST(*u.rms == 0.05, tt::tolerance(1e-9));
    BOOST_TEST(*u.max == 0.05, tt::tolerance(1e-9));
    BOOST_TEST(*u.noise_rms == 0.01, tt::tolerance(1e-9));
    // nu/nu_max: the automaton's occupancy (max 1) equals the continuum's nu/0.65.
    const auto& nu = find(rows, "profile", p2, "nu_over_numax", "continuum", "automaton");
    BOOST_TEST(*nu.rms < 1e-12);
    const auto& T = find(rows, "profile", p2, "T_over_U2", "continuum", "dem");
    BOOST_TEST(*T.rms == 0.002, tt::tolerance(1e-9));
    BOOST_TEST(!find(rows, "profile", p2, "T_over_U2", "continuum", "automaton").noise_rms.has_value());

    // Scalars at U = 2: sigma_b continuum 1000 U^2 = 4000, dem 1100 U^1.5 +- 5 %.
    const double dem = 1100 * std::pow(2.0, 1.5), se = 0.05 * dem;
    const auto& sb = find(rows, "scalar", p2, "normal_stress_bottom", "continuum", "dem");
    BOOST_TEST(*sb.a == 4000.0, tt::tolerance(1e-12));
    BOOST_TEST(*sb.b == dem, tt::tolerance(1e-12));
    BOOST_TEST(*sb.difference == 4000.0 - dem, tt::tolerance(1e-9));
    BOOST_TEST(*sb.combined_stderr == se, tt::tolerance(1e-9));
    BOOST_TEST(*sb.z == (4000.0 - dem) / se, tt::tolerance(1e-9));
    BOOST_TEST(sb.significant());
    // Slip/U: 0.1 vs 0.12 +- 0.01: z = -2, not beyond 2.
    const auto& slip = find(rows, "scalar", p2, "slip_bottom_over_U", "continuum", "dem");
    BOOST_TEST(*slip.difference == -0.02, tt::tolerance(1e-9));
    BOOST_TEST(*slip.z == -2.0, tt::tolerance(1e-9));
    // nu_bar/nu_max: 0.55/0.65 vs the automaton's 0.85/1.
    const auto& nub = find(rows, "scalar", p2, "nu_bar_over_numax", "continuum", "automaton");
    BOOST_TEST(*nub.difference == 0.55 / 0.65 - 0.85, tt::tolerance(1e-9));
    BOOST_TEST(!nub.combined_stderr.has_value());  // both deterministic
    BOOST_TEST(!nub.z.has_value());

    // Exponents: 2 for the continuum and the automaton, 1.5 +- 0.05/(sqrt 2 ln 2) for the dem.
    const auto& nc = find(rows, "exponent", "all", "shear_stress_bottom", "continuum", "");
    BOOST_TEST(*nc.a == 2.0, tt::tolerance(1e-9));
    BOOST_TEST(*nc.fit_points == 3);
    const auto& nd = find(rows, "exponent", "all", "normal_stress_top", "dem", "");
    BOOST_TEST(*nd.a == 1.5, tt::tolerance(1e-9));
    BOOST_TEST(*nd.a_stderr == 0.05 / (std::sqrt(2.0) * std::log(2.0)), tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(metrics_csv_round_trips_the_numbers) {
    auto s = test::make_case("golden_csv");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    const auto rows = compute_metrics(collect(s.c, s.o));
    const auto file = s.dir / "metrics.csv";
    write_file_atomic(file, metrics_csv(rows));
    const std::string p4 = s.c.points[2].id;
    auto r = test::read_metrics_row(file, "scalar", p4, "shear_stress_top", "continuum", "dem");
    BOOST_TEST_REQUIRE(!r.empty());
    const double c = 400 * 16.0, d = 450 * 8.0;
    BOOST_TEST(std::stod(r["difference"]) == c - d, tt::tolerance(1e-7));
    BOOST_TEST(std::stod(r["combined_stderr"]) == 0.05 * d, tt::tolerance(1e-7));
    BOOST_TEST(r["significant"] == "yes");
    BOOST_TEST(r["rms_difference"].empty());
    auto e = test::read_metrics_row(file, "exponent", "all", "shear_stress_top", "dem", "");
    BOOST_TEST(std::stod(e["a"]) == 1.5, tt::tolerance(1e-7));
    BOOST_TEST(e["fit_points"] == "3");
    // Every row has the same number of fields and no NaN/inf anywhere.
    const std::string text = test::slurp(file);
    BOOST_TEST(text.find("nan") == std::string::npos);
    BOOST_TEST(text.find("inf") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(groups_follow_the_swept_keys) {
    auto s = test::make_case("groups", "roughness = [0.0, 0.5]\n");
    std::vector<const OperatingPoint*> pts;
    for (const auto& p : s.c.points) pts.push_back(&p);
    const auto by_speed = speed_groups(pts);
    BOOST_TEST_REQUIRE(by_speed.size() == 2u);  // one per roughness, 3 speeds each
    BOOST_TEST(by_speed[0].points.size() == 3u);
    BOOST_TEST(by_speed[0].label == "R = 0");
    const auto by_roughness = roughness_groups(pts);
    BOOST_TEST_REQUIRE(by_roughness.size() == 3u);  // one per speed
    BOOST_TEST(by_roughness[1].label == "U = 2 m/s");
}

BOOST_AUTO_TEST_SUITE_END()
