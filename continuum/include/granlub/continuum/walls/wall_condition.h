// The GKL wall conditions (S&T 2001 Eqs. 13-15 with the sign table of docs/continuum-model.md §1), written
// once in the wall's own frame so that every solver (the 1-D gap, its shooting cross-check, the trough's
// cross-section) applies the same condition on any wall:
//   n    the unit normal from the wall into the flow (a coordinate scaled by H, like y^),
//   s    the signed slip u^_wall - u^ (dimensionless by U),
//   du/dn  = -R5 Lambda b5 s                                                  (momentum)
//   dnu/dn = -[R6 Lambda b6 + R7 Lambda Pi b7 s^2 + W Pi b8 s du/dn]           (fluctuation energy)
// b5..b8 are the wall family's coefficients at the wall's nu (wall_family.h). A flat wall whose impacts stick and
// slide (WallParams::impacts, walls/flat_wall_impacts.h) scales the traction by h(xi) = sigma/sigma_s and the R6, R7
// terms by g(xi) = delta/delta_s, at the contact points' xi = phi u_s/sqrt(T) = phi |s| sqrt(Pi) xs (xs =
// WallCoefficients::xi_per_slip, phi = WallParams::contact_slip_share): family K's terms are that wall's stick limit
// (at phi), h and g the exact law's share of it (its slip work follows du/dn).
// W is the share of the slip work the condition returns to the flow (slip_work_weight): R8 in S&T's GKL form
// (WallEnergy::GklR8), 1 where the flux into the flow is slip work minus collisional dissipation, as Johnson &
// Jackson 1987 and Jenkins & Richman 1986 / Richman 1988 write it (WallEnergy::SlipWork; docs/continuum-model.md
// §4.5). On the 1-D gap's moving bottom (n = +y^, u^_wall = 1) this is S&T's Eq. 13-15 as written; on the fixed
// top (n = -y^, u^_wall = 0) it is their top-wall form with u^' = -du/dn, nu' = -dnu/dn.
#pragma once
#include <cmath>

#include "granlub/continuum/dual.h"
#include "granlub/continuum/walls/flat_wall_impacts.h"
#include "granlub/continuum/walls/wall_family.h"

namespace granlub::continuum {

// The share W of the slip work that the energy condition returns to the flow.
inline double slip_work_weight(const WallParams& w) { return w.energy == WallEnergy::GklR8 ? w.r8 : 1.0; }

template <class S>
struct WallGradients {
    S du;   // du^/dn
    S dnu;  // dnu/dn
};

// S: the unknowns' scalar (double or a dual); B: the coefficients' scalar (double or a dual). xs: xi per slip.
template <class S, class B>
WallGradients<S> wall_gradients(const WallParams& w, const B& b5, const B& b6, const B& b7, const B& b8, const B& xs,
                                const S& slip, const S& Lambda, const S& Pi) {
    S du = -w.r5 * Lambda * b5 * slip;
    S collisional = w.r6 * Lambda * b6 + w.r7 * Lambda * Pi * b7 * slip * slip;
    if (w.impacts) {  // h(xi), g(xi) with their derivatives through xi (the Jacobians stay exact)
        using std::abs, std::sqrt;
        const S xi = abs(slip) * sqrt(Pi) * xs * w.contact_slip_share;
        const FlatWallImpacts::Factors f = w.impacts->factors(value(xi));
        du = du * chain(xi, f.h, f.dh);
        collisional = collisional * chain(xi, f.g, f.dg);
    }
    const S dnu = -(collisional + slip_work_weight(w) * Pi * b8 * slip * du);
    return {du, dnu};
}

// The same with the family's coefficients at the wall node (values only).
inline WallGradients<double> wall_gradients(const WallParams& w, const WallCoefficients& b, double slip, double Lambda,
                                            double Pi) {
    return wall_gradients(w, b.b5.v, b.b6.v, b.b7.v, b.b8.v, b.xi_per_slip.v, slip, Lambda, Pi);
}

// What a wall removes from the fluctuation energy, per unit wall area in the energy equation's units
// (the flux K dnu/dn the condition imposes is slip work returned minus this), in two parts:
//   collisional: the terms R6, R7 (zero at e_w = 1 with f_t = 0; times g(xi) on a wall whose impacts slide),
//   unreturned slip work: the part 1 - W of the slip work tau^ |s| the condition does not return (§8.5; 1 - R8 with
//   GklR8, none with SlipWork).
// tau_hat = M |du/dn| at the wall.
inline double wall_collisional_sink(const WallParams& w, const WallCoefficients& b, double K, double slip,
                                    double Lambda, double Pi) {
    const double sink = K * (w.r6 * Lambda * b.b6.v + w.r7 * Lambda * Pi * b.b7.v * slip * slip);
    if (!w.impacts) return sink;
    return sink * w.impacts->factors(std::abs(slip) * std::sqrt(Pi) * b.xi_per_slip.v * w.contact_slip_share).g;
}
inline double wall_unreturned_slip_work(const WallParams& w, double slip, double Pi, double tau_hat) {
    return (1.0 - slip_work_weight(w)) * Pi * tau_hat * std::abs(slip);
}
}  // namespace granlub::continuum
