// The core reduction of a wide plane-shear cell (bulk_rheology.h) on synthetic profiles whose answer
// is known: a straight u(y) in the core gives its slope whatever the profile does near the walls; a
// curved core shows in the halves' slopes and in the shear rate's error.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "granlub/error.h"
#include "granlub/particles/bulk_rheology.h"

using namespace granlub;
namespace tt = boost::test_tools;

namespace {

constexpr double kD = 0.787e-3, kRho = 2550.0, kU = 3.0, kH = 0.024, kP = 2250.0;

// n stations across the gap; u/U, nu, T/U^2 from the functions, constant standard errors
Profile synthetic(std::size_t n, const std::function<double(double)>& u, double nu, double T_over_U2) {
    std::vector<double> y(n), uu(n), ue(n, 1e-3), v(n, nu), ve(n, 2e-3), T(n, T_over_U2), Te(n, 1e-6);
    for (std::size_t k = 0; k < n; ++k) {
        y[k] = (static_cast<double>(k) + 0.5) / static_cast<double>(n);
        uu[k] = u(y[k]);
    }
    Profile p;
    p.add("y_over_H", y).add("u_over_U", uu).add("u_over_U_stderr", ue).add("solid_fraction", v);
    p.add("solid_fraction_stderr", ve).add("temperature_over_U2", T).add("temperature_over_U2_stderr", Te);
    return p;
}

CoreRun run_of(const Profile& p, double tau_bottom = 900.0, double tau_top = 900.0) {
    CoreRun r;
    r.profile = &p;
    r.speed = kU;
    r.gap = kH;
    r.normal_bottom = {kP, 10.0};
    r.normal_top = {kP, 10.0};
    r.shear_bottom = {tau_bottom, 5.0};
    r.shear_top = {tau_top, 5.0};
    r.z_bulk = Measured{3.9, 0.01};
    return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_straight_core_gives_its_slope_whatever_the_walls_do) {
    // u/U = 0.9 - 0.8 y/H in the core, and boundary layers (a steep fall) within 0.3 H of each wall
    const auto u = [](double y) {
        const double line = 0.9 - 0.8 * y;
        if (y < 0.3) return line + 0.5 * (0.3 - y);
        if (y > 0.7) return line - 0.5 * (y - 0.7);
        return line;
    };
    const Profile p = synthetic(61, u, 0.58, 4e-4);
    const CoreRheology r = core_rheology(run_of(p), kD, kRho);
    const double gamma = 0.8 * kU / kH;  // 100 1/s
    BOOST_TEST(r.stations == 21u);       // centres in [1/3, 2/3] of 61 slabs
    BOOST_TEST(r.shear_rate.value == gamma, tt::tolerance(1e-9));
    BOOST_TEST(std::abs(r.shear_rate_halves) < 1e-9);
    BOOST_TEST(r.inertial_number.value == gamma * kD / std::sqrt(kP / kRho), tt::tolerance(1e-9));
    BOOST_TEST(r.friction.value == 0.4, tt::tolerance(1e-12));
    BOOST_TEST(r.friction.error > 0.0);
    BOOST_TEST(r.solid_fraction.value == 0.58, tt::tolerance(1e-12));
    BOOST_TEST(r.solid_fraction.error == 2e-3, tt::tolerance(1e-9));  // the correlated bound: no 1/sqrt(n)
    const double Ts = 4e-4 * kU * kU / std::pow(kD * gamma, 2);
    BOOST_TEST(r.temperature_scaled.value == Ts, tt::tolerance(1e-9));
    BOOST_TEST(!r.coordination_core);
    BOOST_TEST(r.coordination->value == 3.9);
    // the slope's error is the propagated one for points on the line: 1e-3 / sqrt(sum (y - ybar)^2)
    double ybar = 0, sxx = 0;
    std::vector<double> yc;
    for (std::size_t k = 0; k < 61; ++k)
        if (const double y = (static_cast<double>(k) + 0.5) / 61.0; y >= 1.0 / 3 && y <= 2.0 / 3) yc.push_back(y), ybar += y;
    ybar /= static_cast<double>(yc.size());
    for (double y : yc) sxx += (y - ybar) * (y - ybar);
    BOOST_TEST(r.shear_rate.error == 1e-3 / std::sqrt(sxx) * kU / kH, tt::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(a_curved_core_shows_in_the_halves_and_the_error) {
    // u/U = 1 - y^2: the slope steepens upward (-2 y), so the upper half shears faster
    const Profile p = synthetic(61, [](double y) { return 1.0 - y * y; }, 0.55, 4e-4);
    const CoreRheology r = core_rheology(run_of(p), kD, kRho);
    BOOST_TEST(r.shear_rate.value == 1.0 * kU / kH, tt::tolerance(1e-6));  // the mean slope over [1/3, 2/3]
    BOOST_TEST(r.shear_rate_halves > 0.25);                                   // -2(0.583) vs -2(0.417): 1/3 of -1
    BOOST_TEST(r.shear_rate_halves < 0.40);
    // the residuals (~1e-3 of u/U) dominate the block errors (1e-3 each): the error grows with them
    const CoreRheology straight = core_rheology(run_of(synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4)), kD, kRho);
    BOOST_TEST(r.shear_rate.error >= straight.shear_rate.error);
}

BOOST_AUTO_TEST_CASE(walls_that_disagree_are_reported_not_hidden) {
    const Profile p = synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    const CoreRheology r = core_rheology(run_of(p, 800.0, 1000.0), kD, kRho);
    BOOST_TEST(r.friction.value == 0.4, tt::tolerance(1e-12));  // the mean of the walls
    BOOST_TEST(r.wall_shear_imbalance == 200.0 / 900.0, tt::tolerance(1e-12));  // over their mean
}

BOOST_AUTO_TEST_CASE(the_core_z_is_preferred_and_bad_input_fails) {
    const Profile p = synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    CoreRun run = run_of(p);
    run.z_core = Measured{4.2, 0.02};
    const CoreRheology r = core_rheology(run, kD, kRho);
    BOOST_TEST(r.coordination_core);
    BOOST_TEST(r.coordination->value == 4.2);
    // too few stations in the core to fit two halves
    const Profile coarse = synthetic(12, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    BOOST_CHECK_THROW(core_rheology(run_of(coarse), kD, kRho), Error);
    // a core that does not flow (u constant)
    const Profile plug = synthetic(61, [](double) { return 0.5; }, 0.55, 4e-4);
    BOOST_CHECK_THROW(core_rheology(run_of(plug), kD, kRho), Error);
}

BOOST_AUTO_TEST_CASE(a_line_fit_weights_by_the_errors) {
    // two precise points on y = 2x and one imprecise far off: the fit follows the precise ones
    const LineFit f = fit_line({0.0, 1.0, 2.0}, {0.0, 2.0, 10.0}, {1e-3, 1e-3, 1e3});
    BOOST_TEST(f.slope == 2.0, tt::tolerance(1e-5));
    BOOST_CHECK_THROW(fit_line({0.0, 1.0}, {0.0, 1.0}, {1.0, 1.0}), Error);
    BOOST_CHECK_THROW(fit_line({1.0, 1.0, 1.0}, {0.0, 1.0, 2.0}, {1.0, 1.0, 1.0}), Error);
}
