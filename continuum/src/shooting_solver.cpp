// Shooting cross-check (docs/continuum-model.md §6.2). See shooting_solver.h.
#include "granlub/continuum/shooting_solver.h"

#include <cmath>
#include <sstream>

#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_odeiv2.h>

#include "gsl_quiet.h"
#include "granlub/continuum/homogeneous.h"
#include "granlub/continuum/walls/wall_condition.h"
#include "granlub/error.h"

namespace granlub::continuum {
namespace {

struct Shooter {
    const Problem* p;
    double cap;
    double Pi;
    bool fill, sym;
};

// y = (u^, u^', nu, nu', int nu dy)
int rhs(double /*y*/, const double z[], double dz[], void* params) {
    const auto* sh = static_cast<const Shooter*>(params);
    const double nu = z[2];
    if (!(nu > 0 && nu < sh->cap)) return GSL_EBADFUNC;
    const auto c = node_coefficients(*sh->p->closures, nu);
    const double B1 = c.dM / c.M, B2 = c.dK / c.K, b3 = c.C / c.K, b4 = c.M / c.K;
    const double L = sh->p->Lambda;
    dz[0] = z[1];
    dz[1] = -B1 * z[3] * z[1];
    dz[2] = z[3];
    dz[3] = -B2 * z[3] * z[3] - L * L * b3 + sh->Pi * b4 * z[1] * z[1];
    dz[4] = nu;
    return GSL_SUCCESS;
}

// Initial state at y^ = 0 from (u^(0), nu(0)) and the bottom wall conditions.
void wall_state(const Shooter& sh, double u0, double nu0, double z[5]) {
    const Problem& p = *sh.p;
    const auto& w = p.bottom.params;
    const auto b = wall_coefficients(p, p.bottom, nu0);
    const auto g = wall_gradients(w, b, 1.0 - u0, p.Lambda, sh.Pi);  // n = +y^
    z[0] = u0;
    z[1] = g.du;
    z[2] = nu0;
    z[3] = g.dnu;
    z[4] = 0;
}

struct Ctx {
    Shooter sh;
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver* drv;
};

int shoot(const gsl_vector* x, void* params, gsl_vector* f) {
    auto* c = static_cast<Ctx*>(params);
    Shooter& sh = c->sh;
    const Problem& p = *sh.p;
    const double u0 = gsl_vector_get(x, 0);
    const double nu0 = sh.cap / (1.0 + std::exp(-gsl_vector_get(x, 1)));
    sh.Pi = sh.fill ? std::exp(gsl_vector_get(x, 2)) : p.Pi;
    double z[5];
    wall_state(sh, u0, nu0, z);
    gsl_odeiv2_driver_reset(c->drv);
    double t = 0;
    const double end = sh.sym ? 0.5 : 1.0;
    const int rc = gsl_odeiv2_driver_apply(c->drv, &t, end, z);
    if (rc != GSL_SUCCESS) {
        // The trajectory left (0, cap): a large residual makes the trust region shrink.
        for (std::size_t k = 0; k < f->size; ++k) gsl_vector_set(f, k, 1e3);
        return GSL_SUCCESS;
    }
    if (sh.sym) {
        gsl_vector_set(f, 0, z[0] - 0.5);
        gsl_vector_set(f, 1, z[3]);
        if (sh.fill) gsl_vector_set(f, 2, 2.0 * z[4] - p.nu_mean);
    } else {
        const auto& w = p.top.params;
        const auto b = wall_coefficients(p, p.top, z[2]);
        const auto g = wall_gradients(w, b, -z[0], p.Lambda, sh.Pi);  // n = -y^: y^-gradients are -g
        gsl_vector_set(f, 0, z[1] + g.du);
        gsl_vector_set(f, 1, z[3] + g.dnu);
        if (sh.fill) gsl_vector_set(f, 2, z[4] - p.nu_mean);
    }
    return GSL_SUCCESS;
}

}  // namespace

Solution solve_shooting(const Problem& p, const SolverSettings& st, const Solution* guess) {
    // its ODE form has no contact stress (docs/continuum-model.md §2.9); the case's settings refuse it, so does this
    if (p.closures->contact().active())
        throw Error("solve_shooting: the shooting cross-check has no contact stress; use solve_fv");
    detail::gsl_quiet();
    Ctx c{};
    c.sh = {&p, p.closures->cap(), p.Pi, p.mode == Mode::Fill, p.symmetric()};
    c.sys = {rhs, nullptr, 5, &c.sh};
    c.drv = gsl_odeiv2_driver_alloc_y_new(&c.sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-13, 1e-11);

    Solution start;
    if (guess) {
        start = *guess;
    } else if (!p.symmetric()) {
        // Unequal walls: start from the symmetric problem with the bottom wall on both sides.
        Problem q = p;
        q.top = p.bottom;
        start = solve_shooting(q, st);
    } else {
        start = uniform_solution(p.mode == Mode::Load ? uniform_shear_load(p) : uniform_shear_fill(p), 2);
    }
    const std::size_t dim = c.sh.fill ? 3 : 2;
    gsl_vector* x = gsl_vector_alloc(dim);
    const double nu0 = start.nu.front();
    gsl_vector_set(x, 0, start.u.front());
    gsl_vector_set(x, 1, std::log(nu0 / (c.sh.cap - nu0)));
    if (c.sh.fill) gsl_vector_set(x, 2, std::log(start.Pi));
    gsl_multiroot_function F{shoot, dim, &c};
    gsl_multiroot_fsolver* solver = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, dim);
    int status = gsl_multiroot_fsolver_set(solver, &F, x);
    int iter = 0;
    double res = 0;
    while (status == GSL_SUCCESS && iter < 200) {
        ++iter;
        status = gsl_multiroot_fsolver_iterate(solver);
        res = 0;
        for (std::size_t k = 0; k < dim; ++k) res = std::max(res, std::abs(gsl_vector_get(solver->f, k)));
        if (gsl_multiroot_test_residual(solver->f, 1e-11) == GSL_SUCCESS) break;
    }
    // hybrids stops with "no progress" at the integrator's round-off floor; accept that floor.
    const bool ok = res < 1e-11 || ((status == GSL_ENOPROG || status == GSL_ENOPROGJ) && res < 1e-8);
    gsl_vector_memcpy(x, solver->x);
    gsl_multiroot_fsolver_free(solver);
    if (!ok) {
        gsl_vector_free(x);
        gsl_odeiv2_driver_free(c.drv);
        std::ostringstream m;
        m << "shooting did not converge after " << iter << " iterations (residual " << res << ", "
          << gsl_strerror(status) << "); use method = \"fv\" (the shooting cross-check is ill-conditioned for large gaps)";
        throw SolverError(m.str());
    }
    // Tabulate the converged trajectory on the FV mesh (mirrored for symmetric walls).
    Solution s;
    const auto n = static_cast<std::size_t>(st.cells) + 1;
    s.y.resize(n);
    s.u.resize(n);
    s.nu.resize(n);
    const double u0 = gsl_vector_get(x, 0);
    const double nu_0 = c.sh.cap / (1.0 + std::exp(-gsl_vector_get(x, 1)));
    c.sh.Pi = c.sh.fill ? std::exp(gsl_vector_get(x, 2)) : p.Pi;
    gsl_vector_free(x);
    double z[5];
    wall_state(c.sh, u0, nu_0, z);
    gsl_odeiv2_driver_reset(c.drv);
    double t = 0;
    for (std::size_t i = 0; i < n; ++i) {
        s.y[i] = static_cast<double>(i) / st.cells;
        if (c.sh.sym && 2 * i > n - 1) {
            const std::size_t j = n - 1 - i;
            s.u[i] = 1.0 - s.u[j];
            s.nu[i] = s.nu[j];
            continue;
        }
        if (s.y[i] > t) gsl_odeiv2_driver_apply(c.drv, &t, s.y[i], z);
        s.u[i] = z[0];
        s.nu[i] = z[2];
    }
    gsl_odeiv2_driver_free(c.drv);
    s.Pi = c.sh.Pi;
    s.iterations = iter;
    s.residual = res;
    return s;
}

}  // namespace granlub::continuum
