// The dimensionless GKL Couette problem (docs/continuum-model.md §5) and its solution.
//   y^ = y/H, u^ = u/U, Lambda = H/sigma, Pi = rho_p U^2 / P_y
//   (M u^')' = 0,   (K nu')' = Pi M u^'^2 - Lambda^2 C                       (§3, §5)
//   y^ = 0 (moving):  u^' = -R5 Lambda b5 (1 - u^)
//                     nu' = -[R6 Lambda b6 + R7 Lambda Pi b7 (1-u^)^2 + W Pi b8 (1-u^) u^']
//   y^ = 1 (fixed):   u^' = -R5 Lambda b5 u^
//                     nu' = +R6 Lambda b6 + R7 Lambda Pi b7 u^2 + W Pi b8 u^ u^'
// (S&T 2001 Eqs. 13-15 with the sign table of §1; W = R8 in their GKL form, 1 with the slip work returned whole:
// walls/wall_condition.h.)
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "granlub/continuum/closures/closure_set.h"
#include "granlub/continuum/walls/wall_family.h"

namespace granlub::continuum {

enum class Mode {
    Load,  // P_y given (Pi known), mean nu out (S&T)
    Fill,  // mean nu given, Pi (hence P_y) out: one extra unknown and the mass constraint
    // P_y given (Pi known) and the grains per wall area (inventory = integral of nu dy / sigma), the gap
    // Lambda out: one extra unknown and the mass constraint (the particle solvers' question, §5.1)
    Inventory,
};

struct WallBC {
    std::shared_ptr<const WallFamily> family;
    WallParams params;
};

struct Problem {
    std::shared_ptr<const Closures> closures;
    double Lambda = 0;   // H / sigma
    double Pi = 0;       // rho_p U^2 / P_y (Load: given; Fill: output)
    double nu_mean = 0;  // target mean solid fraction (Fill)
    double inventory = 0;  // Lambda * mean nu: grains per wall area over sigma (Inventory)
    Mode mode = Mode::Load;
    WallBC bottom, top;  // y^ = 0 moving, y^ = 1 fixed

    bool symmetric() const;  // same family and parameters at both walls
};

// Node values on the uniform mesh y^_i = i/N, i = 0..N.
struct Solution {
    std::vector<double> y, u, nu;
    double Pi = 0;
    double Lambda = 0;            // H / sigma: the problem's, or the solved gap (Inventory)
    int iterations = 0;           // Newton (FV) or multiroot (shooting) iterations, all stages
    double residual = 0;          // final max-norm residual
    int continuation_steps = 0;   // 0 when the direct solve converged
    std::size_t nodes() const { return y.size(); }
};

struct SolverSettings {
    int cells = 200;
    double tolerance = 1e-10;         // max-norm of the FV flux-balance residual
    int max_iterations = 50;          // Newton iterations per solve
    int max_continuation_steps = 200;
};

// Scalar outputs of a solution, dimensionless (§5 "Outputs").
struct Observables {
    double nu_mean = 0, nu_centre = 0, nu_bottom = 0, nu_top = 0;
    double slip_bottom = 0, slip_top = 0;  // u_s/U: 1 - u^(0) and u^(1), both >= 0
    double du_bottom = 0, du_top = 0;      // u^' at the walls (from the wall conditions)
    double tau_bottom = 0, tau_top = 0;    // |tau| / P_y = (sqrt(Pi)/Lambda) M |u^'|
    double T_bottom = 0, T_top = 0, T_centre = 0;  // T / (P_y/rho_p) = 1/f_p
    double nu_max_node = 0;                // largest nu (CS may exceed nu_max)
};

// Node closures: M, K, C and their nu-derivatives.
struct NodeCoefficients {
    double M, dM, K, dK, C, dC;
};
// `pressure` = p/P_y (Closures::state): 1 but on the cross-section with body forces.
NodeCoefficients node_coefficients(const Closures& c, double nu, double pressure = 1.0);

// Wall coefficients at a wall node (under p^ = `pressure`, as node_coefficients), and u^' there from the momentum
// wall condition.
WallCoefficients wall_coefficients(const Problem& p, const WallBC& w, double nu, double pressure = 1.0);
double wall_du(const Problem& p, bool top, double u, double nu);

// The problem with the solution's Pi and Lambda (the solved unknowns of Fill and Inventory), as Load:
// what observe() and energy_balance_defect() evaluate.
Problem solved_problem(const Problem& p, const Solution& s);

Observables observe(const Problem& p, const Solution& s);

// The mechanical energy budget of a solution per unit wall area, in units of P_y U (§8.5):
//   wall work tau U = bulk dissipation int gamma dy + wall dissipation at both walls
// where a wall dissipates its collisional terms (R6, R7) and the part 1 - W of the slip work that the
// energy wall condition does not return to the flow. Trapezoid rule: O(h^2) for the FV solution.
struct EnergyBudget {
    double wall_work = 0, bulk_dissipation = 0, wall_dissipation = 0;
    // wall_dissipation's two parts: the collisional terms and the slip work the condition does not return
    double wall_collisional = 0, wall_unreturned_slip_work = 0;
    // the contact stress's work (§2.9), dissipated in the contacts, in the bulk and at the walls (0 without one)
    double contact_dissipation = 0;
    double relative_defect() const {
        return (wall_work - bulk_dissipation - wall_dissipation - contact_dissipation) / wall_work;
    }
};
EnergyBudget energy_budget(const Problem& p, const Solution& s);

// Global fluctuation-energy balance (§8.5): int S dy - [K nu']_0^1, with S by the trapezoid
// rule and u^' by central differences; O(h^2) for the FV solution.
double energy_balance_defect(const Problem& p, const Solution& s);

}  // namespace granlub::continuum
