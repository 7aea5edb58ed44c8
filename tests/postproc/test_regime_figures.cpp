// The regime figures' pieces on known inputs: the mu(I) law of Jop, Forterre & Pouliquen 2006,
// how a fitted tau-U exponent reads, and which points form a (speed, load) grid.
#include <cmath>

#include <boost/test/unit_test.hpp>

#include "figures/mu_of_i.h"
#include "figures/shear_power_law.h"
#include "statistics/speed_load_grid.h"
#include "statistics/stats.h"

using namespace granlub;
using namespace granlub::postproc;

BOOST_AUTO_TEST_SUITE(regime_figures)

BOOST_AUTO_TEST_CASE(jop_mu_of_i) {
    BOOST_TEST(std::abs(kJopMuS - 0.3819) < 1e-3);  // tan 20.9 deg
    BOOST_TEST(std::abs(kJopMu2 - 0.6434) < 1e-3);  // tan 32.76 deg
    BOOST_TEST(jop_mu(0.0) == kJopMuS);
    BOOST_TEST(std::abs(jop_mu(kJopI0) - 0.5 * (kJopMuS + kJopMu2)) < 1e-12);  // halfway at I_0
    BOOST_TEST(std::abs(jop_mu(1e9) - kJopMu2) < 1e-9);
    BOOST_TEST(jop_mu(0.01) < jop_mu(0.1));
}

BOOST_AUTO_TEST_CASE(fitted_exponents_read_as_bagnold_or_quasi_static) {
    // tau = 3 U^2 and tau = 7 U^0 on steady points: the fit recovers n, the reading follows it
    const std::vector<double> U = {0.4, 0.8, 1.4, 2.0, 2.8};
    std::vector<double> bag, qs;
    for (double u : U) bag.push_back(3 * u * u), qs.push_back(7.0);
    const std::vector<std::optional<double>> none(U.size());
    const auto fb = power_fit(U, bag, none), fq = power_fit(U, qs, none);
    BOOST_TEST_REQUIRE(fb.has_value());
    BOOST_TEST_REQUIRE(fq.has_value());
    BOOST_TEST(std::abs(fb->exponent - 2.0) < 1e-12);
    BOOST_TEST(std::abs(fq->exponent) < 1e-12);
    BOOST_TEST(exponent_reading(*fb) == "Bagnold (collisional)");
    BOOST_TEST(exponent_reading(*fq) == "quasi-static");
    // at the band edges, and in between
    PowerFit f;
    f.exponent = kBagnoldMinExponent;
    BOOST_TEST(exponent_reading(f) == "Bagnold (collisional)");
    f.exponent = std::nextafter(kBagnoldMinExponent, 0.0);
    BOOST_TEST(exponent_reading(f) == "between quasi-static and Bagnold");
    f.exponent = kQuasiStaticMaxExponent;
    BOOST_TEST(exponent_reading(f) == "quasi-static");
    f.exponent = 1.0;
    BOOST_TEST(exponent_reading(f) == "between quasi-static and Bagnold");
    f.exponent_stderr = 0.5;  // 2 within two standard errors
    BOOST_TEST(exponent_reading(f) == "Bagnold (collisional)");
}

namespace {
OperatingPoint point(const char* id, double U, double P, Control c = Control::Load) {
    OperatingPoint p;
    p.id = id;
    p.speed = U;
    p.normal_stress = P;
    p.control = c;
    return p;
}
}  // namespace

BOOST_AUTO_TEST_CASE(which_points_form_a_speed_load_grid) {
    const OperatingPoint a = point("a", 0.4, 500), b = point("b", 2.8, 500), c = point("c", 0.4, 5500),
                         d = point("d", 2.8, 5500);
    const SpeedLoadGrid g = speed_load_grid({&a, &b, &c, &d});
    BOOST_TEST(g.drawn());
    BOOST_TEST(g.speeds.size() == 2u);
    BOOST_TEST(g.per_load.size() == 2u);
    BOOST_TEST(g.per_load.front().points.front()->normal_stress == 500.0);
    // a hole (one solver-independent point missing from the case) still draws
    BOOST_TEST(speed_load_grid({&a, &b, &c}).drawn());
    BOOST_TEST(speed_load_grid({}).why_not == "the case has no operating points");
    BOOST_TEST(speed_load_grid({&a}).why_not.find("the case has one operating point (a)") == 0u);
    BOOST_TEST(speed_load_grid({&a, &b}).why_not.find("one load (P = 500 Pa)") == 0u);
    BOOST_TEST(speed_load_grid({&a, &c}).why_not.find("one speed (U = 0.4 m/s)") == 0u);
    const OperatingPoint f = point("f", 1.0, 0, Control::Fill);
    BOOST_TEST(speed_load_grid({&a, &f}).why_not.find("fill control") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
