// The contact stress (docs/continuum-model.md §2.9a) on the trough's cross-section with the body forces: pi_c = p_c/p
// and the cap nu_P at each node's p. A uniform pressure field p^ reproduces the uniform-pressure solver (p^ = 1) and
// the load p^ P_y (p^ != 1); the exact Jacobian at a varying p^; the budgets per wall; gravity and the centripetal
// force where they act. The constants are the illustrative ones of fixtures.h (not fitted).
#define BOOST_TEST_MODULE continuum_cross_section_contact_body_forces
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "contact_budgets.h"
#include "cross_section_fixtures.h"
#include "fixtures.h"
#include "granlub/continuum/cross_section_solver.h"

using namespace granlub::continuum;
using namespace granlub::continuum::testing;

namespace {

// The largest node difference of u^ and nu between two solutions on one grid.
double max_difference(const CrossSectionSolution& a, const CrossSectionSolution& b) {
    double d = 0;
    for (std::size_t k = 0; k < a.u.size(); ++k)
        d = std::max({d, std::abs(a.u[k] - b.u[k]), std::abs(a.nu[k] - b.nu[k])});
    return d;
}

// pi_c = p_c/p at node k of a solution (p^ = 1 without a pressure field).
double contact_share(const CrossSectionProblem& p, const CrossSectionSolution& s, std::size_t k) {
    return p.gap.closures->contact().ratio(s.nu[k]) / (s.pressure.empty() ? 1.0 : s.pressure[k]);
}

// S&T's gravity over the load, rho_p g d / P_y, and the outer wall's radius of S&T's annulus with W = `width` d.
const Spec kSt = sawyer(1.0);
const double kGravity = kSt.rho * 9.81 * kSt.d / kSt.P;
double annulus(double width) { return 76.2e-3 / kSt.d + width / 2; }

}  // namespace

// The body forces' Newton (Picard: at a given pressure field) with the forces zero, p^ = 1 at every node, is the
// uniform-pressure solver's, from a perturbed guess; and at a uniform p^ = c it is the uniform solver's under the load
// c P_y (Pi/c, Fr/(c P_y)): the local pi_c = p_c/p, the local cap nu_P and the walls' Pi/p^ together.
BOOST_AUTO_TEST_CASE(uniform_pressure_field_is_the_uniform_solver) {
    const CrossSectionSettings st = grid(16, 40);
    const CrossSectionProblem p = contact_trough(1.0, 10, 25);
    const CrossSectionSolution off = solve_cross_section(p, st);
    CrossSectionProblem q = p;
    q.pressure.assign(off.u.size(), 1.0);
    CrossSectionSolution from = off;
    for (std::size_t k = 0; k < from.u.size(); ++k) {
        from.u[k] += 1e-3 * std::sin(3.0 * static_cast<double>(k));
        from.nu[k] *= 1 - 1e-4 * (1 + std::cos(5.0 * static_cast<double>(k)));
    }
    const auto rep = newton_cross_section(q, st, from);
    BOOST_TEST_REQUIRE(rep.converged, rep.why);
    const double d1 = max_difference(from, off);
    BOOST_TEST_MESSAGE("p^ = 1: " << rep.iterations << " Newton iterations, max |du|, |dnu| " << d1);
    BOOST_TEST(d1 < 1e-8);

    const double c = 1.2;
    CrossSectionProblem loaded = p;  // the load c P_y
    loaded.gap.Pi = p.gap.Pi / c;
    ContactStress cs = p.gap.closures->contact();
    cs.coefficient /= c;
    loaded.gap = with_contact(loaded.gap, cs);
    const CrossSectionSolution at_load = solve_cross_section(loaded, st);
    CrossSectionProblem field = p;
    field.pressure.assign(off.u.size(), c);
    BOOST_TEST(cross_section_residual(field, at_load) < 1e-9);
    CrossSectionSolution moved = at_load;
    for (std::size_t k = 0; k < moved.u.size(); ++k) moved.u[k] += 1e-3 * std::sin(3.0 * static_cast<double>(k));
    BOOST_TEST_REQUIRE(newton_cross_section(field, st, moved).converged);
    const double dc = max_difference(moved, at_load);
    BOOST_TEST_MESSAGE("p^ = " << c << ": max |du|, |dnu| against the load " << c << " P_y: " << dc
                               << "; max nu " << *std::max_element(at_load.nu.begin(), at_load.nu.end())
                               << " against the cap nu_P(P_y) " << p.gap.closures->cap());
    BOOST_TEST(dc < 1e-8);
    // the test has bite: under the load 1.2 P_y the bed passes the cap of P_y somewhere
    BOOST_TEST(*std::max_element(at_load.nu.begin(), at_load.nu.end()) > p.gap.closures->cap());
}

