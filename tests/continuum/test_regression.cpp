// Regression numbers of docs/continuum-model.md §7 (§8.7), FV with N = 200 as in the reference.
// Tolerances follow the digits printed in the reference (about 1e-4 relative).
#define BOOST_TEST_MODULE continuum_regression
#include <array>
#include <cmath>

#include <boost/test/unit_test.hpp>

#include "fixtures.h"
#include "granlub/continuum/fv_solver.h"

using namespace granlub::continuum;
using namespace granlub::continuum::testing;

namespace {
struct Result {
    Observables o;
    Solution s;
};
Result solve(const Spec& sp, int cells = 200) {
    const Problem p = problem(sp);
    SolverSettings st;
    st.cells = cells;
    Solution s = solve_fv(p, st);
    return {observe(p, s), s};
}
// node value at y^ = k/10 on the N = 200 mesh
double at(const std::vector<double>& v, int tenth) { return v[static_cast<std::size_t>(20 * tenth)]; }
}  // namespace

// §7.1: default model (K, OGAWA), S&T at P = 5.5 kPa.
BOOST_AUTO_TEST_CASE(sawyer_tichy_default_model) {
    struct Row { double U, nu, nu_c, nu_w, us, tau, ratio; };
    for (const auto& r : {Row{1.4, 0.61039, 0.61278, 0.60549, 0.24783, 1512.30, 0.27496},
                          Row{2.0, 0.57768, 0.58155, 0.56983, 0.35381, 1506.21, 0.27386},
                          Row{2.8, 0.53034, 0.53572, 0.51956, 0.49492, 1496.09, 0.27202}}) {
        BOOST_TEST_CONTEXT("U = " << r.U) {
            const auto [o, s] = solve(sawyer(r.U));
            BOOST_TEST(std::abs(o.nu_mean - r.nu) < 2e-5);
            BOOST_TEST(std::abs(o.nu_centre - r.nu_c) < 2e-5);
            BOOST_TEST(std::abs(o.nu_bottom - r.nu_w) < 2e-5);
            BOOST_TEST(rel(o.slip_bottom * r.U, r.us) < 1e-4);
            BOOST_TEST(rel(o.tau_bottom * 5.5e3, r.tau) < 1e-4);
            BOOST_TEST(rel(o.tau_bottom, r.ratio) < 1e-4);
            BOOST_TEST(rel(o.slip_bottom, 0.177) < 3e-3);  // u_s/U the same at all speeds
        }
    }
}

// §7.2 default-model profiles (T in m^2/s^2): rows y/H = 0 .. 0.5.
BOOST_AUTO_TEST_CASE(sawyer_tichy_default_profiles) {
    const double u[3][6] = {{0.8230, 0.7552, 0.6895, 0.6254, 0.5625, 0.5000},
                            {0.8231, 0.7553, 0.6896, 0.6255, 0.5625, 0.5000},
                            {0.8232, 0.7555, 0.6898, 0.6257, 0.5626, 0.5000}};
    const double nu[3][6] = {{0.6055, 0.6082, 0.6102, 0.6117, 0.6125, 0.6128},
                             {0.5698, 0.5741, 0.5774, 0.5797, 0.5811, 0.5816},
                             {0.5196, 0.5254, 0.5299, 0.5331, 0.5351, 0.5357}};
    const double T[3][6] = {{0.03581, 0.03332, 0.03147, 0.03018, 0.02943, 0.02918},
                            {0.07359, 0.06854, 0.06477, 0.06216, 0.06062, 0.06012},
                            {0.14595, 0.13617, 0.12884, 0.12376, 0.12077, 0.11978}};
    const double speeds[3] = {1.4, 2.0, 2.8};
    for (int k = 0; k < 3; ++k) {
        const Spec sp = sawyer(speeds[k]);
        const Problem p = problem(sp);
        const auto [o, s] = solve(sp);
        for (int j = 0; j < 6; ++j) {
            BOOST_TEST_CONTEXT("U = " << speeds[k] << ", y/H = " << j / 10.0) {
                BOOST_TEST(std::abs(at(s.u, j) - u[k][j]) < 1e-4);
                BOOST_TEST(std::abs(at(s.nu, j) - nu[k][j]) < 1e-4);
                const double Tj = sp.P / sp.rho / p.closures->state(at(s.nu, j)).fp.v;
                BOOST_TEST(rel(Tj, T[k][j]) < 2e-4);
            }
        }
    }
}

