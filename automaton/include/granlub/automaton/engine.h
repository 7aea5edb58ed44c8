// The lattice and its update: JH06's asynchronous CA (ca-model.md §2-3, optional §5).
//
// Data layout (§8): a flat occupancy grid of columns x (rows + 2) cells holding particle indices
// or the sentinels EMPTY / WALL_BOTTOM / WALL_TOP, column-major (x (H + 2) + y + 1) so that a
// grain's 3 x 3 neighbourhood spans about two cache lines; particle state as structure-of-arrays,
// relabelled in grid order every `kRelabelEvery` steps so that neighbours' state is also close in
// memory; the update loop prefetches the grains it will visit next. The step loop allocates
// nothing. These choices change which index a grain has, never the dynamics.
//
// Rng is Philox in production and a scripted source in the rule tests; it needs
// below(n), coin() and uniform(). Two sources: one for the update order, one for the rules.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "granlub/automaton/directions.h"
#include "granlub/automaton/huge_page_allocator.h"
#include "granlub/automaton/params.h"
#include "granlub/automaton/speed_rules.h"

namespace granlub::automaton {

inline constexpr std::int32_t kEmpty = -1;
inline constexpr std::int32_t kWallBottom = -2;
inline constexpr std::int32_t kWallTop = -3;

// Cumulative event counts and wall momentum (lattice units: grain mass x U).
struct Counters {
    std::uint64_t visits = 0;          // particle updates (including grains waiting on their clock)
    std::uint64_t moves = 0;
    std::uint64_t pp = 0;              // grain-grain collisions
    std::uint64_t wall_bottom = 0;
    std::uint64_t wall_top = 0;
    std::uint64_t exhausted = 0;       // "all possible directions exhausted": the grain stays
    double tangential_bottom = 0;      // sum of (u_x after - u_x before) at bottom-wall hits
    double tangential_top = 0;         // same at the top wall (negative: the wall brakes)
    double normal_bottom = 0;          // sum of |v_y before| + |v_y after| at bottom-wall hits
    double normal_top = 0;
};

template <class Rng>
class Engine {
public:
    // An empty lattice (tests place grains with add()).
    Engine(int columns, int rows, const Rules& rules, Rng order_rng, Rng rule_rng)
        : L_(columns), H_(rows), rules_(rules), order_rng_(std::move(order_rng)),
          rng_(std::move(rule_rng)), grid_(static_cast<std::size_t>(rows + 2) * columns, kEmpty),
          kin_(static_cast<std::size_t>(rows), 0) {
        for (int x = 0; x < L_; ++x) {
            grid_[index(x, -1)] = kWallBottom;
            grid_[index(x, H_)] = kWallTop;
        }
        rest_ = 1.0 / rules_.tf_max;
        tf_max_ = rules_.tf_max;
        const double s = rules_.pp_deflect == 45 ? 1 : 2;
        deflect_ = static_cast<int>(s);
        jitter_ = rules_.pp_jitter_deg * std::numbers::pi / 180.0;
    }

    // JH06's initial state (§2.7): N distinct random cells, random directions, u_p uniform on
    // (0, s0_max], clocks at a random phase. Draws come from the rule stream.
    void fill_random(const LatticeSpec& spec) {
        const std::int64_t n = spec.particles();
        std::vector<std::int32_t> cells(static_cast<std::size_t>(L_) * H_);
        for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = static_cast<std::int32_t>(c);
        reserve(static_cast<std::size_t>(n));
        for (std::int64_t k = 0; k < n; ++k) {  // partial Fisher-Yates: N distinct cells
            const auto j = static_cast<std::size_t>(k) +
                           rng_.below(static_cast<std::uint32_t>(cells.size() - static_cast<std::size_t>(k)));
            std::swap(cells[static_cast<std::size_t>(k)], cells[j]);
            const int c = cells[static_cast<std::size_t>(k)];
            const auto d = static_cast<std::uint8_t>(rng_.below(8));
            const double u = std::max((1.0 - rng_.uniform()) * spec.s0_max, 1e-9);
            double clock = 0;
            if (rules_.tf_rounding == TfRounding::Accumulate)
                clock = rng_.uniform();
            else if (u >= rest_)
                clock = rng_.below(static_cast<std::uint32_t>(tf(u)));
            add(c % L_, c / L_, d, u, clock);
        }
    }

