#include "run_all.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/error.h"
#include "granlub/results/results.h"
#include "granlub/run/pipeline.h"
#include "granlub/run/run_lock.h"
#include "modules.h"

namespace granlub::cli {

namespace {

// Engines' sweeps run side by side only when each may count every core as its own: one rank per
// point (MPI ranks busy-wait for each other) and no --threads budget to keep to.
bool side_by_side_allowed(const RunOptions& o) { return o.np <= 1 && o.threads <= 0; }

// The stages of `granlub run`: each solver alone, except consecutive engines, which form one stage.
std::vector<std::vector<const SolverModule*>> stages_of(const std::vector<const SolverModule*>& mods, bool together) {
    std::vector<std::vector<const SolverModule*>> stages;
    for (const auto* m : mods) {
        if (together && m->info.engine && !stages.empty() && stages.back().back()->info.engine)
            stages.back().push_back(m);
        else
            stages.push_back({m});
    }
    return stages;
}

// The engines' sweeps of one stage (`names`: their solvers), each in a thread of its own, under one
// pipeline (its locks taken once; a point that reads another solver's starts once that one is
// done). Each YADE point starts once its DEM point is done, a nice step below (each engine after the
// first yields the cores to the ones before it), so that the DEM runs, on which every chain waits, keep
// the cores and YADE takes what they leave. The kernel shares the cores among the runs: a run's length
// is not known beforehand (YADE's continuation to time_max is decided at its end), so no fixed order is
// chosen. Running a DEM point's two cold runs side by side as well was measured slower (2026-12-06:
// docs/measurements/build-and-run.md). Returns false when a sweep failed.
bool run_side_by_side(const std::vector<const SolverModule*>& group, const std::vector<std::string>& names,
                      const Case& c, const RunOptions& o, const std::function<bool(const SolverModule*)>& run_one) {
    const SweepPipeline pipeline(c, o, names);
    std::vector<char> ok(group.size(), 0);
    std::vector<std::exception_ptr> thrown(group.size());
    {
        std::vector<std::jthread> threads;
        for (std::size_t k = 0; k < group.size(); ++k)
            threads.emplace_back([&, k] {
                if (k > 0) lower_this_thread_priority(10);
                try {
                    ok[k] = run_one(group[k]);
                } catch (...) {
                    thrown[k] = std::current_exception();
                }
                pipeline::ended(names[k]);  // also when it failed before its sweep began
            });
    }
    for (const auto& e : thrown)
        if (e) std::rethrow_exception(e);
    return std::all_of(ok.begin(), ok.end(), [](char v) { return v != 0; });
}

}  // namespace

int run_all(const Case& c, const RunOptions& o, const std::vector<std::string>& solvers) {
    std::vector<const SolverModule*> mods;
    for (const auto& m : solver_modules())
        if (solvers.empty() || std::find(solvers.begin(), solvers.end(), m.name) != solvers.end()) mods.push_back(&m);
    if (mods.empty()) throw Error("no solver selected (and none compiled in)");

    // Bad input stops everything before a run starts (exit 2). A point a solver cannot run is
    // left to its sweep, which names it and runs the other points.
    for (const auto* m : mods) check_input(*m, c, o);
    int rc = 0;
    // one solver's sweep; false when it failed (said on stderr)
    const auto run_one = [&](const SolverModule* m) {
        try {
            return m->run(c, o) == 0;
        } catch (const ResultsInUse&) {
            throw;  // --no-wait and another run holds these results: stop, exit 2
        } catch (const Error& e) {
            fmt::print(stderr, "{}: FAILED: {}\n", m->name, e.what());
            return false;
        }
    };

    const auto groups = stages_of(mods, side_by_side_allowed(o));
    const std::size_t stages = groups.size() + (have_compare() ? 1 : 0);
    std::size_t stage = 0;
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    for (const auto& group : groups) {
        std::vector<std::string> names;
        for (const auto* m : group) names.push_back(m->name);
        fmt::print("== [{}/{}] {} on {} ({} point(s){}), {:.0f} s elapsed\n", ++stage, stages,
                   fmt::join(names, " and "), c.name, c.select(o.point).size(),
                   group.size() > 1 ? fmt::format(" each, side by side: a point of {} starts once the {} point it "
                                                  "reads is done",
                                                  fmt::join(names.begin() + 1, names.end(), " or "), names.front())
                                    : "",
                   elapsed());
        std::fflush(stdout);
        if (group.size() == 1) {
            if (!run_one(group.front())) rc = 1;
            continue;
        }
        if (!run_side_by_side(group, names, c, o, run_one)) rc = 1;
    }
    if (have_compare()) {
        fmt::print("== [{}/{}] compare, {:.0f} s elapsed\n", ++stage, stages, elapsed());
        std::fflush(stdout);
        try {
            if (compare(c, o) != 0) rc = 1;
        } catch (const ResultsInUse&) {
            throw;
        } catch (const Error& e) {
            fmt::print(stderr, "compare: FAILED: {}\n", e.what());
            rc = 1;
        }
    }
    closing_table(c, o);
    fmt::print("\n{} in {:.0f} s{}\n", rc == 0 ? "done" : "finished with failures", elapsed(),
               have_compare() ? fmt::format("; report: {}", (results_root(c, o) / "report" / "index.html").string())
                              : "");
    return rc;
}

}  // namespace granlub::cli
