// The lattice and its update: JH06's asynchronous CA (docs/automaton-model.md §2-3, optional §5).
//
// Data layout (§8): a flat occupancy grid of columns x (rows + 2) cells holding particle indices
// or the sentinels EMPTY / WALL_BOTTOM / WALL_TOP, column-major (x (H + 2) + y + 1) so that a
// grain's 3 x 3 neighbourhood spans about two cache lines; particle state as structure-of-arrays
// (cell index, direction, u_p, clock: 15 bytes a grain in the default mode), relabelled in grid
// order every `kRelabelEvery` steps so that neighbours' state is also close in memory; on large
// lattices the update loop prefetches the grains it will visit next. A grain's position is its
// flat cell index, so a move attempt is one addition and a periodic wrap. The step loop
// allocates nothing. These choices change which index a grain has, never the dynamics.
//
// Rng is Philox in production and a scripted source in the rule tests; it needs
// below(n), coin() and uniform(). Two sources: one for the update order, one for the rules.
#pragma once
#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>
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

// A random source whose coin reservoir can be held outside it (Philox; not the scripted one).
template <class R>
concept CoinReservoir = requires(R r, typename R::Coins& k) {
    { r.coin_from(k) } -> std::same_as<bool>;
    { r.coins() } -> std::same_as<typename R::Coins&>;
};
template <class R, bool = CoinReservoir<R>>
struct CoinStateOf { struct type {}; };
template <class R>
struct CoinStateOf<R, true> { using type = typename R::Coins; };

template <class Rng>
class Engine {
public:
    // An empty lattice (tests place grains with add()).
    Engine(int columns, int rows, const Rules& rules, Rng order_rng, Rng rule_rng)
        : L_(columns), H_(rows), rules_(rules), order_rng_(std::move(order_rng)),
          rng_(std::move(rule_rng)), grid_(static_cast<std::size_t>(rows + 2) * columns, kEmpty),
          kin_(static_cast<std::size_t>(rows), 0) {
        if (rules_.tf_max < 1 || rules_.tf_max > kTfMaxLimit)
            throw std::invalid_argument("automaton: tf_max must be in [1, " + std::to_string(kTfMaxLimit) + "]");
        for (int x = 0; x < L_; ++x) {
            grid_[index(x, -1)] = kWallBottom;
            grid_[index(x, H_)] = kWallTop;
        }
        rest_ = 1.0 / rules_.tf_max;
        tf_max_ = rules_.tf_max;
        const double s = rules_.pp_deflect == 45 ? 1 : 2;
        deflect_ = static_cast<int>(s);
        jitter_ = rules_.pp_jitter_deg * std::numbers::pi / 180.0;
        for (int d = 0; d < 8; ++d) off_[d] = kDx[d] * static_cast<std::int64_t>(stride_) + kDy[d];
        magic_ = ~std::uint64_t{0} / stride_ + 1;
    }

