// The checks of a load-controlled particle run (granlub/particles/load_control.h) that every engine's test
// makes the same way: tests/liggghts/test_dem_load.cpp and tests/yade/test_load.cpp.
#pragma once
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include <boost/test/unit_test.hpp>

#include "granlub/results/results.h"

namespace granlub::test {

struct LoadRun {
    int code = 1;
    std::filesystem::path dir;  // the point's result folder
    Summary summary;            // read when code == 0
};

// Runs solve(stress) -> {exit code, result folder} once per load and caches (several test cases
// read the same runs). Call it from one place per test program (the cache is per Solve type).
template <class Solve>
const LoadRun& cached_load_run(double stress, Solve solve) {
    static std::map<double, LoadRun> cache;
    if (auto it = cache.find(stress); it != cache.end()) return it->second;
    LoadRun r;
    std::tie(r.code, r.dir) = solve(stress);
    if (r.code == 0) r.summary = read_summary(r.dir / "summary.json");
    return cache.emplace(stress, std::move(r)).first->second;
}

// The plate reached the target: P_top within 3 block standard errors of it, an informative error
// bar, rare error clamps, and a plate that moved from its start H and stays inside its limits.
inline void check_target_reached(const Summary& s, double target, double H, double insert_fill) {
    const Scalar& top = s.outputs.at("normal_stress_top");
    const double se = top.stderr_.value_or(0);
    BOOST_TEST_MESSAGE("P_top " << top.value << " +- " << se << " Pa, target " << target << " Pa, gap "
                                << s.value("gap") << " m");
    BOOST_TEST(se > 0.0);
    // the time average over the steady windows equals the target within 3 block standard errors
    BOOST_TEST(std::abs(top.value - target) < 3.0 * se);
    // the error bar itself is informative (not a wide scatter that would pass anything)
    BOOST_TEST(se < 0.15 * target);
    const auto& lc = s.run.at("load_control");
    BOOST_TEST(lc.at("target_normal_stress_Pa").get<double>() == target);
    BOOST_TEST(!lc.at("plate_at_limit_at_end").get<bool>());
    // the window servo's average is the target only while the error clamp is rare (a weighted
    // plate has none)
    BOOST_TEST(lc.contains("updates_error_clamped") == (lc.at("plate") == "window"));
    if (lc.at("plate") == "window")
        BOOST_TEST(lc.at("updates_error_clamped").get<std::size_t>() < lc.at("servo_updates").get<std::size_t>() / 20);
    // the plate moved from its start and stays inside its limits (closest packing, 1.5 H)
    const double gap = s.value("gap");
    BOOST_TEST(std::abs(gap - H) > 1e-4);
    BOOST_TEST(gap > insert_fill * H / 0.7405);
    BOOST_TEST(gap < 1.5 * H);
}

// The result files of a load run: every standard output, `gap` with an error bar, the mean solid
// fraction over the mean gap (N grains of diameter d on the wall area A), a profile of `stations`
// slabs over the mean gap, and gap.csv with one row per servo update (`updates` of them).
inline void check_load_results(const Summary& s, const std::filesystem::path& dir, double grains, double d, double A,
                               std::size_t stations, std::size_t updates) {
    for (const char* name : kStandardOutputs) {
        BOOST_TEST_REQUIRE(s.outputs.count(name) == 1u, name);
        BOOST_TEST(std::isfinite(s.value(name)), name);
    }
    const double gap = s.value("gap");
    BOOST_TEST(s.outputs.at("gap").unit == "m");
    BOOST_TEST(s.outputs.at("gap").stderr_.value_or(0) > 0.0);
    // mean solid fraction = N V_grain / (A gap)
    const double nu = grains * std::numbers::pi / 6.0 * d * d * d / (A * gap);
    BOOST_TEST(std::abs(s.value("mean_solid_fraction") - nu) < 1e-12);
    // the profile spans the mean gap: its slab solid fractions add up to the grains' volume (to a
    // few per cent: grains above the mean gap while the plate is higher are cut off); slabs over
    // the initial gap would not
    const Profile p = read_profile(dir / "profile.csv");
    BOOST_TEST_REQUIRE(p.rows() == stations);
    double sum = 0;
    for (double v : p.column("solid_fraction")) sum += v;
    const double mean = sum / static_cast<double>(stations);
    BOOST_TEST_MESSAGE("profile mean nu " << mean << ", N V / (A gap) " << nu);
    BOOST_TEST(std::abs(mean - nu) < 0.03 * nu);
    // the plate history: time, gap and window stress per servo update
    std::ifstream in(dir / "gap.csv");
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
    BOOST_TEST(rows == s.run.at("load_control").at("servo_updates").get<std::size_t>());
    BOOST_TEST(rows == updates);
}

// A higher load gives a smaller gap (by more than 3 combined standard errors) and a denser packing,
// and the higher target is reached too.
inline void check_higher_load(const Summary& lo, const Summary& hi, double hi_target) {
    const Scalar& g_lo = lo.outputs.at("gap");
    const Scalar& g_hi = hi.outputs.at("gap");
    BOOST_TEST_MESSAGE("gap " << g_lo.value << " m at the lower load, " << g_hi.value << " m at " << hi_target
                              << " Pa");
    BOOST_TEST(g_hi.value < g_lo.value - 3.0 * std::hypot(g_lo.stderr_.value_or(0), g_hi.stderr_.value_or(0)));
    BOOST_TEST(hi.value("mean_solid_fraction") > lo.value("mean_solid_fraction"));
    const Scalar& top = hi.outputs.at("normal_stress_top");
    BOOST_TEST_MESSAGE("P_top " << top.value << " +- " << top.stderr_.value_or(0) << " Pa, target " << hi_target);
    BOOST_TEST(std::abs(top.value - hi_target) < 3.0 * top.stderr_.value_or(0));
}

}  // namespace granlub::test
