// The whole ring, small: plugins/liggghts/examples/ring (make_ring.py, in.ring) on 1 and 2 ranks.
// Checks what a ring cell must do: keep every grain inside meshes whose surfaces turn
// (surface_ang_vel); hold the annular top at its load with the servo (the plate's mean window
// stress is the target, the plate off its limits); shear the bed so that the still top is dragged
// forward and the turning walls held back, with the walls' torques about the axis balancing; the
// walls' forces along the axis carrying the grains' weight besides the load; and, under a load
// light against the centrifugal force, the curvature pushing the grains outward (the slice needs a
// body force for this).
#define BOOST_TEST_MODULE liggghts_ring
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "granlub/statistics/block_average.h"
#include "run_driver.h"

namespace fs = std::filesystem;

namespace {

const fs::path kExample = fs::path(GRANLUB_SOURCE_DIR) / "plugins/liggghts/examples/ring";
constexpr double kD = 0.787e-3, kR = 10 * kD, kW = 4 * kD, kH = 4 * kD;  // make_ring.py's defaults
constexpr double kMass = 2550.0 * M_PI / 6 * kD * kD * kD;
constexpr double kArea = 2 * M_PI * kR * kW;  // the annular top
constexpr std::size_t kGrains = 768;

using Rows = std::vector<std::vector<double>>;

struct Ring {
    double load = 0;  // Pa
    Rows windows;     // 2000-step windows: step, then F_y and T_y of floor, inner, outer, top
    Rows radial;      // 2000-step windows: step, mean radius, grains beyond R
    Rows plate;       // 100-step servo windows: step, plate position, P_w
    Rows grains;      // id x y z radius vx vy vz
};

Rows numbers(const fs::path& file, size_t columns) {
    Rows rows;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ss(line);
        std::vector<double> v;
        double x;
        while (ss >> x) v.push_back(x);
        if (v.size() == columns && ss.eof()) rows.push_back(v);
    }
    return rows;
}

Ring run_ring(int ranks, double load) {
    const std::string folder = "liggghts_ring_np" + std::to_string(ranks);
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / folder;
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string make = "cd '" + dir.string() + "' && python3 '" + (kExample / "make_ring.py").string() +
                             "' --P " + std::to_string(load) + " > make.out 2>&1";
    BOOST_TEST_REQUIRE(std::system(make.c_str()) == 0, "make_ring.py failed: " << dir / "make.out");
    const auto run = granlub::test::run_driver((kExample / "in.ring").string(), "", ranks, folder);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
    return {load, numbers(dir / "torques.txt", 9), numbers(dir / "radial.txt", 3), numbers(dir / "plate.txt", 3),
            numbers(dir / "final.txt", 8)};
}

double mean(const std::vector<double>& v) { return granlub::mean_and_stderr(v).mean; }
double stderr_of_mean(const std::vector<double>& v) { return granlub::mean_and_stderr(v).stderr_; }

