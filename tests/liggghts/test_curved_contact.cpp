// A contact that stays closed along a curved path (issue 48's "explicit position update along a
// curved contact and its correction by separate"). Through the driver and
// tests/liggghts/in.curved_contact: a grain pressed by a body acceleration onto a fixed grain slides
// over it (frictionless) or slips, then rolls (mu = 0.5). The exact motion of its centre on the circle
// of radius d = r_i + r_j, angle theta from the top (the fixed grain's surface does not move):
//   slipping:  d theta'' = g sin theta - mu N,   r omega' = (5/2) mu N,   N = g cos theta - d theta'^2
//   rolling (once d theta' = r omega):  theta'' = (5/7) (g / d) sin theta   (I = 2/5 m r^2)
// per unit mass. Sawyer & Tichy's single pass follows it at first order in dt (the step's pressing
// kick is not in the velocity it resolves, and `separate` lifts the grain back out along the normal);
// the iterated solve (fix impulse/solve: Moreau's free velocity, restitution on the arrival
// velocity) at second order. docs/measurements/liggghts.md, "A contact along a curved path".
#define BOOST_TEST_MODULE liggghts_curved_contact
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "run_driver.h"

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/tests/liggghts/in.curved_contact";

// the deck's grain, body acceleration and start
constexpr double kD = 0.787e-3, kR = kD / 2, kG = 2740.0, kV0 = 0.3, kT = 1e-3;

// theta(t) of the exact motion above (RK4 at 1 ns, a step 10^3 times finer than the finest run)
double exact_angle(double mu, double t_end) {
    using State = std::array<double, 3>;  // theta, theta', spin omega
    bool rolling = false;
    const auto rate = [&](const State& s) -> State {
        if (rolling) {
            const double a = 5.0 / 7.0 * kG / kD * std::sin(s[0]);
            return {s[1], a, a * kD / kR};
        }
        const double n = kG * std::cos(s[0]) - kD * s[1] * s[1];
        return {s[1], (kG * std::sin(s[0]) - mu * n) / kD, 2.5 * mu * n / kR};
    };
    const double h = 1e-9;
    State s{0.0, kV0 / kD, 0.0};
    const long steps = std::lround(t_end / h);
    for (long k = 0; k < steps; ++k) {
        const State k1 = rate(s);
        State y;
        for (int c = 0; c < 3; ++c) y[c] = s[c] + 0.5 * h * k1[c];
        const State k2 = rate(y);
        for (int c = 0; c < 3; ++c) y[c] = s[c] + 0.5 * h * k2[c];
        const State k3 = rate(y);
        for (int c = 0; c < 3; ++c) y[c] = s[c] + h * k3[c];
        const State k4 = rate(y);
        for (int c = 0; c < 3; ++c) s[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
        if (!rolling && mu > 0.0 && kD * s[1] <= kR * s[2]) rolling = true;  // the slip has stopped
    }
    return s[0];
}

// The run's angle at T = 1 ms, radians
double run_angle(double mu, double dt, bool iterate) {
    const long steps = std::lround(kT / dt);
    char vars[160];  // every digit of dt (std::to_string would print 2.5e-6 as 0.000003)
    std::snprintf(vars, sizeof vars, "-var dt %.17g -var nsteps %ld -var mu %g -var iter %s", dt, steps, mu,
                  iterate ? "on" : "off");
    const auto run = granlub::test::run_driver(kDeck, vars, 1, "liggghts_curved_contact");
    const auto r = granlub::test::results(run.output);
    BOOST_TEST_REQUIRE(r.count("dx2") == 1u, run.output);
    return std::atan2(r.at("dx2"), r.at("dy2"));
}

// the angle's error at T, degrees, at dt, dt/2 and dt/4 (dt = 5 us, about the cases' full step); each
// operator and mu is run once for the whole test module
std::array<double, 3> errors(double mu, bool iterate) {
    static std::map<std::pair<double, bool>, std::array<double, 3>> done;
    if (const auto it = done.find({mu, iterate}); it != done.end()) return it->second;
    const double exact = exact_angle(mu, kT);
    std::array<double, 3> e{};
    for (int k = 0; k < 3; ++k) e[k] = (run_angle(mu, 5e-6 / (1 << k), iterate) - exact) * 180.0 / std::numbers::pi;
    BOOST_TEST_MESSAGE("mu " << mu << (iterate ? ", iterated" : ", single pass") << ": angle error at 1 ms (deg), dt "
                             "5 / 2.5 / 1.25 us: " << e[0] << " / " << e[1] << " / " << e[2]);
    return done[{mu, iterate}] = e;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_exact_motion_is_the_quadrature_of_its_energy) {
    // frictionless, energy conservation gives theta' = sqrt(v0^2 / d^2 + 2 g (1 - cos theta) / d), so the
    // time to reach the integrated angle is the integral of dtheta / theta' (Simpson, 2000 panels)
    const double theta = exact_angle(0.0, kT);
    const auto rate = [](double a) { return std::sqrt(kV0 * kV0 / (kD * kD) + 2.0 * kG / kD * (1.0 - std::cos(a))); };
    const int n = 2000;
    double t = 1.0 / rate(0.0) + 1.0 / rate(theta);
    for (int k = 1; k < n; ++k) t += (k % 2 ? 4.0 : 2.0) / rate(theta * k / n);
    t *= theta / n / 3.0;
    BOOST_TEST(t == kT, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(exact_angle(0.5, kT) < theta);  // rolling: part of the energy goes into the spin
}

BOOST_AUTO_TEST_CASE(single_pass_follows_a_curved_contact_at_first_order) {
    for (const double mu : {0.0, 0.5}) {
        const auto e = errors(mu, false);
        // ahead of the exact motion (`separate` lifts the grain out against its load: energy gained)
        for (const double x : e) BOOST_TEST(x > 0.0);
        // first order: each halving halves the error
        BOOST_TEST(e[0] / e[1] > 1.7);
        BOOST_TEST(e[0] / e[1] < 2.3);
        BOOST_TEST(e[1] / e[2] > 1.7);
        BOOST_TEST(e[1] / e[2] < 2.3);
        BOOST_TEST(e[2] < 0.1);  // degrees, at 1.25 us: it converges to the exact motion
    }
}

BOOST_AUTO_TEST_CASE(iterated_solve_follows_it_at_second_order) {
    for (const double mu : {0.0, 0.5}) {
        const auto single = errors(mu, false), solved = errors(mu, true);
        BOOST_TEST(std::abs(solved[0]) < 0.2 * single[0]);
        BOOST_TEST(std::abs(solved[0]) / std::abs(solved[1]) > 3.0);  // second order: a quarter per halving
    }
}