    void reserve(std::size_t n) {
        x_.reserve(n); y_.reserve(n); dir_.reserve(n); up_.reserve(n); clock_.reserve(n); order_.reserve(n);
    }

    static constexpr std::int64_t kRelabelEvery = 64;

    // Place a grain; returns its index. The cell must be an empty particle cell.
    int add(int x, int y, int dir, double up, double clock = 0) {
        const auto i = static_cast<std::int32_t>(x_.size());
        x_.push_back(x);
        y_.push_back(y);
        dir_.push_back(static_cast<std::uint8_t>(dir));
        up_.push_back(up);
        clock_.push_back(clock);
        order_.push_back(i);
        grid_[index(x, y)] = i;
        return i;
    }

    // One time step (§3.1): a fresh uniformly random order of all grains (in-place Fisher-Yates
    // on the previous order), then every grain is updated in that order, each seeing the moves
    // already made in this step.
    void step() {
        const auto n = static_cast<std::uint32_t>(order_.size());
        if (steps_ % kRelabelEvery == 0) relabel();
        ++steps_;
        std::int32_t* order = order_.data();
        for (std::uint32_t k = 0; k + 1 < n; ++k) {
            const std::uint32_t j = k + order_rng_.below(n - k);
            std::swap(order[k], order[j]);
        }
        // Prefetch pipeline: a grain's state kFar visits ahead, its neighbourhood kNear ahead.
        constexpr std::uint32_t kFar = 16, kNear = 8;
        for (std::uint32_t k = 0; k < n; ++k) {
            if (k + kFar < n) {
                const std::int32_t f = order[k + kFar];
                __builtin_prefetch(&up_[f]);
                __builtin_prefetch(&clock_[f]);
                __builtin_prefetch(&x_[f]);
                __builtin_prefetch(&y_[f]);
                __builtin_prefetch(&dir_[f]);
            }
            if (k + kNear < n) {
                const std::int32_t f = order[k + kNear];
                const int xf = x_[f], yf = y_[f];
                __builtin_prefetch(&grid_[index(xf == 0 ? L_ - 1 : xf - 1, yf)]);
                __builtin_prefetch(&grid_[index(xf, yf)]);
                __builtin_prefetch(&grid_[index(xf == L_ - 1 ? 0 : xf + 1, yf)]);
            }
            update(order[k]);
        }
        counters_.visits += n;
    }

    // Renumber the grains in grid order (spatial locality). The dynamics do not depend on labels:
    // the next step's order is a fresh uniform permutation whatever the labels are.
    void relabel() {
        const std::size_t n = x_.size();
        if (n == 0) return;
        sx_.resize(n); sy_.resize(n); sdir_.resize(n); sup_.resize(n); sclock_.resize(n);  // no-op after the first call
        std::int32_t next = 0;
        for (std::size_t c = 0; c < grid_.size(); ++c) {
            const std::int32_t old = grid_[c];
            if (old < 0) continue;
            sx_[next] = x_[old]; sy_[next] = y_[old]; sdir_[next] = dir_[old];
            sup_[next] = up_[old]; sclock_[next] = clock_[old];
            grid_[c] = next++;
        }
        x_.swap(sx_); y_.swap(sy_); dir_.swap(sdir_); up_.swap(sup_); clock_.swap(sclock_);
    }

    // One grain's update (§3.2): the time-factor clock, then the move attempt and collision chain.
    void update(int i) {
        const double u = up_[i];
        if (u < rest_) return;  // at rest: never initiates a move, can still be struck [ASSUMED]
        if (rules_.tf_rounding == TfRounding::Accumulate) {  // continuous rate, cf. LGrM offset
            const double c = clock_[i] + u;
            if (c < 1.0) { clock_[i] = c; return; }
            clock_[i] = c - 1.0;
        } else {  // time factor TF = round(U/u_p) [JH06 §CA]: move once every TF updates
            const double c = clock_[i] + 1.0;
            if (!fires(c, u)) { clock_[i] = c; return; }
            clock_[i] = 0;
        }
        chain(i);
    }

