// Walton's flat-wall impact law averaged over a slipping Maxwellian (walls/flat_wall_impacts.h): the reduced
// quadrature against the law integrated directly, the table against the quadrature, the limits, reference values,
// and the wall condition's derivative through xi.
#define BOOST_TEST_MODULE continuum_flat_wall_impacts
#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/test/unit_test.hpp>

#include "granlub/continuum/dual.h"
#include "granlub/continuum/walls/flat_wall_impacts.h"
#include "granlub/continuum/walls/wall_condition.h"
#include "granlub/error.h"

using namespace granlub::continuum;

namespace {

constexpr double kPi = std::numbers::pi;

// sigma and delta from the impact law itself, the Maxwellian's three velocity components integrated one by one
// (T = m = 1): C_x, C_z Gaussian, c_n with density c_n exp(-c_n^2/2), its range split where an impact turns from
// sliding to sticking (after the c_n-integral the integrand is smooth in g, g = 0 included). Nothing of the
// reduction (erf, Bessel functions, Q2, Q3) is used.
struct Direct {
    double sigma, delta;
};
Direct direct(double xi, double e, double mu, double b0) {
    using Rule = boost::math::quadrature::gauss<double, 30>;
    const double kt = (2.0 / 7.0) * (1.0 + b0), M = mu * (1 + e), cmax = 14.0;
    const auto panels = [](const auto& f, double lo, double hi, int n) {
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += Rule::integrate(f, lo + (hi - lo) * k / n, lo + (hi - lo) * (k + 1) / n);
        return sum;
    };
    const auto gauss = [](double x) { return std::exp(-0.5 * x * x) / std::sqrt(2 * kPi); };
    // E over c_n of one impact's tangential impulse along x (traction) or its tangential loss, at slip (gx, gz)
    const auto per_slip = [&](double gx, double gz, bool traction) {
        const double r = std::hypot(gx, gz), split = std::min(kt * r / M, cmax);
        const auto impact = [&](double c) {
            const bool sticks = kt * r <= M * c;
            const double jt = sticks ? kt * r : M * c;
            const double v = traction ? (r > 0 ? jt * gx / r : 0.0)
                                      : (sticks ? (1 - b0 * b0) * r * r / 7 : jt * r - 1.75 * jt * jt);
            return c * std::exp(-0.5 * c * c) * v;
        };
        return Rule::integrate(impact, 0.0, split) + panels(impact, split, cmax, 3);
    };
    const auto average = [&](bool traction) {
        return panels([&](double cx) {
            return gauss(cx) * panels([&](double cz) { return gauss(cz) * per_slip(xi + cx, cz, traction); },
                                      -10.0, 10.0, 6);
        }, -12.0, 12.0, 8);
    };
    const double Jn = (1 + e) * std::sqrt(kPi / 2);  // E[J_n]; E[c_n^2] = 2
    return {average(true) / Jn, (0.5 * (1 - e * e) * 2 + average(false)) / Jn};
}

}  // namespace

// The closed c_n-integral and the Bessel functions of |g|'s angle against the law integrated component by
// component: to 1e-7 (both are quadratures to ~1e-10).
BOOST_AUTO_TEST_CASE(the_reduction_is_the_impact_law_integrated_directly) {
    for (const auto& [e, mu, b0] : {std::tuple{0.9, 0.5, 0.0}, {0.7, 0.2, 0.4}}) {
        const FlatWallImpacts law(e, mu, b0);
        for (double xi : {0.3, 1.7, 4.0}) {
            BOOST_TEST_CONTEXT("e " << e << ", mu " << mu << ", beta0 " << b0 << ", xi " << xi) {
                const Direct d = direct(xi, e, mu, b0);
                const auto q = law.quadrature(xi);
                BOOST_CHECK_CLOSE_FRACTION(q.sigma_over_xi * xi, d.sigma, 1e-7);
                BOOST_CHECK_CLOSE_FRACTION(q.delta, d.delta, 1e-7);
            }
        }
    }
}

