#include "granlub/continuum/homogeneous.h"

#include <cmath>
#include <sstream>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "granlub/error.h"

namespace granlub::continuum {

UniformShear uniform_state(const Problem& p, double nu) {
    const auto k = [&](const WallBC& w) {
        return w.params.r5 * p.Lambda * wall_coefficients(p, w, nu).b5.v;
    };
    const double k0 = k(p.bottom), k1 = k(p.top);
    UniformShear h;
    h.nu = nu;
    h.shear = 1.0 / (1.0 + 1.0 / k0 + 1.0 / k1);  // -u^' ; the slips are u^'/k at each wall
    h.slip_bottom = h.shear / k0;
    h.slip_top = h.shear / k1;
    h.Pi = p.Pi;
    h.Lambda = p.Lambda;
    return h;
}

namespace {
// Production minus dissipation of the uniform state, divided by f_p f_mu (positive between the
// dilute and the dense root).
double excess(const Problem& p, double nu) {
    const auto s = p.closures->state(nu);
    const double g = uniform_state(p, nu).shear;
    return p.Lambda * p.Lambda * s.fgam.v / (s.fp.v * s.fmu.v) - p.Pi * g * g;
}
}  // namespace

namespace {
// The problem at solid fraction nu: Load as given; Inventory with the gap that holds the grains.
Problem at_nu(const Problem& p, double nu) {
    Problem q = p;
    if (p.mode == Mode::Inventory) q.Lambda = p.inventory / nu;
    return q;
}
double excess_at(const Problem& p, double nu) { return excess(at_nu(p, nu), nu); }
}  // namespace

UniformShear uniform_shear_inventory(const Problem& p) { return uniform_shear_load(p); }

UniformShear uniform_shear_load(const Problem& p) {
    // Scan down from the cap in logit space for the dense sign change (docs/continuum-model.md §6.1: the dense
    // root; the dilute root is the spurious "empty channel" side, §6.3). Inventory: the gap follows nu.
    const double cap = p.closures->cap();
    const auto nu_of = [cap](double s) { return cap / (1.0 + std::exp(-s)); };
    double s_hi = 30.0, f_hi = excess_at(p, nu_of(s_hi));
    double s_lo = s_hi, f_lo = f_hi;
    bool bracket = false;
    for (double s = 30.0 - 0.1; s > -8.0; s -= 0.1) {
        const double f = excess_at(p, nu_of(s));
        if ((f > 0) != (f_hi > 0)) {
            s_lo = s;
            f_lo = f;
            bracket = true;
            break;
        }
        s_hi = s;
        f_hi = f;
    }
    if (!bracket) {
        std::ostringstream m;
        m << "no uniform-shear state exists for Pi = rho U^2/P = " << p.Pi;
        if (p.mode == Mode::Inventory) m << " and grains per wall area / d = " << p.inventory;
        else m << " and Lambda = H/d = " << p.Lambda;
        if (f_hi > 0)
            m << " below the solid-fraction cap " << cap << " (dissipation exceeds shear work even there)"
              << ": lower the normal stress or raise the speed";
        else
            m << " (shear work exceeds dissipation at every solid fraction): raise the normal stress or lower the speed";
        throw SolverError(m.str());
    }
    (void)f_lo;
    struct Ctx {
        const Problem* p;
        double cap;
    } ctx{&p, cap};
    gsl_function F;
    F.function = [](double s, void* v) {
        auto* c = static_cast<Ctx*>(v);
        return excess_at(*c->p, c->cap / (1.0 + std::exp(-s)));
    };
    F.params = &ctx;
    gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(solver, &F, s_lo, s_hi);
    double root = 0.5 * (s_lo + s_hi);
    for (int it = 0; it < 200; ++it) {
        gsl_root_fsolver_iterate(solver);
        root = gsl_root_fsolver_root(solver);
        const double a = gsl_root_fsolver_x_lower(solver), b = gsl_root_fsolver_x_upper(solver);
        if (gsl_root_test_interval(a, b, 1e-15, 1e-14) == GSL_SUCCESS) break;
    }
    gsl_root_fsolver_free(solver);
    const double nu = nu_of(root);
    return uniform_state(at_nu(p, nu), nu);
}

UniformShear uniform_shear_fill(const Problem& p) {
    UniformShear h = uniform_state(p, p.nu_mean);
    const auto s = p.closures->state(p.nu_mean);
    h.Pi = p.Lambda * p.Lambda * s.fgam.v / (s.fp.v * s.fmu.v * h.shear * h.shear);
    return h;
}

Solution uniform_solution(const UniformShear& h, int cells) {
    Solution s;
    const auto n = static_cast<std::size_t>(cells) + 1;
    s.y.resize(n);
    s.u.resize(n);
    s.nu.assign(n, h.nu);
    for (std::size_t i = 0; i < n; ++i) {
        s.y[i] = static_cast<double>(i) / cells;
        s.u[i] = 1.0 - h.slip_bottom - h.shear * s.y[i];
    }
    s.Pi = h.Pi;
    s.Lambda = h.Lambda;
    return s;
}

}  // namespace granlub::continuum
