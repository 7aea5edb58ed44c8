#include "granlub/run/sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/results/failure_record.h"
#include "granlub/run/pipeline.h"
#include "granlub/run/run_lock.h"

namespace granlub {

std::filesystem::path results_root(const Case& c, const RunOptions& o) {
    return o.results_root.empty() ? c.dir / "results" : o.results_root;
}

namespace {
// Options that change a result without changing the case: the run lengths (--full), an explicit
// --seed, and one seed where the point's files pool several. A complete result computed otherwise is
// recomputed, not reused.
std::string run_options_differ(const Summary& s, const RunOptions& o) {
    const bool was_full = s.run.is_object() && s.run.value("full", false);
    if (was_full != o.full) return was_full ? "it was a --full run" : "it was not a --full run";
    if (s.run.is_object() && s.run.contains("seeds")) return "it pools several seeds (granlub/particles/seed_pool.h)";
    if (o.seed && s.provenance.seed != o.seed)
        return s.provenance.seed ? fmt::format("it used seed {}", *s.provenance.seed) : "it used no seed";
    return "";
}

// What a sweep runs: a point, or one realisation of it (Realisations: a member of a set of seeds).
struct Unit {
    const OperatingPoint* point = nullptr;
    std::optional<std::uint64_t> seed;  // a realisation: in <point>/seed-<S>/
    std::string id;                     // the point's id, or "<point>/seed-<S>": its lines, its pipeline name
};

// Runs `one` on every unit, up to `workers` at a time. An exception escaping `one` (bad input)
// lets no further unit start and is rethrown once the running ones have finished.
void run_side_by_side(const std::vector<Unit>& points, std::size_t workers, const std::function<void(const Unit&)>& one) {
    workers = std::min(workers, points.size());
    std::atomic<std::size_t> next{0};
    std::exception_ptr case_error;
    std::mutex error_lock;
    const auto work = [&] {
        for (std::size_t i; (i = next++) < points.size();) {
            {
                std::lock_guard lock(error_lock);
                if (case_error) return;
            }
            try {
                one(points[i]);
            } catch (...) {
                std::lock_guard lock(error_lock);
                if (!case_error) case_error = std::current_exception();
            }
        }
    };
    if (workers <= 1) {
        work();
    } else {
        std::vector<std::jthread> pool;
        for (std::size_t k = 0; k < workers; ++k) pool.emplace_back(work);
    }
    if (case_error) std::rethrow_exception(case_error);
}

}  // namespace

void for_each_run(const Case& c, const RunOptions& o,
                  const std::function<void(const OperatingPoint&, const RunOptions&)>& check) {
    for (const OperatingPoint* p : c.select(o.point))
        for (const bool full : {false, true}) {
            RunOptions variant = o;
            variant.full = full;
            check(*p, variant);
        }
}

std::string realisation_folder(std::uint64_t seed) { return fmt::format("seed-{}", seed); }

namespace {

// The sweep of run_sweep's two forms: `solve` computes a unit into its folder with its options.
using UnitSolver = std::function<PointResult(const OperatingPoint&, const RunOptions&, const std::filesystem::path&)>;
using UnitPool = std::function<void(const OperatingPoint&, const std::filesystem::path&)>;

int sweep_units(const Case& c, const std::string& solver, const RunOptions& o, const std::vector<Unit>& units,
                const UnitSolver& solve, const UnitPool& pool, int points_at_once,
                const std::vector<std::string>& reads) {
    // In a pipeline (pipeline.h), whatever ends this sweep, nothing waits for it any more.
    const struct Ended {
        const std::string& solver;
        ~Ended() { pipeline::ended(solver); }
    } ended{solver};
    const auto root = results_root(c, o);
    // Before anything is read: which points are complete is only known once no other run writes
    // them. The selected points' locks only: runs on other points of the case go on beside this one.
    // A pipeline holds the locks of its solvers already.
    // With a set of seeds, a unit is one realisation: its <point>/seed-<S> lock (and the same member
    // of what it reads), so that other members of the point run beside it (run_lock.h).
    const auto unit_locks = [&](const std::string& s, LockMode mode) {
        std::vector<LockRequest> out;
        for (const Unit& u : units)
            out.push_back(u.seed ? seed_lock(root, s, u.point->id, *u.seed, mode) : point_lock(root, s, u.point->id, mode));
        return out;
    };
    std::vector<LockRequest> locks;
    if (!pipeline::holds(root, solver)) locks = unit_locks(solver, LockMode::Exclusive);
    for (const auto& r : reads)
        if (!pipeline::holds(root, r))
            for (auto& l : unit_locks(r, LockMode::Shared)) locks.push_back(std::move(l));
    const ResultsLock held(std::move(locks), o.wait);
    const ResultKey key = result_key(c, solver);
    std::atomic<int> failed{0};
    std::mutex print;  // one point's lines stay whole when points run side by side
    const auto say = [&print](std::FILE* to, const std::string& line) {
        std::lock_guard lock(print);
        std::fputs(line.c_str(), to);
        std::fflush(to);
    };
    // A realisation's point files are pooled after it: one pooling at a time (the pools of two
    // members of one point would race for its files).
    std::mutex pooling;
    const auto pool_point = [&](const Unit& u) {
        if (!u.seed) return;
        std::lock_guard lock(pooling);
        try {
            // the point's top-level files: <solver>/<point> exclusive while they are pooled (run_lock.h);
            // taken after the member's lock this run holds, as every run takes them, so none waits on another in a circle
            // (a pipeline holds its solvers' point locks already: a second flock would wait on its own)
            const ResultsLock top(pipeline::holds(root, solver)
                                      ? std::vector<LockRequest>{}
                                      : std::vector<LockRequest>{point_lock(root, solver, u.point->id, LockMode::Exclusive)},
                                  o.wait);
            pool(*u.point, result_dir(root, solver, u.point->id));
        } catch (const CaseError&) {
            throw;
        } catch (const std::exception& e) {
            ++failed;
            say(stderr, fmt::format("{} {:<14} FAILED to pool its seeds: {}\n", solver, u.point->id, e.what()));
        }
    };
    const auto run_point = [&](const Unit& u) {
        const OperatingPoint* p = u.point;
        const std::string& id = u.id;
        RunOptions uo = o;
        if (u.seed) uo.seed = u.seed;
        const auto dir = u.seed ? result_dir(root, solver, p->id) / realisation_folder(*u.seed)
                                : result_dir(root, solver, p->id);
        const LoadedResult prev = load_result(dir, key);  // compare's definition of complete too
        const ResultStatus& st = prev.status;
        if (st.state == ResultState::Complete && !o.force) {
            const std::string differs = run_options_differ(*prev.summary, uo);
            if (differs.empty()) {
                say(stdout, fmt::format("{} {:<14} complete, skipped (--force recomputes)\n", solver, id));
                pool_point(u);
                return;
            }
            say(stdout, fmt::format("{} {:<14} complete, but {}: recomputing\n", solver, id, differs));
        }
        if (st.state == ResultState::Stale)
            say(stdout, fmt::format("{} {:<14} stale results, recomputing: {}\n", solver, id, st.reason));
        if (st.state == ResultState::Corrupt)
            say(stdout, fmt::format("{} {:<14} corrupt results, recomputing: {}\n", solver, id, st.reason));
        const auto t0 = std::chrono::steady_clock::now();
        try {
            // The completion marker goes first: a run killed from here on leaves no summary beside
            // its new deck and logs, so the next run recomputes instead of skipping.
            std::filesystem::create_directories(dir);
            std::filesystem::remove(dir / "summary.json");
            remove_point_tables(dir);  // only this run's tables may stand beside its summary
            PointResult r = solve(*p, uo, dir);
            const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (!r.summary.run.contains("wall_clock_s")) r.summary.run["wall_clock_s"] = secs;
            r.summary.run["full"] = o.full;
            write_result(dir, r.profile, r.summary);
            remove_failure(dir);
            say(stdout, fmt::format("{} {:<14} {}  ({:.2f} s)\n", solver, id, r.line, secs));
            pool_point(u);
        } catch (const CaseError&) {
            throw;  // bad input fails the command (exit 2), not one point
        } catch (const NoAnswer& e) {  // not a failure: the model cannot answer this point's question
            say(stdout, fmt::format("{} {:<14} no answer: {}\n", solver, id, e.what()));
            try {
                write_failure(dir, solver, id, e.what(), true);  // the report says why
            } catch (const std::exception& w) {
                say(stderr, fmt::format("{} {:<14} (could not record why: {})\n", solver, id, w.what()));
            }
        } catch (const std::exception& e) {  // Error, bad_alloc, filesystem errors: the sweep goes on
            ++failed;
            const std::string why = dynamic_cast<const std::bad_alloc*>(&e)
                                        ? "out of memory (reduce the case's sizes: cells, grains, steps)"
                                        : e.what();
            say(stderr, fmt::format("{} {:<14} FAILED: {}\n", solver, id, why));
            try {
                write_failure(dir, solver, id, why);  // the report says why the point is missing
            } catch (const std::exception& w) {
                say(stderr, fmt::format("{} {:<14} (could not record the failure: {})\n", solver, id, w.what()));
            }
        }
    };

    // Points are independent (own folder, own seed): up to points_at_once of them run side by
    // side, each exactly as it would alone, so the results do not depend on the count.
    // In a pipeline a point starts once the solvers it reads have finished it, and says when it
    // has finished itself, whatever its outcome.
    const auto run_when_ready = [&](const Unit& u) {
        for (const auto& r : reads) {
            if (pipeline::pending(r, u.id))
                say(stdout, fmt::format("{} {:<14} waits for {} {}, whose results it reads\n", solver, u.id, r, u.id));
            pipeline::wait_for(r, u.id);
        }
        const struct Finished {
            const std::string& solver;
            const std::string& point;
            ~Finished() { pipeline::finished(solver, point); }
        } finished{solver, u.id};
        run_point(u);
    };
    run_side_by_side(units, static_cast<std::size_t>(std::max(1, points_at_once)), run_when_ready);
    if (failed)
        fmt::print(stderr, "{}: {} of {} {} failed; their results were not written\n", solver, failed.load(),
                   units.size(), units.empty() || !units.front().seed ? "point(s)" : "realisation(s)");
    return failed ? 1 : 0;
}

}  // namespace

int run_sweep(const Case& c, const std::string& solver, const RunOptions& o, const PointSolver& solve,
              int points_at_once, const std::vector<std::string>& reads) {
    std::vector<Unit> units;
    for (const OperatingPoint* p : c.select(o.point)) units.push_back({p, std::nullopt, p->id});
    return sweep_units(
        c, solver, o, units, [&](const OperatingPoint& p, const RunOptions&, const std::filesystem::path& dir) {
            return solve(p, dir);
        }, nullptr, points_at_once, reads);
}

int run_sweep(const Case& c, const std::string& solver, const RunOptions& o, const Realisations& r,
              int points_at_once, const std::vector<std::string>& reads) {
    std::vector<Unit> units;
    for (const OperatingPoint* p : c.select(o.point))
        for (const std::uint64_t seed : r.run) units.push_back({p, seed, p->id + "/" + realisation_folder(seed)});
    return sweep_units(c, solver, o, units, r.solve, r.pool, points_at_once, reads);
}

int points_at_once(const RunOptions& o, int points, int machine_cores) {
    if (machine_cores <= 0) machine_cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int cores = o.threads > 0 ? o.threads : machine_cores;
    const int slots = std::max(1, cores / std::max(1, o.np));
    // Fewer than two rounds of single-process points run all at once: rounds would leave cores idle
    // in the last one (3 points on 2 cores take two points' time in rounds, 1.5 shared by the
    // kernel). Each point is a process of its own and runs exactly as alone, so no number changes.
    // Not with MPI ranks (they busy-wait for each other) nor under an explicit --threads.
    if (o.np <= 1 && o.threads <= 0 && points > slots && points < 2 * slots) return points;
    return std::clamp(slots, 1, std::max(1, points));
}

}  // namespace granlub
