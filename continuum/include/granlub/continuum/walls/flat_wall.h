// A flat frictional wall's R5..R8 and slip dissipation from its impact law (docs/continuum-model.md §4.3b),
// for family K ([continuum] wall_roughness = "built" on a plane wall) [DERIVED, ours].
//
// The particle solvers' grain-wall impact is Walton's (1993): normal impulse (1 + e_w) m c_n, tangential impulse
// min(mu_w J_n, (2/7)(1 + beta0) m |g|) against the contact-point slip g, 2/7 = K/(1 + K) with K = 2/5 for a
// solid sphere (plugins/liggghts doc gran_tangential_impulse). Jenkins (1992, J. Appl. Mech. 59, 120) built a
// flat frictional wall's conditions from this law; we take his construction in the limit where every impact
// sticks (mu_w large against |g|/c_n) and, our assumption, without the grains' spin (g = the grain's slip):
// a Maxwellian at T with mean slip u_s hitting the wall at the rate that carries the normal stress P,
// Z = P / ((1 + e_w) m sqrt(pi T / 2)), gives
//   traction      S = Z (2/7)(1 + beta0) m u_s = R5 sqrt(2/pi) P u_s / ((1 + e_w) sqrt T),  R5 = (2/7)(1 + beta0),
//   dissipation   D = Z m [(1 - e_w^2) T + (1/7)(1 - beta0^2)(u_s^2 + 2T)]:
//     its T-part    sqrt(2/pi) P sqrt(T) [(1 - e_w) + (2/7)(1 - beta0^2)/(1 + e_w)] = R6 sqrt(2/pi)(1 - e_w) P sqrt T
//                   with R6 = 1 + (2/7)(1 - beta0^2)/(1 - e_w^2),
//     its slip part (1 - beta0)/2 of the slip work S u_s: R7 = R5 with f_t = (1 - beta0)/2,
// which is family K's structure (kinetic.cpp) with these factors and the flux into the flow slip work minus D
// (wall_energy = "slip_work"; R8 weighs nothing there and is set to R5 for the record).
// The grains' spin ([continuum] flat_wall_spin) [ASSUMPTION, ours]: a grain beside the wall is struck by the wall
// below and by the grains above; in a steady state the torques of the two sides' tangential impulses balance.
// Both sides carry the same normal stress and follow the same sticking law (J_t/J_n = (2/7)(1 + beta0) g /
// ((1 + e) c_n) whatever the pair's masses), so with the grains above at rest relative to it and the same impact
// speeds c_n on both sides the two contact points slip alike: the wall contact slips at a share phi = 1/2 of the
// grain's slip u_s ("torque_balance"). Weighting the upper impacts by the grains' relative normal speed (sqrt 2
// the wall's) would give phi = 1/(1 + sqrt 2) = 0.41; we take the simpler 1/2. The particle runs measure
// 0.40-0.47 (on the poly twin, docs/measurements/continuum.md: a check, not a fit). Then g = phi u_s in the law:
// R5 = R7 = (2/7)(1 + beta0) phi and the wall's
// share of the slip work dissipated f_t = (1 - beta0) phi / 2 (the upper contacts' loss is the bulk's); the
// T-part of D (R6) does not depend on it. phi = 1 ("none") is the spin-free law above.
// Impacts that slide (the cap mu_w J_n, reached where |g| > (7/2) mu_w (1 + e_w) c_n / (1 + beta0)): these are the
// law's stick limit, which flat_wall_impacts.h ([continuum] flat_wall_impacts = "stick_and_slide") scales to the whole
// law at the contact points' slip phi u_s.
#pragma once

namespace granlub::continuum {

// Walton's tangential restitution of sticking impacts that the particle solvers use by default ([dem] beta0 = 0,
// the stick limit; YADE's viscel e_t = 0.01 is near it) [ASSUMPTION: the case's particle settings are not read].
inline constexpr double kFlatWallBeta0 = 0.0;

// The share of the grains' slip at which their contact points slip on the wall: "torque_balance" (1/2) or "none"
// (1: no spin).
inline constexpr double kFlatWallTorqueBalanceShare = 0.5;

struct FlatWallFactors {
    double r5, r6, r7, r8, slip_dissipation;
};

inline FlatWallFactors flat_wall_from_impact_law(double e_w, double contact_slip_share, double beta0 = kFlatWallBeta0) {
    const double r5 = (2.0 / 7.0) * (1.0 + beta0) * contact_slip_share;
    const double r6 = 1.0 + (2.0 / 7.0) * (1.0 - beta0 * beta0) / (1.0 - e_w * e_w);
    return {r5, r6, r5, r5, 0.5 * (1.0 - beta0) * contact_slip_share};
}

}  // namespace granlub::continuum
