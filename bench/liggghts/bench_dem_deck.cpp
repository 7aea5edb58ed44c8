// Cost of `granlub dem`'s own deck, in one run on one machine state:
//   sawyer2001        cases/sawyer2001 at U = 2.0 m/s, the deck and grains `granlub dem` writes
//                     (5315 grains, four walls with per-step force sampling, gravity, centripetal
//                     force), with the Sawyer-Tichy impulse model
//   sawyer2001_hertz  the same deck, grains and step with LIGGGHTS' own `hertz tangential history`
//                     at E = 0.2 GPa (at the case's 63 GPa, and at the engine cross-check's 1 GPa,
//                     the step does not resolve a Hertz contact: grains are lost within 100 steps;
//                     0.2 GPa runs, overlaps ~0.003 d under the load): what the impulse model costs
//                     per step against the stock model (it must not be slower)
//   sawyer2001_2ranks the impulse deck on 2 MPI ranks
// each as LIGGGHTS' loop time of a timed run after a warm-up run, in ns per grain-step (and the
// CPU time of the whole process tree, the steadier number on a shared machine). From LIGGGHTS'
// own statistics of each 1-rank run, where the loop goes: listed pairs per grain, neighbour builds
// per 1000 steps, the pair loop per listed pair, one build per grain.
// The deck is made by running `granlub dem` once on a copy of the case with a short run (same
// time step as the default run); the warm-up is its servo loop cut to kWarmup steps, then one timed
// run (sawyer_deck says why). Each configuration runs kRepeats times in interleaved rounds and the
// summary takes medians: one 2.6 s run on a shared VM scattered by +-20 % (244-335 ns measured).
// (The ratio against examples/in.shear, a contact-free gas, is retired: bench_liggghts still times
// that example's models.)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "run_liggghts.h"

namespace fs = std::filesystem;
using granlub::bench::Measured;

