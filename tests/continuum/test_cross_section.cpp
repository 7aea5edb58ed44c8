// Checks of the trough's cross-section solver (continuum/README.md "The trough's cross-section"): the 1-D solver
// reproduced with the side walls removed, second order on a manufactured solution, and the momentum and energy
// budgets per wall.
#define BOOST_TEST_MODULE continuum_cross_section
#include <algorithm>
#include <cmath>

#include <boost/test/unit_test.hpp>

#include "cross_section_fixtures.h"
#include "fixtures.h"
#include "granlub/continuum/cross_section_solver.h"
#include "granlub/continuum/fv_solver.h"
#include "granlub/continuum/walls/flat_wall.h"
#include "granlub/continuum/walls/flat_wall_impacts.h"
#include "granlub/continuum/walls/wall_condition.h"

using namespace granlub::continuum;
using namespace granlub::continuum::testing;

namespace {

// S&T's cell (fixtures.h) with its trough: W = 19 mm, side walls as the floor.
CrossSectionProblem trough(const Spec& sp, double W = 19e-3) {
    CrossSectionProblem p;
    p.gap = problem(sp);
    p.outer = p.inner = p.gap.bottom;
    p.width = W / sp.d;
    return p;
}

}  // namespace

// Without side walls (periodic in z) every column is the 1-D solution on the same nodes in y^.
BOOST_AUTO_TEST_CASE(periodic_cross_section_reproduces_the_1d_solver) {
    for (const Mode mode : {Mode::Load, Mode::Inventory}) {
        BOOST_TEST_CONTEXT("mode " << static_cast<int>(mode)) {
            Spec sp = sawyer(2.0);
            CrossSectionProblem p = trough(sp);
            p.periodic = true;
            p.gap.mode = mode;
            p.gap.inventory = 0.595 * sp.H / sp.d;
            SolverSettings s1;
            s1.cells = 200;
            const Solution one = solve_fv(p.gap, s1);
            const CrossSectionSolution two = solve_cross_section(p, grid(200, 4));
            double du = 0, dnu = 0;
            for (int j = 0; j < two.nz(); ++j)
                for (int i = 0; i < two.ny(); ++i) {
                    du = std::max(du, std::abs(two.u[two.at(i, j)] - one.u[static_cast<std::size_t>(i)]));
                    dnu = std::max(dnu, std::abs(two.nu[two.at(i, j)] - one.nu[static_cast<std::size_t>(i)]));
                }
            BOOST_TEST(du < 1e-6);
            BOOST_TEST(dnu < 1e-6);
            BOOST_TEST(std::abs(two.Lambda - one.Lambda) < 1e-6 * one.Lambda);
            const auto o2 = observe(p, two);
            const auto o1 = observe(p.gap, one);
            BOOST_TEST(std::abs(o2.walls[0].tau - o1.tau_bottom) < 1e-6 * o1.tau_bottom);
            BOOST_TEST(std::abs(o2.walls[1].tau - o1.tau_top) < 1e-6 * o1.tau_top);
            BOOST_TEST(std::abs(o2.walls[0].slip - o1.slip_bottom) < 1e-6);
            BOOST_TEST(std::abs(o2.nu_mean - o1.nu_mean) < 1e-6);
        }
    }
}

namespace {

// A manufactured solution on the rectangle with all four walls: u* and nu* smooth and varying both ways; the
// sources make them exact solutions of the continuous problem, the wall corrections make them satisfy each wall's
// condition (wall_condition.h, evaluated here through the same interface).
class Manufactured : public CrossSectionSource {
public:
    Manufactured(const CrossSectionProblem& p) : p_(p), A_(p.aspect(p.gap.Lambda)) {}
    double u(double y, double z) const { return 0.8 - 0.6 * y + 0.1 * std::sin(kPi * z / A_) * y; }
    double nu(double y, double z) const { return 0.55 + 0.03 * std::cos(kPi * y) * std::cos(kPi * z / A_); }

