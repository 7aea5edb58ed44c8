// The contact stress (docs/continuum-model.md §2.9, §2.9a) on the trough's cross-section: the 1-D branch reproduced
// with the side walls removed, the exact Jacobian of the 9-point stencil, the quasi-static limit mu -> mu_c on a wide
// section, and the momentum and energy budgets per wall with the contacts' dissipation. The constants are the
// illustrative ones of fixtures.h (not fitted).
#define BOOST_TEST_MODULE continuum_cross_section_contact
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "contact_budgets.h"
#include "cross_section_fixtures.h"
#include "fixtures.h"
#include "granlub/continuum/cross_section_solver.h"
#include "granlub/continuum/fv_solver.h"

using namespace granlub::continuum;
using namespace granlub::continuum::testing;

// Without side walls (periodic in z^) every column is the 1-D solution with the branch on the same nodes in y^: the
// tangential gradient vanishes and the 2-D direction is the 1-D sgn_eps.
BOOST_AUTO_TEST_CASE(periodic_cross_section_reproduces_the_1d_branch) {
    for (const Mode mode : {Mode::Load, Mode::Inventory}) {
        BOOST_TEST_CONTEXT("mode " << static_cast<int>(mode)) {
            CrossSectionProblem p = contact_trough(1.0, 20, 60);
            p.periodic = true;
            p.gap.mode = mode;
            p.gap.inventory = 0.55 * p.gap.Lambda;
            SolverSettings s1;
            s1.cells = 200;
            const Solution one = solve_fv(p.gap, s1);
            // solve_cross_section starts from the 1-D solution (where the cross-section's residual must vanish); Newton
            // from a guess varying along z^ and off in Lambda must come back to it
            const CrossSectionSolution two = solve_cross_section(p, grid(200, 4));
            BOOST_TEST(cross_section_residual(p, two) < 1e-9);
            CrossSectionSolution from = two;
            for (int j = 0; j < from.nz(); ++j)
                for (int i = 0; i < from.ny(); ++i) {
                    from.u[from.at(i, j)] += 0.01 * std::sin(2 * kPi * j / from.nz()) * std::sin(kPi * i / from.cells_y);
                    from.nu[from.at(i, j)] *= 1 - 0.001 * (1 + std::cos(2 * kPi * j / from.nz()));
                }
            from.Lambda *= 1.01;
            const auto rep = newton_cross_section(p, grid(200, 4), from);
            BOOST_TEST_REQUIRE(rep.converged, rep.why);
            double du = 0, dnu = 0;
            for (const CrossSectionSolution* x : {&two, static_cast<const CrossSectionSolution*>(&from)})
                for (int j = 0; j < x->nz(); ++j)
                    for (int i = 0; i < x->ny(); ++i) {
                        du = std::max(du, std::abs(x->u[x->at(i, j)] - one.u[static_cast<std::size_t>(i)]));
                        dnu = std::max(dnu, std::abs(x->nu[x->at(i, j)] - one.nu[static_cast<std::size_t>(i)]));
                    }
            BOOST_TEST(std::abs(from.Lambda - one.Lambda) < 1e-6 * one.Lambda);
            const auto o2 = observe(p, two);
            const auto o1 = observe(p.gap, one);
            const EnergyBudget b1 = energy_budget(p.gap, one);
            BOOST_TEST_MESSAGE("mode " << static_cast<int>(mode) << ": Newton from the perturbed guess in "
                                       << rep.iterations << " iterations; max |du| " << du << ", |dnu| " << dnu
                                       << ", tau top " << o2.walls[1].tau << " vs " << o1.tau_top << ", contacts' share "
                                       << o2.contact_dissipation / (o2.walls[0].work) << " vs "
                                       << b1.contact_dissipation / b1.wall_work);
            BOOST_TEST(b1.contact_dissipation > 0.2 * b1.wall_work);  // the branch carries a real share
            BOOST_TEST(du < 1e-6);
            BOOST_TEST(dnu < 1e-6);
            BOOST_TEST(std::abs(two.Lambda - one.Lambda) < 1e-6 * one.Lambda);
            BOOST_TEST(std::abs(o2.walls[0].tau - o1.tau_bottom) < 1e-6 * o1.tau_bottom);
            BOOST_TEST(std::abs(o2.walls[1].tau - o1.tau_top) < 1e-6 * o1.tau_top);
            BOOST_TEST(std::abs(o2.walls[0].slip - o1.slip_bottom) < 1e-6);
            BOOST_TEST(std::abs(o2.nu_mean - o1.nu_mean) < 1e-6);
            // per unit width (over A) the cross-section's contact dissipation is the gap's, both over P_y U
            BOOST_TEST(std::abs(o2.contact_dissipation / p.aspect(two.Lambda) - b1.contact_dissipation) <
                       1e-6 * b1.contact_dissipation);
        }
    }
}

