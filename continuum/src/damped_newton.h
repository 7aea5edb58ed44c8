// The damped Newton iteration and the continuation both finite-volume solvers share (the 1-D gap, fv_solver.cpp,
// and the trough's cross-section, cross_section_solver.cpp; docs/continuum-model.md §6.1):
//   steps limited to |du^| <= 0.5, |ds| <= 3 and |dlambda| <= 1, Armijo backtracking on the max norm,
//   converged below the tolerance, or at the round-off floor (a full step that no longer reduces the residual);
//   continuation in t from an easy problem (t = 0) to the target (t = 1), the step grown after easy solves and
//   halved after hard or failed ones.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include "granlub/continuum/fv_solver.h"

namespace granlub::continuum::detail {

// F (a discretisation) provides, for unknowns X (u^ and s of every node) and the bordering unknown lambda:
//   double evaluate(const X& x, double lam, bool jacobian)  the max-norm residual (infinity when not finite)
//   bool step(X& dx, double& dlam)                           the Newton step of the last evaluate(..., true)
//   void step_sizes(const X& dx, double& du, double& ds)     max |du^| and max |ds| of a step
//   void advance(X& out, const X& x, double a, const X& dx)  out = x + a dx
// `dx` and `xt` are work space shaped like `x`. On return x and lam hold the last iterate.
template <class F, class X>
NewtonReport damped_newton(F& fv, X& x, double& lam, X& dx, X& xt, double tolerance, int max_iterations) {
    NewtonReport rep;
    double norm = fv.evaluate(x, lam, true);
    for (int it = 0;; ++it) {
        rep.iterations = it;
        rep.residual = norm;
        if (norm < tolerance) {
            rep.converged = true;
            break;
        }
        if (it >= max_iterations) {
            rep.why = "Newton did not converge in " + std::to_string(max_iterations) + " iterations";
            break;
        }
        if (!std::isfinite(norm)) {
            rep.why = "the residual is not finite";
            break;
        }
        double dlam = 0;
        if (!fv.step(dx, dlam)) {
            rep.why = "singular Newton matrix";
            break;
        }
        double step_u = 0, step_s = 0;
        fv.step_sizes(dx, step_u, step_s);
        double alpha = std::min({1.0, 0.5 / std::max(step_u, 1e-300), 3.0 / std::max(step_s, 1e-300),
                                 1.0 / std::max(std::abs(dlam), 1e-300)});
        bool accepted = false;
        for (int k = 0; k < 40; ++k) {
            fv.advance(xt, x, alpha, dx);
            if (fv.evaluate(xt, lam + alpha * dlam, false) <= (1.0 - 1e-4 * alpha) * norm) {
                accepted = true;
                break;
            }
            alpha *= 0.5;
        }
        const double step_max = alpha * std::max({step_u, step_s, std::abs(dlam)});
        if (!accepted) {
            if (norm < 1e3 * tolerance) {  // round-off floor
                rep.converged = true;
                break;
            }
            rep.why = "the line search could not reduce the residual";
            break;
        }
        std::swap(x, xt);
        lam += alpha * dlam;
        norm = fv.evaluate(x, lam, true);
        if (step_max < 1e-13 && norm < 1e3 * tolerance) {
            rep.iterations = it + 1;
            rep.residual = norm;
            rep.converged = true;
            break;
        }
    }
    return rep;
}

struct ContinuationReport {
    bool reached = false;  // t = 1 solved
    int steps = 0;
    double t = 0;          // the last t solved
    NewtonReport last;     // the last Newton solve (why it failed, when it stalled)
};

// How a continuation adapts its step: the first step in t, grown by 1.5 after a Newton solve of at most `easy`
// iterations, halved after one of more than `hard` or a failed one.
struct StepPolicy {
    int easy = 4, hard = 8;
    double first = 0.1;
};

// From the solution `s` at t = 0 to t = 1: solve(t, trial) runs Newton on the problem at t from `trial` (a copy of
// the last solution) and returns its report. `total` accumulates the Newton iterations.
template <class Sol, class Solve>
ContinuationReport continuation(Sol& s, const Solve& solve, int max_steps, int& total, const StepPolicy& policy = {}) {
    ContinuationReport c;
    double dt = policy.first;
    while (c.t < 1.0) {
        if (++c.steps > max_steps || dt < 1e-5) return c;
        const double tn = std::min(1.0, c.t + dt);
        Sol trial = s;
        c.last = solve(tn, trial);
        total += c.last.iterations;
        if (c.last.converged) {
            s = std::move(trial);
            c.t = tn;
            if (c.last.iterations <= policy.easy) dt *= 1.5;
            else if (c.last.iterations > policy.hard) dt *= 0.5;  // hard step: go slower next time
        } else {
            dt *= 0.5;
        }
    }
    c.reached = true;
    return c;
}

}  // namespace granlub::continuum::detail