    void volume(double y, double z, double& su, double& snu) const override {
        const double k = kPi / A_, s = std::sin(k * z), c = std::cos(k * z), sy = std::sin(kPi * y), cy = std::cos(kPi * y);
        const double uy = -0.6 + 0.1 * s, uz = 0.1 * k * c * y, uyy = 0, uzz = -0.1 * k * k * s * y;
        const double ny = -0.03 * kPi * sy * c, nz = -0.03 * k * cy * s;
        const double nyy = -0.03 * kPi * kPi * cy * c, nzz = -0.03 * k * k * cy * c;
        const auto cf = node_coefficients(*p_.gap.closures, nu(y, z));
        const double divMu = cf.dM * (ny * uy + nz * uz) + cf.M * (uyy + uzz);
        const double divKn = cf.dK * (ny * ny + nz * nz) + cf.K * (nyy + nzz);
        const double L = p_.gap.Lambda, Pi = p_.gap.Pi;
        su = -divMu;
        snu = -(divKn - (Pi * cf.M * (uy * uy + uz * uz) - L * L * cf.C));
    }
    void wall(CrossSectionWall w, double y, double z, double& du, double& dnu) const override {
        const double k = kPi / A_;
        const double uy = -0.6 + 0.1 * std::sin(k * z), uz = 0.1 * k * std::cos(k * z) * y;
        const double ny = -0.03 * kPi * std::sin(kPi * y) * std::cos(k * z);
        const double nz = -0.03 * k * std::cos(kPi * y) * std::sin(k * z);
        double dn_u = 0, dn_nu = 0, u_wall = 1;
        switch (w) {
            case CrossSectionWall::Floor: dn_u = uy, dn_nu = ny; break;
            case CrossSectionWall::Top: dn_u = -uy, dn_nu = -ny, u_wall = 0; break;
            case CrossSectionWall::Outer: dn_u = uz, dn_nu = nz; break;
            case CrossSectionWall::Inner: dn_u = -uz, dn_nu = -nz; break;
        }
        const WallBC& bc = p_.wall(w);
        const auto g = wall_gradients(bc.params, wall_coefficients(p_.gap, bc, nu(y, z)), u_wall - u(y, z),
                                      p_.gap.Lambda, p_.gap.Pi);
        du = dn_u - g.du;
        dnu = dn_nu - g.dnu;
    }

private:
    const CrossSectionProblem& p_;
    double A_;
};

}  // namespace

// The discrete solution converges to the manufactured one at second order (max norm over the nodes).
BOOST_AUTO_TEST_CASE(manufactured_solution_converges_at_second_order) {
    CrossSectionProblem p = trough(sawyer(2.0));
    p.outer.params.restitution = 0.8;  // walls that differ
    p.inner.params.r5 = 0.7;
    const Manufactured m(p);
    p.source = &m;
    const double A = p.aspect(p.gap.Lambda);
    std::vector<double> err;
    for (int n : {8, 16, 32}) {
        const CrossSectionSettings st = grid(n, 2 * n);
        CrossSectionSolution s;
        s.cells_y = st.cells_y, s.cells_z = st.cells_z;
        s.u.resize(static_cast<std::size_t>(s.ny() * s.nz())), s.nu.resize(s.u.size());
        for (int j = 0; j < s.nz(); ++j)
            for (int i = 0; i < s.ny(); ++i) {
                const double y = static_cast<double>(i) / st.cells_y, z = j * A / st.cells_z;
                s.u[s.at(i, j)] = m.u(y, z);
                s.nu[s.at(i, j)] = m.nu(y, z);
            }
        s.Lambda = p.gap.Lambda;
        const auto rep = newton_cross_section(p, st, s);
        BOOST_TEST_REQUIRE(rep.converged, rep.why);
        double e = 0;
        for (int j = 0; j < s.nz(); ++j)
            for (int i = 0; i < s.ny(); ++i) {
                const double y = static_cast<double>(i) / st.cells_y, z = j * A / st.cells_z;
                e = std::max({e, std::abs(s.u[s.at(i, j)] - m.u(y, z)), std::abs(s.nu[s.at(i, j)] - m.nu(y, z))});
            }
        err.push_back(e);
        BOOST_TEST_MESSAGE("manufactured: " << n << " x " << 2 * n << " cells, max error " << e);
    }
    for (std::size_t k = 1; k < err.size(); ++k) {
        const double order = std::log2(err[k - 1] / err[k]);
        BOOST_TEST_MESSAGE("observed order " << order);
        BOOST_TEST(order > 1.8);
        BOOST_TEST(order < 2.3);
    }
}

