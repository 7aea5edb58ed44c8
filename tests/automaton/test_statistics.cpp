// Statistical regression tests of docs/automaton-model.md §7.2 (cheap CI variant: 3000 steps averaged over
// steps 1000-2999) against the reference prototype's numbers in §6.1-6.3. Each tolerance is
// derived from standard errors: 5 sigma of (our measured standard error combined with the
// reference's seed-to-seed scatter, 0.001 per §4.4/§6.1) plus the rounding of the printed
// reference, and never looser than the plan's own tolerance (§7.2).
#define BOOST_TEST_MODULE automaton_statistics
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <iostream>

#include "granlub/automaton/ensemble.h"

using namespace granlub::automaton;

namespace {

constexpr double kRefScatter = 0.001;  // seed-to-seed scatter of the prototype (§4.4: <= 0.001-0.002)

Params ci(double R = 0.65) {
    Params p;
    p.run.steps = 3000;
    p.run.t_avg_start = 1000;
    p.run.block = 500;
    p.run.replicas = 3;  // "3 seeds" (§7.2)
    p.run.seed = 2024;
    p.rules.R_bottom = p.rules.R_top = p.rules.p_drag = R;
    return p;
}

// |ours - ref| within the derived tolerance; prints the numbers either way.
void near(const std::string& what, const Stat& ours, double ref, double ref_rounding, double spec_tol) {
    const double tol = std::min(spec_tol, 5 * std::hypot(ours.stderr_, kRefScatter) + ref_rounding);
    BOOST_TEST_MESSAGE(what << ": " << ours.mean << " +- " << ours.stderr_ << " vs " << ref << " (tol " << tol << ")");
    BOOST_CHECK_MESSAGE(std::abs(ours.mean - ref) <= tol, what << ": " << ours.mean << " +- " << ours.stderr_
                                                               << " vs reference " << ref << ", tolerance " << tol);
}

}  // namespace

BOOST_AUTO_TEST_CASE(default_case_profiles) {
    const EnsembleResult r = run_ensemble(ci());
    // u/U: §6.1 (mean of seeds A and B, 3 decimals); nu: §6.3 "base" row (3 decimals).
    const double u_ref[10] = {0.8535, 0.848, 0.7905, 0.7305, 0.6655, 0.5975, 0.5215, 0.442, 0.341, 0.3425};
    const double nu_ref[10] = {0.786, 0.832, 0.840, 0.852, 0.862, 0.868, 0.874, 0.874, 0.880, 0.834};
    for (int y = 0; y < 10; ++y) {
        near("u/U row " + std::to_string(y), r.rows_.u[y], u_ref[y], 0.0005, 0.01);
        near("nu row " + std::to_string(y), r.rows_.nu[y], nu_ref[y], 0.0005, 0.01);
    }
    near("slip bottom", r.slip_bottom, 0.146, 0.0005, 0.01);
    near("slip top", r.slip_top, 0.344, 0.0005, 0.015);
    near("slip bottom fit", r.slip_bottom_fit, 0.026, 0.0005, 0.01);
    near("slip top fit", r.slip_top_fit, 0.261, 0.0005, 0.015);
    // Qualitative acceptance (§7.3): monotonic interior, dilute at both walls, steady.
    for (int y = 1; y < 9; ++y) BOOST_TEST(r.rows_.u[y].mean < r.rows_.u[y - 1].mean);
    double nu_max = 0;
    for (const auto& s : r.rows_.nu) nu_max = std::max(nu_max, s.mean);
    BOOST_TEST(r.rows_.nu[0].mean < nu_max);
    BOOST_TEST(r.rows_.nu[9].mean < nu_max);
    BOOST_TEST(r.steady.reached, r.steady.note);
    BOOST_TEST(r.steady.step <= 1000);
    // Event counts per run scale to the prototype's (§6.1: 2.76e6 moves, 1.38e7 collisions per
    // 8.5e6 updates): as rates per grain-step.
    near("moves per update", r.moves, 2.76e6 / 8.5e6, 0.005 / 8.5, 0.01);
    near("grain collisions per update", r.pp, 1.38e7 / 8.5e6, 0.005 / 0.85, 0.05);
}

