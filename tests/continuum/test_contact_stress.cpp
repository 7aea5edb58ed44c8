// The rate-independent contact stress (docs/continuum-model.md §2.9; closures/contact_stress.h): its quasi-static
// limit (mu -> mu_c, nu -> nu_P as I -> 0) in homogeneous shear and in the solver on a wide gap, the mechanical
// energy budget with the contacts' dissipation, the exact Jacobian, mesh convergence and the limit eps -> 0 of the
// regularised sign. The constants are illustrative (not fitted): nu_P near 0.60 under the load.
#define BOOST_TEST_MODULE continuum_contact_stress
#include <cmath>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "fixtures.h"
#include "granlub/continuum/fv_solver.h"
#include "granlub/continuum/simple_shear.h"

using namespace granlub::continuum;
using namespace granlub::continuum::testing;

namespace {

constexpr double kMuC = kIllustrativeMuC;

ContactStress contact(double friction = kMuC, double eps = 1e-2) { return illustrative_contact(friction, eps); }

// The S&T grains between family-K walls, a gap of `lambda` grain diameters, speed U, load 5.5 kPa; the kinetic
// theory alone.
Problem couette(double U, double lambda) {
    Problem p = problem(sawyer(U));
    p.Lambda = lambda;
    return p;
}

SolverSettings mesh(int cells) {
    SolverSettings s;
    s.cells = cells;
    return s;
}

}  // namespace

// The root nu_P of p_c = P is the cap, and the closed-form homogeneous shear (simple_shear.h) reaches the
// quasi-static limit there: I -> 0, mu = mu_c + (1 - pi_c)(mu_KT - mu_c) -> mu_c, from above when the kinetic
// mu_KT at nu_P exceeds mu_c, from below otherwise.
BOOST_AUTO_TEST_CASE(homogeneous_shear_reaches_mu_c_at_nu_P) {
    const double nuP = contact().limit();
    BOOST_CHECK_CLOSE_FRACTION(contact().ratio(nuP), 1.0, 1e-9);
    BOOST_TEST(nuP > 0.59);
    BOOST_TEST(nuP < 0.61);
    const Closures base = *make_closures("ogawa", 0.9);
    const double mu_kt = simple_shear_at_nu(base, nuP).stress_ratio;
    BOOST_TEST_MESSAGE("kinetic mu at nu_P = " << nuP << ": " << mu_kt);
    BOOST_TEST(mu_kt > 0.25);
    BOOST_TEST(mu_kt < 0.35);
    for (double mu_c : {0.2, 0.36}) {
        const Closures with = base.with_contact(contact(mu_c));
        BOOST_CHECK_CLOSE_FRACTION(with.cap(), nuP, 1e-12);
        double last = 1e300, last_I = 1e300;
        for (double gap : {1e-2, 1e-3, 1e-4, 1e-6}) {
            const SimpleShear s = simple_shear_at_nu(with, nuP - gap);
            BOOST_TEST_CONTEXT("mu_c " << mu_c << ", nu_P - nu = " << gap << ": I = " << s.inertial
                                       << ", mu = " << s.stress_ratio) {
                BOOST_TEST((s.stress_ratio > mu_c) == (mu_kt > mu_c));
                BOOST_TEST(std::abs(s.stress_ratio - mu_c) < last);
                BOOST_TEST(s.inertial < last_I);
                last = std::abs(s.stress_ratio - mu_c);
                last_I = s.inertial;
            }
        }
        BOOST_TEST(last_I < 2e-3);
        BOOST_TEST(last < 1e-4);
    }
}

// The regularised sign sgn_eps(x) = x/sqrt(x^2 + eps^2) -> sgn(x) pointwise as eps -> 0.
BOOST_AUTO_TEST_CASE(regularised_sign_tends_to_the_sign) {
    for (double x : {0.5, -0.01, 1e-3}) {
        double last = 1e300;
        for (double eps : {1e-2, 1e-3, 1e-4, 1e-6}) {
            const double err = std::abs(contact(kMuC, eps).sign(x) - (x > 0 ? 1.0 : -1.0));
            BOOST_TEST(err < last);
            last = err;
        }
        BOOST_TEST(last < 1e-6);
    }
    BOOST_TEST(contact().sign(0.0) == 0.0);
}

