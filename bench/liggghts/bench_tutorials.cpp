// LIGGGHTS' own tutorials (our short derived decks, tests/liggghts/tutorials/) with the tutorial's
// Hertz model and with model impulse at the models' defaults, at the tutorial's own step, run one
// after the other (interleaved: Hertz, impulse, per deck). Printed at the end, per deck: the
// impulse / Hertz ratio of the whole deck's CPU time and of the last run's loop time (the bed at
// rest for heatTransfer_1 and the pour; the relaxation for packing). heatTransfer_1 also per phase
// (pour: the grains fall and land, the first 5000 steps; settle: to step 20000; rest: 5000 steps),
// with the solver's active set off (every contact in every sweep: the cost before it), with an
// impact's jolt solved to the bed's limit (impact_tolerance 0: the cost before it) and at the
// impulse model's own larger step (3.7 dt, the same simulated time), all against Hertz at the
// tutorial's step. Issue 53's target: within 3x Hertz. The machine may be shared: read the ratios,
// not the seconds (--benchmark_filter=heat runs heatTransfer_1 alone).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "run_liggghts.h"

namespace {

using granlub::bench::Measured;
std::map<std::string, Measured> g_results;

const std::string kHertz = " -var model 'hertz tangential history'";
const std::string kImpulse = " -var model 'impulse tangential impulse'";

void deck(benchmark::State& state, const std::string& name, const std::string& file, const std::string& vars) {
    Measured m;
    for (auto _ : state) {
        m = granlub::bench::run_liggghts("/tmp", std::string(GRANLUB_TUTORIAL_DECKS) + "/" + file, vars, 1);
        if (m.loop_s <= 0) {
            state.SkipWithError("LIGGGHTS run failed (no loop time)");
            return;
        }
    }
    g_results[name] = m;
    state.counters["cpu_s"] = m.cpu_s;
    state.counters["last_loop_s"] = m.loop_s;
}

// heatTransfer_1: 890 grains poured (5000 steps), settled to step 20000, then 5000 steps at rest (dt
// 2.5e-5 s); at 3.7 dt = 9.2e-5 s (0.02 d of travel per step at the pour's fastest 1.74 m/s, granlub's
// step rule) the same simulated time
const std::string kHeat = " -var pour 5000 -var settle 20000 -var rest 5000";
const std::string kHeatBig = " -var dt 0.0000925 -var pour 1351 -var settle 5405 -var rest 1351";
const std::string kNoActiveSet = " -var solver 1 -var solve 'active_set no'";
const std::string kExactImpacts = " -var solver 1 -var solve 'impact_tolerance 0'";
// cohesion (in.noCohesion): 250 grains, 30000 steps of pouring and spreading, 5000 more (dt 1e-5 s)
const std::string kPour = " -var steps 30000 -var rest 5000";
// packing grown to 0.5 (rigid spheres fit), 10000 steps of growth, 2000 of relaxation (dt 1e-5 s)
const std::string kPack = " -var target 0.5 -var grow 10000 -var relax 2000";

BENCHMARK_CAPTURE(deck, heat_hertz, "heat_hertz", "in.heat_bed", kHertz + kHeat)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, heat_impulse, "heat_impulse", "in.heat_bed", kImpulse + kHeat)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, heat_impulse_all_contacts, "heat_impulse_all", "in.heat_bed", kImpulse + kHeat + kNoActiveSet)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, heat_impulse_exact_impacts, "heat_impulse_exact", "in.heat_bed", kImpulse + kHeat + kExactImpacts)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, heat_impulse_own_step, "heat_impulse_big", "in.heat_bed", kImpulse + kHeatBig)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, pour_hertz, "pour_hertz", "in.pour", kHertz + kPour)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, pour_impulse, "pour_impulse", "in.pour", kImpulse + kPour)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, pack_hertz, "pack_hertz", "in.packing", kHertz + kPack)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(deck, pack_impulse, "pack_impulse", "in.packing", kImpulse + kPack)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    std::printf("\nimpulse / Hertz at the tutorial's step (target <= 3):\n");
    for (const char* d : {"heat", "pour", "pack"}) {
        const auto h = g_results.find(std::string(d) + "_hertz"), i = g_results.find(std::string(d) + "_impulse");
        if (h == g_results.end() || i == g_results.end()) continue;
        std::printf("  %-5s whole deck (CPU) %.2f   last run (loop) %.2f\n", d, i->second.cpu_s / h->second.cpu_s,
                    i->second.loop_s / h->second.loop_s);
    }
    // heatTransfer_1 per phase: the deck's runs are the insertion, the pour, the settling, the rest
    const auto h = g_results.find("heat_hertz");
    if (h != g_results.end() && h->second.loops.size() == 4) {
        std::printf("\nheatTransfer_1 per phase, impulse / Hertz at the tutorial's step (loop times):\n");
        for (const char* v : {"heat_impulse", "heat_impulse_all", "heat_impulse_exact", "heat_impulse_big"}) {
            const auto i = g_results.find(v);
            if (i == g_results.end() || i->second.loops.size() != 4) continue;
            const auto& a = i->second.loops;
            const auto& b = h->second.loops;
            std::printf("  %-18s pour %.2f   settle %.2f   rest %.2f   pour+settle %.2f\n", v, a[1] / b[1], a[2] / b[2],
                        a[3] / b[3], (a[1] + a[2]) / (b[1] + b[2]));
        }
    }
    return 0;
}
