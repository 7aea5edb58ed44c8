// Costs of the impulse contact model in LIGGGHTS on the same 5120-grain shear cell
// (examples/in.shear, with per-step wall-stress sampling), measured as LIGGGHTS' own loop time of
// the timed run after a warm-up run, plus the CPU time of the whole process (the machine may be
// shared: CPU time is the steadier number). At the end, the ratios are printed:
//   cost per particle-step, impulse (single pass) / hooke-history          (target <= 1.0)
//   cost per particle-step, iterated (the models' default) / single pass
//   simulated time per CPU-second, impulse / Hertz (glass)    (target >= 20)
//   2 ranks vs 1 rank, loop time per step
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "run_liggghts.h"

namespace {

using granlub::bench::Measured;
std::map<std::string, Measured> g_results;

Measured run_deck(const std::string& vars, int np, double dt, double warmup, double steps) {
    char extra[128];
    std::snprintf(extra, sizeof extra, " -var dt %.17g -var warmup %.0f -var steps %.0f", dt, warmup, steps);
    Measured m = granlub::bench::run_liggghts("/tmp", GRANLUB_SHEAR_DECK, vars + extra, np);
    m.steps = steps;
    m.all_steps = warmup + steps;
    m.dt = dt;
    return m;
}

void shear(benchmark::State& state, const std::string& name, const std::string& vars, int np, double dt,
           double warmup, double steps) {
    Measured m;
    for (auto _ : state) {
        m = run_deck(vars, np, dt, warmup, steps);
        if (m.loop_s <= 0) {
            state.SkipWithError("LIGGGHTS run failed (no loop time)");
            return;
        }
        state.SetIterationTime(m.loop_s);
    }
    g_results[name] = m;
    state.counters["atoms"] = m.atoms;
    state.counters["particle_steps_per_s"] = m.atoms * m.steps / m.loop_s;
    state.counters["us_per_1000_particle_steps"] = 1e9 * m.loop_s / (m.atoms * m.steps);
    state.counters["cpu_us_per_1000_particle_steps"] = 1e9 * m.cpu_s / (m.atoms * m.all_steps);
    state.counters["sim_s_per_cpu_s"] = m.all_steps * m.dt / m.cpu_s;
}

// Same cell, same time step (1 us): cost per particle-step. Sawyer & Tichy's single pass, as
// granlub's sheared cases run it (iterate off; the models' default is iterate on).
const std::string kImpulse = "-var model impulse -var tang impulse -var settings 'iterate off'";
// S&T's operator alone, without the overlap removal that is the default since 2026-11-23
const std::string kImpulseNoSeparate = "-var model impulse -var tang impulse -var settings 'iterate off separate off'";
// the models' defaults: the contacts solved together (iterate on, the fix impulse/solve the pair makes)
const std::string kImpulseIterated = "-var model impulse -var tang impulse";
const std::string kHooke = "-var model hooke -var tang history -var E 5e6";
// Hertz at glass stiffness: 0.15 Rayleigh times for d = 1 mm, E = 63 GPa, nu = 0.23 (8.0e-8 s).
const std::string kHertz = "-var model hertz -var tang history -var E 63e9";
const double kHertzDt = 0.15 * M_PI * 0.5e-3 * std::sqrt(2500.0 / (63e9 / (2 * 1.23))) / (0.1631 * 0.23 + 0.8766);
// The impulse model at granlub dem's default step (0.02 d per step at U = 1 m/s).
const double kImpulseDt = 0.02 * 1e-3 / 1.0;

}  // namespace

BENCHMARK_CAPTURE(shear, impulse_1rank, "impulse", kImpulse, 1, 1e-6, 1000, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, impulse_separate_off_1rank, "impulse_nosep", kImpulseNoSeparate, 1, 1e-6, 1000, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, impulse_iterated_1rank, "impulse_iterated", kImpulseIterated, 1, 1e-6, 1000, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, hooke_history_1rank, "hooke", kHooke, 1, 1e-6, 1000, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, impulse_2ranks, "impulse_np2", kImpulse, 2, 1e-6, 1000, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, hooke_history_2ranks, "hooke_np2", kHooke, 2, 1e-6, 1000, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, impulse_granlub_step, "impulse_dt", kImpulse, 1, kImpulseDt, 500, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(shear, hertz_glass, "hertz", kHertz, 1, kHertzDt, 500, 2000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    auto has = [](const char* k) { return g_results.count(k) && g_results[k].loop_s > 0; };
    auto per_ps = [](const Measured& m) { return m.loop_s / (m.atoms * m.steps); };
    auto cpu_ps = [](const Measured& m) { return m.cpu_s / (m.atoms * m.all_steps); };
    std::printf("\nRatios (loop time = wall clock of the timed run; CPU = whole process)\n");
    if (has("impulse") && has("hooke"))
        std::printf("  cost per particle-step impulse / hooke-history: %.2f (loop), %.2f (CPU)   target <= 1.0\n",
                    per_ps(g_results["impulse"]) / per_ps(g_results["hooke"]),
                    cpu_ps(g_results["impulse"]) / cpu_ps(g_results["hooke"]));
    if (has("impulse") && has("impulse_nosep"))
        std::printf("  cost per particle-step impulse (separate on, default) / separate off: %.2f (loop), %.2f (CPU)\n",
                    per_ps(g_results["impulse"]) / per_ps(g_results["impulse_nosep"]),
                    cpu_ps(g_results["impulse"]) / cpu_ps(g_results["impulse_nosep"]));
    if (has("impulse") && has("impulse_iterated"))
        std::printf("  cost per particle-step iterated (the models' default) / single pass: %.2f (loop), %.2f (CPU)\n",
                    per_ps(g_results["impulse_iterated"]) / per_ps(g_results["impulse"]),
                    cpu_ps(g_results["impulse_iterated"]) / cpu_ps(g_results["impulse"]));
    if (has("impulse_dt") && has("hertz")) {
        const auto& a = g_results["impulse_dt"];
        const auto& b = g_results["hertz"];
        std::printf("  simulated time per CPU-second impulse (dt %.3g s) / Hertz glass (dt %.3g s): %.0f   target >= 20\n",
                    a.dt, b.dt, (a.all_steps * a.dt / a.cpu_s) / (b.all_steps * b.dt / b.cpu_s));
    }
    if (has("impulse") && has("impulse_np2"))
        std::printf("  impulse loop time per step, 2 ranks / 1 rank: %.2f\n",
                    g_results["impulse_np2"].loop_s / g_results["impulse"].loop_s);
    if (has("hooke") && has("hooke_np2"))
        std::printf("  hooke loop time per step, 2 ranks / 1 rank: %.2f\n",
                    g_results["hooke_np2"].loop_s / g_results["hooke"].loop_s);
    return 0;
}
