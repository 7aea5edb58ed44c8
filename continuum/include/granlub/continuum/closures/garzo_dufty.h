// Shear viscosity and conductivity of Garzo & Dufty 1999 (Phys. Rev. E 59, 5895, Eqs. (6.x) as the
// extended-kinetic-theory papers use them: Jenkins & Berzi 2010, Berzi & Vescovi 2015), dimensionless as
// in viscosity.h / conductivity.h, with G = nu g0 (docs/continuum-model.md §2.5).
// [SRC: read in SedFoam, solver/kineticTheoryModels/viscosityModel/GarzoDufty/GarzoDuftyViscosity.C
// (mua, without saltation) and conductivityModel/GarzoDufty/GarzoDuftyConductivity.C; the GD paper's
// equation numbers themselves were not read]
//   f_mu = (5 sqrt(pi)/96) { mu_k [1 + (4/5)(1+e) G] + (384/(25 pi)) (1+e) nu G },
//          mu_k = [1 - (2/5)(1+e)(1-3e) G] / {g0 [1 - (1-e)^2/4 - 5(1-e^2)/24]}
//   f_k  = (225 sqrt(pi)/1152) { k_k [1 + (6/5)(1+e) G] + (2304/(225 pi)) (1+e) nu G },
//          k_k = 32 [1 + (3/5)(1+e)^2 (2e-1) G] / {(16 - 7(1-e)) (1+e) g0}
// SedFoam's conductivity also subtracts 32/((16 - 7(1-e))(1+e) g0), labelled "Correction"; it cancels
// the dilute (Chapman-Enskog) conductivity at e = 1 and its source is not stated, so it is left out
// [ASSUMPTION]. Pressure and the e_p-dissipation are those of LSJC (pressure.h, dissipation.h), identical
// in both theories. The grad-nu flux of GD is neglected, as Jenkins & Berzi do [ASSUMPTION].
// Checks (tests): at e = 1, nu -> 0 both reduce to the Chapman-Enskog values 5 sqrt(pi)/96 and
// 75 sqrt(pi)/384, as LSJC's do.
#pragma once
#include <cmath>
#include <numbers>

namespace granlub::continuum::closures {

template <class S>
S f_mu_gd(S nu, S g, double e) {
    constexpr double pi = std::numbers::pi;
    const S G = nu * g;
    const S mu_k = (1.0 - 0.4 * (1.0 + e) * (1.0 - 3.0 * e) * G) /
                   ((1.0 - 0.25 * (1.0 - e) * (1.0 - e) - (5.0 / 24.0) * (1.0 - e * e)) * g);
    return (5.0 * std::sqrt(pi) / 96.0) *
           (mu_k * (1.0 + 0.8 * (1.0 + e) * G) + (384.0 / (25.0 * pi)) * (1.0 + e) * nu * G);
}

template <class S>
S f_kappa_gd(S nu, S g, double e) {
    constexpr double pi = std::numbers::pi;
    const S G = nu * g;
    const S k_k = 32.0 * (1.0 + 0.6 * (1.0 + e) * (1.0 + e) * (2.0 * e - 1.0) * G) /
                  ((16.0 - 7.0 * (1.0 - e)) * (1.0 + e) * g);
    return (225.0 * std::sqrt(pi) / 1152.0) *
           (k_k * (1.0 + 1.2 * (1.0 + e) * G) + (2304.0 / (225.0 * pi)) * (1.0 + e) * nu * G);
}

}  // namespace granlub::continuum::closures
