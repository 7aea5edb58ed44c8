// The whole ring, small: plugins/liggghts/examples/ring (make_ring.py, in.ring) on 1 and 2 ranks.
// Checks what a ring cell must do: keep every grain inside meshes whose surfaces turn
// (surface_ang_vel), shear the bed so that the still top is dragged forward and the turning walls
// held back, with the walls' torques about the axis balancing over the steady windows; the wall
// forces along the axis carrying the grains' weight; and the curvature pushing the grains outward
// (the slice needs a body force for this).
#define BOOST_TEST_MODULE liggghts_ring
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_driver.h"

namespace fs = std::filesystem;

namespace {

const fs::path kExample = fs::path(GRANLUB_SOURCE_DIR) / "plugins/liggghts/examples/ring";
constexpr double kD = 0.787e-3, kR = 10 * kD, kW = 4 * kD, kH = 4 * kD;  // make_ring.py's defaults
constexpr double kMass = 2550.0 * M_PI / 6 * kD * kD * kD;

struct Ring {
    std::vector<std::vector<double>> windows;  // step, then F_y and T_y of floor, inner, outer, top
    std::vector<std::vector<double>> grains;   // id x y z radius vx vy vz
};

std::vector<std::vector<double>> numbers(const fs::path& file, size_t columns) {
    std::vector<std::vector<double>> rows;
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

Ring run_ring(int ranks) {
    const std::string folder = "liggghts_ring_np" + std::to_string(ranks);
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / folder;
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string make = "cd '" + dir.string() + "' && python3 '" + (kExample / "make_ring.py").string() + "' > make.out 2>&1";
    BOOST_TEST_REQUIRE(std::system(make.c_str()) == 0, "make_ring.py failed: " << dir / "make.out");
    const auto run = granlub::test::run_driver((kExample / "in.ring").string(), "", ranks, folder);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
    return {numbers(dir / "torques.txt", 9), numbers(dir / "final.txt", 8)};
}

void check(const Ring& r, int ranks) {
    BOOST_TEST_CONTEXT(ranks << " rank(s)") {
        // every grain still there and inside the trough: the chord of a facet lies inside its
        // circle by at most R_out (1 - cos(pi/256)) = 0.0009 d; 'separate on' leaves no overlap
        BOOST_TEST_REQUIRE(r.grains.size() == 768u);
        const double tol = 2e-3 * kD, rad = 0.5 * kD;
        double r_sum = 0;
        size_t outer_half = 0;
        for (const auto& g : r.grains) {
            const double rr = std::hypot(g[1], g[3]);
            BOOST_TEST(rr <= kR + kW / 2 - rad + tol, "grain " << g[0] << " at r = " << rr);
            BOOST_TEST(rr >= kR - kW / 2 + rad - tol, "grain " << g[0] << " at r = " << rr);
            BOOST_TEST(g[2] >= rad - tol, "grain " << g[0] << " at y = " << g[2]);
            BOOST_TEST(g[2] <= kH - rad + tol, "grain " << g[0] << " at y = " << g[2]);
            r_sum += rr;
            outer_half += rr > kR;
        }
        // the curvature pushes the bed outward: measured mean radius 0.62 d beyond the trough's
        // middle and 2.4 times as many grains in the outer half as in the inner (1.2, the ratio
        // of the halves' areas, for a bed spread evenly)
        const double r_mean = r_sum / static_cast<double>(r.grains.size());
        BOOST_TEST_MESSAGE("mean radius " << (r_mean - kR) / kD << " d beyond R; outer half " << outer_half);
        BOOST_TEST(r_mean > kR + 0.3 * kD);
        BOOST_TEST(outer_half > 2 * (r.grains.size() - outer_half));

        // windows 6-10 (steps 12 000-20 000; steady from ~6000 steps): torque about the axis and
        // force along it, means of the window means
        BOOST_TEST_REQUIRE(r.windows.size() == 10u);
        double t_floor = 0, t_sides = 0, t_top = 0, f_sum = 0;
        for (size_t w = 5; w < 10; ++w) {
            const auto& v = r.windows[w];
            t_floor += v[2] / 5;
            t_sides += (v[4] + v[6]) / 5;
            t_top += v[8] / 5;
            f_sum += (v[1] + v[3] + v[5] + v[7]) / 5;
        }
        const double weight = 768 * kMass * 9.81;
        BOOST_TEST_MESSAGE("torques (N m): floor " << t_floor << ", side walls " << t_sides << ", top " << t_top
                                                  << "; walls' axial force + weight " << f_sum + weight << " N (weight "
                                                  << weight << ")");
        BOOST_TEST(t_top > 0.0);                  // the still top is dragged along the rotation
        BOOST_TEST(t_floor + t_sides < 0.0);      // the turning walls are held back
        BOOST_TEST(std::abs(t_floor + t_sides + t_top) < 0.1 * t_top);  // balance (measured 1 %)
        BOOST_TEST(std::abs(f_sum + weight) < 0.1 * weight);           // the walls carry the weight (0.4-0.8 %)
    }
}

}  // namespace

BOOST_AUTO_TEST_CASE(ring_one_rank) { check(run_ring(1), 1); }
BOOST_AUTO_TEST_CASE(ring_two_ranks) { check(run_ring(2), 2); }
