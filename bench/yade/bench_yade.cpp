// YADE vs LIGGGHTS cost per particle-step on the same case and physics: bench/yade/hertz_cell
// (sawyer2001's cell, 5316 grains, Hertz-Mindlin in both, same time step and initial grains).
// Each iteration runs `granlub <engine> CASE --force` and reports the engine's own loop time
// (summary.json run.loop_time_s, start-up and coarse-graining excluded) as the manual time.
// Counters: grain-steps per second and ns per grain-step; the ratio is printed at the end.
// Run: build/bench/bench_yade [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "granlub/error.h"
#include "granlub/results/results.h"
#include "granlub/run/process.h"

namespace fs = std::filesystem;

namespace {

std::map<std::string, double> g_ns_per_grain_step;

void run_engine(benchmark::State& state, const std::string& engine) {
    const fs::path case_dir = fs::path(GRANLUB_SOURCE_DIR) / "bench" / "yade" / "hertz_cell";
    const fs::path root = fs::temp_directory_path() / "granlub-bench-yade";
    fs::create_directories(root);
    for (auto _ : state) {
        const auto r = granlub::run_process(
            {GRANLUB_COMMAND, engine, case_dir.string(), "--force", "--results", root.string()}, root,
            root / (engine + ".log"), 1800);
        if (r.exit_code != 0) {
            state.SkipWithError(("granlub " + engine + " failed: " + r.describe() + ", see " +
                                 (root / (engine + ".log")).string())
                                    .c_str());
            return;
        }
        const granlub::Summary s = granlub::read_summary(root / engine / "U2.0" / "summary.json");
        const double loop = s.run.at("loop_time_s").get<double>();
        const double grains = s.run.contains("grains") ? s.run.at("grains").get<double>() : s.run.at("atoms").get<double>();
        const double steps = s.run.at("steps").get<double>();
        state.SetIterationTime(loop);
        state.counters["grains"] = grains;
        state.counters["steps"] = steps;
        state.counters["grain_steps_per_s"] = grains * steps / loop;
        state.counters["ns_per_grain_step"] = 1e9 * loop / (grains * steps);
        g_ns_per_grain_step[engine] = 1e9 * loop / (grains * steps);
    }
}

void BM_liggghts_hertz(benchmark::State& state) { run_engine(state, "dem"); }
void BM_yade_hertz(benchmark::State& state) { run_engine(state, "yade"); }

}  // namespace

BENCHMARK(BM_liggghts_hertz)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_yade_hertz)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (g_ns_per_grain_step.count("dem") && g_ns_per_grain_step.count("yade"))
        std::printf("YADE / LIGGGHTS cost per grain-step (Hertz-Mindlin, same cell): %.2f (%.0f ns vs %.0f ns)\n",
                    g_ns_per_grain_step["yade"] / g_ns_per_grain_step["dem"], g_ns_per_grain_step["yade"],
                    g_ns_per_grain_step["dem"]);
    return 0;
}
