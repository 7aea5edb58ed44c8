// What a user waits for, on this machine, in one go:
//   main_job  `granlub run cases/sawyer2001` (every solver, the report) from the built tree: its wall
//             time, and per DEM point the grain-steps per second and the share of the point's time
//             the Delta-t check took (refine_dt: the full-step run in dt_full/, the answer at
//             Delta-t/2 beside it; refine_halvings = 2: where that pair failed, the Delta-t/2 run in
//             dt_half/ and the answer at Delta-t/4)
//   ring      with --ring only (tens of minutes): `granlub run cases/sawyer2001_ring --np 2` without
//             YADE (which has no ring), its wall time and the DEM's grain-steps per second
// Each runs into a results folder of its own under the system's temporary directory (--force: every
// point computed). The per-step cost of the contact model against LIGGGHTS' hertz/history is
// bench_liggghts_deck's.
// Run: build/bench/bench_main_job [--ring]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/error.h"
#include "granlub/run/process.h"
#include "granlub/results/results.h"

namespace fs = std::filesystem;

namespace {

struct DemPoint {
    std::string id;
    double wall_s = 0, check_s = 0, grain_steps_per_s = 0;  // check_s: the runs the answer was checked with
    int halvings = 0;                                          // 0: no check; 2: answered at a quarter step
};
struct Measured {
    double wall_s = 0;
    std::vector<DemPoint> dem;
};
Measured g_main, g_ring;

// Every DEM point folder of a results root: its time, its refinement run's time, its throughput.
std::vector<DemPoint> dem_points(const fs::path& root) {
    std::vector<DemPoint> v;
    if (!fs::is_directory(root / "dem")) return v;
    for (const auto& e : fs::directory_iterator(root / "dem")) {
        if (!fs::exists(e.path() / "summary.json")) continue;
        const granlub::Summary s = granlub::read_summary(e.path() / "summary.json");
        DemPoint p;
        p.id = e.path().filename().string();
        p.wall_s = s.run.value("wall_clock_s", 0.0);
        p.grain_steps_per_s = s.run.value("atom_steps_per_s", 0.0);
        if (s.run.contains("dt_refinement") && s.run.at("dt_refinement").contains("full_step_run")) {
            const auto& rec = s.run.at("dt_refinement");
            p.halvings = rec.value("halvings", 1);
            for (const char* run : {"full_step_run", "half_step_run"})
                if (rec.contains(run)) p.check_s += rec.at(run).value("wall_clock_s", 0.0);
        }
        v.push_back(p);
    }
    std::sort(v.begin(), v.end(), [](const DemPoint& a, const DemPoint& b) { return a.id < b.id; });
    return v;
}

void run_case(benchmark::State& state, const std::string& name, const std::vector<std::string>& extra,
              Measured& out) {
    const fs::path case_dir = fs::path(GRANLUB_SOURCE_DIR) / "cases" / name;
    const fs::path root = fs::temp_directory_path() / ("granlub-bench-" + name);
    fs::create_directories(root);
    std::vector<std::string> argv{GRANLUB_COMMAND, "run", case_dir.string(), "--force", "--results", root.string()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const auto r = granlub::run_process(argv, root, root / "run.log", 4 * 3600);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (r.exit_code != 0) {
            state.SkipWithError(
                ("granlub run failed: " + r.describe() + ", see " + (root / "run.log").string()).c_str());
            return;
        }
        state.SetIterationTime(wall);
        out.wall_s = wall;
        out.dem = dem_points(root);
    }
    state.counters["wall_s"] = out.wall_s;
}

void BM_main_job(benchmark::State& state) { run_case(state, "sawyer2001", {}, g_main); }
void BM_ring(benchmark::State& state) {
    run_case(state, "sawyer2001_ring", {"--np", "2", "--solvers", "continuum,automaton,dem"}, g_ring);
}

void print(const char* what, const Measured& m) {
    if (m.wall_s <= 0) return;
    std::printf("%s: %.0f s wall\n", what, m.wall_s);
    for (const auto& p : m.dem)
        std::printf("  dem %-8s %6.0f s, %.3g grain-steps/s%s\n", p.id.c_str(), p.wall_s, p.grain_steps_per_s,
                    p.halvings > 0
                        ? (std::string(p.halvings == 2 ? ", the answer at Delta-t/4 " : ", the answer at Delta-t/2 ") +
                           std::to_string(static_cast<int>(100 * (p.wall_s - p.check_s) / p.wall_s + 0.5)) +
                           " % of it (the coarser runs it is checked with the rest)")
                              .c_str()
                        : ", no Delta-t check");
}

}  // namespace

BENCHMARK(BM_main_job)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

int main(int argc, char** argv) {
    std::vector<char*> args;
    bool ring = false;
    for (int i = 0; i < argc; ++i)
        if (std::strcmp(argv[i], "--ring") == 0)
            ring = true;
        else
            args.push_back(argv[i]);
    if (ring) benchmark::RegisterBenchmark("BM_ring", BM_ring)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    print("main job (cases/sawyer2001)", g_main);
    print("whole ring (cases/sawyer2001_ring, 2 ranks)", g_ring);
    return 0;
}
