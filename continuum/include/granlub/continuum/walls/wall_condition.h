// The GKL wall conditions (S&T 2001 Eqs. 13-15 with the sign table of docs/continuum-model.md §1), written
// once in the wall's own frame so that every solver (the 1-D gap, its shooting cross-check, the trough's
// cross-section) applies the same condition on any wall:
//   n    the unit normal from the wall into the flow (a coordinate scaled by H, like y^),
//   s    the signed slip u^_wall - u^ (dimensionless by U),
//   du/dn  = -R5 Lambda b5 s                                                  (momentum)
//   dnu/dn = -[R6 Lambda b6 + R7 Lambda Pi b7 s^2 + R8 Pi b8 s du/dn]          (fluctuation energy)
// b5..b8 are the wall family's coefficients at the wall's nu (wall_family.h). On the 1-D gap's moving
// bottom (n = +y^, u^_wall = 1) this is S&T's Eq. 13-15 as written; on the fixed top (n = -y^, u^_wall = 0)
// it is their top-wall form with u^' = -du/dn, nu' = -dnu/dn.
#pragma once
#include <cmath>

#include "granlub/continuum/walls/wall_family.h"

namespace granlub::continuum {

template <class S>
struct WallGradients {
    S du;   // du^/dn
    S dnu;  // dnu/dn
};

// S: the unknowns' scalar (double or a dual); B: the coefficients' scalar (double or a dual).
template <class S, class B>
WallGradients<S> wall_gradients(const WallParams& w, const B& b5, const B& b6, const B& b7, const B& b8, const S& slip,
                                const S& Lambda, const S& Pi) {
    const S du = -w.r5 * Lambda * b5 * slip;
    const S dnu = -(w.r6 * Lambda * b6 + w.r7 * Lambda * Pi * b7 * slip * slip + w.r8 * Pi * b8 * slip * du);
    return {du, dnu};
}

// The same with the family's coefficients at the wall node (values only).
inline WallGradients<double> wall_gradients(const WallParams& w, const WallCoefficients& b, double slip, double Lambda,
                                            double Pi) {
    return wall_gradients(w, b.b5.v, b.b6.v, b.b7.v, b.b8.v, slip, Lambda, Pi);
}

// What a wall removes from the fluctuation energy, per unit wall area in the energy equation's units
// (the flux K dnu/dn the condition imposes is slip work returned minus this): the collisional terms
// R6, R7 and the part (1 - R8) of the slip work tau^ |s| the condition does not return (§8.5).
// tau_hat = M |du/dn| at the wall.
inline double wall_energy_sink(const WallParams& w, const WallCoefficients& b, double K, double slip, double Lambda,
                               double Pi, double tau_hat) {
    return K * (w.r6 * Lambda * b.b6.v + w.r7 * Lambda * Pi * b.b7.v * slip * slip) +
           (1.0 - w.r8) * Pi * tau_hat * std::abs(slip);
}

}  // namespace granlub::continuum
