// Correlation length of extended kinetic theory (docs/continuum-model.md §2.7): the collisional
// dissipation is divided by L* = L/d >= 1, the size of the clusters whose correlated velocities
// dissipate less than molecular chaos assumes (Jenkins 2006, 2007).
//   jenkins2007: L* = max{1, (1/2) [30 (1 - e) nu^2 g0 / (1 + pi/12)]^{1/3}}
//   [SRC: Jenkins 2007 (Granular Matter 10, 47) as coded in SedFoam kineticTheoryModel.C (the first
//   version, kept there as a comment); the paper's own equation not read. L* > 1 only above
//   nu ~ 0.5 at e = 0.9.] e is e_p, as SedFoam has it.
//   jenkins_berzi: the later form, proportional to the shear rate over the fluctuation speed,
//     L* = max{1, (c/2) [2J/(15(1 - e^2))]^{1/2} (d gdot/T^{1/2}) G^{1/3}},  G = nu g0,
//     with a constant c of order one fitted to simulations (Jenkins & Berzi 2010, Berzi, di Prisco &
//     Vescovi 2011) [ASSUMPTION: recalled, the papers not read; c is an input, key
//     correlation_constant]. Taken at its homogeneous-shear value, where production = dissipation gives
//     (d gdot/T^{1/2})^2 = f_gamma1/(f_mu L*) with f_mu = 8 nu G J/(5 sqrt(pi)) and
//     f_gamma1 = (12/sqrt(pi)) (1 - e_eff^2) nu G (L* = 1), so that J cancels [DERIVED]:
//       L*^3 = (c^2/4) (1 - e_eff^2)/(1 - e^2) G^{2/3},   L* = max{1, [(c^2/4) r]^{1/3} G^{2/9}}
//     (SedFoam's current kineticTheoryModel.C has the same G^{2/9} with a coefficient of its own). Using the
//     homogeneous value at the local nu in the Couette problem, where walls heat the grains, is
//     [ASSUMPTION]: it keeps L* a function of nu alone, as jenkins2007.
// The max is taken exactly (a kink where L* leaves 1; Newton copes, the derivative is one-sided).
#pragma once
#include <cmath>
#include <numbers>

#include "granlub/continuum/dual.h"

namespace granlub::continuum::closures {

template <class S>
S correlation_length_jenkins2007(S nu, S g, double e) {
    using std::cbrt;
    const S L = 0.5 * cbrt(30.0 * (1.0 - e) * nu * nu * g / (1.0 + std::numbers::pi / 12.0));
    return value(L) > 1.0 ? L : S(1.0);
}

// r = (1 - e_eff^2)/(1 - e_p^2), the friction factor of the dissipation (1 when frictionless).
template <class S>
S correlation_length_jenkins_berzi(S nu, S g, double c, double r) {
    using std::pow;
    const S L = std::cbrt(0.25 * c * c * r) * pow(nu * g, 2.0 / 9.0);
    return value(L) > 1.0 ? L : S(1.0);
}

}  // namespace granlub::continuum::closures