// The Dual<19> Jacobian with the contact stress at a pressure field varying over the cross-section (gravity,
// exaggerated 5 times, and the centripetal force), at the solution and away from it.
BOOST_AUTO_TEST_CASE(exact_jacobian_with_body_forces) {
    CrossSectionProblem p = contact_trough(1.0, 8, 12);
    p.body.gravity = 5 * kGravity;
    p.body.radius = annulus(12);
    CrossSectionSolution s = solve_cross_section(p, grid(8, 10));
    BOOST_TEST_REQUIRE(s.pressure.size() == s.u.size());
    const auto [lo, hi] = std::minmax_element(s.pressure.begin(), s.pressure.end());
    BOOST_TEST(*hi - *lo > 0.05);
    const double at_solution = cross_section_jacobian_defect(p, s, 1e-7);
    for (std::size_t k = 0; k < s.u.size(); ++k) {
        s.u[k] += 0.01 * std::sin(7.0 * static_cast<double>(k));
        s.nu[k] -= 1e-4 * (1 + std::cos(5.0 * static_cast<double>(k)));
    }
    const double away = cross_section_jacobian_defect(p, s, 1e-7);
    BOOST_TEST_MESSAGE("p^ " << *lo << " .. " << *hi << ": Jacobian defect " << at_solution << " at the solution, "
                             << away << " away from it");
    BOOST_TEST(at_solution < 1e-5);
    BOOST_TEST(away < 1e-5);
}

// The walls' forces balance (the body forces act across the trough, not along it) and the energy budget closes at
// second order: neither force does work on a flow along the trough.
BOOST_AUTO_TEST_CASE(budgets_close_per_wall_with_body_forces) {
    CrossSectionProblem p = contact_trough(1.0, 10, 30);
    p.body.gravity = kGravity;
    p.body.radius = annulus(30);
    check_contact_budgets(p, [](const CrossSectionObservables& o) {
        BOOST_TEST(std::abs(o.walls[1].normal - 1.0) < 1e-10);  // the top carries the load
    });
}

// Gravity on the periodic section (no side walls, so p^ is the hydrostatic column): the pressure grows towards the
// floor, and so does the contact pressure's share pi_c = p_c/p against the section without gravity (the same shear
// under more pressure is nearer the quasi-static limit). The centripetal force on the trough loads the outer wall
// more than the inner one.
BOOST_AUTO_TEST_CASE(gravity_raises_the_contact_share_towards_the_floor_and_the_outer_wall_carries_more) {
    CrossSectionProblem p = contact_trough(1.0, 20, 8);
    p.periodic = true;
    CrossSectionProblem g = p;
    g.body.gravity = 5 * kGravity;
    const CrossSectionSettings st = grid(40, 4);
    const CrossSectionSolution s0 = solve_cross_section(p, st), s = solve_cross_section(g, st);
    const auto share = [&](int i) { return contact_share(g, s, s.at(i, 0)) - contact_share(p, s0, s0.at(i, 0)); };
    const int N = st.cells_y;
    BOOST_TEST_MESSAGE("gravity x5: p^ floor " << s.pressure[s.at(0, 0)] << ", mid " << s.pressure[s.at(N / 2, 0)]
                                               << "; pi_c floor " << contact_share(g, s, s.at(0, 0)) << " (without "
                                               << contact_share(p, s0, s0.at(0, 0)) << "), mid "
                                               << contact_share(g, s, s.at(N / 2, 0)) << " ("
                                               << contact_share(p, s0, s0.at(N / 2, 0)) << "), top "
                                               << contact_share(g, s, s.at(N, 0)) << " ("
                                               << contact_share(p, s0, s0.at(N, 0)) << ")");
    BOOST_TEST(s.pressure[s.at(0, 0)] > 1.05);
    BOOST_TEST(share(0) > share(N / 2));
    BOOST_TEST(share(N / 2) > share(N));
    BOOST_TEST(share(0) > 0.0);

    CrossSectionProblem t = contact_trough(1.0, 10, 30);
    t.body.gravity = kGravity;
    t.body.radius = annulus(30);
    const auto o = observe(t, solve_cross_section(t, grid(20, 60)));
    BOOST_TEST_MESSAGE("centripetal force: normal stress / P_y outer " << o.walls[2].normal << ", inner "
                                                                      << o.walls[3].normal << ", floor "
                                                                      << o.walls[0].normal << "; tau / P_y outer "
                                                                      << o.walls[2].tau << ", inner " << o.walls[3].tau);
    BOOST_TEST(o.walls[2].normal > o.walls[3].normal);
    BOOST_TEST(o.walls[2].tau > o.walls[3].tau);
}
