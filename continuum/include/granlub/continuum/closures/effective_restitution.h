// Friction through an effective restitution e_eff (docs/continuum-model.md §2.6): frictional spheres
// dissipate as frictionless ones with e_eff < e_p. It enters the collisional dissipation only, as
// gamma(e_eff) = gamma(e_p) (1 - e_eff^2)/(1 - e_p^2) (SedFoam and CFDEM-PRINCETON do the same).
//   jenkins_zhang:       Jenkins & Zhang 2002 (Phys. Fluids 14, 1228), tangential restitution 0:
//     mu0 = (7/2) mu_p (1 + e), A = 1 - (2/pi) atan(mu0)
//     a1 = (mu_p/mu0) [pi mu0 A + 2 mu0^2/(1 + mu0^2) (1 - 2 mu_p/mu0)]
//     a2 = (5/2)(mu_p/mu0) [(pi/2) mu0 A + (mu0^2 - mu0^4)/(1 + mu0^2)^2]
//     b1 = mu_p^2/(1 + mu0^2),  b2 = (1/2)(mu_p/mu0) [(pi/2) mu0 A + mu0^2/(1 + mu0^2)]
//     e_eff = e - (a1 - a2 b1/b2)/2
//     [SRC: read in SedFoam solver/kineticTheoryModels/kineticTheoryModel/kineticTheoryModel.C;
//      the paper's equation numbers not read]
//   chialvo_sundaresan:  Chialvo & Sundaresan 2013 (Phys. Fluids 25, 070603, Eqs. 22-23):
//     e_eff = e - (3/2) mu_p exp(-3 mu_p)
//     [SRC: read in SedFoam kineticTheoryModel.C (comment) and CFDEM-PRINCETON kineticTheoryModel.C]
// Values at e = 0.9, mu_p = 0.5 (tests): 0.6634 (JZ02), 0.7326 (CS13).
#pragma once
#include <cmath>
#include <numbers>
#include <string>

namespace granlub::continuum::closures {

inline double e_eff_jenkins_zhang(double e, double mu_p) {
    if (!(mu_p > 0)) return e;
    constexpr double pi = std::numbers::pi;
    const double mu0 = 3.5 * mu_p * (1.0 + e);
    const double A = 1.0 - (2.0 / pi) * std::atan(mu0);
    const double m2 = mu0 * mu0;
    const double a1 = (mu_p / mu0) * (pi * mu0 * A + 2.0 * m2 / (1.0 + m2) * (1.0 - 2.0 * mu_p / mu0));
    const double a2 = 2.5 * (mu_p / mu0) * (0.5 * pi * mu0 * A + (m2 - m2 * m2) / ((1.0 + m2) * (1.0 + m2)));
    const double b1 = mu_p * mu_p / (1.0 + m2);
    const double b2 = 0.5 * (mu_p / mu0) * (0.5 * pi * mu0 * A + m2 / (1.0 + m2));
    return e - 0.5 * (a1 - a2 * b1 / b2);
}

inline double e_eff_chialvo_sundaresan(double e, double mu_p) { return e - 1.5 * mu_p * std::exp(-3.0 * mu_p); }

// [continuum] friction_restitution by name: "none" gives e back.
inline double e_eff(const std::string& name, double e, double mu) {
    if (name == "jenkins_zhang") return e_eff_jenkins_zhang(e, mu);
    if (name == "chialvo_sundaresan") return e_eff_chialvo_sundaresan(e, mu);
    return e;
}

}  // namespace granlub::continuum::closures