// Momentum: the walls' forces balance (the flux form conserves it exactly); energy: the walls' work equals the bulk
// dissipation plus what each wall takes (slip work minus the flux it returns), to O(h^2).
BOOST_AUTO_TEST_CASE(budgets_close_per_wall) {
    const CrossSectionProblem p = trough(sawyer(2.0));
    std::vector<double> defects;
    for (int n : {10, 20, 40}) {
        const CrossSectionSolution s = solve_cross_section(p, grid(n, 5 * n / 2));
        const auto o = observe(p, s);
        BOOST_TEST(std::abs(o.force_balance) < 1e-8);
        for (const auto& w : o.walls) BOOST_TEST(w.present);
        // the moving walls push, the top holds back; the top's work is 0
        BOOST_TEST(o.walls[0].force > 0);
        BOOST_TEST(o.walls[1].force < 0);
        BOOST_TEST(o.walls[1].work == 0.0);
        // equal side walls, equal forces
        BOOST_TEST(std::abs(o.walls[2].force - o.walls[3].force) < 1e-8 * o.walls[2].force);
        defects.push_back(std::abs(o.energy_defect));
        BOOST_TEST_MESSAGE(n << " cells across: energy defect " << o.energy_defect << ", side share " << o.side_share);
    }
    BOOST_TEST(defects.back() < 1e-3);
    BOOST_TEST(defects[1] / defects[2] > 3.0);  // second order: x4 per halving
}

// Body forces. Gravity alone on the periodic section has no curl: p^ is the hydrostatic column under the load,
// p^(y) = 1 + Lambda g^ int_y^1 nu dy (the trapezoid rule is the FV balance's own quadrature). With the centripetal
// force the outer wall carries more than the inner one, and the budgets still close.
BOOST_AUTO_TEST_CASE(body_forces_give_the_hydrostatic_column_and_load_the_outer_wall) {
    const Spec sp = sawyer(2.0);
    CrossSectionProblem p = trough(sp);
    p.periodic = true;
    p.body.gravity = sp.rho * 9.81 * sp.d / sp.P;
    const CrossSectionSolution s = solve_cross_section(p, grid(40, 4));
    BOOST_TEST_REQUIRE(s.pressure.size() == s.u.size());
    const double h = 1.0 / s.cells_y, k = p.gap.Lambda * p.body.gravity;
    double column = 1.0, worst = 0;
    for (int i = s.cells_y; i >= 0; --i) {
        if (i < s.cells_y) column += k * 0.5 * h * (s.nu[s.at(i, 0)] + s.nu[s.at(i + 1, 0)]);
        for (int j = 0; j < s.nz(); ++j) worst = std::max(worst, std::abs(s.pressure[s.at(i, j)] - column));
    }
    BOOST_TEST(worst < 1e-10);
    BOOST_TEST(column > 1.01);  // rho g H nu / P ~ 1 % more on the floor
    // and the floor feels it: more pressure, more shear than without gravity
    CrossSectionProblem p0 = p;
    p0.body = {};
    const auto o = observe(p, s), o0 = observe(p0, solve_cross_section(p0, grid(40, 4)));
    BOOST_TEST(std::abs(o.walls[0].normal - column) < 1e-10);
    BOOST_TEST(o.walls[0].tau > o0.walls[0].tau);

    CrossSectionProblem q = trough(sp);
    q.body.gravity = p.body.gravity;
    q.body.radius = (76.2e-3 + 9.5e-3) / sp.d;
    const CrossSectionSolution r = solve_cross_section(q, grid(20, 50));
    const auto oq = observe(q, r);
    BOOST_TEST(oq.walls[2].normal > oq.walls[3].normal);
    BOOST_TEST(oq.walls[2].tau > oq.walls[3].tau);
    BOOST_TEST(std::abs(oq.walls[1].normal - 1.0) < 1e-10);  // the top carries the load
    BOOST_TEST(std::abs(oq.force_balance) < 1e-8);
    BOOST_TEST(std::abs(oq.energy_defect) < 5e-3);
}

