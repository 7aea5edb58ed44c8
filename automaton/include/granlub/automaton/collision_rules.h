// The collision rules of the CA as plain functions: what a wall or a struck grain does to the
// mover's speed and direction (docs/automaton-model.md §3.3-3.4; vector mode §5). The engine's step
// loop and the rule tests call these same functions. Speeds are JH06 Eqs. 6-9 (speed_rules.h);
// lattice units, U = 1. Random draws are passed in as callables, so that each rule draws exactly
// what it needs, in the same order, from whichever source the caller holds. The rules the step loop
// calls per collision are forced inline: they replace code that was written inside the loop, and
// the loop's speed depends on them staying there (bench_automaton).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "granlub/automaton/directions.h"
#include "granlub/automaton/speed_rules.h"

namespace granlub::automaton {

// The two directions a mover may leave in after a collision, in the order it tries them.
struct Candidates {
    unsigned first, second;
};

// Grain-grain, jh mode, the mover's direction (Table P) [RECON]: the billiard 90-degree rule, the
// mover leaves at d +- deflect notches (2: +-90 degrees, 1: +-45 degrees), and JH06's "two possible
// resulting directions ... chosen randomly": `plus_first` (a coin, 0 or 1) picks the side tried
// first. A mask, not a branch: the coin is unpredictable.
[[gnu::always_inline]] inline Candidates billiard_deflection(unsigned d, unsigned deflect, unsigned plus_first) {
    const unsigned a = (d + deflect) & 7u, b = (d - deflect) & 7u;
    const unsigned first = b ^ ((a ^ b) & (0u - plus_first));
    return {first, a ^ b ^ first};
}

// Grain-wall, jh mode, the direction (Tables W-T, W-B): specular reflection (dx, dy) -> (dx, -dy)
// [RECON]; at the moving bottom wall the reflected direction turns one notch toward +x, never past
// NE, when drag() says so [ASSUMPTION: probability p_drag]. drag() is asked only where a notch can turn
// the direction, so elsewhere the rule draws nothing.
template <class Drag>
[[gnu::always_inline]] inline unsigned wall_reflection(unsigned d, bool bottom, Drag&& drag) {
    unsigned out = kReflect[d];
    if (bottom && out != NE && drag()) out = kDrag[out];
    return out;
}

// Grain-wall, jh mode, the speed: JH06 Eqs. 6-7 on the scalar u_p, in sequence (`sequential`) or,
// as the alternative reading, Eq. 7 alone for a normal impact (dx = 0) and Eq. 6 alone otherwise.
[[gnu::always_inline]] inline double wall_speed_jh(double u, unsigned d, double U_w, double R, double e_w, bool sequential) {
    return sequential ? wall_sequential(u, U_w, R, e_w) : wall_by_incidence(u, U_w, R, e_w, kDx[d] == 0);
}

// Vector mode [ASSUMPTION]: stochastic king-move rounding of a velocity onto the 8 directions,
// unbiased in the mean. Sets `speed` to min(max(|vx|, |vy|), U) and returns the direction; draws
// below(8) for a zero velocity, else one uniform() when the minor component is not zero.
template <class Rng>
[[gnu::always_inline]] inline unsigned discretise(Rng& rng, double vx, double vy, double& speed) {
    const double ax = std::abs(vx), ay = std::abs(vy);
    const double s = std::max(ax, ay);
    if (s == 0.0) {
        speed = 0.0;
        return rng.below(8);
    }
    int dx, dy;
    if (ax >= ay) {
        dx = vx > 0 ? 1 : -1;
        dy = (ay > 0 && rng.uniform() < ay / ax) ? (vy > 0 ? 1 : -1) : 0;
    } else {
        dy = vy > 0 ? 1 : -1;
        dx = (ax > 0 && rng.uniform() < ax / ay) ? (vx > 0 ? 1 : -1) : 0;
    }
    speed = std::min(s, 1.0);
    return from_step(dx, dy);
}

// Vector mode, grain-wall velocity: JH06 Eq. 6 on the tangential component (toward the wall
// speed U_w), Eq. 7 on the normal one (whose wall value is 0).
struct Velocity {
    double x, y;
};
[[gnu::always_inline]] inline Velocity vector_wall_velocity(Velocity v, double U_w, double R, double e_w) {
    return {eq6_roughness(v.x, U_w, R), -e_w * v.y};
}

// Vector mode, grain-grain [ASSUMPTION]: the mover (direction d, speed u_i) hits grain j (dir_j, u_j)
// along a line of centres jittered uniformly by +-jitter radians; if they approach, JH06 Eqs. 8-9
// act on the normal components, tangential components are kept, and both grains are rounded back
// onto the lattice (mover first). If not, the mover deflects by +-45 degrees (`coin` picks the side)
// or, with `wait`, ends its update: then the result has wait = true.
struct VectorHit {
    bool wait = false;
    Candidates next{};
    bool two = false;  // both candidates open (deflection), else only next.first
};
// Inlined into the chain, as the engine's own code was: called out of line, the chain's state would
// leave its registers (measured: vector mode 8-15 % slower).
template <class Rng, class Coin>
[[gnu::always_inline]] inline VectorHit vector_grain_grain(Rng& rng, Coin&& coin, double jitter, double e_p, bool wait,
                                                          unsigned d, double& u_i, double& u_j, std::uint8_t& dir_j) {
    const double theta = d * (std::numbers::pi / 4) + jitter * (2.0 * rng.uniform() - 1.0);
    const double nx = std::cos(theta), ny = std::sin(theta);
    const double ui = u_i, uj = u_j;
    const int dj = dir_j;
    double vix = ui * kDx[d], viy = ui * kDy[d];
    double vjx = uj * kDx[dj], vjy = uj * kDy[dj];
    const double a1 = vix * nx + viy * ny, a2 = vjx * nx + vjy * ny;
    VectorHit h;
    if (a1 <= a2) {  // not approaching: no impact
        if (wait) {
            h.wait = true;
            return h;
        }
        const bool plus_first = coin();
        const unsigned a = rotate(static_cast<int>(d), 1), b = rotate(static_cast<int>(d), -1);
        h.next = plus_first ? Candidates{a, b} : Candidates{b, a};
        h.two = true;
        return h;
    }
    const double a1f = 0.5 * ((1 - e_p) * a1 + (1 + e_p) * a2);
    const double a2f = 0.5 * ((1 - e_p) * a2 + (1 + e_p) * a1);
    vix += (a1f - a1) * nx; viy += (a1f - a1) * ny;
    vjx += (a2f - a2) * nx; vjy += (a2f - a2) * ny;
    const unsigned di = discretise(rng, vix, viy, u_i);
    h.next = {di, di};
    double uj1 = uj;
    dir_j = static_cast<std::uint8_t>(discretise(rng, vjx, vjy, uj1));
    u_j = uj1;
    return h;
}

}  // namespace granlub::automaton