namespace {

constexpr double kWarmup = 500;
constexpr double kSteps = 2000;
constexpr int kRepeats = 5;
constexpr long kHertzModulus = 200000000;  // Pa: the stiffest Hertz contact the deck's step resolves (top)
std::map<std::string, std::vector<Measured>> g_runs;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Median over the repeats of one configuration (loop and CPU separately), and the spread of the loop time.
struct Summary {
    double loop_ns = 0, cpu_ns = 0, loop_min = 0, loop_max = 0, loop_s = 0;
    int ranks = 1;
    // where the loop time goes, from LIGGGHTS' own statistics (medians)
    double neighbours = 0, builds_per_1000 = 0, pair_ns_per_pair = 0, neigh_ns_per_build = 0, pair_ns = 0, neigh_ns = 0;
};
Summary summarize(const std::vector<Measured>& runs) {
    auto med = [&runs](auto of) {
        std::vector<double> v;
        for (const auto& m : runs) v.push_back(of(m));
        return median(v);
    };
    std::vector<double> loop;
    for (const auto& m : runs) loop.push_back(m.ns_per_grain_step());
    Summary r;
    r.loop_ns = median(loop);
    r.loop_min = *std::min_element(loop.begin(), loop.end());
    r.loop_max = *std::max_element(loop.begin(), loop.end());
    r.cpu_ns = med([](const Measured& m) { return m.cpu_ns_per_grain_step(); });
    r.loop_s = med([](const Measured& m) { return m.loop_s; });
    r.ranks = runs.front().ranks;
    r.neighbours = med([](const Measured& m) { return m.neighbours; });
    r.builds_per_1000 = med([](const Measured& m) { return m.builds_per_1000_steps(); });
    r.pair_ns_per_pair = med([](const Measured& m) { return m.pair_ns_per_listed_pair(); });
    r.neigh_ns_per_build = med([](const Measured& m) { return m.neigh_ns_per_grain_build(); });
    r.pair_ns = med([](const Measured& m) { return m.pair_ns_per_grain_step(); });
    r.neigh_ns = med([](const Measured& m) { return m.neigh_ns_per_grain_step(); });
    return r;
}

// Writes <build>/bench/liggghts/sawyer2001/results/dem/U2.0/in.bench; returns its folder ("" on failure).
std::string sawyer_deck() {
    static std::string dir;
    if (!dir.empty()) return dir;
    const fs::path root = fs::path(GRANLUB_BENCH_DIR) / "sawyer2001";
    fs::remove_all(root);
    fs::create_directories(root);
    // a short run (granlub dem wants >= 20 wall-stress samples of 100 steps), snapshots as in the default
    // run: the case's own [dem] section gets these keys instead of its time and without refine_dt (the
    // deck at the case's full step; TOML allows a section once)
    std::ifstream src(fs::path(GRANLUB_SAWYER_CASE) / "case.toml");
    std::stringstream text;
    text << src.rdbuf();
    std::string toml = std::regex_replace(text.str(), std::regex(R"((^|\n)(time|snapshots|refine_dt|refine_time)\s*=[^\n]*)"), "$1");
    const std::string keys = "time = 0.016\nsnapshots = 8\n";
    if (toml.find("\n[dem]\n") != std::string::npos)
        toml.replace(toml.find("\n[dem]\n"), 7, "\n[dem]\n" + keys);
    else
        toml += "\n[dem]\n" + keys;
    std::ofstream(root / "case.toml") << toml;
    const std::string cmd = std::string(GRANLUB_CLI_PATH) + " dem '" + root.string() +
                            "' --point U2.0 --threads 1 > '" + (root / "granlub.out").string() + "' 2>&1";
    if (std::system(cmd.c_str()) != 0) return "";
    const fs::path point = root / "results" / "dem" / "U2.0";
    std::ifstream in(point / "in.granlub");
    std::stringstream deck;
    deck << in.rdbuf();
    // Under load control the deck runs a servo loop of `run N post no` windows and then its persistence
    // and final-state blocks (the latter dumps every grain every step). The bench keeps the loop for
    // the warm-up (kWarmup / N windows), cuts everything after it, and times one run with the plate
    // where the loop left it: every per-step cost of the deck (walls, wall-force sums, body forces,
    // snapshots) without the per-window restarts. A fixed-fill deck has one `run`: warm-up + timed.
    const std::string written = deck.str();
    std::string timed;
    std::smatch window;
    const std::string loop_end = "jump SELF servo\n";
    if (std::regex_search(written, window, std::regex(R"(\nrun\s+(\d+) post no\n)")) &&
        written.find("jump SELF servo\n") != std::string::npos) {
        const long windows = std::lround(kWarmup / std::stod(window[1].str()));
        timed = written.substr(0, written.find(loop_end) + loop_end.size());
        timed = std::regex_replace(timed, std::regex(R"(\nvariable update loop \d+\n)"),
                                   "\nvariable update loop " + std::to_string(windows) + "\n");
        timed += "run ${steps}\n";
    } else {
        timed = std::regex_replace(written, std::regex(R"(\nrun\s+\d+\n)"), "\nrun ${warmup}\nrun ${steps}\n");
    }
    if (timed == written) return "";
    std::ofstream(point / "in.bench") << timed;
    dir = point.string();
    return dir;
}

// The same deck with LIGGGHTS' hertz/history for every pair and wall at the same step: in.bench_hertz
// beside in.bench ("" when the deck's model lines are not where this expects them).
std::string hertz_deck(const std::string& dir) {
    std::ifstream in(fs::path(dir) / "in.bench");
    std::stringstream text;
    text << in.rdbuf();
    const std::string impulse = text.str();
    std::string hertz = std::regex_replace(impulse, std::regex(R"(model impulse tangential impulse[^\n]*?(primitive|\n))"),
                                           "model hertz tangential history $1");
    // wall lines carry their keywords after the primitive; drop the impulse model's own
    hertz = std::regex_replace(hertz, std::regex(R"( beta0 \S+ separate \S+( bounce_speed \S+)?( iterate \S+)?)"), "");
    std::smatch e;  // youngsModulus peratomtype E1 E2 ...: every type at kHertzModulus
    if (std::regex_search(hertz, e, std::regex(R"(youngsModulus peratomtype(( \S+)+))"))) {
        std::istringstream values(e[1].str());
        std::string soft, v;
        while (values >> v) soft += " " + std::to_string(kHertzModulus);
        hertz.replace(static_cast<std::size_t>(e.position(1)), static_cast<std::size_t>(e.length(1)), soft);
    }
    if (hertz == impulse || hertz.find("model impulse") != std::string::npos) return "";
    std::ofstream(fs::path(dir) / "in.bench_hertz") << hertz;
    return "in.bench_hertz";
}

void run(benchmark::State& state, const std::string& name, const std::string& model, int np) {
    const std::string dir = sawyer_deck();
    if (dir.empty()) {
        state.SkipWithError("granlub dem could not write the sawyer2001 deck (see bench/liggghts/sawyer2001)");
        return;
    }
    const std::string deck = model == "hertz" ? hertz_deck(dir) : "in.bench";
    if (deck.empty()) {
        state.SkipWithError("the deck's model lines changed: the hertz variant could not be written");
        return;
    }
    char vars[96];
    std::snprintf(vars, sizeof vars, "-var warmup %.0f -var steps %.0f ", kWarmup, kSteps);
    Measured m;
    for (auto _ : state) {
        m = granlub::bench::run_liggghts(dir, deck, vars, np);
        if (m.loop_s <= 0) {
            state.SkipWithError("LIGGGHTS run failed (no loop time)");
            return;
        }
        state.SetIterationTime(m.loop_s);
    }
    m.steps = kSteps;
    m.all_steps = kWarmup + kSteps;
    g_runs[name].push_back(m);
    state.counters["atoms"] = m.atoms;
    state.counters["ns_per_grain_step"] = m.ns_per_grain_step();
    state.counters["cpu_ns_per_grain_step"] = m.cpu_ns_per_grain_step();
}

}  // namespace