// h, g and their xi-derivatives from the table (cubic Hermite in asinh xi) against the quadrature between the nodes,
// and the asymptotes beyond the table: to 1e-6 (relative; the derivatives to 1e-5 of theirs, or of h/100 and g/100
// where they vanish, at xi -> 0, h and g being even in xi), over friction
// from 0.01 to 1e6, e_w from 0 to 0.95 and beta0 from -0.6 to 1.
BOOST_AUTO_TEST_CASE(the_table_agrees_with_the_quadrature) {
    for (const auto& [e, mu, b0] : {std::tuple{0.9, 0.5, 0.0}, {0.9, 0.05, 0.0}, {0.9, 1e6, 0.0}, {0.0, 0.3, 0.0},
                                   {0.7, 2.0, 0.4}, {0.95, 0.1, -0.6}, {0.5, 0.01, 1.0}}) {
        const FlatWallImpacts law(e, mu, b0);
        double worst = 0, worst_d = 0;
        for (double xi = 0.0; xi < 3 * law.xi_max(); xi = xi < 1e-3 ? 1e-3 : xi * 1.0437) {
            const auto f = law.factors(xi);
            const auto q = law.quadrature(xi);
            const double ks = law.sigma_stick(1.0), ds = law.delta_stick(xi);
            const double dds = std::sqrt(2 / kPi) / (1 + e) * (1 - b0 * b0) * 2 * xi / 7;
            const double h = q.sigma_over_xi / ks, g = q.delta / ds;
            const double dh = q.d_sigma_over_xi / ks, dg = (q.d_delta * ds - q.delta * dds) / (ds * ds);
            worst = std::max({worst, std::abs(f.h / h - 1), std::abs(f.g / g - 1)});
            worst_d = std::max({worst_d, std::abs(f.dh - dh) / std::max(std::abs(dh), 1e-2 * h),
                                std::abs(f.dg - dg) / std::max(std::abs(dg), 1e-2 * g)});
        }
        BOOST_TEST_MESSAGE("e " << e << " mu " << mu << " beta0 " << b0 << ": table to " << worst << ", derivatives to "
                                << worst_d << " (xi_max " << law.xi_max() << ")");
        BOOST_TEST(worst < 1e-6);
        BOOST_TEST(worst_d < 1e-5);
    }
}

// The reference values of a direct midpoint sum over the same law (mu_w = 0.5, e_w = 0.9, beta0 = 0; 4 digits).
BOOST_AUTO_TEST_CASE(reference_values) {
    const FlatWallImpacts law(0.9, 0.5, 0.0);
    for (const auto& [xi, sigma, delta] : {std::tuple{1.0, 0.1118, 0.2526}, {2.0, 0.2148, 0.4169},
                                           {3.0, 0.3023, 0.6770}, {4.0, 0.3710, 1.0153},
                                           {6.0, 0.4538, 1.8509}, {8.0, 0.4860, 2.7966}}) {
        BOOST_TEST(std::abs(law.sigma(xi) - sigma) < 1e-4, "xi " << xi << ": sigma " << law.sigma(xi));
        BOOST_TEST(std::abs(law.delta(xi) - delta) < 1e-4, "xi " << xi << ": delta " << law.delta(xi));
    }
}

