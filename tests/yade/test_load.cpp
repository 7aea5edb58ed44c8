// `granlub yade` with control = "load": the servo-controlled top plate (the servo of `granlub dem`,
// granlub/servo.h) reaches the target normal stress within 3 block standard errors, a higher load
// gives a smaller gap and a denser packing, and the result files are those of `granlub dem`
// (gap, run.load_control, gap.csv). Skipped when YADE is not installed.
#define BOOST_TEST_MODULE yade_load
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>

#include "granlub/results.h"
#include "yade_installed.h"
#include "yade_test_case.h"

using namespace granlub;
using namespace granlub::yade;
using namespace granlub::yade::test;
namespace fs = std::filesystem;

namespace {

// The tiny cell (291 grains, H = 4 mm, U = 2 m/s) under load. Softer viscel contacts (t_c = 50 us,
// dt = 2.5 us) let 16000 steps cover 0.04 s, ~7 s of YADE per point: the plate first rises (the
// shear dilates the layer), then settles within ~0.02 s.
Case load_case(double stress) {
    return tiny_case_edits({{"control = \"fill\"", "control = \"load\"\nnormal_stress = " + std::to_string(stress)},
                            {"time = 1.5e-3", "time = 0.04"},
                            {"snapshots = 30", "snapshots = 20"}},
                           "contact_time = 5e-5\nservo_every = 100\nstations = 6\n");
}

struct Run {
    int code = 1;
    fs::path dir;
    Summary summary;
};

// Runs once per load and caches (several test cases read the same runs).
const Run& run_load(double stress) {
    static std::map<double, Run> cache;
    auto it = cache.find(stress);
    if (it != cache.end()) return it->second;
    const Case c = load_case(stress);
    RunOptions o;
    o.results_root = scratch("load-" + std::to_string(static_cast<int>(stress)));
    Run r;
    r.code = run(c, o);
    r.dir = result_dir(o.results_root, "yade", c.points.front().id);
    if (r.code == 0) r.summary = read_summary(r.dir / "summary.json");
    return cache.emplace(stress, std::move(r)).first->second;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(load, *boost::unit_test::precondition(YadeInstalled()))

BOOST_AUTO_TEST_CASE(plate_reaches_the_target_normal_stress) {
    const Run& r = run_load(200.0);
    BOOST_TEST_REQUIRE(r.code == 0);
    const Scalar& top = r.summary.outputs.at("normal_stress_top");
    const double se = top.stderr_.value_or(0);
    BOOST_TEST_MESSAGE("P_top " << top.value << " +- " << se << " Pa, target 200 Pa, gap "
                                << r.summary.value("gap") << " m");
    BOOST_TEST(se > 0.0);
    // the time average over the steady windows equals the target within 3 block standard errors
    BOOST_TEST(std::abs(top.value - 200.0) < 3.0 * se);
    // the error bar itself is informative (not a wide scatter that would pass anything)
    BOOST_TEST(se < 0.15 * 200.0);
    const auto& lc = r.summary.run.at("load_control");
    BOOST_TEST(lc.at("target_normal_stress_Pa").get<double>() == 200.0);
    BOOST_TEST(!lc.at("plate_at_limit_at_end").get<bool>());
    // the window average is the target only while the error clamp is rare
    BOOST_TEST(lc.at("updates_error_clamped").get<std::size_t>() < lc.at("servo_updates").get<std::size_t>() / 20);
    // the plate moved from its start (4 mm) and stays inside its limits
    const double gap = r.summary.value("gap");
    BOOST_TEST(std::abs(gap - 4e-3) > 1e-4);
    BOOST_TEST(gap > 0.5 * 4e-3 / 0.7405);
    BOOST_TEST(gap < 1.5 * 4e-3);
}

BOOST_AUTO_TEST_CASE(load_results_are_complete_and_use_the_mean_gap) {
    const Run& r = run_load(200.0);
    BOOST_TEST_REQUIRE(r.code == 0);
    BOOST_TEST((result_status(r.dir, load_case(200.0).inputs_hash("yade")).state == ResultState::Complete));
    for (const char* name : kStandardOutputs) {
        BOOST_TEST_REQUIRE(r.summary.outputs.count(name) == 1u, name);
        BOOST_TEST(std::isfinite(r.summary.value(name)), name);
    }
    const double gap = r.summary.value("gap");
    BOOST_TEST(r.summary.outputs.at("gap").unit == "m");
    BOOST_TEST(r.summary.outputs.at("gap").stderr_.value_or(0) > 0.0);
    // mean solid fraction = N V_grain / (A gap), as granlub dem
    const Case c = load_case(200.0);
    const double d = c.grains.diameter;
    const double n = static_cast<double>(r.summary.run.at("grains").get<long>());
    const double nu = n * std::numbers::pi / 6.0 * d * d * d / (c.cell.length * c.cell.width * gap);
    BOOST_TEST(std::abs(r.summary.value("mean_solid_fraction") - nu) < 1e-12);
    // the profile spans the mean gap: its slab solid fractions add up to the grains' volume (to a
    // few per cent: grains above the mean gap while the plate is higher are cut off)
    const Profile p = read_profile(r.dir / "profile.csv");
    BOOST_TEST_REQUIRE(p.rows() == 6u);
    double sum = 0;
    for (double v : p.column("solid_fraction")) sum += v;
    BOOST_TEST_MESSAGE("profile mean nu " << sum / 6 << ", N V / (A gap) " << nu);
    BOOST_TEST(std::abs(sum / 6.0 - nu) < 0.03 * nu);
    // the plate history: time, gap and window stress per servo update
    std::ifstream in(r.dir / "gap.csv");
    BOOST_TEST_REQUIRE(static_cast<bool>(in));
    std::string line;
    std::size_t rows = 0;
    bool header = false;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            BOOST_TEST(line == "time_s,gap_m,normal_stress_top_Pa");
            header = true;
            continue;
        }
        ++rows;
    }
    BOOST_TEST(rows == r.summary.run.at("load_control").at("servo_updates").get<std::size_t>());
    BOOST_TEST(rows == 160u);  // 16000 steps / 100
    // the driver's parameters carry the servo
    const auto params = nlohmann::json::parse(read_text(r.dir / "params.json"));
    BOOST_TEST(params.at("servo").at("every").get<int>() == 100);
    BOOST_TEST(params.at("servo").at("target_stress").get<double>() == 200.0);
}

BOOST_AUTO_TEST_CASE(higher_load_gives_a_smaller_gap_and_denser_packing) {
    const Run& lo = run_load(200.0);
    const Run& hi = run_load(800.0);
    BOOST_TEST_REQUIRE(lo.code == 0);
    BOOST_TEST_REQUIRE(hi.code == 0);
    const Scalar& g_lo = lo.summary.outputs.at("gap");
    const Scalar& g_hi = hi.summary.outputs.at("gap");
    BOOST_TEST_MESSAGE("gap at 200 Pa " << g_lo.value << ", at 800 Pa " << g_hi.value);
    BOOST_TEST(g_hi.value < g_lo.value - 3.0 * std::hypot(*g_lo.stderr_, *g_hi.stderr_));
    BOOST_TEST(hi.summary.value("mean_solid_fraction") > lo.summary.value("mean_solid_fraction"));
    const Scalar& top = hi.summary.outputs.at("normal_stress_top");
    BOOST_TEST_MESSAGE("P_top " << top.value << " +- " << top.stderr_.value_or(0) << " Pa, target 800 Pa");
    BOOST_TEST(std::abs(top.value - 800.0) < 3.0 * top.stderr_.value_or(0));
}

BOOST_AUTO_TEST_SUITE_END()
