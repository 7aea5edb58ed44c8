// A rate-independent contact stress beside the kinetic one (docs/continuum-model.md §2.9), in the additive form
//   p = p_KT + p_c(nu),   tau = tau_KT + mu_c p_c(nu) sgn_eps(u'),
// with Johnson & Jackson's (1987) frictional pressure
//   p_c = Fr (nu - nu_min)^n / (nu_c - nu)^m  for nu > nu_min, 0 below
// [SRC: frictionalPressure in OpenFOAM-dev's kineticTheoryModels/frictionalStressModel/JohnsonJackson
// (Fr, eta = n, p = m, alphaMinFriction = nu_min, alphaMax = nu_c; OpenFOAM also floors nu_c - nu at alphaDeltaMin,
// which granlub does not: its logit cap keeps nu below the root nu_P of p_c = P); the paper not read] and the shear
// s_c = mu_c p_c (mu_c = sin phi: OpenFOAM's frictional viscosity is built from p_c sin phi). Only the kinetic
// stress works on the fluctuations: the contact stress's work is dissipated in the contacts (Johnson & Jackson's
// choice [LIT]; [ASSUMPTION] here). Its constants have no defaults: they are to be fitted on the bulk-rheology
// table (issue 73, item 1).
// sgn(u') is regularised, sgn_eps(x) = x/sqrt(x^2 + eps^2) [ASSUMPTION: a numerical choice, so that Newton has a
// derivative where the bed stops shearing (T -> 0, the contact shear carrying the whole stress)]; eps =
// sign_width in units of u^' = du^/dy^ (the Couette gap's mean |u^'| is O(1)); eps -> 0 is checked in the tests.
// In the eliminated-T formulation the problem sees pi_c = p_c/p: p = P_y of the point, so a Closures object carries
// it per point (closure_set.h, Closures::with_contact), or the local p = p^ P_y of the cross-section's body forces
// (Closures::state's `pressure` p^; docs/continuum-model.md §2.9a).
#pragma once
#include <cmath>

#include "granlub/continuum/dual.h"

namespace granlub::continuum {

struct ContactStress {
    double coefficient = 0;  // Fr / P_y (dimensionless, per point)
    double onset = 0.5;      // nu_min
    double jamming = 0.6;    // nu_c
    double n = 2, m = 5;     // exponents
    double friction = 0;     // mu_c
    double sign_width = 1e-2;  // eps of sgn_eps (see above; tests/continuum/test_contact_stress.cpp checks eps -> 0)
    bool active() const { return coefficient > 0; }

    // sgn_eps(x) = x/sqrt(x^2 + eps^2), templated on the scalar: direction() with no tangential gradient.
    template <class S>
    S sign(const S& x) const {
        return direction(x, S(0.0));
    }
    // The component along n of the regularised unit strain-rate direction grad u^ / |grad u^|_eps, for the gradient's
    // components g_n along n and g_t across it: g_n / sqrt(g_n^2 + g_t^2 + eps^2). On the cross-section (u(y, z))
    // the contact shear is mu_c p_c grad u / |grad u|_eps: Schaeffer's (1987) frictional viscosity p_c sin phi/|grad u|
    // [SRC: JohnsonJacksonSchaefferFrictionalStress.C::nu of OpenFOAM (openfoamdotcom), nu_f = p_f sin phi / (2
    // sqrt(II_D') + SMALL), sqrt(II_D') = |grad u|/2 here; the paper not read], regularised with the 1-D eps
    // [ASSUMPTION: the sources give the rate-independent stress, not this regularisation; it keeps |tau_c| <= mu_c p_c,
    // and with g_t = 0 it is the 1-D sgn_eps bit for bit (x*x + 0 is x*x)].
    template <class S>
    S direction(const S& gn, const S& gt) const {
        using std::sqrt;
        return gn / sqrt(gn * gn + gt * gt + sign_width * sign_width);
    }
    // The finite-volume fluxes of the contact shear in the momentum equation's units, M u^' (the solvers' u^, y^ =
    // y/H): scale() x pi_c x direction, scale = mu_c Lambda / sqrt(Pi) (tau_c/P = mu_c pi_c x direction).
    template <class S>
    S scale(const S& Lambda, const S& Pi) const {
        using std::sqrt;
        return friction * Lambda / sqrt(Pi);
    }
    // ... through a face between two nodes: pi_c the mean of theirs, g_n the face difference, g_t the tangential
    // gradient at the face (0 in 1-D); at a wall, pi_c of the wall node with the wall condition's gradient.
    template <class S>
    S face_flux(const S& pa, const S& pb, const S& gn, const S& gt) const {
        return 0.5 * (pa + pb) * direction(gn, gt);
    }
    template <class S>
    S wall_flux(const S& pw, const S& gn, const S& gt) const {
        return pw * direction(gn, gt);
    }

    // pi_c = p_c / P_y and its nu-derivative, templated on the scalar (exact dual derivatives).
    template <class S>
    S ratio(const S& nu) const {
        using std::pow;
        if (!(value(nu) > onset)) return S(0.0);
        return coefficient * pow(nu - onset, n) / pow(jamming - nu, m);
    }
    template <class S>
    S dratio(const S& nu) const {
        if (!(value(nu) > onset)) return S(0.0);
        return ratio(nu) * (n / (nu - onset) + m / (jamming - nu));
    }
    // The solid fraction at which p_c = level x P_y (T = 0 there): the bed's limit under this load (level 1), or under
    // a local pressure p = level x P_y (the cross-section's body forces) (bisection; onset < it < jamming).
    double limit(double level = 1.0) const {
        double lo = onset, hi = jamming;
        for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
            const double mid = 0.5 * (lo + hi);
            (ratio(mid) < level ? lo : hi) = mid;
        }
        return lo;
    }
};

}  // namespace granlub::continuum
