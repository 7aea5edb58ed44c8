// Granular pressure of Lun, Savage, Jeffrey & Chepurniy 1984 (LSJC), dimensionless:
//   p = rho_p T f_p(nu),  f_p = nu [1 + 4 eta nu g0]          (docs/continuum-model.md §2.1; MFiX GT_PDE_LUN)
// with eta = (1 + e_p)/2. f_p' uses the analytic g0' (§2.4).
#pragma once

namespace granlub::continuum::closures {

template <class S>
S f_p(S nu, S g, double eta) {
    return nu * (1.0 + 4.0 * eta * nu * g);
}

// d f_p / d nu = 1 + 8 eta nu g0 + 4 eta nu^2 g0'
template <class S>
S df_p(S nu, S g, S dg, double eta) {
    return 1.0 + 8.0 * eta * nu * g + 4.0 * eta * nu * nu * dg;
}

}  // namespace granlub::continuum::closures