BOOST_AUTO_TEST_CASE(slip_falls_with_roughness) {
    // §6.2 table, both walls at R, with its settings: 10 000 steps averaged over 2000-9999 (at
    // R = 0 a 3000-step window is too noisy for the top slip: standard error 0.01).
    const double R[6] = {0.0, 0.25, 0.5, 0.65, 0.75, 1.0};
    const double sb[6] = {0.272, 0.198, 0.160, 0.146, 0.140, 0.127};
    const double st[6] = {0.448, 0.416, 0.371, 0.343, 0.324, 0.285};
    double prev = 1.0;
    for (int k = 0; k < 6; ++k) {
        Params p = ci(R[k]);
        p.run.steps = 10000;
        p.run.t_avg_start = 2000;
        p.run.replicas = 1;
        const EnsembleResult r = run_ensemble(p);
        near("slip bottom R=" + std::to_string(R[k]), r.slip_bottom, sb[k], 0.0005, 0.015);
        near("slip top R=" + std::to_string(R[k]), r.slip_top, st[k], 0.0005, 0.015);
        BOOST_TEST(r.slip_bottom.mean < prev);  // strictly decreasing
        prev = r.slip_bottom.mean;
    }
}

BOOST_AUTO_TEST_CASE(rule_switches_move_the_numbers_as_measured) {
    // §6.3 (3000 steps, averaged over 1000-2999): each switch's slips.
    struct Case {
        const char* name;
        void (*set)(Rules&);
        double sb, st;
    };
    const Case cases[] = {
        {"pp_deflect=45", [](Rules& r) { r.pp_deflect = 45; }, 0.130, 0.241},
        {"struck_dir=keep", [](Rules& r) { r.struck_dir = StruckDir::Keep; }, 0.122, 0.255},
        {"wall_speed=by_incidence", [](Rules& r) { r.wall_speed = WallSpeed::ByIncidence; }, 0.156, 0.494},
        {"p_drag=0", [](Rules& r) { r.p_drag = 0; }, 0.196, 0.338},
        {"tf_rounding=ceil", [](Rules& r) { r.tf_rounding = TfRounding::Ceil; }, 0.158, 0.312},
        {"tf_rounding=accumulate", [](Rules& r) { r.tf_rounding = TfRounding::Accumulate; }, 0.152, 0.343},
        {"e_p=1.0", [](Rules& r) { r.e_p = 1.0; }, 0.282, 0.314},
    };
    for (const Case& c : cases) {
        Params p = ci();
        p.run.replicas = 2;
        c.set(p.rules);
        const EnsembleResult r = run_ensemble(p);
        near(std::string(c.name) + " slip bottom", r.slip_bottom, c.sb, 0.0005, 0.01);
        near(std::string(c.name) + " slip top", r.slip_top, c.st, 0.0005, 0.015);
    }
}

BOOST_AUTO_TEST_CASE(vector_mode_profiles) {
    // §6.4, R = 0.65: 10 000 steps averaged over 2000-9999; the profile is the signed <u_p dx>.
    Params p = ci();
    p.rules.mode = Mode::Vector;
    p.run.steps = 10000;
    p.run.t_avg_start = 2000;
    p.run.replicas = 1;
    const EnsembleResult r = run_ensemble(p);
    const double ux_ref[10] = {0.54, 0.32, 0.24, 0.18, 0.14, 0.12, 0.10, 0.08, 0.06, 0.03};  // 2 decimals
    const double nu_ref[10] = {0.792, 0.767, 0.787, 0.813, 0.841, 0.867, 0.889, 0.903, 0.922, 0.918};
    for (int y = 0; y < 10; ++y) {
        near("vector u_x/U row " + std::to_string(y), r.rows_.u[y], ux_ref[y], 0.005, 0.01);
        near("vector nu row " + std::to_string(y), r.rows_.nu[y], nu_ref[y], 0.0005, 0.01);
    }
    near("vector slip bottom", r.slip_bottom, 0.461, 0.0005, 0.01);
    near("vector slip top", r.slip_top, 0.034, 0.0005, 0.015);
    BOOST_TEST(r.steady.reached, r.steady.note);
}
