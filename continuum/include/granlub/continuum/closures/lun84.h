// The LSJC 1984 closure set (docs/continuum-model.md §2.1): pressure.h, viscosity.h, conductivity.h,
// dissipation.h at one solid fraction. The family `lun84` of the closure registry (src/closures/lun84.cpp).
#pragma once
#include "granlub/continuum/closures/conductivity.h"
#include "granlub/continuum/closures/dissipation.h"
#include "granlub/continuum/closures/family.h"
#include "granlub/continuum/closures/pressure.h"
#include "granlub/continuum/closures/viscosity.h"

namespace granlub::continuum {

// The functions LSJC share with Garzo & Dufty: pressure f_p, f_p' and the e_p-dissipation f_gamma.
template <class S>
ClosureState<S> lsjc_pressure_and_dissipation(const ClosureParams& p, S nu, S g, S dg) {
    namespace c = closures;
    const double eta = p.eta();
    ClosureState<S> s{};
    s.nu = nu;
    s.g = g;
    s.dg = dg;
    s.fp = c::f_p(nu, g, eta);
    s.dfp = c::df_p(nu, g, dg, eta);
    s.fgam = c::f_gamma(nu, g, eta);
    return s;
}

// Every function but G (formed by Closures once e_eff and L* are applied).
template <class S>
ClosureState<S> lun84_state(const ClosureParams& p, S nu, S g, S dg) {
    namespace c = closures;
    const double eta = p.eta();
    ClosureState<S> s = lsjc_pressure_and_dissipation(p, nu, g, dg);
    s.fmu = c::f_mu(nu, g, eta, p.alpha);
    s.fk = c::f_kappa(nu, g, eta);
    s.fphi = p.dufour ? c::f_phi(nu, g, dg, eta) : S(0.0);
    return s;
}

}  // namespace granlub::continuum
