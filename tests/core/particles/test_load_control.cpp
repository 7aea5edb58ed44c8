// The engine-independent results of a load-controlled run (load_control.h) on hand-made series
// with known answers, and the servo keys' resolution (servo.h).
#include <cmath>
#include <numbers>
#include <string>

#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/particles/load_control.h"
#include "granlub/particles/servo.h"

using namespace granlub;

namespace {

ServoSettings servo(double target) {
    ServoSettings s;
    s.load = true;
    s.target_stress = target;
    s.servo_every = 100;
    s.servo_gain = 0.05;
    s.servo_max_error = kServoMaxError;
    s.gap_min = 1e-3;
    s.gap_max = 6e-3;
    return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(window_stresses_average_the_blocks_of_each_servo_window) {
    // blocks of 50 steps, windows of 100: two blocks per window
    const std::vector<double> steps{50, 100, 150, 200, 250, 300};
    const std::vector<double> top{1, 3, 5, 7, 100, 300};
    const PlateSeries plate{{100, 200, 300}, {4e-3, 4.1e-3, 4.2e-3}};
    const auto w = window_stresses(servo(10), steps, top, plate);
    BOOST_TEST_REQUIRE(w.size() == 3u);
    BOOST_TEST(w[0] == 2.0);
    BOOST_TEST(w[1] == 6.0);
    BOOST_TEST(w[2] == 200.0);
    const std::string csv = gap_csv(servo(10), 1e-5, steps, top, plate, "hand-made");
    BOOST_TEST(csv.find("# hand-made\n") == 0u);
    BOOST_TEST(csv.find("time_s,gap_m,normal_stress_top_Pa\n0.001,0.004,2\n0.002,0.0041,6\n0.003,0.0042,200\n") !=
               std::string::npos);
}

BOOST_AUTO_TEST_CASE(load_summary_counts_limits_and_clamps) {
    // 20 windows: the plate at the box top in the last two, one window stress above (1 + 3) x target
    const ServoSettings s = servo(10);
    PlateSeries plate;
    std::vector<double> steps, top;
    for (int j = 1; j <= 20; ++j) {
        plate.step.push_back(100.0 * j);
        plate.gap.push_back(j > 18 ? s.gap_max : 4e-3 + 1e-5 * (j % 3));
        for (int b : {50, 100}) {
            steps.push_back(100.0 * (j - 1) + b);
            top.push_back(j == 5 ? 45.0 : 10.0);
        }
    }
    SteadyWindow win;
    win.plate_start = 10;
    std::map<std::string, Scalar> out{{"normal_stress_top", Scalar{9.0, 0.5, "Pa"}}};
    std::string line;
    const auto lc = load_summary({.servo = s,
                                  .initial_gap = 4e-3,
                                  .wall_step = steps,
                                  .top_stress = top,
                                  .plate = plate,
                                  .window = win,
                                  .blocks = 5,
                                  .grains = 100,
                                  .solids_volume = 100 * std::numbers::pi / 6.0 * 1e-9,
                                  .area = 1e-4},
                                 out, line);
    double mean = 0;
    for (std::size_t j = 10; j < 20; ++j) mean += plate.gap[j] / 10.0;
    BOOST_TEST(out.at("gap").value == mean, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(out.at("gap").unit == "m");
    const double nu = 100 * std::numbers::pi / 6.0 * 1e-9 / (1e-4 * mean);
    BOOST_TEST(out.at("mean_solid_fraction").value == nu, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(lc.at("normal_stress_top_over_target").get<double>() == 0.9, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(lc.at("deviation_in_stderr").get<double>() == -2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(lc.at("servo_updates").get<std::size_t>() == 20u);
    BOOST_TEST(lc.at("servo_updates_used").get<std::size_t>() == 10u);
    BOOST_TEST(lc.at("updates_at_plate_limit").get<std::size_t>() == 2u);
    BOOST_TEST(lc.at("updates_error_clamped").get<std::size_t>() == 1u);
    BOOST_TEST(lc.at("plate_at_limit_at_end").get<bool>());
    BOOST_TEST(lc.at("gap_file").get<std::string>() == kGapFile);
    BOOST_TEST(line.find("PLATE AT ITS LIMIT") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(steady_window_waits_for_the_plate) {
    // flat wall stresses from the start; the plate settles only after 30 of 60 windows
    std::vector<double> steps, stress;
    for (int i = 1; i <= 120; ++i) {
        steps.push_back(50.0 * i);
        stress.push_back(10.0 + ((i * 7919) % 13) * 0.1);
    }
    PlateSeries plate;
    for (int j = 1; j <= 60; ++j) {
        plate.step.push_back(100.0 * j);
        plate.gap.push_back(j <= 30 ? 5e-3 - 3e-5 * j : 4.1e-3 + 1e-6 * ((j * 31) % 5));
    }
    const SteadyWindow alone = steady_window({{"stress", stress, kStressDrift}}, steps, 50, 1e-5, nullptr, 100);
    const SteadyWindow w = steady_window({{"stress", stress, kStressDrift}}, steps, 50, 1e-5, &plate, 100);
    BOOST_TEST_MESSAGE("wall start alone " << alone.wall_start << ", with the plate " << w.wall_start
                                           << ", plate start " << w.plate_start);
    BOOST_TEST(alone.wall_start < 20u);
    BOOST_TEST(plate.step[w.plate_start] >= 3000.0);  // the plate's transient is left out ...
    BOOST_TEST(steps[w.wall_start] - 50.0 == plate.step[w.plate_start] - 100.0);  // ... from the same step on
    BOOST_TEST(w.t_start == (steps[w.wall_start] - 50.0) * 1e-5, boost::test_tools::tolerance(1e-12));
}
