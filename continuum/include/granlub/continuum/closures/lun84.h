// The LSJC 1984 closure set at one solid fraction, and the combinations the Couette problem needs
// after eliminating T with p_yy = P (docs/continuum-model.md §3):
//   G = f_k f_p'/f_p - f_phi,   M = f_mu f_p^{-1/2},   K = G f_p^{-3/2},   C = f_gamma f_p^{-3/2}
//   (M u')' = 0,   (K nu')' = Pi M u'^2 - Lambda^2 C        (dimensionless, §5)
#pragma once
#include <memory>

#include "granlub/continuum/closures/conductivity.h"
#include "granlub/continuum/closures/dissipation.h"
#include "granlub/continuum/closures/pressure.h"
#include "granlub/continuum/closures/viscosity.h"
#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {

struct Lun84Params {
    double restitution = 0.9;  // e_p
    double alpha = 1.0;        // viscosity factor c_a = (2 + alpha)/3; 1 = original LSJC
    bool dufour = true;        // include the grad-nu heat-flux term f_phi (§2.2)
    double eta() const { return 0.5 * (1.0 + restitution); }
};

template <class S>
struct Lun84State {
    S nu, g, dg, fp, dfp, fmu, fk, fphi, fgam, G;
    S M() const { using std::sqrt; return fmu / sqrt(fp); }
    S K() const { using std::sqrt; return G / (fp * sqrt(fp)); }
    S C() const { using std::sqrt; return fgam / (fp * sqrt(fp)); }
};

template <class S>
Lun84State<S> lun84_state(const Lun84Params& p, S nu, S g, S dg) {
    namespace c = closures;
    const double eta = p.eta();
    Lun84State<S> s{};
    s.nu = nu;
    s.g = g;
    s.dg = dg;
    s.fp = c::f_p(nu, g, eta);
    s.dfp = c::df_p(nu, g, dg, eta);
    s.fmu = c::f_mu(nu, g, eta, p.alpha);
    s.fk = c::f_kappa(nu, g, eta);
    s.fphi = p.dufour ? c::f_phi(nu, g, dg, eta) : S(0.0);
    s.fgam = c::f_gamma(nu, g, eta);
    s.G = s.fk * s.dfp / s.fp - s.fphi;
    return s;
}

// The closure set of one case: LSJC with the chosen g0.
class Closures {
public:
    Closures(Lun84Params p, std::shared_ptr<const RadialDistribution> g0) : p_(p), g0_(std::move(g0)) {}
    // All functions at nu, with exact d/dnu in the dual parts.
    Lun84State<D1> state(D1 nu) const { return lun84_state(p_, nu, g0_->g0(nu), g0_->dg0(nu)); }
    Lun84State<D1> state(double nu) const { return state(D1::variable(nu, 0)); }
    const Lun84Params& params() const { return p_; }
    const RadialDistribution& g0() const { return *g0_; }
    double numax() const { return g0_->numax(); }
    double cap() const { return g0_->cap(); }

private:
    Lun84Params p_;
    std::shared_ptr<const RadialDistribution> g0_;
};

}  // namespace granlub::continuum