// Plane side walls whose impacts stick and slide (walls/flat_wall_impacts.h; wall_roughness = "built"): the Dual<19>
// Jacobian through each wall node's xi against central differences, the budgets closing at second order, and per
// side wall its force and its sink the law's, sum over its nodes of sigma(xi) P and delta(xi) P sqrt(T) (trapezoid
// rule, as observe() sums), xi = u_s/sqrt(T) from each node's slip and nu.
BOOST_AUTO_TEST_CASE(sliding_plane_side_walls_follow_the_law_and_close_the_budgets) {
    CrossSectionProblem p = trough(sawyer(2.0));
    const FlatWallFactors f = flat_wall_from_impact_law(0.9, 1.0);  // no spin
    p.outer.params = WallParams{0.9, f.r5, f.r6, f.r7, f.r8, f.slip_dissipation, WallEnergy::SlipWork};
    p.outer.params.impacts = flat_wall_impacts(0.9, 0.5, kFlatWallBeta0);
    p.inner = p.outer;
    const FlatWallImpacts& law = *p.outer.params.impacts;
    std::vector<double> defects;
    for (int n : {10, 20, 40}) {
        CrossSectionSolution s = solve_cross_section(p, grid(n, 5 * n / 2));
        const auto o = observe(p, s);
        BOOST_TEST(std::abs(o.force_balance) < 1e-8);
        defects.push_back(std::abs(o.energy_defect));
        for (int w : {2, 3}) {
            const int j = w == 2 ? 0 : s.cells_z;
            double force = 0, sink = 0;
            for (int i = 0; i <= s.cells_y; ++i) {
                const double ds = (i == 0 || i == s.cells_y ? 0.5 : 1.0) / s.cells_y;
                const std::size_t k = s.at(i, j);
                const double fp = p.gap.closures->state(s.nu[k]).fp.v, xi = (1 - s.u[k]) * std::sqrt(s.Pi * fp);
                const auto q = law.quadrature(xi);
                force += ds * q.sigma_over_xi * xi;
                sink += ds * q.delta / std::sqrt(s.Pi * fp);  // D/(P U): delta sqrt(T)/U, T/U^2 = 1/(Pi f_p)
            }
            BOOST_TEST(o.walls[w].force == force, boost::test_tools::tolerance(1e-6));
            BOOST_TEST(o.walls[w].sink == sink, boost::test_tools::tolerance(1e-6));
        }
        BOOST_TEST_MESSAGE(n << " cells across: energy defect " << o.energy_defect << ", side share " << o.side_share
                             << ", side slip " << o.walls[2].slip);
        if (n == 10) {
            BOOST_TEST(cross_section_jacobian_defect(p, s, 1e-7) < 1e-5);
            for (std::size_t k = 0; k < s.u.size(); ++k) {
                s.u[k] += 0.01 * std::sin(7.0 * static_cast<double>(k));
                s.nu[k] -= 1e-4 * (1 + std::cos(5.0 * static_cast<double>(k)));
            }
            BOOST_TEST(cross_section_jacobian_defect(p, s, 1e-7) < 1e-5);
        }
    }
    BOOST_TEST(defects.back() < 1e-3);
    BOOST_TEST(defects[1] / defects[2] > 3.0);
}
