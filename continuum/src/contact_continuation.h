// The contact stress's continuation (docs/continuum-model.md §2.9), shared by the 1-D gap (fv_solver.cpp) and the
// trough's cross-section (cross_section_solver.cpp): the contact pressure at full strength without its shear
// (mu_c = 0; the solver's own kinetic solve, or if that fails from the kinetic solution with the coefficient scaled
// by t from 0 to 1, the cap nu_P following; the cross-section starts there, ContactPath), then the contact shear,
// mu_c scaled by t from 0 to 1.
#pragma once
#include <algorithm>
#include <sstream>
#include <string>

#include "damped_newton.h"
#include "granlub/continuum/closures/closure_set.h"
#include "granlub/error.h"

namespace granlub::continuum::detail {

// The closures of `c` with the contact stress `cs` scaled: its coefficient (Fr) by `coefficient`, mu_c by `friction`.
inline std::shared_ptr<const Closures> scaled_contact(const Closures& c, const ContactStress& cs, double coefficient,
                                                      double friction) {
    ContactStress s = cs;
    s.coefficient *= coefficient;
    s.friction *= friction;
    return std::make_shared<Closures>(c.with_contact(s));
}

// How the continuation starts, its first step in t, and where a start sits below the next problem's cap nu_P (the
// cap moves with t, and a start at the cap has a singular Jacobian in the logit unknown): at least `relative` x nu_P
// and `of_range` x (nu_P - nu_min) below it.
struct ContactPath {
    bool pressure_at_once = true;  // the kinetic solve with the full contact pressure first, the scaled one if it fails
    double first = 1.0;            // the whole way is tried first (it is enough on the 1-D cases measured)
    int hard = 12;                 // a step that needed more Newton iterations halves the next one
    double relative = 1e-6, of_range = 0;
};

// scaled(coefficient, friction): the problem with the contact stress scaled (scaled_contact); kinetic(problem): the
// solver's solve without the contact continuation (throws SolverError); newton(problem, solution): Newton from the
// solution; cap(problem): the logit cap of the problem's closures. `target` names the operating point in messages.
template <class Sol, class Scaled, class Kinetic, class Newton, class Cap>
Sol contact_continuation(const ContactStress& cs, const Scaled& scaled, const Kinetic& kinetic, const Newton& newton,
                         const Cap& cap, int max_steps, const std::string& target, const ContactPath& path = {}) {
    // Newton's iterations here are 5-7 at most steps (the residual's floor is near the tolerance): "easy" is 6; the
    // step is halved on failure.
    const StepPolicy policy{6, path.hard, path.first};
    Sol s;
    int total = 0, steps = 0;
    const auto continue_in = [&](const auto& at, const char* what) {
        const auto c = continuation(
            s,
            [&](double t, Sol& trial) {
                const auto q = at(t);
                const double nu_P = cap(q);
                const double top = std::min(nu_P * (1 - path.relative), nu_P - path.of_range * (nu_P - cs.onset));
                for (double& nu : trial.nu) nu = std::min(nu, top);
                return newton(q, trial);
            },
            max_steps, total, policy);
        steps += c.steps;
        if (!c.reached) {
            std::ostringstream m;
            m << "the contact stress's continuation in " << what << " (§2.9) stalled before " << target << " after "
              << steps << " steps (last Newton residual " << c.last.residual << ": " << c.last.why
              << "); try a larger [continuum] max_continuation_steps or other contact_* constants";
            throw SolverError(m.str());
        }
    };
    const auto from_kinetic = [&] {
        s = kinetic(scaled(0.0, 0.0));
        total = s.iterations;
        steps = s.continuation_steps;
        continue_in([&](double t) { return scaled(t, 0.0); }, "its pressure");
    };
    if (path.pressure_at_once) {
        try {
            s = kinetic(scaled(1.0, 0.0));
            total = s.iterations;
            steps = s.continuation_steps;
        } catch (const SolverError&) {
            from_kinetic();
        }
    } else {
        from_kinetic();
    }
    if (cs.friction > 0) continue_in([&](double t) { return scaled(1.0, t); }, "its friction");
    s.iterations = total;
    s.continuation_steps = steps;
    return s;
}

}  // namespace granlub::continuum::detail