    // Does a grain of speed u (>= U/TF_max) move when its clock reaches c (integer-valued >= 1)?
    // I.e. c >= TF(u) with TF = round_half_up(U/u) (or ceil), capped at TF_max (§2.4). Written
    // with a multiplication instead of a division: for integers c, c >= floor(1/u + 1/2)
    // <=> u (c + 1/2) > 1, and c >= ceil(1/u) <=> u c >= 1.
    bool fires(double c, double u) const {
        if (c >= tf_max_) return true;
        return rules_.tf_rounding == TfRounding::Ceil ? u * c >= 1.0 : u * (c + 0.5) > 1.0;
    }

    // Time factor of a moving grain (u >= U/TF_max), §2.4: the first clock value that fires.
    int tf(double u) const {
        int t = std::clamp(static_cast<int>(1.0 / u), 1, rules_.tf_max);  // within one of the answer
        while (t > 1 && fires(t - 1, u)) --t;
        while (!fires(t, u)) ++t;
        return t;
    }

    // Accessors (tests, sampler, snapshots).
    int columns() const { return L_; }
    int rows() const { return H_; }
    std::size_t size() const { return x_.size(); }
    int x(int i) const { return x_[i]; }
    int y(int i) const { return y_[i]; }
    int dir(int i) const { return dir_[i]; }
    double up(int i) const { return up_[i]; }
    double clock(int i) const { return clock_[i]; }
    void set_dir(int i, int d) { dir_[i] = static_cast<std::uint8_t>(d); }
    void set_up(int i, double u) { up_[i] = u; }
    void set_clock(int i, double c) { clock_[i] = c; }
    // Cell content at (x, y), y in [-1, rows]: a grain index or a sentinel.
    std::int32_t cell(int x, int y) const { return grid_[index(x, y)]; }
    const Counters& counters() const { return counters_; }
    const Rules& rules() const { return rules_; }
    Rng& rule_rng() { return rng_; }
    const BigVector<int>& xs() const { return x_; }
    const BigVector<int>& ys() const { return y_; }
    const BigVector<std::uint8_t>& dirs() const { return dir_; }
    const BigVector<double>& speeds() const { return up_; }
    // Streamwise lattice displacements made from each row since the last take_kin() (u_kin, §4.2).
    std::vector<std::int64_t>& kin() { return kin_; }

    // The invariants of §3.5 that hold at any time; "" when all hold, else what failed.
    std::string check_invariants() const {
        std::size_t found = 0;
        for (int yy = -1; yy <= H_; ++yy)
            for (int xx = 0; xx < L_; ++xx) {
                const std::int32_t c = cell(xx, yy);
                if (yy == -1 && c != kWallBottom) return "bottom wall row damaged";
                if (yy == H_ && c != kWallTop) return "top wall row damaged";
                if (yy < 0 || yy >= H_) continue;
                if (c >= 0) {
                    ++found;
                    if (static_cast<std::size_t>(c) >= x_.size() || x_[c] != xx || y_[c] != yy)
                        return "cell (" + std::to_string(xx) + "," + std::to_string(yy) + ") holds grain " +
                               std::to_string(c) + " which is elsewhere";
                } else if (c != kEmpty) {
                    return "wall sentinel inside the particle rows";
                }
            }
        if (found != x_.size()) return "grain count on the grid " + std::to_string(found) + " != " +
                                       std::to_string(x_.size());
        for (std::size_t i = 0; i < up_.size(); ++i)
            if (!(up_[i] >= 0.0 && up_[i] <= 1.0)) return "u_p of grain " + std::to_string(i) + " outside [0, U]";
        return "";
    }

private:
    struct Candidates {  // outgoing directions of a collision, already in random order (§3.2)
        int n = 0;
        std::uint8_t c[2] = {0, 0};
    };

    std::size_t index(int x, int y) const { return static_cast<std::size_t>(x) * stride_ + static_cast<std::size_t>(y + 1); }

