// Sweeps side by side in one process, each point of a reader starting as soon as the point it
// reads is done (`granlub run`: YADE's warm start reads the final state of each DEM point, so YADE's
// point U2.8 can run while DEM's U1.4 still does, instead of every YADE point waiting for the
// whole DEM sweep).
//
// The pipeline takes, before any of its sweeps starts, every lock those sweeps would take
// (run_lock.h; the selected points of each of its solvers exclusively), and its sweeps do not take those again:
// a second descriptor in the same process would be set against the first by flock(2). A sweep of a
// pipeline solver (run_sweep) waits, before each point, until each solver it reads that is in the
// pipeline has finished that point (computed, skipped as complete, or failed) or ended its sweep,
// and says when it has finished each of its own. Outside a pipeline nothing of this applies.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/run/run_lock.h"
#include "granlub/run/sweep.h"

namespace granlub {

class SweepPipeline {
public:
    // `solvers`: the sweeps that will run side by side while this object lives, on the results of
    // `c` (results_root(c, o)). Takes their locks, waiting or not as o.wait (ResultsInUse). One
    // pipeline per process at a time (a second one throws Error).
    SweepPipeline(const Case& c, const RunOptions& o, std::vector<std::string> solvers);
    ~SweepPipeline();
    SweepPipeline(const SweepPipeline&) = delete;
    SweepPipeline& operator=(const SweepPipeline&) = delete;

private:
    ResultsLock locks_;
};

namespace pipeline {
// Whether this process's pipeline holds `solver`'s locks (its selected points) under `results_root`.
bool holds(const std::filesystem::path& results_root, const std::string& solver);
// Whether wait_for(solver, point) would block now.
bool pending(const std::string& solver, const std::string& point);
// Blocks until `solver`'s sweep has finished `point` or ended; at once when `solver` is not in
// the pipeline (or there is none).
void wait_for(const std::string& solver, const std::string& point);
// `solver`'s sweep has finished `point` (computed, skipped or failed).
void finished(const std::string& solver, const std::string& point);
// `solver`'s sweep has returned or thrown: nothing waits for it any more.
void ended(const std::string& solver);
}  // namespace pipeline

// Engines started from the calling thread, and from the threads it starts later, run `steps`
// nice levels lower than granlub (setpriority(2); on Linux the nice value is per thread and
// inherited by new threads and forked processes). For a sweep that should leave the cores to
// another's engines when both want them: the result of a run does not depend on its priority.
void lower_this_thread_priority(int steps);

}  // namespace granlub