// §7.2: JJ / LS reference numbers.
BOOST_AUTO_TEST_CASE(sawyer_tichy_jj_ls) {
    struct Row { double U, nu, us, tau, nu_c, nu_w; };
    for (const auto& r : {Row{1.4, 0.58785, 0.18358, 1613.68, 0.58868, 0.58619},
                          Row{2.0, 0.55782, 0.25314, 1615.26, 0.55876, 0.55594},
                          Row{2.8, 0.51852, 0.33854, 1613.95, 0.51937, 0.51681}}) {
        BOOST_TEST_CONTEXT("U = " << r.U) {
            Spec sp = sawyer(r.U);
            sp.wall = "johnson_jackson";
            sp.g0 = "lun_savage";
            const auto [o, s] = solve(sp);
            BOOST_TEST(std::abs(o.nu_mean - r.nu) < 2e-5);
            BOOST_TEST(std::abs(o.nu_centre - r.nu_c) < 2e-5);
            BOOST_TEST(std::abs(o.nu_bottom - r.nu_w) < 2e-5);
            BOOST_TEST(rel(o.slip_bottom * r.U, r.us) < 1e-4);
            BOOST_TEST(rel(o.tau_bottom * 5.5e3, r.tau) < 1e-4);
        }
    }
}

// §7.2 sensitivity table: mean nu for each wall family and g0 (3 decimals).
BOOST_AUTO_TEST_CASE(sawyer_tichy_g0_and_wall_variants) {
    struct Row { const char* wall; const char* g0; std::array<double, 3> nu; };
    const Row rows[] = {{"kinetic", "ogawa", {0.610, 0.578, 0.530}},
                        {"kinetic", "lun_savage", {0.592, 0.565, 0.529}},
                        {"kinetic", "ma_ahmadi", {0.639, 0.622, 0.588}},
                        {"kinetic", "torquato", {0.630, 0.611, 0.579}},
                        {"kinetic", "carnahan_starling", {0.733, 0.673, 0.608}},
                        {"johnson_jackson", "ogawa", {0.606, 0.569, 0.516}},
                        {"johnson_jackson", "lun_savage", {0.588, 0.558, 0.519}},
                        {"johnson_jackson", "ma_ahmadi", {0.638, 0.618, 0.578}},
                        {"johnson_jackson", "torquato", {0.628, 0.606, 0.570}},
                        {"johnson_jackson", "carnahan_starling", {0.729, 0.665, 0.595}}};
    const double speeds[3] = {1.4, 2.0, 2.8};
    for (const auto& r : rows) {
        for (int k = 0; k < 3; ++k) {
            BOOST_TEST_CONTEXT(r.wall << " / " << r.g0 << ", U = " << speeds[k]) {
                Spec sp = sawyer(speeds[k]);
                sp.wall = r.wall;
                sp.g0 = r.g0;
                BOOST_TEST(std::abs(solve(sp).o.nu_mean - r.nu[static_cast<std::size_t>(k)]) < 6e-4);
            }
        }
    }
}