// What every run must do, whatever its load.
void check_common(const Ring& r) {
    // every grain still there and inside the trough: the chord of a facet lies inside its circle
    // by at most R_out (1 - cos(pi/256)) = 0.0009 d; 'separate on' leaves no overlap
    BOOST_TEST_REQUIRE(r.grains.size() == kGrains);
    const double tol = 2e-3 * kD, rad = 0.5 * kD;
    for (const auto& g : r.grains) {
        const double rr = std::hypot(g[1], g[3]);
        BOOST_TEST(rr <= kR + kW / 2 - rad + tol, "grain " << g[0] << " at r = " << rr);
        BOOST_TEST(rr >= kR - kW / 2 + rad - tol, "grain " << g[0] << " at r = " << rr);
        BOOST_TEST(g[2] >= rad - tol, "grain " << g[0] << " at y = " << g[2]);
    }

    // the servo (200 windows of 100 steps; steady from ~6000 steps): over the second half the
    // mean window stress is the target (an integral controller), the plate never at a limit
    BOOST_TEST_REQUIRE(r.plate.size() == 201u);  // step 0 and every window
    std::vector<double> p_w, h;
    for (const auto& v : r.plate)
        if (v[0] > 10000) p_w.push_back(v[2]), h.push_back(v[1]);
    const double h_min = kGrains * M_PI / 6 * kD * kD * kD / (0.7405 * kArea), h_max = 1.4 * kH;
    const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    BOOST_TEST_MESSAGE("top: P_w " << mean(p_w) << " +- " << stderr_of_mean(p_w) << " Pa (target " << r.load
                                   << "); plate " << *lo / kD << " .. " << *hi / kD << " d");
    BOOST_TEST(std::abs(mean(p_w) - r.load) < 0.05 * r.load);
    BOOST_TEST(*lo > h_min);
    BOOST_TEST(*hi < h_max);
    for (const auto& g : r.grains) BOOST_TEST(g[2] <= *hi - rad + tol, "grain " << g[0] << " above the plate");

    // windows 6-10 (steps 12 000-20 000): torque about the axis and force along it
    BOOST_TEST_REQUIRE(r.windows.size() == 10u);
    double t_floor = 0, t_sides = 0, t_top = 0, f_top = 0;
    std::vector<double> f_sum;
    for (size_t w = 5; w < 10; ++w) {
        const auto& v = r.windows[w];
        t_floor += v[2] / 5;
        t_sides += (v[4] + v[6]) / 5;
        t_top += v[8] / 5;
        f_top += v[7] / 5;
        f_sum.push_back(v[1] + v[3] + v[5] + v[7]);
    }
    const double weight = kGrains * kMass * 9.81;
    const double imbalance = mean(f_sum) + weight, imbalance_se = stderr_of_mean(f_sum);
    BOOST_TEST_MESSAGE("torques (N m): floor " << t_floor << ", side walls " << t_sides << ", top " << t_top
                                              << "; top force " << f_top << " N; walls' axial force + weight "
                                              << imbalance << " +- " << imbalance_se << " N (weight " << weight << ")");
    BOOST_TEST(t_top > 0.0);                                        // the still top is dragged along the rotation
    BOOST_TEST(t_floor + t_sides < 0.0);                            // the turning walls are held back
    BOOST_TEST(std::abs(t_floor + t_sides + t_top) < 0.05 * t_top);  // balance (measured 0.02-0.4 %)
    // the floor and side walls carry the load and the weight; a mesh re-made at each servo window
    // instead of moved left 14 % of the weight out (5 standard errors)
    BOOST_TEST(std::abs(imbalance) < 3 * imbalance_se + 0.05 * weight);
}

// Radial distribution over windows 6-10: mean radius beyond R (d) and grains beyond R.
std::pair<double, double> radial(const Ring& r) {
    BOOST_TEST_REQUIRE(r.radial.size() == 10u);
    double shift = 0, beyond = 0;
    for (size_t w = 5; w < 10; ++w) shift += (r.radial[w][1] - kR) / kD / 5, beyond += r.radial[w][2] / 5;
    return {shift, beyond};
}

}  // namespace

// The sawyer2001 load (5.5 kPa), ten times the centrifugal force per grain here: the bed fills the
// trough; measured: the grains beyond R in the ratio of the halves' areas (11:9), mean radius
// 0.18 d beyond R (0.13 d for grains spread evenly).
BOOST_AUTO_TEST_CASE(ring_under_the_case_load_one_rank) {
    const Ring r = run_ring(1, 5500.0);
    check_common(r);
    // the example's reduction runs on it and finds the same top stress
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / "liggghts_ring_np1";
    const std::string stats = "cd '" + dir.string() + "' && python3 '" + (kExample / "ring_stats.py").string() +
                              "' --from 0.05 > stats.out 2>&1";
    BOOST_TEST_REQUIRE(std::system(stats.c_str()) == 0, "ring_stats.py failed: " << dir / "stats.out");
    std::ifstream out(dir / "stats.out");
    std::string line;
    double p_top = 0;
    while (std::getline(out, line))
        if (line.rfind("  P_top ", 0) == 0) p_top = std::stod(line.substr(8));
    double p_windows = 0;  // the same windows 6-10 from torques.txt
    for (size_t w = 5; w < 10; ++w) p_windows += r.windows[w][7] / kArea / 5;
    BOOST_TEST(p_top == p_windows, boost::test_tools::tolerance(1e-4));
    const auto [shift, beyond] = radial(r);
    BOOST_TEST_MESSAGE("5.5 kPa: mean radius " << shift << " d beyond R; " << beyond << " of " << kGrains
                                               << " grains beyond R");
}

// A light load (1 kPa, about twice the centrifugal force per grain, U^2/R = 52 g): the curvature
// pushes the bed outward. Measured: 2.1 times as many grains beyond R as inside it (1.22 for an
// even spread), mean radius 0.55 d beyond R (0.13 d even).
BOOST_AUTO_TEST_CASE(ring_under_a_light_load_two_ranks) {
    const Ring r = run_ring(2, 1000.0);
    check_common(r);
    const auto [shift, beyond] = radial(r);
    BOOST_TEST_MESSAGE("1 kPa: mean radius " << shift << " d beyond R; " << beyond << " of " << kGrains
                                             << " grains beyond R");
    BOOST_TEST(shift > 0.3);
    BOOST_TEST(beyond > 1.6 * (kGrains - beyond));
}
