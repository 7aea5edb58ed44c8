// Fluctuation-energy conductivities of LSJC 1984 (docs/continuum-model.md §2.1; MFiX GT_PDE_LUN):
//   q_y = -kappa dT/dy - kappa_phi dnu/dy,  kappa = rho_p sigma T^{1/2} f_k,
//   kappa_phi = rho_p sigma T^{3/2} f_phi
//   k*    = 75 sqrt(pi) / (48 eta (41 - 33 eta))
//   f_k   = k*/g { [1 + 12/5 eta nu g][1 + 12/5 eta^2 (4 eta - 3) nu g] + 64/(25 pi) (41 - 33 eta)(eta nu g)^2 }
//   f_phi = k*/g (12/5) eta (eta - 1)(2 eta - 1) [1 + 12/5 eta nu g] (nu g' + 2 g)     (<= 0 for e < 1)
// The grad-nu ("Dufour-like") term f_phi is commented out in MFiX and its sign is uncertain
// (§2.2); it changes nu_mean by < 1e-4 here. It is on by default behind the `dufour` key.
#pragma once
#include <cmath>
#include <numbers>

namespace granlub::continuum::closures {

inline double k_star(double eta) {
    return 75.0 * std::sqrt(std::numbers::pi) / (48.0 * eta * (41.0 - 33.0 * eta));
}

template <class S>
S f_kappa(S nu, S g, double eta) {
    constexpr double pi = std::numbers::pi;
    const S eng = eta * nu * g;
    const S bracket = (1.0 + 2.4 * eng) * (1.0 + 2.4 * eta * (4.0 * eta - 3.0) * eng) +
                      (64.0 / (25.0 * pi)) * (41.0 - 33.0 * eta) * eng * eng;
    return k_star(eta) * bracket / g;
}

template <class S>
S f_phi(S nu, S g, S dg, double eta) {
    const S eng = eta * nu * g;
    return k_star(eta) * 2.4 * eta * (eta - 1.0) * (2.0 * eta - 1.0) * (1.0 + 2.4 * eng) * (nu * dg + 2.0 * g) / g;
}

}  // namespace granlub::continuum::closures
