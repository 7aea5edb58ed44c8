// The whole ring's geometry (granlub/particles/annulus.h): the equal-area map onto the slice's frame, the
// walls' loads as slice wall forces, the torque balance, and the ring insertion (overlap-free,
// inside the trough, seeded, a clear error when the grains do not fit).
#include <cmath>
#include <numbers>
#include <random>

#include <boost/test/unit_test.hpp>

#include "granlub/particles/annulus.h"
#include "granlub/error.h"

using namespace granlub;

namespace {

constexpr double kPi = std::numbers::pi;
const Annulus kRing{0.05, 0.02};  // r from 0.04 to 0.06 m

// A grain at radius r, angle theta (theta = atan2(-z, x)), height y, turning rigidly at omega.
void add_turning(ParticleSet& p, double r, double theta, double y, double omega) {
    const double x = r * std::cos(theta), z = -r * std::sin(theta);
    // velocity omega r along e_theta = d(x, z)/d(theta) / r = (-sin, -cos)
    p.push_back(x, y, z, -omega * r * std::sin(theta), 0.0, -omega * r * std::cos(theta), 1e-3);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(annulus)

BOOST_AUTO_TEST_CASE(the_map_takes_the_walls_to_the_slice_sides_and_keeps_volumes) {
    ParticleSet ring, s;
    add_turning(ring, kRing.outer(), 0.0, 0.001, 1.0);
    add_turning(ring, kRing.inner(), kPi / 2, 0.002, 1.0);
    add_turning(ring, kRing.R, 3 * kPi / 2, 0.003, 1.0);
    to_slice(ring, kRing, s);
    BOOST_TEST_REQUIRE(s.size() == 3u);
    BOOST_TEST(s.z[0] == -0.5 * kRing.W, boost::test_tools::tolerance(1e-12));  // the outer wall
    BOOST_TEST(s.z[1] == 0.5 * kRing.W, boost::test_tools::tolerance(1e-12));   // the inner wall
    BOOST_TEST(s.x[0] == 0.0, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(s.x[1] == kRing.R * kPi / 2, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(s.x[2] == kRing.R * 3 * kPi / 2, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(s.y[2] == 0.003);
    // a rigid rotation at Omega is u = Omega R everywhere, no motion across
    for (std::size_t i = 0; i < 3; ++i) {
        BOOST_TEST(s.vx[i] == kRing.R, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(std::abs(s.vz[i]) < 1e-12);
    }
    // equal area: grains spread evenly over the trough's area land evenly across the slice's width
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    ParticleSet even;
    for (int i = 0; i < 200000; ++i) {
        const double ri = kRing.inner(), ro = kRing.outer();
        add_turning(even, std::sqrt(ri * ri + u(rng) * (ro * ro - ri * ri)), 2 * kPi * u(rng), 0.001, 1.0);
    }
    to_slice(even, kRing, s);
    int outer_half = 0;
    for (double z : s.z) outer_half += z < 0;
    // binomial standard error 0.0011: within 4 of them of a half; by radius 55 % lie beyond R
    BOOST_TEST(std::abs(outer_half / 200000.0 - 0.5) < 0.0045);
}

BOOST_AUTO_TEST_CASE(wall_loads_become_slice_stresses_and_torques_balance) {
    RingWallLoads w;
    // top torque +2, floor -1.2, outer -0.5, inner -0.3 (N m): balanced; axial forces (N)
    for (int i = 0; i < 10; ++i) {
        w.step.push_back(100.0 * (i + 1));
        w.fy_floor.push_back(-10.0), w.t_floor.push_back(-1.2);
        w.fy_top.push_back(9.0), w.t_top.push_back(2.0);
        w.fy_outer.push_back(-0.4), w.t_outer.push_back(-0.5);
        w.fy_inner.push_back(-0.1), w.t_inner.push_back(-0.3);
    }
    const BlockEstimate b = ring_torque_balance(w, 0, 5);
    BOOST_TEST(std::abs(b.mean) < 1e-15);
    // a missing wall's torque shows as an imbalance of its share of the top's
    w.t_outer.assign(10, 0.0);
    BOOST_TEST(ring_torque_balance(w, 0, 5).mean == 0.25, boost::test_tools::tolerance(1e-12));
    w.t_outer.assign(10, -0.5);

    const WallForceSeries f = ring_wall_forces(w, kRing);
    BOOST_TEST_REQUIRE(f.rows() == 10u);
    const double A = kRing.area(), L = 2 * kPi * kRing.R;
    BOOST_TEST(A == kPi * (kRing.outer() * kRing.outer() - kRing.inner() * kRing.inner()),
               boost::test_tools::tolerance(1e-12));
    // a uniform stress tau on the floor has the torque tau * polar_moment(): the shear force is T A / J
    BOOST_TEST(std::abs(f.fx_bottom[3]) == 1.2 * A / kRing.polar_moment(), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(f.fx_top[3]) == 2.0 * A / kRing.polar_moment(), boost::test_tools::tolerance(1e-12));
    // a side wall's stress T / (2 pi r^2 H) on its height: the force over the slice's side L H
    BOOST_TEST(std::abs(f.fx_side1[3]) == 0.5 * L / (2 * kPi * kRing.outer() * kRing.outer()),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(f.fx_side2[3]) == 0.3 * L / (2 * kPi * kRing.inner() * kRing.inner()),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(f.fy_bottom[3]) == 10.0);
    BOOST_TEST(std::abs(f.fy_top[3]) == 9.0);
}

BOOST_AUTO_TEST_CASE(ring_insertion_is_overlap_free_inside_and_seeded) {
    const double d = 2e-3, h = 8e-3, sag = 1e-5;
    InsertionOptions opt;
    opt.seed = 7;
    opt.wall_speed = 2.0;
    const ParticleSet p = insert_ring_grains(kRing, h, d, 700, opt, sag);
    BOOST_TEST_REQUIRE(p.size() == 700u);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = std::hypot(p.x[i], p.z[i]);
        BOOST_TEST(r - 0.5 * d >= kRing.inner() + sag - 1e-12);
        BOOST_TEST(r + 0.5 * d <= kRing.outer() - sag + 1e-12);
        BOOST_TEST(p.y[i] >= 0.5 * d - 1e-12);
        BOOST_TEST(p.y[i] <= h - 0.5 * d + 1e-12);
        for (std::size_t j = 0; j < i; ++j) {
            const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j];
            if (dx * dx + dy * dy + dz * dz < d * d * (1 - 1e-12)) BOOST_FAIL("grains " << i << " and " << j << " overlap");
        }
    }
    const ParticleSet q = insert_ring_grains(kRing, h, d, 700, opt, sag);
    BOOST_TEST(q.x == p.x);
    BOOST_TEST(q.vz == p.vz);
    opt.seed = 8;
    BOOST_TEST(insert_ring_grains(kRing, h, d, 700, opt, sag).x != p.x);

    const std::size_t most = ring_capacity(kRing, h, d, sag);
    BOOST_TEST(most >= 700u);
    BOOST_CHECK_EXCEPTION(insert_ring_grains(kRing, h, d, most + 1, opt, sag), CaseError, [&](const CaseError& e) {
        return std::string(e.what()).find(std::to_string(most)) != std::string::npos;
    });
}

BOOST_AUTO_TEST_SUITE_END()
