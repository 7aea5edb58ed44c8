// The step loop of Engine (engine.h): the update order, each grain's clock, and the move attempt
// with its collision chain (docs/automaton-model.md §3.1-3.2). The rules a collision applies are
// plain functions (collision_rules.h, speed_rules.h, time_factor.h); this file only moves state
// between the lattice and those functions, fast: everything a step touches sits in one local Ctx,
// draws happen in a fixed order, and large lattices prefetch the grains visited next.
// Included at the end of engine.h; not a header of its own.
#pragma once
#include "granlub/automaton/collision_rules.h"
#include "granlub/automaton/engine.h"

namespace granlub::automaton {

template <class Rng>
typename Engine<Rng>::Ctx Engine<Rng>::context() {
    Ctx c;
    c.grid = grid_.data(); c.pos = pos_.data(); c.dir = dir_.data(); c.up = up_.data();
    c.tick = tick_.data(); c.acc = acc_.data(); c.kin = kin_.data(); c.rng = &rng_;
    c.coins = take_coins(rng_);
    c.ncell = static_cast<std::int64_t>(grid_.size());
    for (int d = 0; d < 8; ++d) c.off[d] = off_[d];
    c.row = row_of_;
    c.rest = rest_; c.tf_max = tf_max_;
    c.e_p = rules_.e_p; c.eq89_weight = eq8_9_weight(rules_.e_p);
    c.R[0] = rules_.R_top; c.R[1] = rules_.R_bottom;
    c.e_w[0] = rules_.e_w_top; c.e_w[1] = rules_.e_w_bottom;
    c.p_drag = rules_.p_drag; c.jitter = jitter_;
    c.sequential = rules_.wall_speed == WallSpeed::Sequential;
    c.line = rules_.struck_dir == StruckDir::Line;
    c.vec_wait = rules_.vec_blocked == VecBlocked::Wait;
    c.deflect = deflect_;
    // The running totals themselves (not per-step partial sums), so that the wall momentum
    // sums are accumulated in exactly the same order as one update at a time.
    const Counters& k = counters_;
    c.moves = k.moves; c.pp = k.pp; c.exhausted = k.exhausted;
    wall_sums_ = {{k.wall_top, k.wall_bottom}, {k.tangential_top, k.tangential_bottom}, {k.normal_top, k.normal_bottom}};
    c.walls = &wall_sums_;
    return c;
}

template <class Rng>
void Engine<Rng>::commit(const Ctx& c) {
    give_back_coins(rng_, c.coins);
    Counters& k = counters_;
    k.moves = c.moves; k.pp = c.pp; k.exhausted = c.exhausted;
    const auto& w = wall_sums_;
    k.wall_top = w.hits[0]; k.wall_bottom = w.hits[1];
    k.tangential_top = w.tangential[0]; k.tangential_bottom = w.tangential[1];
    k.normal_top = w.normal[0]; k.normal_bottom = w.normal[1];
}

template <class Rng>
template <Mode M, TfRounding T>
void Engine<Rng>::update_as(int i) {
    Ctx c = context();
    visit<M, T>(c, i);
    commit(c);
}

// A grain's state kFar visits ahead, its grid neighbourhood kNear ahead (large lattices only).
// 16/8 measured best of 16/8, 24/12, 32/16 and 48/24 at 850 000 grains.
template <class Rng>
template <TfRounding T>
inline void Engine<Rng>::prefetch_ahead(const Ctx& c, const std::int32_t* order, std::uint32_t k, std::uint32_t n) {
    constexpr std::uint32_t kFar = 16, kNear = 8;
    if (k + kFar < n) {
        const std::int32_t f = order[k + kFar];
        __builtin_prefetch(c.up + f);
        // Neighbours' labels are close to f (relabelled in grid order): the speeds a chain will
        // strike are mostly within a column (~H labels) of f.
        __builtin_prefetch(c.up + std::max(f - 8, 0), 1);
        __builtin_prefetch(c.up + std::min<std::int64_t>(f + 8, n - 1), 1);
        __builtin_prefetch(c.pos + f);
        __builtin_prefetch(c.dir + f);
        if constexpr (T == TfRounding::Accumulate) __builtin_prefetch(c.acc + f);
        else __builtin_prefetch(c.tick + f);
    }
    if (k + kNear < n) {
        const std::int64_t p = c.pos[order[k + kNear]];
        const std::int64_t w = p - c.row.stride, e = p + c.row.stride;
        __builtin_prefetch(c.grid + (w < 0 ? w + c.ncell : w));
        __builtin_prefetch(c.grid + p);
        __builtin_prefetch(c.grid + (e >= c.ncell ? e - c.ncell : e));
    }
}

// The whole step for one (mode, clock rule): shuffle + updates, chunk by chunk. The update order
// is an in-place Fisher-Yates pass on the previous order; positions [0, s) of the pass are final,
// and the order stream is separate from the rule stream, so the pass can run one chunk ahead of the
// visits in its own tight loop (the visit loop keeps its registers) with draws and outcome those of
// a full shuffle followed by the updates. On large lattices a whole chunk's partners are drawn
// first and their slots prefetched. A grain whose time factor is up calls attempt(c, i, u): its
// move attempt and collision chain in step(), a count in step_clocks_only().
template <class Rng>
template <TfRounding T, bool Prefetch, class Attempt>
void Engine<Rng>::run(Attempt attempt) {
    const auto n = static_cast<std::uint32_t>(order_.size());
    if (n == 0) return;
    Ctx c = context();
    std::int32_t* const order = order_.data();
    constexpr std::uint32_t kChunk = 64;
    std::uint32_t s = 0;  // positions < s are final
    auto shuffle_chunk = [&] {
        const std::uint32_t end = std::min(n, s + kChunk);
        if constexpr (Prefetch) {
            std::uint32_t partner[kChunk];
            for (std::uint32_t q = s; q < end; ++q) {
                const std::uint32_t j = q + 1 < n ? q + order_rng_.below(n - q) : q;
                partner[q - s] = j;
                __builtin_prefetch(order + j, 1);
            }
            for (std::uint32_t q = s; q < end; ++q) std::swap(order[q], order[partner[q - s]]);
        } else {
            for (std::uint32_t q = s; q < end; ++q)
                if (q + 1 < n) std::swap(order[q], order[q + order_rng_.below(n - q)]);
        }
        s = end;
    };
    shuffle_chunk();
    // The next grain's speed and clock are read before the current chain runs, and its
    // "go" decided from them, so that this hard-to-predict branch resolves early. The speed
    // is checked again at the visit (the chain may have struck the grain); the clock only
    // changes at the grain's own visit.
    std::int32_t ni = order[0];
    double nu = c.up[ni];
    ClockOf<T> nk = load_clock<T>(c, ni);
    for (std::uint32_t k0 = 0; k0 < n; k0 += kChunk) {
        if (s < n) shuffle_chunk();  // now s >= k0 + kChunk (or n): one chunk ahead
        const std::uint32_t kend = std::min(n, k0 + kChunk);
        for (std::uint32_t k = k0; k < kend; ++k) {
            if constexpr (Prefetch) prefetch_ahead<T>(c, order, k, n);
            const std::int32_t i = ni;
            double u = nu;
            const ClockOf<T> kc = nk;
            ClockOf<T> k1;
            bool go = clock_decides<T>(u, kc, k1, c.rest, c.tf_max);
            if (k + 1 < n) {
                ni = order[k + 1];
                nu = c.up[ni];
                nk = load_clock<T>(c, ni);
            }
            const double u_now = c.up[i];
            if (u_now != u) [[unlikely]] {  // struck since it was read
                u = u_now;
                go = clock_decides<T>(u, kc, k1, c.rest, c.tf_max);
            }
            store_clock<T>(c, i, k1);
            if (go) attempt(c, i, u);
        }
    }
    commit(c);
}

// One visit: the clock, then the chain when the grain's time factor is up.
template <class Rng>
template <Mode M, TfRounding T>
inline void Engine<Rng>::visit(Ctx& c, std::int32_t i) {
    const double u = c.up[i];
    ClockOf<T> k1;
    const bool go = clock_decides<T>(u, load_clock<T>(c, i), k1, c.rest, c.tf_max);
    store_clock<T>(c, i, k1);
    if (go) chain<M>(c, i, u);
}

// The move attempt and collision chain of §3.2: try the current direction; an empty target
// is taken; a wall or grain collides, and the grain tries again in the new direction until
// it moves or every candidate direction has been tried. The mover's speed and direction are
// kept in registers and stored once at the end (a chain never strikes the mover itself).
template <class Rng>
template <Mode M>
inline void Engine<Rng>::chain(Ctx& c, std::int32_t i, double u) {
    const std::int64_t p = c.pos[i];
    unsigned d = c.dir[i];
    unsigned tried = 0;
    for (;;) {
        tried |= 1u << d;
        std::int64_t t = p + c.off[d];  // periodic x [JH06 §CA]: only x wraps
        t += t < 0 ? c.ncell : 0;
        t -= t >= c.ncell ? c.ncell : 0;
        const std::int32_t occ = c.grid[t];
        if (occ == kEmpty) {
            c.grid[p] = kEmpty;
            c.grid[t] = i;
            c.pos[i] = static_cast<std::uint32_t>(t);
            c.kin[c.row(static_cast<std::uint32_t>(p))] += kDx[d];
            ++c.moves;
            break;
        }
        Candidates next;
        bool two;
        if (occ >= 0) {
            ++c.pp;
            if constexpr (M == Mode::JH) {
                // Grain-grain, jh mode (§3.4): JH06 Eqs. 8-9 on both speeds; the struck grain moves
                // off along the line of centres [ASSUMPTION] (struck_dir = line); the mover's two
                // candidates in the order a coin picks.
                double uj = c.up[occ];
                eq8_9_collide_weighted(u, uj, c.eq89_weight);
                c.up[occ] = uj;
                if (c.line) c.dir[occ] = static_cast<std::uint8_t>(d);
                next = billiard_deflection(d, c.deflect, draw_coin(*c.rng, c.coins));
                two = true;
            } else {
                const VectorHit h = vector_grain_grain(
                    *c.rng, [&] { return draw_coin(*c.rng, c.coins); }, c.jitter, c.e_p, c.vec_wait, d, u,
                    c.up[occ], c.dir[occ]);
                if (h.wait) break;  // vec_blocked = wait
                next = h.next;
                two = h.two;
            }
        } else {
            const unsigned out = wall<M>(c, d, occ == kWallBottom, u);
            next = {out, out};
            two = false;
        }
        // The first candidate unless it would re-hit a blocked neighbour, then the second;
        // when both were tried, "all possible directions are exhausted": the grain stays,
        // keeping the first. Selects, not branches: after the first hit, whether the first
        // candidate was tried is a coin toss.
        const unsigned c0 = next.first, c1 = two ? next.second : c0;
        const unsigned try_next = (tried >> c0) & 1u ? c1 : c0;
        const bool stop = (tried >> try_next) & 1u;
        d = stop ? c0 : try_next;
        if (stop) {
            ++c.exhausted;
            break;
        }
    }
    c.dir[i] = static_cast<std::uint8_t>(d);
    c.up[i] = u;
}

// Particle-wall collision (§3.3; vector mode §5): applies the rules to the mover's speed u,
// adds the hit to the wall sums and returns the outgoing direction.
template <class Rng>
template <Mode M>
inline unsigned Engine<Rng>::wall(Ctx& c, unsigned d, bool bottom, double& u) {
    const double U_w = bottom ? 1.0 : 0.0;
    const double R = c.R[bottom], e_w = c.e_w[bottom];
    const double u0 = u;
    unsigned out;
    double ux0, ux1, vy0, vy1;
    if constexpr (M == Mode::JH) {
        const double u1 = wall_speed_jh(u0, d, U_w, R, e_w, c.sequential);
        u = u1;
        out = wall_reflection(d, bottom, [&] { return c.p_drag > 0 && c.rng->uniform() < c.p_drag; });
        ux0 = u0; ux1 = u1; vy0 = u0; vy1 = u1;  // u_p is the streamwise velocity (§4.1)
    } else {
        const Velocity v{u0 * kDx[d], u0 * kDy[d]};
        const Velocity v1 = vector_wall_velocity(v, U_w, R, e_w);
        out = discretise(*c.rng, v1.x, v1.y, u);
        ux0 = v.x; ux1 = u * kDx[out];
        vy0 = std::abs(v.y); vy1 = std::abs(v1.y);
    }
    ++c.walls->hits[bottom];
    c.walls->tangential[bottom] += ux1 - ux0;
    c.walls->normal[bottom] += vy0 + vy1;
    return out;
}

}  // namespace granlub::automaton
