// Throughput of the CA engine (issue 4): particle updates per second on one core for the JH06
// default case, how the cost per update scales with lattice size up to ~1e6 grains, the cost of
// the pieces (update order, random numbers, sampling), and the ensemble's thread scaling.
// items_per_second = particle updates per CPU second. Compare with JH06: 850 grains x 10 000
// steps in 1.92 h (Mathematica 5, 3.2 GHz) = 1.23e3 updates per second.
//
// Issue 4's target is >= 1e8 updates/s on one core for BM_StepDefault (jh) and a cost per update
// that stays flat up to 1e6 grains (BM_StepScaling). Measured on the 2-vCPU build VM (Xeon
// 2.6 GHz, quiet, median of 3; automaton/README.md "Performance" has the table):
// BM_StepDefault 3.9e7/s (jh), 1.8e7/s (vector); BM_StepSkeleton 1.0-1.07e8/s (the step with
// its collision chains counted, not run); BM_StepScaling 3.9e7/s at 850 grains, 2.5e7/s at
// 0.85-1.02e6 grains. Run with --benchmark_repetitions=3 on a quiet core; the
// numbers move by 10-20 % with the load of the other vCPU.
#include <benchmark/benchmark.h>

#include "granlub/automaton/ensemble.h"

using namespace granlub::automaton;

namespace {

Params lattice(int columns, int rows) {
    Params p;
    p.lattice.columns = columns;
    p.lattice.rows = rows;
    return p;
}

// A lattice brought to steady state first (the transient is ~100 steps).
Lattice steady(const Params& p) {
    Lattice e = make_lattice(p, 0);
    for (int t = 0; t < 200; ++t) e.step();
    return e;
}

}  // namespace

// One step of the JH06 default case (100 x 10, 850 grains), engine only.
static void BM_StepDefault(benchmark::State& st) {
    Params p = lattice(100, 10);
    if (st.range(0) == 1) p.rules.mode = Mode::Vector;
    Lattice e = steady(p);
    for (auto _ : st) e.step();
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(e.size()));
    st.counters["grains"] = static_cast<double>(e.size());
}
BENCHMARK(BM_StepDefault)->Arg(0)->Arg(1)->ArgName("vector");

// The floor under BM_StepDefault/vector:0: the same steady lattice, the same shuffle, clocks and
// "does it move" decisions, but the attempts are counted instead of made (Engine::step_clocks_only).
// BM_StepDefault / BM_StepSkeleton is the share of the step that the collision chains cost.
static void BM_StepSkeleton(benchmark::State& st) {
    Lattice e = steady(lattice(100, 10));
    std::uint64_t attempts = 0;
    for (auto _ : st) attempts += e.step_clocks_only();
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(e.size()));
    st.counters["attempts_per_update"] =
        static_cast<double>(attempts) / (static_cast<double>(st.iterations()) * static_cast<double>(e.size()));
}
BENCHMARK(BM_StepSkeleton);

// Steps plus per-step sampling, as run by the ensemble.
static void BM_StepAndSample(benchmark::State& st) {
    Params p = lattice(100, 10);
    Lattice e = steady(p);
    p.run.steps = 1 << 30;
    Sampler s(p.lattice.rows, p.lattice.columns, p.run);
    std::int64_t t = 0;
    for (auto _ : st) {
        e.step();
        s.after_step(t++ % 1000000, e);
    }
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(e.size()));
}
BENCHMARK(BM_StepAndSample);

// Scaling: 10 rows, L columns, fill 0.85 -> N = 8.5 L grains; the last size holds 1.02e6 grains.
static void BM_StepScaling(benchmark::State& st) {
    const Params p = lattice(static_cast<int>(st.range(0)), static_cast<int>(st.range(1)));
    Lattice e = make_lattice(p, 0);
    for (int t = 0; t < 20; ++t) e.step();
    for (auto _ : st) e.step();
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(e.size()));
    st.counters["grains"] = static_cast<double>(e.size());
}
BENCHMARK(BM_StepScaling)
    ->Args({100, 10})->Args({1000, 10})->Args({10000, 10})->Args({100000, 10})->Args({100000, 12})
    ->Unit(benchmark::kMillisecond);

// The update order alone: in-place Fisher-Yates of N indices with Philox draws.
static void BM_Shuffle(benchmark::State& st) {
    const auto n = static_cast<std::uint32_t>(st.range(0));
    std::vector<std::int32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = static_cast<std::int32_t>(i);
    Philox g(1, 0);
    for (auto _ : st) {
        for (std::uint32_t k = 0; k + 1 < n; ++k) std::swap(order[k], order[k + g.below(n - k)]);
        benchmark::DoNotOptimize(order.data());
    }
    st.SetItemsProcessed(st.iterations() * n);
}
BENCHMARK(BM_Shuffle)->Arg(850)->Arg(850000);

// One word at a time through the engine's interface (includes the call and buffer overhead).
static void BM_Philox(benchmark::State& st) {
    Philox g(1, 0);
    for (auto _ : st) benchmark::DoNotOptimize(g.next32());
    st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_Philox);

// The batched generator alone (SIMD, kPhiloxBatch blocks per call): 32-bit words per second.
static void BM_PhiloxBatch(benchmark::State& st) {
    std::vector<std::uint32_t> buf(4 * kPhiloxBatch);
    std::uint64_t ctr = 0;
    for (auto _ : st) {
        philox4x32_10_batch(ctr, 0, {1, 2}, buf.data());
        ctr += kPhiloxBatch;
        benchmark::DoNotOptimize(buf.data());
    }
    st.SetItemsProcessed(st.iterations() * 4 * kPhiloxBatch);
}
BENCHMARK(BM_PhiloxBatch);

// A whole default-case point: replicas x 10 000 steps, threads = range(1).
static void BM_Ensemble(benchmark::State& st) {
    Params p = lattice(100, 10);
    p.run.replicas = static_cast<int>(st.range(0));
    p.run.threads = static_cast<int>(st.range(1));
    for (auto _ : st) {
        const EnsembleResult r = run_ensemble(p);
        benchmark::DoNotOptimize(r.slip_bottom.mean);
    }
    st.SetItemsProcessed(st.iterations() * p.run.replicas * p.run.steps * p.lattice.particles());
}
BENCHMARK(BM_Ensemble)->Args({2, 1})->Args({2, 2})->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

BENCHMARK_MAIN();
