#include "run_all.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/results.h"
#include "granlub/run_lock.h"
#include "modules.h"

namespace granlub::cli {

int run_all(const Case& c, const RunOptions& o, const std::vector<std::string>& solvers) {
    std::vector<const SolverModule*> mods;
    for (const auto& m : solver_modules())
        if (solvers.empty() || std::find(solvers.begin(), solvers.end(), m.name) != solvers.end()) mods.push_back(&m);
    if (mods.empty()) throw Error("no solver selected (and none compiled in)");

    // Bad input stops everything before a run starts (exit 2). A point a solver cannot run is
    // left to its sweep, which names it and runs the other points.
    for (const auto* m : mods) {
        try {
            m->check(c, o);
        } catch (const CaseError&) {
            throw;
        } catch (const Error&) {
        }
    }
    int rc = 0;

    const std::size_t stages = mods.size() + (have_compare() ? 1 : 0);
    std::size_t stage = 0;
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    for (const auto* m : mods) {
        fmt::print("== [{}/{}] {} on {} ({} point(s)), {:.0f} s elapsed\n", ++stage, stages, m->name, c.name,
                   c.select(o.point).size(), elapsed());
        std::fflush(stdout);
        try {
            if (m->run(c, o) != 0) rc = 1;
        } catch (const ResultsInUse&) {
            throw;  // --no-wait and another run holds these results: stop, exit 2
        } catch (const Error& e) {
            fmt::print(stderr, "{}: FAILED: {}\n", m->name, e.what());
            rc = 1;
        }
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