// The Dual<19> Jacobian of the 9-point stencil with the contact shear (its pressure, the regularised direction with
// the tangential gradients, the walls' and corners' terms) against central differences, at a converged state and
// away from it, with side walls and periodic.
BOOST_AUTO_TEST_CASE(exact_jacobian_matches_finite_differences) {
    for (const bool periodic : {false, true})
        for (const double mu_c : {0.0, kIllustrativeMuC}) {
            BOOST_TEST_CONTEXT("periodic " << periodic << ", mu_c " << mu_c) {
                CrossSectionProblem p = contact_trough(1.0, 8, 12, mu_c);
                p.periodic = periodic;
                CrossSectionSolution s = solve_cross_section(p, grid(8, 10));
                const double at_solution = cross_section_jacobian_defect(p, s, 1e-7);
                for (std::size_t k = 0; k < s.u.size(); ++k) {
                    s.u[k] += 0.01 * std::sin(7.0 * static_cast<double>(k));
                    s.nu[k] -= 1e-4 * (1 + std::cos(5.0 * static_cast<double>(k)));
                }
                const double away = cross_section_jacobian_defect(p, s, 1e-7);
                BOOST_TEST_MESSAGE("periodic " << periodic << ", mu_c " << mu_c << ": Jacobian defect " << at_solution
                                               << " at the solution, " << away << " away from it");
                BOOST_TEST(at_solution < 1e-5);
                BOOST_TEST(away < 1e-5);
            }
        }
}

// A wide cross-section (20 diameters deep, 80 wide; one cell per diameter, enough for the wall's mu: 30 x 120 cells move it
// by < 7e-4) at falling speed: the top wall's mu = tau/P falls towards mu_c and
// stays above it. The kinetic theory alone (LSJC, no correlation length) levels off near its own mu instead, far
// from mu_c: it fails the same check.
BOOST_AUTO_TEST_CASE(wide_section_mu_tends_to_mu_c_as_the_speed_falls) {
    double last = 1e300;
    for (double U : {2.0, 1.0, 0.5, 0.25}) {
        const CrossSectionProblem p = contact_trough(U, 20, 80);
        const auto o = observe(p, solve_cross_section(p, grid(20, 80)));
        const double mu = o.walls[1].tau;
        BOOST_TEST_MESSAGE("U = " << U << ": top mu = " << mu << " (floor " << o.walls[0].tau << ", sides "
                                  << o.walls[2].tau << ", side share " << o.side_share << ", max nu " << o.nu_max_node
                                  << ")");
        BOOST_TEST_CONTEXT("U = " << U << ": mu = " << mu) {
            BOOST_TEST(mu > kIllustrativeMuC);
            BOOST_TEST(mu < last);
            last = mu;
        }
    }
    BOOST_TEST(last - kIllustrativeMuC < 0.02);
    const CrossSectionProblem k = contact_trough(0.25, 20, 80, -1);
    const double kinetic = observe(k, solve_cross_section(k, grid(20, 80))).walls[1].tau;
    BOOST_TEST_MESSAGE("U = 0.25, the kinetic theory alone: top mu = " << kinetic);
    BOOST_TEST(std::abs(kinetic - kIllustrativeMuC) > 0.05);
}

// Momentum: the walls' forces (kinetic + contact tractions) balance exactly (the contact fluxes are conservative: a
// face's tangential gradient is the mean of its two nodes'); energy: the walls' work equals the bulk dissipation, the
// walls' sinks and the contacts' dissipation, to O(h^2).
BOOST_AUTO_TEST_CASE(budgets_close_per_wall_with_the_contact_stress) {
    const CrossSectionProblem p = contact_trough(1.0, 10, 30);
    check_contact_budgets(p, [](const CrossSectionObservables& o) {
        BOOST_TEST(o.walls[0].force > 0);
        BOOST_TEST(o.walls[1].force < 0);
        BOOST_TEST(o.walls[1].work == 0.0);
        BOOST_TEST(std::abs(o.walls[2].force - o.walls[3].force) < 1e-8 * o.walls[2].force);
    });
}
