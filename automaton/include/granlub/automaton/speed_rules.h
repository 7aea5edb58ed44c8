// The speed equations of JH06 acting on the scalar u_p (lattice units, U = 1), docs/automaton-model.md §3.3-3.4.
// Results are clamped to [0, 1]: mathematically every rule is a convex combination of values in
// [0, U] (§3.5); the clamp only removes last-bit rounding above U.
#pragma once
#include <algorithm>

namespace granlub::automaton {

inline double clamp_unit(double u) { return std::min(std::max(u, 0.0), 1.0); }

// JH06 Eq. 6 (roughness): u_f = u_i + R (U_w - u_i).
inline double eq6_roughness(double u, double U_w, double R) { return u + R * (U_w - u); }
// JH06 Eq. 7 (wall restitution): u_f = U_w - e_w (U_w - u_i).
inline double eq7_restitution(double u, double U_w, double e_w) { return U_w - e_w * (U_w - u); }

// Wall hit, `sequential` (default, [ASSUMPTION]): Eq. 6 then Eq. 7, so that
// U_w - u_f = e_w (1 - R)(U_w - u_i).
inline double wall_sequential(double u, double U_w, double R, double e_w) {
    return clamp_unit(eq7_restitution(eq6_roughness(u, U_w, R), U_w, e_w));
}
// Wall hit, `by_incidence` ([ASSUMPTION] alternative reading): Eq. 7 alone for a normal impact
// (incoming N or S), Eq. 6 alone for an oblique one.
inline double wall_by_incidence(double u, double U_w, double R, double e_w, bool normal_impact) {
    return clamp_unit(normal_impact ? eq7_restitution(u, U_w, e_w) : eq6_roughness(u, U_w, R));
}

// JH06 Eqs. 8-9 (equal masses, restitution e_p), written as u1 + a (u2 - u1) with
// a = (1 + e_p)/2 so that u1 + u2 is conserved to the last bit:
//   u1f = ((1-e_p) u1 + (1+e_p) u2)/2,  u2f = ((1-e_p) u2 + (1+e_p) u1)/2.
inline double eq8_9_weight(double e_p) { return 0.5 * (1.0 + e_p); }
// The collision with the weight a = eq8_9_weight(e_p) computed once (the engine holds it per step).
inline void eq8_9_collide_weighted(double& u1, double& u2, double a) {
    const double delta = a * (u2 - u1);
    u1 = clamp_unit(u1 + delta);
    u2 = clamp_unit(u2 - delta);
}
inline void eq8_9_collide(double& u1, double& u2, double e_p) { eq8_9_collide_weighted(u1, u2, eq8_9_weight(e_p)); }

}  // namespace granlub::automaton
