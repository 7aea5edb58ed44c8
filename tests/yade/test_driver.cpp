// The driver in YADE: binary collisions give the case's restitution (grain-grain and grain-wall,
// both contact laws), Hertz contact durations match LIGGGHTS' stiffness (R* = r at a wall), the
// tiny deck runs to completion with parseable, deterministic results, and a driver failure
// inside YADE is reported. Skipped when YADE is not installed.
#define BOOST_TEST_MODULE yade_driver
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "granlub/error.h"
#include "granlub/results/results.h"
#include "granlub/yade/driver.h"
#include "granlub/run/process.h"
#include "granlub/yade/settings.h"
#include "yade_installed.h"
#include "yade_test_case.h"

using namespace granlub;
using namespace granlub::yade;
using namespace granlub::yade::test;
namespace fs = std::filesystem;
namespace tt = boost::test_tools;

namespace {

// Restitution targets that differ per material, including low ones where ViscElMat's e_n and
// the measured e differ most (docs/yade-notes.md §3). Side walls take the bottom wall's material.
const std::pair<std::string, std::string> kGrains85{"restitution = 0.9\nfriction = 0.5\n\n[walls]",
                                                    "restitution = 0.85\nfriction = 0.5\n\n[walls]"};
const std::pair<std::string, std::string> kMixedWalls{
    "[walls]\nrestitution = 0.9\nfriction = 0.5\nroughness = 0.5\n",
    "[walls]\nrestitution = 0.65\nfriction = 0.5\nroughness = 0.5\n[walls.top]\nrestitution = 0.8\n"};
const std::pair<std::string, std::string> kElasticGrains{kGrains85.first,
                                                         "restitution = 1.0\nfriction = 0.5\n\n[walls]"};
const std::pair<std::string, std::string> kElasticWalls{kMixedWalls.first,
                                                        "[walls]\nrestitution = 1.0\nfriction = 0.5\nroughness = 0.5\n"};
const char* kHertzFine = "model = \"hertz\"\ntime_step = 1e-8\n";

// Hertz contact duration of an elastic head-on impact (Johnson 1985, eq. 11.24):
// t = 2.868 (m*^2 / (R* E*^2 v))^(1/5), E* = 1 / ((1 - nu^2)/E x 2) for two glass bodies.
double hertz_duration(double m_star, double r_star, double e_star, double v) {
    return 2.868 * std::pow(m_star * m_star / (r_star * e_star * e_star * v), 0.2);
}

}  // namespace

BOOST_AUTO_TEST_CASE(viscel_restitution_is_the_case_value, *boost::unit_test::precondition(YadeInstalled())) {
    const Case c = tiny_case_edits({kGrains85, kMixedWalls}, "");
    const OperatingPoint& p = c.points.at(0);
    const Settings s = resolve_settings(c, p, RunOptions{});
    const Restitution r = measure_restitution(c, p, s, scratch("collide-viscel"));
    // e_n is calibrated in YADE, so the measured e is the case's to the search tolerance
    BOOST_TEST(r.e.grain == 0.85, tt::tolerance(1e-4));
    BOOST_TEST(r.e.bottom == 0.65, tt::tolerance(1e-4));
    BOOST_TEST(r.e.top == 0.8, tt::tolerance(1e-4));
    BOOST_TEST(r.e.side == 0.65, tt::tolerance(1e-4));  // side walls: the bottom wall's material
    // ViscElMat's contact lasts t_c, grain-grain and grain-wall alike (the walls have a mass)
    BOOST_TEST(r.duration.grain == s.contact_time, tt::tolerance(0.02));
    BOOST_TEST(r.duration.bottom == s.contact_time, tt::tolerance(0.02));
    BOOST_TEST(r.en.at("bottom").get<double>() < 0.65);  // the raw e_n differs from e (clipped attraction)
}

BOOST_AUTO_TEST_CASE(hertz_restitution_and_stiffness, *boost::unit_test::precondition(YadeInstalled())) {
    // a small time step resolves the contact duration to ~0.5 %
    const Case c = tiny_case_edits({kGrains85, kMixedWalls}, kHertzFine);
    const OperatingPoint& p = c.points.at(0);
    const Settings s = resolve_settings(c, p, RunOptions{});
    const Restitution r = measure_restitution(c, p, s, scratch("collide-hertz"));
    // Tsuji et al. (1992) damping, the LIGGGHTS hertz form: e within 1 % of the target
    BOOST_TEST(r.e.grain == 0.85, tt::tolerance(0.01));
    BOOST_TEST(r.e.bottom == 0.65, tt::tolerance(0.01));
    BOOST_TEST(r.e.top == 0.8, tt::tolerance(0.01));

    // elastic impacts: the durations follow Hertz with LIGGGHTS' R* (r/2 for two grains, r at a
    // wall, where YADE alone would use r/2) and E* of glass on glass
    const Case both = tiny_case_edits({kElasticGrains, kElasticWalls}, kHertzFine);
    const Settings se = resolve_settings(both, both.points.at(0), RunOptions{});
    const Restitution re = measure_restitution(both, both.points.at(0), se, scratch("collide-hertz-elastic"));
    const double rad = 0.5 * both.grains.diameter;
    const double m = both.grains.density * 4.0 / 3.0 * std::numbers::pi * rad * rad * rad;
    const double nu = both.grains.poisson_ratio;
    const double E_star = both.grains.youngs_modulus / (2.0 * (1.0 - nu * nu));
    BOOST_TEST(re.e.grain == 1.0, tt::tolerance(2e-3));
    BOOST_TEST(re.duration.grain == hertz_duration(0.5 * m, 0.5 * rad, E_star, 1.0), tt::tolerance(0.01));
    BOOST_TEST(re.duration.bottom == hertz_duration(m, rad, E_star, 1.0), tt::tolerance(0.01));
    BOOST_TEST(re.duration.top == hertz_duration(m, rad, E_star, 1.0), tt::tolerance(0.01));
}