// The stencil's Dual<7> Jacobian with the contact stress (its pressure, the regularised sign, the wall terms)
// against central differences, at a converged state and away from it.
BOOST_AUTO_TEST_CASE(exact_jacobian_matches_finite_differences) {
    for (double mu_c : {0.0, kMuC}) {
        BOOST_TEST_CONTEXT("mu_c = " << mu_c) {
            const Problem p = with_contact(couette(3.0, 20), contact(mu_c));
            Solution s = solve_fv(p, mesh(40));
            BOOST_TEST(fv_jacobian_defect(p, s, 1e-7) < 1e-5);
            for (std::size_t i = 0; i < s.nodes(); ++i) {
                s.u[i] += 0.01 * std::sin(7.0 * static_cast<double>(i));
                s.nu[i] -= 1e-4 * (1 + std::cos(5.0 * static_cast<double>(i)));
            }
            BOOST_TEST(fv_jacobian_defect(p, s, 1e-7) < 1e-5);
        }
    }
}

// The solver on a wide gap (60 grain diameters) at falling speed: mu at the walls falls towards mu_c and stays
// above it, and mid-gap nu rises towards nu_P. The kinetic theory alone (LSJC, no correlation length) levels off
// near its own mu at nu_max instead, far from mu_c: it fails the same check.
BOOST_AUTO_TEST_CASE(wide_gap_mu_tends_to_mu_c_as_the_speed_falls) {
    const double nuP = contact().limit();
    double last_mu = 1e300, last_gap = 1e300, kinetic = 0;
    for (double U : {2.0, 1.0, 0.5, 0.25}) {
        const Problem p = with_contact(couette(U, 60), contact());
        const auto o = observe(p, solve_fv(p, mesh(200)));
        const Problem k = couette(U, 60);
        kinetic = observe(k, solve_fv(k, mesh(200))).tau_top;
        BOOST_TEST_MESSAGE("U = " << U << ": mu = " << o.tau_top << ", mid-gap nu = " << o.nu_centre << " (nu_P "
                                  << nuP << "), kinetic alone mu = " << kinetic);
        BOOST_TEST_CONTEXT("U = " << U << ": mu = " << o.tau_top << ", mid-gap nu = " << o.nu_centre) {
            BOOST_TEST(o.tau_top > kMuC);
            BOOST_TEST(o.tau_top < last_mu);
            BOOST_TEST(o.nu_centre < nuP);
            BOOST_TEST(nuP - o.nu_centre < last_gap);
            last_mu = o.tau_top;
            last_gap = nuP - o.nu_centre;
        }
    }
    BOOST_TEST(last_mu - kMuC < 0.02);
    BOOST_TEST(std::abs(kinetic - kMuC) > 0.05);
}

// The same on the rough cases' extended theory (Garzo-Dufty, Chialvo-Sundaresan g0 to nu_c = 0.587, e_eff =
// 0.733, Jenkins-Berzi L* with c = 0.44) with Johnson & Jackson's constants (Fr = 0.05 Pa, n = 2, m = 5, nu_min =
// 0.5) at 2250 Pa and mu_c = 0.36 (illustrative, not fitted): here the kinetic theory alone has mu -> 0 as I -> 0
// (L* diverges at nu_c), and the branch holds mu at mu_c.
BOOST_AUTO_TEST_CASE(extended_theory_mu_tends_to_mu_c_where_the_kinetic_theory_goes_to_zero) {
    ClosureParams cp;
    cp.restitution = 0.9;
    cp.dissipation_restitution = 0.733;
    cp.correlation_length = CorrelationLength::JenkinsBerzi;
    cp.correlation_constant = 0.44;
    const auto kinetic = std::make_shared<const Closures>(
        cp, std::shared_ptr<const RadialDistribution>(make_g0("chialvo_sundaresan", 0.587)),
        make_closure_family("garzo_dufty"));
    ContactStress jj;
    jj.coefficient = 0.05 / 2250;
    jj.onset = 0.5;
    jj.jamming = 0.587;
    jj.n = 2;
    jj.m = 5;
    jj.friction = 0.36;
    // eps = 1e-3: with the default 1e-2 the regularised sign's deficit at the wall, mu_c pi_c eps^2/(2 u^'^2) with
    // |u^'| ~ 1, is 2e-5, which puts mu at U = 0.1 m/s 7e-6 below mu_c (1.3e-5 above it with eps = 1e-3)
    jj.sign_width = 1e-3;
    std::vector<double> with, without;
    for (double U : {2.0, 0.5, 0.1}) {
        Spec sp = sawyer(U, 2250);
        sp.d = 1.6e-3;
        sp.rho = 2500;
        Problem k = problem(sp);
        k.closures = kinetic;
        k.Lambda = 30;
        const Problem p = with_contact(k, jj);
        with.push_back(observe(p, solve_fv(p, mesh(200))).tau_top);
        without.push_back(observe(k, solve_fv(k, mesh(200))).tau_top);
        BOOST_TEST_MESSAGE("U = " << U << ": mu " << with.back() << " with the branch, " << without.back()
                                  << " without");
    }
    for (std::size_t i = 0; i < with.size(); ++i) BOOST_TEST(with[i] > 0.36);
    BOOST_TEST(with[2] < with[0]);
    BOOST_TEST(with[2] - 0.36 < 0.03);
    BOOST_TEST(without[2] < without[0]);
    BOOST_TEST(without[2] < 0.36 - 0.05);
}

