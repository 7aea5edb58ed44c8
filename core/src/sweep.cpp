#include "granlub/sweep.h"

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

std::filesystem::path results_root(const Case& c, const RunOptions& o) {
    return o.results_root.empty() ? c.dir / "results" : o.results_root;
}

int run_sweep(const Case& c, const std::string& solver, const RunOptions& o, const PointSolver& solve) {
    const auto points = c.select(o.point);
    const auto root = results_root(c, o);
    const std::string hash = c.inputs_hash(solver);
    int failed = 0;
    for (const OperatingPoint* p : points) {
        const auto dir = result_dir(root, solver, p->id);
        const ResultStatus st = result_status(dir, hash);
        if (st.state == ResultState::Complete && !o.force) {
            fmt::print("{} {:<14} complete, skipped (--force recomputes)\n", solver, p->id);
            std::fflush(stdout);
            continue;
        }
        if (st.state == ResultState::Stale) fmt::print("{} {:<14} stale results, recomputing\n", solver, p->id);
        std::filesystem::create_directories(dir);
        const auto t0 = std::chrono::steady_clock::now();
        try {
            PointResult r = solve(*p, dir);
            const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (!r.summary.run.contains("wall_clock_s")) r.summary.run["wall_clock_s"] = secs;
            write_result(dir, r.profile, r.summary);
            fmt::print("{} {:<14} {}  ({:.2f} s)\n", solver, p->id, r.line, secs);
        } catch (const Error& e) {
            ++failed;
            fmt::print(stderr, "{} {:<14} FAILED: {}\n", solver, p->id, e.what());
        }
        std::fflush(stdout);
        std::fflush(stderr);
    }
    if (failed)
        fmt::print(stderr, "{}: {} of {} point(s) failed; their results were not written\n", solver, failed,
                   points.size());
    return failed ? 1 : 0;
}

}  // namespace granlub