// §7.2 "other variants of the default".
BOOST_AUTO_TEST_CASE(sawyer_tichy_model_variants) {
    struct Row { const char* what; std::array<double, 3> nu; };
    const auto variant = [](int which, Spec sp) {
        Problem p = problem(sp);
        for (WallBC* w : {&p.bottom, &p.top}) {
            if (which == 1) w->params.slip_dissipation = 0.5;
            if (which == 2) w->params.r6 = 1;
            if (which == 3) w->params.r8 = 1;
            if (which == 4) w->params.r5 = w->params.r6 = w->params.r7 = w->params.r8 = 1;
        }
        return p;
    };
    const Row rows[] = {{"alpha = 1.6", {0.608, 0.573, 0.524}}, {"f_t = 0.5", {0.616, 0.588, 0.545}},
                        {"R6 = 1", {0.612, 0.580, 0.534}},      {"R8 = 1", {0.604, 0.567, 0.516}},
                        {"all R = 1", {0.597, 0.555, 0.500}},   {"nu_max = 0.64", {0.602, 0.571, 0.525}}};
    const double speeds[3] = {1.4, 2.0, 2.8};
    SolverSettings st;
    for (int v = 0; v < 6; ++v) {
        for (int k = 0; k < 3; ++k) {
            BOOST_TEST_CONTEXT(rows[v].what << ", U = " << speeds[k]) {
                Spec sp = sawyer(speeds[k]);
                if (v == 0) sp.alpha = 1.6;
                if (v == 5) sp.numax = 0.64;
                const Problem p = (v >= 1 && v <= 4) ? variant(v, sp) : problem(sp);
                const auto o = observe(p, solve_fv(p, st));
                BOOST_TEST(std::abs(o.nu_mean - rows[v].nu[static_cast<std::size_t>(k)]) < 6e-4);
                if (v == 1) BOOST_TEST(o.nu_bottom > o.nu_centre);  // f_t = 0.5: walls denser than the centre
                if (v == 4) BOOST_TEST(std::abs(o.slip_bottom - 0.106) < 6e-4);
            }
        }
    }
}

// §7.4: Jasti & Higgs parameters, default model, load and fill.
BOOST_AUTO_TEST_CASE(jasti_higgs_default_model) {
    struct Row { double P, nu, nu_c, nu_w, us, tau; };
    for (const auto& r : {Row{2.5e3, 0.54535, 0.54825, 0.53956, 0.2584, 880.6},
                          Row{5.5e3, 0.59362, 0.59553, 0.58977, 0.2589, 1949.7},
                          Row{10e3, 0.61651, 0.61775, 0.61398, 0.2591, 3554.4}}) {
        BOOST_TEST_CONTEXT("P = " << r.P) {
            const auto [o, s] = solve(jasti(r.P));
            BOOST_TEST(std::abs(o.nu_mean - r.nu) < 2e-5);
            BOOST_TEST(std::abs(o.nu_centre - r.nu_c) < 2e-5);
            BOOST_TEST(std::abs(o.nu_bottom - r.nu_w) < 2e-5);
            BOOST_TEST(std::abs(o.slip_bottom * 2.0 - r.us) < 1e-4);
            BOOST_TEST(rel(o.tau_bottom * r.P, r.tau) < 1e-4);
        }
    }
    struct Fill { double nu, P, nu_c, nu_w, tau; };
    for (const auto& r : {Fill{0.55, 2.66e3, 0.55282, 0.54435, 937.7}, Fill{0.595, 5.66e3, 0.59687, 0.59122, 2008.3}}) {
        BOOST_TEST_CONTEXT("fill nu = " << r.nu) {
            Spec sp = jasti();
            sp.mode = Mode::Fill;
            sp.nu_mean = r.nu;
            const auto [o, s] = solve(sp);
            const double P = sp.rho * 4.0 / s.Pi;
            BOOST_TEST(std::abs(o.nu_mean - r.nu) < 1e-9);
            BOOST_TEST(rel(P, r.P) < 2e-3);  // the reference gives P to 3 digits
            BOOST_TEST(std::abs(o.nu_centre - r.nu_c) < 2e-5);
            BOOST_TEST(std::abs(o.nu_bottom - r.nu_w) < 2e-5);
            BOOST_TEST(rel(o.tau_bottom * P, r.tau) < 1e-4);
        }
    }
    // profile at 5.5 kPa, y/H = 0 .. 0.5 (the rest mirrors)
    const double u[6] = {0.8706, 0.7943, 0.7194, 0.6457, 0.5727, 0.5000};
    const double nu[6] = {0.5898, 0.5919, 0.5935, 0.5946, 0.5953, 0.5955};
    const double T[6] = {0.05268, 0.05046, 0.04877, 0.04759, 0.04688, 0.04665};
    const Spec sp = jasti();
    const Problem p = problem(sp);
    const auto [o, s] = solve(sp);
    for (int j = 0; j < 6; ++j) {
        BOOST_TEST(std::abs(at(s.u, j) - u[j]) < 1e-4);
        BOOST_TEST(std::abs(at(s.nu, j) - nu[j]) < 1e-4);
        BOOST_TEST(rel(sp.P / sp.rho / p.closures->state(at(s.nu, j)).fp.v, T[j]) < 2e-4);
    }
}