#define GRANLUB_BENCH(name, ...) \
    BENCHMARK_CAPTURE(run, name, __VA_ARGS__)->UseManualTime()->Iterations(1)->Repetitions(kRepeats)->Unit(benchmark::kSecond)
GRANLUB_BENCH(sawyer2001_1rank, "sawyer", "impulse", 1);
GRANLUB_BENCH(sawyer2001_hertz_1rank, "sawyer_hertz", "hertz", 1);
GRANLUB_BENCH(sawyer2001_2ranks, "sawyer_np2", "impulse", 2);

int main(int argc, char** argv) {
    // interleaved rounds unless the caller chose: a slow minute of the machine then hits every configuration
    std::vector<char*> args(argv, argv + argc);
    static char interleave[] = "--benchmark_enable_random_interleaving=true";
    if (std::none_of(args.begin(), args.end(), [](const char* a) { return std::strstr(a, "interleaving"); }))
        args.insert(args.begin() + 1, interleave);
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    std::map<std::string, Summary> r;
    for (const auto& [k, runs] : g_runs) r[k] = summarize(runs);
    auto has = [&](const char* k) { return r.count(k) && r[k].loop_s > 0; };
    std::printf("\nsawyer2001 deck (U2.0), impulse and hertz/history: medians of %d runs each (loop time = wall clock of "
                "the timed run; CPU = whole process, warm-up included)\n",
                kRepeats);
    for (const auto& [k, v] : r)
        std::printf("  %-10s %4.0f ns per grain-step (loop; runs %.0f-%.0f), %4.0f (CPU)\n", k.c_str(), v.loop_ns,
                    v.loop_min, v.loop_max, v.cpu_ns);
    // One rank only: on several, LIGGGHTS' times are per rank while its counts are global.
    std::printf("  where the loop goes (1 rank, medians; LIGGGHTS' Pair and Neigh times, listed pairs of its half list):\n"
                "  %-10s %8s %8s %14s %14s %12s %12s\n", "", "pairs/gr", "builds", "Pair ns/pair", "Neigh ns/gr",
                "Pair ns/gs", "Neigh ns/gs");
    for (const auto& [k, v] : r)
        if (v.ranks == 1)
            std::printf("  %-10s %8.2f %8.0f %14.1f %14.0f %12.0f %12.0f\n", k.c_str(), v.neighbours,
                        v.builds_per_1000, v.pair_ns_per_pair, v.neigh_ns_per_build, v.pair_ns, v.neigh_ns);
    std::printf("  (pairs/gr: listed pairs per grain; builds: neighbour-list builds per 1000 steps; Pair ns/pair: pair\n"
                "  loop per listed pair and step; Neigh ns/gr: one build per grain; ns/gs: per grain-step)\n");
    if (has("sawyer") && has("sawyer_hertz"))
        std::printf("  impulse / hertz-history on the same deck and step: %.2f (loop), %.2f (CPU)   target <= 1.0\n",
                    r["sawyer"].loop_ns / r["sawyer_hertz"].loop_ns, r["sawyer"].cpu_ns / r["sawyer_hertz"].cpu_ns);
    if (has("sawyer") && has("sawyer_np2"))
        std::printf("  sawyer2001 speed-up, 2 ranks vs 1 (median loop times): %.2f   target >= 1.8\n",
                    r["sawyer"].loop_s / r["sawyer_np2"].loop_s);
    return 0;
}