BOOST_AUTO_TEST_CASE(tiny_deck_runs_and_is_deterministic, *boost::unit_test::precondition(YadeInstalled())) {
    const Case c = tiny_case();
    RunOptions o;
    o.results_root = scratch("tiny");
    BOOST_TEST_REQUIRE(run(c, o) == 0);
    const fs::path dir = o.results_root / "yade" / "U2.0";
    const Profile prof = read_profile(dir / "profile.csv");
    const Summary sum = read_summary(dir / "summary.json");
    BOOST_TEST((result_status(dir, c.inputs_hash("yade")).state == ResultState::Complete));
    for (const char* name : kStandardOutputs) BOOST_TEST(std::isfinite(sum.value(name)), name);
    for (const char* col : kProfileColumns) BOOST_TEST(prof.has(col), col);
    BOOST_TEST(prof.rows() == 20u);
    // the grains fill the box to the point's solid fraction; the coarse-graining keeps it
    BOOST_TEST(sum.value("mean_solid_fraction") == 0.5, tt::tolerance(0.01));
    // a sheared, loaded layer: positive stresses, flow between the wall speeds
    BOOST_TEST(sum.value("normal_stress_bottom") > 0);
    BOOST_TEST(sum.value("normal_stress_top") > 0);
    BOOST_TEST(sum.value("shear_stress_top") > 0);
    for (double u : prof.column("u_over_U")) {
        BOOST_TEST(u > -0.2);
        BOOST_TEST(u < 1.2);
    }
    BOOST_TEST(sum.run.at("steps").get<long long>() == 3000);
    BOOST_TEST(sum.run.at("max_overlap_over_d").get<double>() < 0.02);  // stiff contacts
    // the inertial numbers (core granlub/statistics/flow_regime.h), the coordination number and the order (the
    // snapshots hold x, y, z); the contact persistence from three snapshots after the run, as
    // granlub dem measures it (issue 50)
    BOOST_TEST(std::isfinite(sum.run.at("flow_regime").at("inertial_number_mid_gap").get<double>()));
    BOOST_TEST(sum.run.at("flow_regime").at("regime").is_string());
    BOOST_TEST(sum.run.at("flow_regime").at("coordination_number").get<double>() > 0.0);
    const double persistence = sum.run.at("flow_regime").at("contact_persistence").get<double>();
    BOOST_TEST(persistence >= 0.0);
    BOOST_TEST(persistence <= 1.0);
    BOOST_TEST(sum.run.at("flow_regime").at("persistence_snapshots").get<int>() == 3);
    BOOST_TEST(!fs::exists(dir / "contacts.bin"));  // read and removed
    BOOST_TEST(sum.value("q6") > 0.0);
    BOOST_TEST(sum.value("q6") < 0.7);
    BOOST_TEST(!fs::exists(dir / "samples.bin"));                        // raw snapshots removed
    BOOST_TEST(fs::exists(dir / "yade.log"));
    BOOST_TEST(fs::exists(o.results_root / "initial" / "U2.0" / "particles.csv"));

    // same case, same seed, -j1: the same numbers
    RunOptions again = o;
    again.force = true;
    again.results_root = scratch("tiny-again");
    BOOST_TEST_REQUIRE(run(c, again) == 0);
    const Summary sum2 = read_summary(again.results_root / "yade" / "U2.0" / "summary.json");
    for (const char* name : kStandardOutputs) BOOST_TEST(sum2.value(name) == sum.value(name), name);
}

BOOST_AUTO_TEST_CASE(driver_failure_inside_yade_is_reported, *boost::unit_test::precondition(YadeInstalled())) {
    const Case c = tiny_case();
    const OperatingPoint& p = c.points.at(0);
    const Settings s = resolve_settings(c, p, RunOptions{});
    auto params = collision_params(c, p, s, 1.0);
    params["materials"]["top"]["restitution"] = 1.5;  // the driver checks its own inputs too
    try {
        run_driver(locate_driver(), scratch("driver-rejects"), params, p.id, 120);
        BOOST_FAIL("expected SolverError");
    } catch (const SolverError& e) {
        const std::string m = e.what();
        BOOST_TEST(m.find("exit code 2") != std::string::npos);
        BOOST_TEST(m.find("materials.top.restitution") != std::string::npos);
    }
}
