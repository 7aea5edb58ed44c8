// The invariants of docs/automaton-model.md §3.5 over long random runs (every rule variant), and
// determinism: same seed = same numbers, for any thread count.
#define BOOST_TEST_MODULE automaton_invariants
#include <boost/test/unit_test.hpp>

#include "granlub/automaton/ensemble.h"
#include "granlub/automaton/invariants.h"

using namespace granlub::automaton;

namespace {

Params small(std::int64_t steps = 1000) {
    Params p;  // JH06 default: 100 x 10, fill 0.85
    p.run.steps = steps;
    p.run.t_avg_start = 0;
    p.run.block = 100;
    return p;
}

void check_run(const Params& p, int steps) {
    Lattice e = make_lattice(p, 0);
    const std::size_t n = e.size();
    BOOST_TEST(n == 850u);
    BOOST_REQUIRE_EQUAL(check_invariants(e), "");
    for (int t = 0; t < steps; ++t) {
        e.step();
        const std::string bad = check_invariants(e);  // occupancy, single occupancy, 0 <= u_p <= U
        BOOST_REQUIRE_MESSAGE(bad.empty(), "step " << t << ": " << bad);
    }
    BOOST_TEST(e.size() == n);
    BOOST_TEST(e.counters().visits == static_cast<std::uint64_t>(steps) * n);
    BOOST_TEST(e.counters().moves > 0u);
}

}  // namespace

BOOST_AUTO_TEST_CASE(invariants_default_rules) { check_run(small(), 1000); }

BOOST_AUTO_TEST_CASE(invariants_every_switch) {
    std::vector<Params> variants(8, small());
    variants[0].rules.pp_deflect = 45;
    variants[1].rules.struck_dir = StruckDir::Keep;
    variants[2].rules.wall_speed = WallSpeed::ByIncidence;
    variants[3].rules.tf_rounding = TfRounding::Ceil;
    variants[4].rules.tf_rounding = TfRounding::Accumulate;
    variants[5].rules.mode = Mode::Vector;
    variants[6].rules.mode = Mode::Vector;
    variants[6].rules.vec_blocked = VecBlocked::Wait;
    variants[7].rules.p_drag = 0;
    for (const Params& p : variants) check_run(p, 300);
}

BOOST_AUTO_TEST_CASE(clocks_only_step_decides_but_moves_nothing) {
    // step_clocks_only() (the floor measured by bench_automaton's BM_StepSkeleton) must make
    // every grain's time-factor decision as step() does and leave the lattice itself untouched.
    Lattice e = make_lattice(small(), 0);
    for (int t = 0; t < 200; ++t) e.step();
    const std::size_t n = e.size();
    std::vector<int> x(n), y(n), d(n);
    std::vector<double> u(n), k(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = e.x(static_cast<int>(i)); y[i] = e.y(static_cast<int>(i)); d[i] = e.dir(static_cast<int>(i));
        u[i] = e.up(static_cast<int>(i)); k[i] = e.clock(static_cast<int>(i));
    }
    const Counters before = e.counters();
    const std::uint64_t attempts = e.step_clocks_only();
    std::uint64_t expected = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int g = static_cast<int>(i);
        BOOST_REQUIRE(e.x(g) == x[i] && e.y(g) == y[i] && e.dir(g) == d[i] && e.up(g) == u[i]);
        const bool moving = u[i] >= 1.0 / e.rules().tf_max;
        const bool go = moving && e.fires(k[i] + 1, u[i]);
        expected += go;
        BOOST_REQUIRE_EQUAL(e.clock(g), !moving ? k[i] : (go ? 0.0 : k[i] + 1));
    }
    BOOST_TEST(attempts == expected);
    BOOST_TEST(attempts > n / 4);  // ~2/3 of the grains attempt a move in a step
    BOOST_TEST(e.counters().moves == before.moves);
    BOOST_TEST(e.counters().pp == before.pp);
    BOOST_TEST(check_invariants(e) == "");
}

BOOST_AUTO_TEST_CASE(momentum_balance_jh) {
    // In jh mode Eqs. 8-9 conserve the sum of u_p in every collision, so in steady state the
    // streamwise momentum the moving wall puts in equals what the stationary wall takes out.
    Params p = small(3000);
    p.run.t_avg_start = 1000;
    p.run.block = 500;
    p.run.replicas = 2;
    const EnsembleResult r = run_ensemble(p);
    const double in = r.tangential_bottom.mean, out = -r.tangential_top.mean;
    const double se = std::hypot(r.tangential_bottom.stderr_, r.tangential_top.stderr_);
    BOOST_TEST(in > 0);
    BOOST_TEST(std::abs(in - out) < 5 * se + 1e-12);
}

BOOST_AUTO_TEST_CASE(same_seed_same_numbers_any_thread_count) {
    Params p = small(1000);
    p.run.replicas = 3;
    p.run.seed = 99;
    p.run.threads = 1;
    const EnsembleResult a = run_ensemble(p);
    p.run.threads = 3;
    const EnsembleResult b = run_ensemble(p);
    const EnsembleResult c = run_ensemble(p);
    for (int y = 0; y < a.rows; ++y) {
        BOOST_TEST(a.rows_.u[y].mean == b.rows_.u[y].mean);  // bitwise
        BOOST_TEST(a.rows_.u[y].stderr_ == b.rows_.u[y].stderr_);
        BOOST_TEST(a.rows_.nu[y].mean == b.rows_.nu[y].mean);
        BOOST_TEST(b.rows_.temp[y].mean == c.rows_.temp[y].mean);
    }
    BOOST_TEST(a.totals.moves == b.totals.moves);
    BOOST_TEST(a.totals.pp == c.totals.pp);
    p.run.seed = 100;  // and a different seed gives different numbers
    const EnsembleResult d = run_ensemble(p);
    BOOST_TEST(d.totals.moves != a.totals.moves);
}

BOOST_AUTO_TEST_CASE(steady_state_block_test) {
    // A synthetic block sequence: a transient block, then agreement -> steady from block 1.
    RunSpec run = Params().run;  // the keys' defaults
    run.block = 500;
    run.t_avg_start = 2000;
    std::vector<Block> blocks(6);
    for (int b = 0; b < 6; ++b) {
        blocks[b].start = 500 * b;
        blocks[b].up = {b == 0 ? 0.5 : 0.85, 0.5};
        blocks[b].nu = {0.8, 0.8};
        blocks[b].has = {true, true};
        blocks[b].mean_up = b == 0 ? 0.3 : 0.6;
    }
    SteadyState s = steady_state(run, blocks);
    BOOST_TEST(s.reached);
    BOOST_TEST(s.step == 500);
    blocks[4].up[1] = 0.6;  // a jump late in the run: steady only after it
    s = steady_state(run, blocks);
    BOOST_TEST(s.step == -1);
    BOOST_TEST(!s.reached);
}
