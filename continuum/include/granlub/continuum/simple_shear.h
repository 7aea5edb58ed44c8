// Homogeneous simple shear of the closures (docs/continuum-model.md §8.3, §8.6): without walls production equals
// dissipation, mu_v gamma_dot^2 = gamma, so with p = P
//   T/(d gamma_dot)^2 = f_mu/f_gamma,   mu = tau/p = sqrt(f_mu f_gamma)/f_p,   I = gamma_dot d/sqrt(P/rho_p) = sqrt(f_gamma/(f_mu f_p))
// (f_gamma with e_eff and L*, as the solver has it; with a contact stress fp is fpk/(1 - p_c/P) and mu gains
// mu_c p_c/P, §2.9). The bulk rheology mu(I), nu(I) the Couette solutions are
// measured against: what the walls add or take is the solution's mu over this one at its own mid-gap I.
#pragma once
#include "granlub/continuum/closures/closure_set.h"

namespace granlub::continuum {

struct SimpleShear {
    double nu = 0;
    double inertial = 0;       // I
    double stress_ratio = 0;   // mu = tau/p
    double temperature = 0;    // T/(d gamma_dot)^2
};

// The state at a solid fraction.
SimpleShear simple_shear_at_nu(const Closures& c, double nu);
// The dense state at an inertial number: I(nu) rises from 0 in the dilute limit to a maximum and falls to 0 at
// the closures' cap; this is the root above the maximum. Throws granlub::SolverError when I exceeds the maximum.
SimpleShear simple_shear_at_inertial(const Closures& c, double inertial);

}  // namespace granlub::continuum