// The mechanical budget tau U = integral(gamma + mu_c p_c |gamma_dot|) dy + the walls' sinks closes to second order
// (docs/continuum-model.md §8.5 with the contacts' dissipation), and mu and the slip converge at second order.
BOOST_AUTO_TEST_CASE(energy_budget_and_mesh_convergence_at_second_order) {
    const Problem p = with_contact(couette(1.0, 20), contact());
    std::vector<double> mu, nu, defect;
    for (int cells : {50, 100, 200, 400}) {
        const Solution s = solve_fv(p, mesh(cells));
        const auto o = observe(p, s);
        mu.push_back(o.tau_top);
        nu.push_back(o.slip_top);
        const EnergyBudget b = energy_budget(p, s);
        BOOST_TEST(b.contact_dissipation > 0.2 * b.wall_work);  // the branch carries a real share
        BOOST_TEST_MESSAGE(cells << " cells: contacts' share of the work " << b.contact_dissipation / b.wall_work);
        defect.push_back(std::abs(b.relative_defect()));
    }
    // the ratios of successive differences on the three finest meshes (4 at second order)
    const double r_mu = (mu[2] - mu[1]) / (mu[3] - mu[2]), r_nu = (nu[2] - nu[1]) / (nu[3] - nu[2]);  // nu: the slip
    BOOST_TEST_MESSAGE("mu " << mu[0] << " " << mu[1] << " " << mu[2] << " " << mu[3] << " (ratios " << r_mu << ", slip "
                             << r_nu << "); budget defects " << defect[0] << " " << defect[1] << " " << defect[2]
                             << " " << defect[3]);
    for (int i = 0; i < 3; ++i) BOOST_TEST(defect[i] / defect[i + 1] > 3.5);
    BOOST_TEST(defect[3] < 1e-4);
    BOOST_TEST(r_mu > 3.3);  // second order: 4 (first order would give 2, third 8)
    BOOST_TEST(r_mu < 4.7);
    BOOST_TEST(r_nu > 3.3);
    BOOST_TEST(r_nu < 4.7);
    BOOST_TEST(std::abs(mu[3] - mu[2]) < 1e-5 * mu[3]);
}

// eps -> 0: the solution converges as the sign's width vanishes (the differences shrink with eps).
BOOST_AUTO_TEST_CASE(solution_converges_as_the_sign_width_vanishes) {
    std::vector<double> mu;
    for (double eps : {4e-2, 2e-2, 1e-2, 5e-3, 2.5e-3}) {
        const Problem p = with_contact(couette(1.0, 20), contact(kMuC, eps));
        mu.push_back(observe(p, solve_fv(p, mesh(200))).tau_top);
    }
    BOOST_TEST_MESSAGE("mu at eps 4e-2 ... 2.5e-3: " << mu[0] << " " << mu[1] << " " << mu[2] << " " << mu[3] << " "
                                                     << mu[4]);
    for (int i = 0; i + 2 < 5; ++i) BOOST_TEST(std::abs(mu[i + 2] - mu[i + 1]) < 0.6 * std::abs(mu[i + 1] - mu[i]) + 1e-12);
    BOOST_TEST(std::abs(mu[4] - mu[2]) < 1e-4 * mu[2]);  // the default eps = 1e-2 is converged to 1e-4
}
