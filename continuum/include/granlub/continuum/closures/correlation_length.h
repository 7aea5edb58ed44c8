// Correlation length of extended kinetic theory (docs/continuum-model.md §2.7): the collisional
// dissipation is divided by L* = L/d >= 1, the size of the clusters whose correlated velocities
// dissipate less than molecular chaos assumes (Jenkins 2006, 2007).
//   jenkins2007: L* = max{1, (1/2) [30 (1 - e) nu^2 g0 / (1 + pi/12)]^{1/3}}
//   [SRC: Jenkins 2007 (Granular Matter 10, 47) as coded in SedFoam kineticTheoryModel.C (the first
//   version, kept there as a comment); the paper's own equation not read. L* > 1 only above
//   nu ~ 0.5 at e = 0.9.] e is e_p, as SedFoam has it.
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

}  // namespace granlub::continuum::closures