// §7.4: with JJ walls the J&H flow is denser at the walls than in the centre.
BOOST_AUTO_TEST_CASE(jasti_higgs_jj_walls_are_dense) {
    Spec sp = jasti();
    sp.wall = "johnson_jackson";
    const auto [o, s] = solve(sp);
    BOOST_TEST(std::abs(o.nu_bottom - 0.5984) < 1e-4);
    BOOST_TEST(std::abs(o.nu_centre - 0.5904) < 1e-4);
    BOOST_TEST(std::abs(o.slip_bottom - 0.099) < 6e-4);
    BOOST_TEST(std::abs(o.tau_bottom - 0.382) < 6e-4);
}

// §7.4: slip against roughness (all R equal), both families.
BOOST_AUTO_TEST_CASE(jasti_higgs_slip_against_roughness) {
    const double R[7] = {0.10, 0.20, 0.35, 0.50, 0.65, 0.80, 1.00};
    const double k_slip[7] = {0.354, 0.273, 0.201, 0.158, 0.129, 0.109, 0.089};
    const double jj_slip[7] = {0.329, 0.239, 0.165, 0.125, 0.099, 0.081, 0.065};
    const double k_dnu[7] = {0.004, 0.007, 0.009, 0.008, 0.006, 0.003, -0.000};
    const double jj_dnu[7] = {0.003, 0.004, 0.002, -0.003, -0.008, -0.013, -0.019};
    for (int i = 0; i < 7; ++i) {
        for (const char* wall : {"kinetic", "johnson_jackson"}) {
            BOOST_TEST_CONTEXT(wall << ", R = " << R[i]) {
                Spec sp = jasti();
                sp.R = R[i];
                sp.wall = wall;
                const auto o = solve(sp).o;
                const bool k = wall[0] == 'k';
                BOOST_TEST(std::abs(o.slip_bottom - (k ? k_slip[i] : jj_slip[i])) < 6e-4);
                BOOST_TEST(std::abs(o.nu_centre - o.nu_bottom - (k ? k_dnu[i] : jj_dnu[i])) < 6e-4);
            }
        }
    }
}

// §7.5: fill mode at nu_mean = 0.595 with S&T parameters: Pi = 1.32887 and tau/P = 0.2745
// at every speed, so P and tau scale with U^2.
BOOST_AUTO_TEST_CASE(sawyer_tichy_fill_mode) {
    const double U[5] = {0.4, 0.8, 1.4, 2.0, 2.8};
    const double P[5] = {307, 1228, 3761, 7676, 15044};
    const double tau[5] = {84.3, 337.1, 1032.3, 2106.7, 4129.1};
    for (int k = 0; k < 5; ++k) {
        BOOST_TEST_CONTEXT("U = " << U[k]) {
            Spec sp = sawyer(U[k]);
            sp.mode = Mode::Fill;
            sp.nu_mean = 0.595;
            const auto [o, s] = solve(sp);
            BOOST_TEST(rel(s.Pi, 1.32887) < 2e-5);
            BOOST_TEST(std::abs(o.tau_bottom - 0.2745) < 1e-4);
            const double Pk = sp.rho * U[k] * U[k] / s.Pi;
            BOOST_TEST(std::abs(Pk - P[k]) < 0.5 + 1e-4 * P[k]);
            BOOST_TEST(std::abs(o.tau_bottom * Pk - tau[k]) < 0.05 + 1e-4 * tau[k]);
        }
    }
}
