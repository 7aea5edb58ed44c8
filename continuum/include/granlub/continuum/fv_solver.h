// Vertex-centred finite volumes + Newton in logit-nu (docs/continuum-model.md §6.1).
//   unknowns (u^_i, s_i) interleaved, nu_i = cap / (1 + exp(-s_i)); in Fill mode also lambda = ln Pi
//   face coefficients are node averages; wall half-cells take their fluxes from the wall conditions
//   exact Jacobian: node closures in Dual<1>, the stencil in Dual<7> (§2.4)
//   linear algebra: block-tridiagonal (2x2 Eigen blocks) LU, bordered for the Fill constraint
#pragma once
#include <string>

#include "granlub/continuum/problem.h"

namespace granlub::continuum {

struct NewtonReport {
    bool converged = false;
    int iterations = 0;
    double residual = 0;
    std::string why;  // when not converged
};

// Newton from `s` (which must be on a mesh of settings.cells cells); `s` holds the last iterate.
NewtonReport newton_fv(const Problem& p, const SolverSettings& settings, Solution& s);

// Full FV solve: uniform-shear guess, Newton, and automatic continuation (in ln Pi or mean nu,
// and ln Lambda) when Newton fails. Throws granlub::SolverError with the last residual.
Solution solve_fv(const Problem& p, const SolverSettings& settings);

// The largest difference between the exact Jacobian at a Load-mode state and central differences with `step` in
// u^ and in the logit unknown, relative to max(1, |entry|); for tests (§2.4).
double fv_jacobian_defect(const Problem& p, const Solution& s, double step);

// The FV residual (flux balance per control volume) of a solution, max norm; for tests.
double fv_residual_norm(const Problem& p, const Solution& s);

}  // namespace granlub::continuum
