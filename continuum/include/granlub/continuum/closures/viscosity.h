// Shear viscosity of LSJC 1984, dimensionless: mu = rho_p sigma T^{1/2} f_mu(nu)   (docs/continuum-model.md §2.1)
//   f_mu = c_a (5 sqrt(pi)/96) { [1 + 8/5 eta nu g][1 + 8/5 eta (3 eta - 2) nu g] / (eta (2 - eta) g)
//                                 + 768/(25 pi) eta nu^2 g }
// c_a = (2 + alpha)/3; alpha = 1 is the original LSJC theory, MFiX uses 1.6 [SRC: MFiX
// constant_mod.f]. Elastic dilute limit: 5 sqrt(pi)/96 (Chapman-Enskog), checked in the tests.
#pragma once
#include <cmath>
#include <numbers>

namespace granlub::continuum::closures {

template <class S>
S f_mu(S nu, S g, double eta, double alpha) {
    constexpr double pi = std::numbers::pi;
    const double c_alpha = (2.0 + alpha) / 3.0;
    const S eng = eta * nu * g;
    const S kinetic = (1.0 + 1.6 * eng) * (1.0 + 1.6 * (3.0 * eta - 2.0) * eng) / (eta * (2.0 - eta) * g);
    const S collisional = (768.0 / (25.0 * pi)) * eta * nu * nu * g;
    return c_alpha * (5.0 * std::sqrt(pi) / 96.0) * (kinetic + collisional);
}

}  // namespace granlub::continuum::closures