    // JH06's initial state (§2.5): N distinct random cells, random directions, u_p uniform on
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
        pos_.reserve(n); dir_.reserve(n); up_.reserve(n); order_.reserve(n);
        if (accumulate()) acc_.reserve(n); else tick_.reserve(n);
    }

    static constexpr std::int64_t kRelabelEvery = 64;
    // The integer clock is 16 bits wide (tf_rounding = round/ceil): tf_max is limited to this.
    static constexpr int kTfMaxLimit = 65535;

    // Place a grain; returns its index. The cell must be an empty particle cell.
    int add(int x, int y, int dir, double up, double clock = 0) {
        const auto i = static_cast<std::int32_t>(pos_.size());
        pos_.push_back(static_cast<std::uint32_t>(index(x, y)));
        dir_.push_back(static_cast<std::uint8_t>(dir));
        up_.push_back(up);
        if (accumulate()) acc_.push_back(clock); else tick_.push_back(static_cast<std::uint16_t>(clock));
        order_.push_back(i);
        grid_[index(x, y)] = i;
        return i;
    }

    // One time step (§3.1): a fresh uniformly random order of all grains (in-place Fisher-Yates
    // on the previous order), then every grain is updated in that order, each seeing the moves
    // already made in this step. The shuffle runs a chunk of positions ahead of the updates
    // (position k of the Fisher-Yates pass is final once it has been swapped, and the order
    // stream is separate from the rule stream), so draws and outcome are those of a full shuffle
    // followed by the updates.
    void step() {
        if (steps_ % kRelabelEvery == 0) relabel();
        ++steps_;
        const bool big = order_.size() > kPrefetchFrom;
        const bool acc = accumulate(), ceil = rules_.tf_rounding == TfRounding::Ceil;
        if (rules_.mode == Mode::JH) {
            if (acc) big ? run<Mode::JH, TfRounding::Accumulate, true>() : run<Mode::JH, TfRounding::Accumulate, false>();
            else if (ceil) big ? run<Mode::JH, TfRounding::Ceil, true>() : run<Mode::JH, TfRounding::Ceil, false>();
            else big ? run<Mode::JH, TfRounding::Round, true>() : run<Mode::JH, TfRounding::Round, false>();
        } else {
            if (acc) big ? run<Mode::Vector, TfRounding::Accumulate, true>() : run<Mode::Vector, TfRounding::Accumulate, false>();
            else if (ceil) big ? run<Mode::Vector, TfRounding::Ceil, true>() : run<Mode::Vector, TfRounding::Ceil, false>();
            else big ? run<Mode::Vector, TfRounding::Round, true>() : run<Mode::Vector, TfRounding::Round, false>();
        }
        counters_.visits += order_.size();
    }

    // Benchmark only (bench_automaton BM_StepSkeleton): a default-rule step (jh, round) that
    // counts the move attempts instead of making them. The shuffle, the clocks and the "does it
    // move" decision run as in step(); nothing moves or collides, so the lattice is frozen.
    // Its cost is the floor under the update order and the clocks that every step pays.
    // Returns this step's number of attempts.
    std::uint64_t step_skeleton() {
        skipped_attempts_ = 0;
        if (order_.size() > kPrefetchFrom) run<Mode::JH, TfRounding::Round, true, false>();
        else run<Mode::JH, TfRounding::Round, false, false>();
        return skipped_attempts_;
    }

    // Renumber the grains in grid order (spatial locality). The dynamics do not depend on labels:
    // the next step's order is a fresh uniform permutation whatever the labels are.
    void relabel() {
        const std::size_t n = pos_.size();
        if (n == 0) return;
        spos_.resize(n); sdir_.resize(n); sup_.resize(n);  // no-op after the first call
        if (accumulate()) sacc_.resize(n); else stick_.resize(n);
        std::int32_t next = 0;
        for (std::size_t c = 0; c < grid_.size(); ++c) {
            const std::int32_t old = grid_[c];
            if (old < 0) continue;
            spos_[next] = pos_[old]; sdir_[next] = dir_[old]; sup_[next] = up_[old];
            if (accumulate()) sacc_[next] = acc_[old]; else stick_[next] = tick_[old];
            grid_[c] = next++;
        }
        pos_.swap(spos_); dir_.swap(sdir_); up_.swap(sup_);
        if (accumulate()) acc_.swap(sacc_); else tick_.swap(stick_);
    }

    // One grain's update (§3.2): the time-factor clock, then the move attempt and collision chain.
    void update(int i) {
        if (accumulate()) update_as<TfRounding::Accumulate>(i);
        else if (rules_.tf_rounding == TfRounding::Ceil) update_as<TfRounding::Ceil>(i);
        else update_as<TfRounding::Round>(i);
    }

    // Does a grain of speed u (>= U/TF_max) move when its clock reaches c (integer-valued >= 1)?
    // I.e. c >= TF(u) with TF = round_half_up(U/u) (or ceil), capped at TF_max (§2.4). Written
    // with a multiplication instead of a division: for integers c, c >= floor(1/u + 1/2)
    // <=> u (c + 1/2) > 1, and c >= ceil(1/u) <=> u c >= 1.
    bool fires(double c, double u) const {
        return rules_.tf_rounding == TfRounding::Ceil ? fires_as<TfRounding::Ceil>(c, u, tf_max_)
                                                      : fires_as<TfRounding::Round>(c, u, tf_max_);
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
    std::size_t size() const { return pos_.size(); }
    int x(int i) const { return static_cast<int>(pos_[i] / stride_); }
    int y(int i) const { return row_of(pos_[i]); }
    int dir(int i) const { return dir_[i]; }
    double up(int i) const { return up_[i]; }
    double clock(int i) const { return accumulate() ? acc_[i] : tick_[i]; }
    void set_dir(int i, int d) { dir_[i] = static_cast<std::uint8_t>(d); }
    void set_up(int i, double u) { up_[i] = u; }
    void set_clock(int i, double c) {
        if (accumulate()) acc_[i] = c; else tick_[i] = static_cast<std::uint16_t>(c);
    }
    // Cell content at (x, y), y in [-1, rows]: a grain index or a sentinel.
    std::int32_t cell(int x, int y) const { return grid_[index(x, y)]; }
    const Counters& counters() const { return counters_; }
    const Rules& rules() const { return rules_; }
    Rng& rule_rng() { return rng_; }
    // Grain i's cell as a flat grid index x (rows + 2) + y + 1; row_of() gives its row.
    const BigVector<std::uint32_t>& cells() const { return pos_; }
    // Row y of grid index c (a division by the column length done with two multiplications:
    // Lemire, Kaser & Kurz, "Faster remainder by direct computation", 2019).
    int row_of(std::uint32_t c) const {
        __extension__ using u128 = unsigned __int128;
        const std::uint64_t low = magic_ * c;
        return static_cast<int>((static_cast<u128>(low) * stride_) >> 64) - 1;
    }
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
                    if (static_cast<std::size_t>(c) >= pos_.size() || x(c) != xx || y(c) != yy)
                        return "cell (" + std::to_string(xx) + "," + std::to_string(yy) + ") holds grain " +
                               std::to_string(c) + " which is elsewhere";
                } else if (c != kEmpty) {
                    return "wall sentinel inside the particle rows";
                }
            }
        if (found != pos_.size()) return "grain count on the grid " + std::to_string(found) + " != " +
                                         std::to_string(pos_.size());
        for (std::size_t i = 0; i < up_.size(); ++i)
            if (!(up_[i] >= 0.0 && up_[i] <= 1.0)) return "u_p of grain " + std::to_string(i) + " outside [0, U]";
        return "";
    }

