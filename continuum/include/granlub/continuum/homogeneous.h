// The uniform-shear solution (docs/continuum-model.md §6.1 "Initial guess", §8.4): nu uniform, u linear with slip.
// With adiabatic walls (R6 = R7 = R8 = 0) it is the exact solution; otherwise the initial guess.
//   Lambda^2 f_gamma(nu) = Pi f_mu f_p s^2,   s = -u^' = 1/(1 + 1/k0 + 1/k1),  k = R5 Lambda b5(nu)
// (for equal walls s = 1 - 2 u_s with u_s = 1/(2 + R5 Lambda b5), docs/continuum-model.md §6.1).
#pragma once
#include "granlub/continuum/problem.h"

namespace granlub::continuum {

struct UniformShear {
    double nu = 0;
    double slip_bottom = 0, slip_top = 0;  // u_s/U at each wall
    double shear = 0;                      // -u^'
    double Pi = 0;
    double Lambda = 0;  // H / sigma (Inventory: the gap that holds the grains at nu)
};

// Shear and slips of the uniform state at a given nu.
UniformShear uniform_state(const Problem& p, double nu);
// Load mode: the dense root nu of the energy equation for the problem's Pi (Brent).
// Throws granlub::SolverError when there is none.
UniformShear uniform_shear_load(const Problem& p);
// Inventory mode: the dense root nu with Lambda = inventory / nu.
UniformShear uniform_shear_inventory(const Problem& p);
// Fill mode: the Pi that makes nu = p.nu_mean the uniform solution.
UniformShear uniform_shear_fill(const Problem& p);
// Solution on the mesh from the uniform state.
Solution uniform_solution(const UniformShear& h, int cells);

}  // namespace granlub::continuum