    // The move attempt and collision chain of §3.2: try the current direction; an empty target
    // is taken; a wall or grain collides, and the grain tries again in the new direction until
    // it moves or every candidate direction has been tried.
    void chain(int i) {
        unsigned tried = 0;
        const int xi = x_[i], yi = y_[i];
        for (;;) {
            const int d = dir_[i];
            tried |= 1u << d;
            int tx = xi + kDx[d];
            tx = tx < 0 ? tx + L_ : (tx >= L_ ? tx - L_ : tx);  // periodic x [JH06 §CA]
            const int ty = yi + kDy[d];
            const std::size_t target = index(tx, ty);
            const std::int32_t occ = grid_[target];
            if (occ == kEmpty) {
                grid_[index(xi, yi)] = kEmpty;
                grid_[target] = i;
                x_[i] = tx;
                y_[i] = ty;
                kin_[yi] += kDx[d];
                ++counters_.moves;
                return;
            }
            Candidates C;
            if (occ >= 0)
                C = rules_.mode == Mode::JH ? collide_jh(i, occ, d) : collide_vector(i, occ, d);
            else
                C = wall(i, d, occ == kWallBottom);
            if (C.n == 0) return;  // vector mode, vec_blocked = wait
            std::uint8_t next = C.c[0];
            dir_[i] = next;
            if (tried & (1u << next)) {  // would re-hit a blocked neighbour
                if (C.n == 2 && !(tried & (1u << C.c[1]))) {
                    next = C.c[1];
                    dir_[i] = next;
                } else {
                    ++counters_.exhausted;  // "all possible directions are exhausted": stay
                    return;
                }
            }
        }
    }

    // Particle-wall collision (§3.3, Tables W-B / W-T; vector mode §5).
    Candidates wall(int i, int d, bool bottom) {
        const double U_w = bottom ? 1.0 : 0.0;
        const double R = bottom ? rules_.R_bottom : rules_.R_top;
        const double e_w = bottom ? rules_.e_w_bottom : rules_.e_w_top;
        const double u0 = up_[i];
        Candidates C{1, {0, 0}};
        double ux0, ux1, vy0, vy1;
        if (rules_.mode == Mode::JH) {
            // Speed: JH06 Eqs. 6-7 on the scalar u_p.
            const double u1 = rules_.wall_speed == WallSpeed::Sequential
                                  ? wall_sequential(u0, U_w, R, e_w)
                                  : wall_by_incidence(u0, U_w, R, e_w, kDx[d] == 0);
            up_[i] = u1;
            // Direction: specular reflection [RECON]; at the moving wall, with probability
            // p_drag, one notch toward +x, never past NE [ASSUMED].
            std::uint8_t out = kReflect[d];
            if (bottom && out != NE && rules_.p_drag > 0 && rng_.uniform() < rules_.p_drag) out = kDrag[out];
            C.c[0] = out;
            ux0 = u0; ux1 = u1; vy0 = u0; vy1 = u1;  // u_p is the streamwise velocity (§4.1)
        } else {
            // Vector mode [ASSUMED]: Eq. 6 on the tangential, Eq. 7 on the normal component.
            const double vx = u0 * kDx[d], vy = u0 * kDy[d];
            const double vx1 = eq6_roughness(vx, U_w, R);
            const double vy1v = -e_w * vy;
            C.c[0] = discretise(vx1, vy1v, i);
            ux0 = vx; ux1 = up_[i] * kDx[C.c[0]];
            vy0 = std::abs(vy); vy1 = std::abs(vy1v);
        }
        if (bottom) {
            ++counters_.wall_bottom;
            counters_.tangential_bottom += ux1 - ux0;
            counters_.normal_bottom += vy0 + vy1;
        } else {
            ++counters_.wall_top;
            counters_.tangential_top += ux1 - ux0;
            counters_.normal_top += vy0 + vy1;
        }
        return C;
    }