private:
    // Grains from which the step loop prefetches (measured: below ~5e4 grains the state sits in
    // L2 and prefetching costs more than it saves).
    static constexpr std::size_t kPrefetchFrom = 50000;

    // Everything the update loop touches, copied into one local object for the duration of a
    // step (or a single update): raw pointers, rule parameters and event counters. Being local,
    // its fields live in registers; members would be reloaded after every store through the
    // state arrays (they may alias as far as the compiler knows).
    struct Ctx {
        std::int32_t* grid;
        std::uint32_t* pos;
        std::uint8_t* dir;
        double* up;
        std::uint16_t* tick;
        double* acc;
        std::int64_t* kin;
        Rng* rng;
        typename CoinStateOf<Rng>::type coins;  // the rule stream's coin reservoir, in registers
        std::int64_t ncell;
        std::int64_t off[8];
        std::uint64_t magic;
        std::uint32_t stride;
        double rest, tf_max;
        double e_p, half_1pe;  // e_p and (1 + e_p)/2 of Eqs. 8-9
        double R[2], e_w[2];   // [top, bottom]
        double p_drag, jitter;
        bool sequential, line, vec_wait;
        int deflect;
        std::uint64_t moves, pp, exhausted;
        // Wall hits are rare (~0.15 a visit): their sums stay in memory, indexed [top, bottom],
        // so that they do not compete for registers with the collision chain.
        struct WallSums {
            std::uint64_t hits[2];
            double tangential[2], normal[2];
        }* walls;
    };

    Ctx context() {
        Ctx c;
        c.grid = grid_.data(); c.pos = pos_.data(); c.dir = dir_.data(); c.up = up_.data();
        c.tick = tick_.data(); c.acc = acc_.data(); c.kin = kin_.data(); c.rng = &rng_;
        if constexpr (CoinReservoir<Rng>) c.coins = rng_.coins();
        c.ncell = static_cast<std::int64_t>(grid_.size());
        for (int d = 0; d < 8; ++d) c.off[d] = off_[d];
        c.magic = magic_;
        c.stride = stride_;
        c.rest = rest_; c.tf_max = tf_max_;
        c.e_p = rules_.e_p; c.half_1pe = 0.5 * (1.0 + rules_.e_p);
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
    void commit(const Ctx& c) {
        if constexpr (CoinReservoir<Rng>) rng_.coins() = c.coins;
        Counters& k = counters_;
        k.moves = c.moves; k.pp = c.pp; k.exhausted = c.exhausted;
        const auto& w = wall_sums_;
        k.wall_top = w.hits[0]; k.wall_bottom = w.hits[1];
        k.tangential_top = w.tangential[0]; k.tangential_bottom = w.tangential[1];
        k.normal_top = w.normal[0]; k.normal_bottom = w.normal[1];
    }

    bool accumulate() const { return rules_.tf_rounding == TfRounding::Accumulate; }
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(x) * stride_ + static_cast<std::size_t>(y + 1); }

    template <TfRounding T>
    static bool fires_as(double c, double u, double tf_max) {
        return (c >= tf_max) | (T == TfRounding::Ceil ? u * c >= 1.0 : u * (c + 0.5) > 1.0);
    }

    template <TfRounding T>
    void update_as(int i) {
        Ctx c = context();
        if (rules_.mode == Mode::JH) visit<Mode::JH, T>(c, i); else visit<Mode::Vector, T>(c, i);
        commit(c);
    }

    // The whole step for one (mode, clock rule): shuffle + updates, chunk by chunk (see step()).
    // Positions [0, s) of the Fisher-Yates pass are final; the pass runs one chunk ahead of the
    // visits in its own tight loop (so that the visit loop keeps its registers), and on large
    // lattices draws a whole chunk's partners first, prefetching their slots.
    template <Mode M, TfRounding T, bool Prefetch, bool Attempts = true>
    void run() {
        const auto n = static_cast<std::uint32_t>(order_.size());
        if (n == 0) return;
        Ctx c = context();
        std::int32_t* const order = order_.data();
        constexpr std::uint32_t kChunk = 64, kFar = 16, kNear = 8;
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
                if constexpr (Prefetch) {
                    // A grain's state kFar visits ahead, its grid neighbourhood kNear ahead.
                    if (k + kFar < n) {
                        const std::int32_t f = order[k + kFar];
                        __builtin_prefetch(c.up + f);
                        // Neighbours' labels are close to f (relabelled in grid order): the
                        // speeds a chain will strike are mostly within a column (~H labels) of f.
                        __builtin_prefetch(c.up + std::max(f - 8, 0), 1);
                        __builtin_prefetch(c.up + std::min<std::int64_t>(f + 8, n - 1), 1);
                        __builtin_prefetch(c.pos + f);
                        __builtin_prefetch(c.dir + f);
                        if constexpr (T == TfRounding::Accumulate) __builtin_prefetch(c.acc + f);
                        else __builtin_prefetch(c.tick + f);
                    }
                    if (k + kNear < n) {
                        const std::int64_t p = c.pos[order[k + kNear]];
                        const std::int64_t w = p - c.stride, e = p + c.stride;
                        __builtin_prefetch(c.grid + (w < 0 ? w + c.ncell : w));
                        __builtin_prefetch(c.grid + p);
                        __builtin_prefetch(c.grid + (e >= c.ncell ? e - c.ncell : e));
                    }
                }
                const std::int32_t i = ni;
                double u = nu;
                const ClockOf<T> kc = nk;
                ClockOf<T> k1;
                bool go = decide<T>(c, u, kc, k1);
                if (k + 1 < n) {
                    ni = order[k + 1];
                    nu = c.up[ni];
                    nk = load_clock<T>(c, ni);
                }
                const double u_now = c.up[i];
                if (u_now != u) [[unlikely]] {  // struck since it was read
                    u = u_now;
                    go = decide<T>(c, u, kc, k1);
                }
                store_clock<T>(c, i, k1);
                if constexpr (Attempts) {
                    if (go) chain<M>(c, i, u);
                } else {
                    skipped_attempts_ += go;
                }
            }
        }
        commit(c);
    }

    // The clock (§3.2, §2.4). A grain at rest (u < U/TF_max) never initiates a move and keeps
    // its clock; it can still be struck [ASSUMED]. Otherwise the clock advances, and the grain
    // moves ("go") when its time factor is up. Selects, not branches.
    template <TfRounding T>
    using ClockOf = std::conditional_t<T == TfRounding::Accumulate, double, unsigned>;
    template <TfRounding T>
    static ClockOf<T> load_clock(const Ctx& c, std::int32_t i) {
        if constexpr (T == TfRounding::Accumulate) return c.acc[i]; else return c.tick[i];
    }
    template <TfRounding T>
    static void store_clock(Ctx& c, std::int32_t i, ClockOf<T> k) {
        if constexpr (T == TfRounding::Accumulate) c.acc[i] = k; else c.tick[i] = static_cast<std::uint16_t>(k);
    }
    template <TfRounding T>
    static bool decide(const Ctx& c, double u, ClockOf<T> k0, ClockOf<T>& k1) {
        const bool moving = u >= c.rest;
        bool go;
        if constexpr (T == TfRounding::Accumulate) {  // continuous rate, cf. LGrM offset
            const double a = k0 + u;
            go = moving && a >= 1.0;
            k1 = !moving ? k0 : (go ? a - 1.0 : a);
        } else {  // time factor TF = round(U/u_p) [JH06 §CA]: move once every TF updates
            const unsigned t = k0 + 1u;
            go = moving && fires_as<T>(static_cast<double>(t), u, c.tf_max);
            k1 = !moving ? k0 : (go ? 0u : t);
        }
        return go;
    }

    // One visit: the clock, then the chain when the grain's time factor is up.
    template <Mode M, TfRounding T>
    [[gnu::always_inline]] inline void visit(Ctx& c, std::int32_t i) {
        const double u = c.up[i];
        ClockOf<T> k1;
        const bool go = decide<T>(c, u, load_clock<T>(c, i), k1);
        store_clock<T>(c, i, k1);
        if (go) chain<M>(c, i, u);
    }

    // The move attempt and collision chain of §3.2: try the current direction; an empty target
    // is taken; a wall or grain collides, and the grain tries again in the new direction until
    // it moves or every candidate direction has been tried. The mover's speed and direction are
    // kept in registers and stored once at the end (a chain never strikes the mover itself).
    template <Mode M>
    [[gnu::always_inline]] inline void chain(Ctx& c, std::int32_t i, double u) {
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
                c.kin[row(c, p)] += kDx[d];
                ++c.moves;
                break;
            }
            unsigned c0, c1;
            bool two;
            if (occ >= 0) {
                if constexpr (M == Mode::JH) {
                    // Grain-grain, jh mode (§3.4, Table P): JH06 Eqs. 8-9 on the scalars; the mover
                    // leaves at +-90 degrees (billiard 90-degree rule, random side) [RECON]; the
                    // struck grain moves off along the line of centres [ASSUMED] (struck_dir = line).
                    ++c.pp;
                    double uj = c.up[occ];
                    const double delta = c.half_1pe * (uj - u);
                    u = clamp_unit(u + delta);
                    c.up[occ] = clamp_unit(uj - delta);
                    if (c.line) c.dir[occ] = static_cast<std::uint8_t>(d);
                    // "two possible resulting directions ... chosen randomly": a coin, used as a
                    // mask (no branch on it).
                    const unsigned plus_first = coin(c);
                    const unsigned a = (d + c.deflect) & 7u, b = (d - c.deflect) & 7u;
                    c0 = b ^ ((a ^ b) & (0u - plus_first));
                    c1 = a ^ b ^ c0;
                    two = true;
                } else {
                    if (!collide_vector(c, occ, d, u, c0, c1, two)) break;  // vec_blocked = wait
                }
            } else {
                c0 = wall<M>(c, d, occ == kWallBottom, u);
                c1 = c0;
                two = false;
            }
            // The first candidate unless it would re-hit a blocked neighbour, then the second;
            // when both were tried, "all possible directions are exhausted": the grain stays,
            // keeping the first. Selects, not branches: after the first hit, whether the first
            // candidate was tried is a coin toss.
            if (!two) c1 = c0;
            const unsigned next = (tried >> c0) & 1u ? c1 : c0;
            const bool stop = (tried >> next) & 1u;
            d = stop ? c0 : next;
            if (stop) {
                ++c.exhausted;
                break;
            }
        }
        c.dir[i] = static_cast<std::uint8_t>(d);
        c.up[i] = u;
    }

    static bool coin(Ctx& c) {
        if constexpr (CoinReservoir<Rng>) return c.rng->coin_from(c.coins);
        else return c.rng->coin();
    }

    static int row(const Ctx& c, std::int64_t p) {
        __extension__ using u128 = unsigned __int128;
        const std::uint64_t low = c.magic * static_cast<std::uint32_t>(p);
        return static_cast<int>((static_cast<u128>(low) * c.stride) >> 64) - 1;
    }

    // Particle-wall collision (§3.3, Tables W-B / W-T; vector mode §5); u is the mover's speed,
    // updated; returns the outgoing direction.
    template <Mode M>
    [[gnu::always_inline]] inline unsigned wall(Ctx& c, unsigned d, bool bottom, double& u) {
        const double U_w = bottom ? 1.0 : 0.0;
        const double R = c.R[bottom], e_w = c.e_w[bottom];
        const double u0 = u;
        unsigned out;
        double ux0, ux1, vy0, vy1;
        if constexpr (M == Mode::JH) {
            // Speed: JH06 Eqs. 6-7 on the scalar u_p.
            const double u1 = c.sequential ? wall_sequential(u0, U_w, R, e_w)
                                           : wall_by_incidence(u0, U_w, R, e_w, kDx[d] == 0);
            u = u1;
            // Direction: specular reflection [RECON]; at the moving wall, with probability
            // p_drag, one notch toward +x, never past NE [ASSUMED].
            out = kReflect[d];
            if (bottom && out != NE && c.p_drag > 0 && c.rng->uniform() < c.p_drag) out = kDrag[out];
            ux0 = u0; ux1 = u1; vy0 = u0; vy1 = u1;  // u_p is the streamwise velocity (§4.1)
        } else {
            // Vector mode [ASSUMED]: Eq. 6 on the tangential, Eq. 7 on the normal component.
            const double vx = u0 * kDx[d], vy = u0 * kDy[d];
            const double vx1 = eq6_roughness(vx, U_w, R);
            const double vy1v = -e_w * vy;
            out = discretise(c, vx1, vy1v, u);
            ux0 = vx; ux1 = u * kDx[out];
            vy0 = std::abs(vy); vy1 = std::abs(vy1v);
        }
        ++c.walls->hits[bottom];
        c.walls->tangential[bottom] += ux1 - ux0;
        c.walls->normal[bottom] += vy0 + vy1;
        return out;
    }

    // Grain-grain collision, vector mode (§5) [ASSUMED]: Eqs. 8-9 on the normal components along
    // a jittered line of centres, tangential components kept, both grains re-discretised.
    // Returns false when the grain waits (not approaching, vec_blocked = wait).
    bool collide_vector(Ctx& c, std::int32_t j, unsigned d, double& u, unsigned& c0, unsigned& c1, bool& two) {
        ++c.pp;
        const double theta = d * (std::numbers::pi / 4) + c.jitter * (2.0 * c.rng->uniform() - 1.0);
        const double nx = std::cos(theta), ny = std::sin(theta);
        const double ui = u, uj = c.up[j];
        const int dj = c.dir[j];
        double vix = ui * kDx[d], viy = ui * kDy[d];
        double vjx = uj * kDx[dj], vjy = uj * kDy[dj];
        const double a1 = vix * nx + viy * ny, a2 = vjx * nx + vjy * ny;
        if (a1 <= a2) {  // not approaching: no impact
            if (c.vec_wait) return false;
            const bool plus_first = coin(c);
            const unsigned a = rotate(static_cast<int>(d), 1), b = rotate(static_cast<int>(d), -1);
            c0 = plus_first ? a : b;
            c1 = plus_first ? b : a;
            two = true;
            return true;
        }
        const double a1f = 0.5 * ((1 - c.e_p) * a1 + (1 + c.e_p) * a2);
        const double a2f = 0.5 * ((1 - c.e_p) * a2 + (1 + c.e_p) * a1);
        vix += (a1f - a1) * nx; viy += (a1f - a1) * ny;
        vjx += (a2f - a2) * nx; vjy += (a2f - a2) * ny;
        c0 = discretise(c, vix, viy, u);
        c1 = c0;
        two = false;
        double uj1 = uj;
        c.dir[j] = static_cast<std::uint8_t>(discretise(c, vjx, vjy, uj1));
        c.up[j] = uj1;
        return true;
    }

    // Stochastic king-move rounding of a velocity onto the 8 directions, unbiased in the mean
    // (§5); sets the speed to min(max(|vx|, |vy|), U) and returns the direction.
    static unsigned discretise(Ctx& c, double vx, double vy, double& speed) {
        const double ax = std::abs(vx), ay = std::abs(vy);
        const double s = std::max(ax, ay);
        if (s == 0.0) {
            speed = 0.0;
            return c.rng->below(8);
        }
        int dx, dy;
        if (ax >= ay) {
            dx = vx > 0 ? 1 : -1;
            dy = (ay > 0 && c.rng->uniform() < ay / ax) ? (vy > 0 ? 1 : -1) : 0;
        } else {
            dy = vy > 0 ? 1 : -1;
            dx = (ax > 0 && c.rng->uniform() < ax / ay) ? (vx > 0 ? 1 : -1) : 0;
        }
        speed = std::min(s, 1.0);
        return from_step(dx, dy);
    }

    int L_, H_;
    std::uint32_t stride_ = static_cast<std::uint32_t>(H_) + 2;  // grid column length
    Rules rules_;
    Rng order_rng_;
    Rng rng_;
    double rest_ = 0.02;
    double tf_max_ = 50;
    int deflect_ = 2;
    double jitter_ = 0;
    std::int64_t off_[8] = {};     // grid-index offset of a step in each direction
    std::uint64_t magic_ = 0;      // for row_of()
    BigVector<std::int32_t> grid_;
    BigVector<std::uint32_t> pos_;  // flat grid index of each grain's cell
    BigVector<std::uint8_t> dir_;
    BigVector<double> up_;
    BigVector<std::uint16_t> tick_;  // integer clock (round / ceil)
    BigVector<double> acc_;          // progress clock (accumulate)
    BigVector<std::int32_t> order_;
    std::vector<std::int64_t> kin_;
    std::int64_t steps_ = 0;
    BigVector<std::uint32_t> spos_;  // relabelling scratch, allocated once
    BigVector<std::uint8_t> sdir_;
    BigVector<double> sup_, sacc_;
    BigVector<std::uint16_t> stick_;
    Counters counters_;
    std::uint64_t skipped_attempts_ = 0;  // step_skeleton() only
    typename Ctx::WallSums wall_sums_{};  // wall sums during a step (Ctx::walls points here)
};

}  // namespace granlub::automaton
