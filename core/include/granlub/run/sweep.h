// Running a solver over the operating points of a case: the locks on its points (run_lock.h),
// selection (--point), resume (skip points whose results are complete and current unless
// --force), timing, atomic result writing and one printed line per point. Every solver's
// `granlub <solver>` command goes through this.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/results/results.h"

namespace granlub {

struct RunOptions {
    std::string point;                        // empty: all points
    bool force = false;                       // recompute complete points
    std::optional<std::uint64_t> seed;        // statistical solvers; with a set of seeds, the one member to run
    std::string seeds;                        // particle engines: --seeds N|LIST ("" = [particles] seeds;
                                              // granlub/particles/seeds.h)
    int np = 1;                               // MPI ranks (dem)
    int threads = 0;                          // 0: solver default
    bool vtk = false;                         // write ParaView files where supported
    bool full = false;                        // full-fidelity run lengths (the *_full case keys)
                                              // instead of the quick defaults
    std::filesystem::path results_root;       // empty: <case dir>/results
    bool wait = true;                         // results locked by another run: wait for it (--wait),
                                              // or fail at once, exit 2 (--no-wait); run_lock.h
};

std::filesystem::path results_root(const Case& c, const RunOptions& o);

struct PointResult {
    Profile profile;
    Summary summary;     // start from make_summary(); outputs and run filled by the solver
    std::string line;    // short one-line report, e.g. "nu=0.612 tau=1512 Pa slip=0.177 U"
};

// solve(point, dir) computes one point; `dir` is the point's result folder (created), where a
// solver may leave extra files (logs, decks, VTK). Throws SolverError on failure.
using PointSolver = std::function<PointResult(const OperatingPoint&, const std::filesystem::path& dir)>;

// Calls check(point, options) for every selected point, once with the quick and once with the
// --full run lengths: how each solver's check() finds at `granlub check` time what its run would
// reject (a solver's check throws CaseError for bad input, SolverError for what it cannot run).
void for_each_run(const Case& c, const RunOptions& o,
                  const std::function<void(const OperatingPoint&, const RunOptions&)>& check);

// Returns the process exit code: 0 if every selected point is complete afterwards, 1 otherwise.
// Failures of one point are reported and the sweep goes on with the next. Up to `points_at_once`
// points run side by side (solvers whose points are separate processes: see points_at_once()).
// The sweep holds the selected points of its solver locked (exclusive) from start to end, and the
// same points of the solvers in `reads` shared (yade's warm start reads dem's): o.wait says whether
// it waits for another run holding one of them or throws ResultsInUse (run_lock.h). Under a SweepPipeline of the solver
// (pipeline.h) the pipeline holds those locks, and each point waits for the points it reads.
int run_sweep(const Case& c, const std::string& solver, const RunOptions& o, const PointSolver& solve,
              int points_at_once = 1, const std::vector<std::string>& reads = {});

// A point answered by several realisations (the particle engines' seeds, granlub/particles/seeds.h):
// each member of `run` is computed into <point>/seed-<S>/ as a point of its own (skipped when
// complete with that seed, recomputed when stale; its own failure record), by solve() given the
// options with seed = S. After each member that is complete (computed or skipped), pool() rewrites
// the point's own files, <point>/profile.csv and summary.json, from the members found there; a
// pipeline (pipeline.h) knows each member as "<point>/seed-<S>". Members of a point, and points,
// share the `points_at_once` slots.
struct Realisations {
    std::vector<std::uint64_t> run;  // the members this sweep computes, ascending
    std::function<PointResult(const OperatingPoint&, const RunOptions&, const std::filesystem::path& dir)> solve;
    std::function<void(const OperatingPoint&, const std::filesystem::path& point_dir)> pool;
};
int run_sweep(const Case& c, const std::string& solver, const RunOptions& o, const Realisations& r,
              int points_at_once = 1, const std::vector<std::string>& reads = {});

// The folder of a point's realisation with seed S inside the point's folder: "seed-<S>".
std::string realisation_folder(std::uint64_t seed);

// How many single-process points fit the machine: --threads (default: all cores) over --np ranks
// per point, at least 1 and at most `points`; all of them when they are fewer than two rounds of
// single-rank points and --threads is not given (the kernel shares the cores; no idle last round).
// machine_cores: 0 = this machine's.
int points_at_once(const RunOptions& o, int points, int machine_cores = 0);

}  // namespace granlub