    // Grain-grain collision, jh mode (§3.4, Table P): JH06 Eqs. 8-9 on the scalars; the mover
    // leaves at +-90 degrees (billiard 90-degree rule, random side) [RECON]; the struck grain
    // moves off along the line of centres [ASSUMED] (struck_dir = line).
    Candidates collide_jh(int i, int j, int d) {
        ++counters_.pp;
        eq8_9_collide(up_[i], up_[j], rules_.e_p);
        if (rules_.struck_dir == StruckDir::Line) dir_[j] = static_cast<std::uint8_t>(d);
        const bool plus_first = rng_.coin();  // "two possible resulting directions ... chosen randomly"
        const std::uint8_t a = rotate(d, deflect_), b = rotate(d, -deflect_);
        return plus_first ? Candidates{2, {a, b}} : Candidates{2, {b, a}};
    }

    // Grain-grain collision, vector mode (§5) [ASSUMED]: Eqs. 8-9 on the normal components along
    // a jittered line of centres, tangential components kept, both grains re-discretised.
    Candidates collide_vector(int i, int j, int d) {
        ++counters_.pp;
        const double theta = d * (std::numbers::pi / 4) + jitter_ * (2.0 * rng_.uniform() - 1.0);
        const double nx = std::cos(theta), ny = std::sin(theta);
        const double ui = up_[i], uj = up_[j];
        const int dj = dir_[j];
        double vix = ui * kDx[d], viy = ui * kDy[d];
        double vjx = uj * kDx[dj], vjy = uj * kDy[dj];
        const double a1 = vix * nx + viy * ny, a2 = vjx * nx + vjy * ny;
        if (a1 <= a2) {  // not approaching: no impact
            if (rules_.vec_blocked == VecBlocked::Wait) return Candidates{0, {0, 0}};
            const bool plus_first = rng_.coin();
            const std::uint8_t a = rotate(d, 1), b = rotate(d, -1);
            return plus_first ? Candidates{2, {a, b}} : Candidates{2, {b, a}};
        }
        const double a1f = 0.5 * ((1 - rules_.e_p) * a1 + (1 + rules_.e_p) * a2);
        const double a2f = 0.5 * ((1 - rules_.e_p) * a2 + (1 + rules_.e_p) * a1);
        vix += (a1f - a1) * nx; viy += (a1f - a1) * ny;
        vjx += (a2f - a2) * nx; vjy += (a2f - a2) * ny;
        const std::uint8_t di = discretise(vix, viy, i);
        dir_[j] = discretise(vjx, vjy, j);
        return Candidates{1, {di, 0}};
    }

    // Stochastic king-move rounding of a velocity onto the 8 directions, unbiased in the mean
    // (§5); sets u_p = min(max(|vx|, |vy|), U) and returns the direction.
    std::uint8_t discretise(double vx, double vy, int i) {
        const double ax = std::abs(vx), ay = std::abs(vy);
        const double s = std::max(ax, ay);
        if (s == 0.0) {
            up_[i] = 0.0;
            return static_cast<std::uint8_t>(rng_.below(8));
        }
        int dx, dy;
        if (ax >= ay) {
            dx = vx > 0 ? 1 : -1;
            dy = (ay > 0 && rng_.uniform() < ay / ax) ? (vy > 0 ? 1 : -1) : 0;
        } else {
            dy = vy > 0 ? 1 : -1;
            dx = (ax > 0 && rng_.uniform() < ax / ay) ? (vx > 0 ? 1 : -1) : 0;
        }
        up_[i] = std::min(s, 1.0);
        return from_step(dx, dy);
    }

    int L_, H_;
    std::size_t stride_ = static_cast<std::size_t>(H_) + 2;  // grid column length
    Rules rules_;
    Rng order_rng_;
    Rng rng_;
    double rest_ = 0.02;
    double tf_max_ = 50;
    int deflect_ = 2;
    double jitter_ = 0;
    BigVector<std::int32_t> grid_;
    BigVector<int> x_, y_;
    BigVector<std::uint8_t> dir_;
    BigVector<double> up_;
    BigVector<double> clock_;
    BigVector<std::int32_t> order_;
    std::vector<std::int64_t> kin_;
    std::int64_t steps_ = 0;
    BigVector<int> sx_, sy_;  // relabelling scratch, allocated once
    BigVector<std::uint8_t> sdir_;
    BigVector<double> sup_, sclock_;
    Counters counters_;
};

}  // namespace granlub::automaton
