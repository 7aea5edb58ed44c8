// Collisional dissipation of LSJC 1984 (docs/continuum-model.md §2.1):
//   gamma = rho_p T^{3/2} f_gamma(nu) / sigma,  f_gamma = (48/sqrt(pi)) eta (1 - eta) nu^2 g0
//         = (12/sqrt(pi)) (1 - e_p^2) nu^2 g0
#pragma once
#include <cmath>
#include <numbers>

namespace granlub::continuum::closures {

template <class S>
S f_gamma(S nu, S g, double eta) {
    return (48.0 / std::sqrt(std::numbers::pi)) * eta * (1.0 - eta) * nu * nu * g;
}

}  // namespace granlub::continuum::closures
