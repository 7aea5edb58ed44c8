// The lattice and its update: JH06's asynchronous CA (docs/automaton-model.md §2-3, optional §5).
// This file holds the Engine class, its state and its accessors. The step loop is in
// engine_step.h, the collision rules it applies in collision_rules.h and speed_rules.h, the clock
// in time_factor.h, the invariant check in invariants.h.
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
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "granlub/automaton/coin_source.h"
#include "granlub/automaton/directions.h"
#include "granlub/automaton/huge_page_allocator.h"
#include "granlub/automaton/params.h"
#include "granlub/automaton/row_index.h"
#include "granlub/automaton/static_dispatch.h"
#include "granlub/automaton/time_factor.h"

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
        if (rules_.tf_max < 1 || rules_.tf_max > kTfMaxLimit)
            throw std::invalid_argument("automaton: tf_max must be in [1, " + std::to_string(kTfMaxLimit) + "]");
        for (int x = 0; x < L_; ++x) {
            grid_[index(x, -1)] = kWallBottom;
            grid_[index(x, H_)] = kWallTop;
        }
        rest_ = 1.0 / rules_.tf_max;
        tf_max_ = rules_.tf_max;
        deflect_ = rules_.pp_deflect == 45 ? 1 : 2;
        jitter_ = rules_.pp_jitter_deg * std::numbers::pi / 180.0;
        for (int d = 0; d < 8; ++d) off_[d] = kDx[d] * static_cast<std::int64_t>(stride_) + kDy[d];
        row_of_ = RowIndex(stride_);
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

    // One time step (§3.1): a fresh uniformly random order of all grains, then every grain is
    // updated in that order, each seeing the moves already made in this step (engine_step.h).
    // The loop is compiled once per mode, clock rule and lattice size class.
    void step() {
        if (steps_ % kRelabelEvery == 0) relabel();
        ++steps_;
        with_constant(rules_.mode, [&](auto m) {
            constexpr Mode M = decltype(m)::value;
            step_with([this](Ctx& c, std::int32_t i, double u) { chain<M>(c, i, u); });
        });
        counters_.visits += order_.size();
    }

    // The step's update order and clocks without the moves: the same shuffle, clocks and "does it
    // move" decisions as step(), but a grain whose time factor is up is counted instead of making
    // its move attempt, so nothing moves or collides (the clocks advance, the order stream is
    // drawn; steps and counters stay). Returns the count. What step() costs beyond this is the
    // cost of the collision chains (bench_automaton's BM_StepSkeleton).
    std::uint64_t step_clocks_only() {
        std::uint64_t attempts = 0;
        step_with([&attempts](Ctx&, std::int32_t, double) { ++attempts; });
        return attempts;
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
        with_constant(rules_.tf_rounding, [&](auto t) {
            with_constant(rules_.mode, [&](auto m) { this->template update_as<decltype(m)::value, decltype(t)::value>(i); });
        });
    }

    // Does a grain of speed u (>= U/TF_max) move when its clock reaches c (integer-valued >= 1)?
    // I.e. c >= TF(u) with TF = round_half_up(U/u) (or ceil), capped at TF_max (time_factor.h).
    bool fires(double c, double u) const {
        return rules_.tf_rounding == TfRounding::Ceil ? automaton::fires<TfRounding::Ceil>(c, u, tf_max_)
                                                      : automaton::fires<TfRounding::Round>(c, u, tf_max_);
    }

    // Time factor of a moving grain (u >= U/TF_max), §2.4: the first clock value that fires.
    int tf(double u) const {
        int t = std::clamp(static_cast<int>(1.0 / u), 1, rules_.tf_max);  // within one of the answer
        while (t > 1 && fires(t - 1, u)) --t;
        while (!fires(t, u)) ++t;
        return t;
    }

    // Accessors (tests, sampler, snapshots, invariants).
    int columns() const { return L_; }
    int rows() const { return H_; }
    std::size_t size() const { return pos_.size(); }
    int x(int i) const { return static_cast<int>(pos_[i] / stride_); }
    int y(int i) const { return row_of(pos_[i]); }
    int dir(int i) const { return dir_[i]; }
    double up(int i) const { return up_[i]; }
    double clock(int i) const { return accumulate() ? acc_[i] : tick_[i]; }
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
    int row_of(std::uint32_t c) const { return row_of_(c); }
    const BigVector<std::uint8_t>& dirs() const { return dir_; }
    const BigVector<double>& speeds() const { return up_; }
    // Streamwise lattice displacements made from each row since the last take_kin() (u_kin, §4.2).
    std::vector<std::int64_t>& kin() { return kin_; }

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
        CoinState<Rng> coins;  // the rule stream's coin reservoir, in registers
        std::int64_t ncell;
        std::int64_t off[8];
        RowIndex row;
        double rest, tf_max;
        double e_p, eq89_weight;  // e_p and (1 + e_p)/2 of Eqs. 8-9
        double R[2], e_w[2];      // [top, bottom]
        double p_drag, jitter;
        bool sequential, line, vec_wait;
        unsigned deflect;
        std::uint64_t moves, pp, exhausted;
        // Wall hits are rare (~0.15 a visit): their sums stay in memory, indexed [top, bottom],
        // so that they do not compete for registers with the collision chain.
        struct WallSums {
            std::uint64_t hits[2];
            double tangential[2], normal[2];
        }* walls;
    };

    // The step loop (engine_step.h). step_with() runs run<>() for the clock rule and lattice size;
    // `attempt(c, i, u)` is what a grain whose time factor is up does.
    Ctx context();
    void commit(const Ctx& c);
    template <class Attempt>
    void step_with(Attempt attempt) {
        const bool big = order_.size() > kPrefetchFrom;
        with_constant(rules_.tf_rounding, [&](auto t) {
            with_constant(big, [&](auto p) { this->template run<decltype(t)::value, decltype(p)::value>(attempt); });
        });
    }
    template <TfRounding T, bool Prefetch, class Attempt>
    void run(Attempt attempt);
    template <Mode M, TfRounding T>
    void update_as(int i);
    template <Mode M, TfRounding T>
    [[gnu::always_inline]] inline void visit(Ctx& c, std::int32_t i);
    template <Mode M>
    [[gnu::always_inline]] inline void chain(Ctx& c, std::int32_t i, double u);
    template <Mode M>
    [[gnu::always_inline]] inline unsigned wall(Ctx& c, unsigned d, bool bottom, double& u);
    template <TfRounding T>
    [[gnu::always_inline]] static inline void prefetch_ahead(const Ctx& c, const std::int32_t* order, std::uint32_t k,
                                                            std::uint32_t n);

    template <TfRounding T>
    static ClockOf<T> load_clock(const Ctx& c, std::int32_t i) {
        if constexpr (T == TfRounding::Accumulate) return c.acc[i]; else return c.tick[i];
    }
    template <TfRounding T>
    static void store_clock(Ctx& c, std::int32_t i, ClockOf<T> k) {
        if constexpr (T == TfRounding::Accumulate) c.acc[i] = k; else c.tick[i] = static_cast<std::uint16_t>(k);
    }

    bool accumulate() const { return rules_.tf_rounding == TfRounding::Accumulate; }
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(x) * stride_ + static_cast<std::size_t>(y + 1); }

    int L_, H_;
    std::uint32_t stride_ = static_cast<std::uint32_t>(H_) + 2;  // grid column length
    Rules rules_;
    Rng order_rng_;
    Rng rng_;
    double rest_ = 0.02;
    double tf_max_ = 50;
    unsigned deflect_ = 2;
    double jitter_ = 0;
    std::int64_t off_[8] = {};     // grid-index offset of a step in each direction
    RowIndex row_of_;
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
    typename Ctx::WallSums wall_sums_{};  // wall sums during a step (Ctx::walls points here)
};

}  // namespace granlub::automaton

#include "granlub/automaton/engine_step.h"
