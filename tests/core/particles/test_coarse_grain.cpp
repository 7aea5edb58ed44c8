// Slice volumes, coarse-grained fields, block averages and the steady-state detector.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "granlub/particles/coarse_grain.h"

using namespace granlub;

BOOST_AUTO_TEST_CASE(slices_of_a_sphere_add_up_to_the_sphere) {
    const double r = 0.4e-3, yc = 1.234e-3;
    const double whole = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    BOOST_TEST(std::abs(sphere_slice_volume(yc, r, 0, 1) - whole) < 1e-12 * whole);
    double sum = 0;
    for (int k = 0; k < 37; ++k) sum += sphere_slice_volume(yc, r, k * 1e-4, (k + 1) * 1e-4);
    BOOST_TEST(std::abs(sum - whole) < 1e-12 * whole);
    // a hemisphere
    BOOST_TEST(std::abs(sphere_slice_volume(yc, r, yc, 1) - 0.5 * whole) < 1e-12 * whole);
    BOOST_TEST(sphere_slice_volume(yc, r, yc + r, 1) == 0.0);
}

BOOST_AUTO_TEST_CASE(fields_recover_fill_velocity_and_temperature) {
    // A slab of grains on a regular grid, moving with a linear profile u = U y / H plus a
    // known Gaussian fluctuation of variance s^2 per component: T must come out as s^2.
    const double H = 1.0, L = 1.0, W = 1.0, r = 0.01, U = 2.0, s = 0.1;
    std::mt19937_64 g(5);
    std::normal_distribution<double> nd(0.0, s);
    SliceCoarseGrainer cg({0.0, H, 5}, L * W);
    const int n = 20;
    double vol = 0;
    for (int snap = 0; snap < 200; ++snap) {
        ParticleSet p;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) {
                    const double y = (j + 0.5) / n * H;
                    p.push_back((i + 0.5) / n, y, (k + 0.5) / n - 0.5, U * y / H + nd(g), nd(g), nd(g), r);
                }
        if (snap == 0)
            for (double rr : p.radius) vol += 4.0 / 3.0 * std::numbers::pi * rr * rr * rr;
        cg.add_snapshot(p, snap);
    }
    const Profile prof = cg.profile(U, 0, 10);
    BOOST_TEST(prof.rows() == 5u);
    const auto& nu = prof.column("solid_fraction");
    const auto& u = prof.column("u_over_U");
    const auto& T = prof.column("temperature_over_U2");
    const auto& y = prof.column("y_over_H");
    for (std::size_t k = 0; k < 5; ++k) {
        BOOST_TEST(std::abs(nu[k] - vol / (L * W * H)) < 1e-9);
        // u over a slab is the mean of the grains in it: slab centres for this symmetric grid
        BOOST_TEST(std::abs(u[k] - y[k]) < 0.01);
        // T includes the spread of the mean profile across the slab (grains at 4 heights):
        // var of y within a slab of width 0.2 on 4 points spaced 0.05 = 0.05^2 * 5/4
        const double shear_part = U * U * 0.05 * 0.05 * 1.25 / 3.0;
        BOOST_TEST(std::abs(T[k] * U * U - (s * s + shear_part)) < 0.05 * s * s);
    }
    BOOST_TEST(std::abs(cg.mean_solid_fraction(0, 200) - vol / (L * W * H)) < 1e-9);
    // standard errors are small but not zero
    BOOST_TEST(prof.column("u_over_U_stderr")[2] > 0.0);
    BOOST_TEST(prof.column("u_over_U_stderr")[2] < 0.01);
}

BOOST_AUTO_TEST_CASE(a_grain_straddling_stations_is_split_by_volume) {
    SliceCoarseGrainer cg({0.0, 1.0, 2}, 1.0);
    ParticleSet p;
    p.push_back(0.5, 0.5, 0.0, 1.0, 0.0, 0.0, 0.1);  // half in each station
    cg.add_snapshot(p);
    const auto f = cg.fields(0, 1);
    const double half = 0.5 * 4.0 / 3.0 * std::numbers::pi * 1e-3;
    BOOST_TEST(std::abs(f.nu[0] - half / 0.5) < 1e-12);
    BOOST_TEST(std::abs(f.nu[1] - half / 0.5) < 1e-12);
    BOOST_TEST(f.ux[0] == 1.0);
    BOOST_TEST(f.T[0] == 0.0);
}

BOOST_AUTO_TEST_CASE(block_average_of_independent_samples) {
    std::mt19937_64 g(11);
    std::normal_distribution<double> nd(3.0, 2.0);
    std::vector<double> x(100000);
    for (double& v : x) v = nd(g);
    const auto e = block_average(x, 20);
    BOOST_TEST(e.blocks == 20u);
    const double expected = 2.0 / std::sqrt(100000.0);
    BOOST_TEST(std::abs(e.mean - 3.0) < 5 * expected);
    BOOST_TEST(e.stderr_ > 0.4 * expected);
    BOOST_TEST(e.stderr_ < 1.8 * expected);
}

BOOST_AUTO_TEST_CASE(mean_and_stderr_of_block_values) {
    // 1, 2, 3, 4: mean 2.5, sample variance 5/3, standard error sqrt(5/3 / 4)
    const std::vector<double> v{1, 2, 3, 4};
    const auto e = mean_and_stderr(v);
    BOOST_TEST(e.mean == 2.5);
    BOOST_TEST(std::abs(e.stderr_ - std::sqrt(5.0 / 12.0)) < 1e-15);
    BOOST_TEST(e.blocks == 4u);
    const std::vector<double> one{7};
    BOOST_TEST(mean_and_stderr(one).stderr_ == 0.0);  // one block: no error estimate
    BOOST_TEST(mean_and_stderr({}).blocks == 0u);
}

