// Independent cross-check: shooting on the ODE form (docs/continuum-model.md §6.2), the papers' "double loop" as a
// multidimensional Newton (gsl_multiroot hybrids) around gsl_odeiv2 rk8pd:
//   u^'' = -B1 nu' u^',   nu'' = -B2 nu'^2 - Lambda^2 b3 + Pi b4 u^'^2
//   B1 = d ln M/dnu, B2 = d ln K/dnu, b3 = f_gamma/G, b4 = f_mu f_p/G
// Unknowns (u^(0), logit nu(0)) [+ ln Pi in Fill mode]; symmetric walls integrate to y^ = 1/2
// (residuals u^(1/2) - 1/2, nu'(1/2)), otherwise to y^ = 1 with the top wall conditions.
// Ill-conditioned for large Lambda: use only as a cross-check at small gaps (§6.2).
#pragma once
#include "granlub/continuum/problem.h"

namespace granlub::continuum {

// `guess` (optional) seeds the unknowns; otherwise the uniform-shear state. Throws
// granlub::SolverError when the root finder fails.
Solution solve_shooting(const Problem& p, const SolverSettings& settings, const Solution* guess = nullptr);

}  // namespace granlub::continuum