// mu_w -> infinity: every impact sticks (h = g = 1, the stick limit's closed forms); xi -> infinity: every impact
// slides, sigma -> mu_w; in between the traction never exceeds either cap.
BOOST_AUTO_TEST_CASE(stick_and_slide_limits) {
    const FlatWallImpacts stick(0.9, 1e6, 0.0);
    const double c0 = std::sqrt(2 / kPi);
    for (double xi : {0.0, 0.5, 2.0, 3.4, 10.0}) {
        BOOST_TEST(std::abs(stick.factors(xi).h - 1) < 1e-6);
        BOOST_TEST(std::abs(stick.factors(xi).g - 1) < 1e-6);
        BOOST_CHECK_CLOSE_FRACTION(stick.sigma_stick(xi) + 1e-300, (2.0 / 7.0) * c0 * xi / 1.9 + 1e-300, 1e-14);
        BOOST_CHECK_CLOSE_FRACTION(stick.delta_stick(xi), c0 / 1.9 * ((1 - 0.81) + (xi * xi + 2) / 7), 1e-14);
    }
    const FlatWallImpacts law(0.9, 0.5, 0.0);
    for (double xi : {50.0, 200.0, 1e4}) BOOST_CHECK_CLOSE_FRACTION(law.sigma(xi), 0.5 * (1 - 0.5 / (xi * xi)), 1e-6);
    BOOST_TEST(std::abs(law.sigma(1e4) - 0.5) < 1e-8);
    double last = 0;
    for (double xi = 0.01; xi < 100; xi *= 1.1) {
        BOOST_TEST(law.sigma(xi) > last);
        BOOST_TEST(law.sigma(xi) < std::min(0.5, law.sigma_stick(xi)));
        BOOST_TEST(law.delta(xi) < law.delta_stick(xi));
        last = law.sigma(xi);
    }
    BOOST_CHECK_THROW(FlatWallImpacts(0.9, 0.0, 0.0), granlub::Error);
    BOOST_CHECK_THROW(FlatWallImpacts(1.0, 0.5, 0.0), granlub::Error);
    BOOST_TEST(flat_wall_impacts(0.9, 0.5, 0.0) == flat_wall_impacts(0.9, 0.5, 0.0));  // tabulated once
}

// The wall condition with the law: du/dn = stick-limit du/dn x h(xi), the R6, R7 terms x g(xi), xi = |s| sqrt(Pi) xs;
// its dual derivatives (slip, Pi, xs, as the solvers' Jacobians take them) against central differences; without
// the law exactly the linear condition.
BOOST_AUTO_TEST_CASE(wall_condition_through_xi_has_exact_derivatives) {
    WallParams w{0.9, 2.0 / 7.0, 1.0 + (2.0 / 7.0) / 0.19, 2.0 / 7.0, 2.0 / 7.0, 0.5};
    w.energy = WallEnergy::SlipWork;
    const double b5 = 0.31, b6 = 0.12, b7 = 0.05, b8 = 0.9, L = 5.1, Pi = 1.9, xs = 1.3;
    const auto plain = wall_gradients(w, b5, b6, b7, b8, xs, 0.4, L, Pi);
    BOOST_TEST(plain.du == -w.r5 * L * b5 * 0.4);
    w.impacts = flat_wall_impacts(0.9, 0.5, 0.0);
    for (double slip : {0.4, -0.25, 1e-3}) {
        const auto g = wall_gradients(w, b5, b6, b7, b8, xs, slip, L, Pi);
        const auto f = w.impacts->factors(std::abs(slip) * std::sqrt(Pi) * xs);
        BOOST_CHECK_CLOSE_FRACTION(g.du, -w.r5 * L * b5 * slip * f.h, 1e-14);
        const double coll = (w.r6 * L * b6 + w.r7 * L * Pi * b7 * slip * slip) * f.g;
        BOOST_CHECK_CLOSE_FRACTION(g.dnu, -(coll + Pi * b8 * slip * g.du), 1e-14);
        using D3 = Dual<3>;
        const auto d = wall_gradients(w, D3(b5), D3(b6), D3(b7), D3(b8), D3::variable(xs, 2), D3::variable(slip, 0),
                                      D3(L), D3::variable(Pi, 1));
        const double args[3] = {slip, Pi, xs}, eps = 1e-6;
        for (int k = 0; k < 3; ++k) {
            double a[3] = {args[0], args[1], args[2]}, b[3] = {args[0], args[1], args[2]};
            a[k] += eps, b[k] -= eps;
            const auto p = wall_gradients(w, b5, b6, b7, b8, a[2], a[0], L, a[1]);
            const auto m = wall_gradients(w, b5, b6, b7, b8, b[2], b[0], L, b[1]);
            BOOST_TEST(std::abs(d.du.d[k] - (p.du - m.du) / (2 * eps)) < 1e-7 * std::max(1.0, std::abs(d.du.d[k])),
                       "slip " << slip << ", direction " << k);
            BOOST_TEST(std::abs(d.dnu.d[k] - (p.dnu - m.dnu) / (2 * eps)) < 1e-7 * std::max(1.0, std::abs(d.dnu.d[k])),
                       "slip " << slip << ", direction " << k);
        }
    }
}
