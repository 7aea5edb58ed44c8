// Ensembles (issue 4, item 3): independent replicas run in parallel threads, one pair of Philox
// streams each (order, rules), pooled into means with standard errors. Replica r's numbers
// depend only on (seed, r), and pooling is in replica order, so the output is identical for any
// thread count.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "granlub/automaton/engine.h"
#include "granlub/automaton/params.h"
#include "granlub/automaton/philox.h"
#include "granlub/automaton/sampler.h"
#include "granlub/statistics/block_average.h"

namespace granlub::automaton {

using Lattice = Engine<Philox>;

// A lattice built and filled for replica r of `p` (§2.5).
Lattice make_lattice(const Params& p, int replica);

using Stat = BlockEstimate;  // mean and standard error over the window blocks

struct RowStats {
    std::vector<Stat> u;       // the mode's velocity: <u_p> (jh) or <u_p dx> (vector), over U
    std::vector<Stat> up;      // <u_p>/U
    std::vector<Stat> ux;      // <u_p dx>/U
    std::vector<Stat> ukin;    // streamwise displacement per grain-step
    std::vector<Stat> temp;    // variance of the mode's streamwise velocity, over U^2
    std::vector<Stat> nu;      // occupancy
};

struct SteadyState {
    bool reached = false;        // every replica passed the block test by t_avg_start, no drift
    std::int64_t step = -1;      // latest step from which a replica was steady (-1: never)
    double drift = 0;            // largest |slope| of <u_p> over the last 5 blocks, U per block
    std::string note;            // why not, when not
};

// JH06's literal steady-state protocol (docs/automaton-model.md §4.5), when run.steady_protocol = Runs.
struct RunsProtocol {
    bool used = false;
    bool converged = false;              // consecutive readings agreed before runs_max_steps
    std::vector<std::int64_t> lengths;   // T_1, T_2, ... as run
    std::vector<double> du, dnu;         // max_y |du|/U, max_y |dnu| of run k vs run k-1 (k >= 2)
    int du_row = -1, dnu_row = -1;       // rows of the last maxima
    std::string note;                    // why not converged
};

struct EnsembleResult {
    int rows = 0, columns = 0;
    std::int64_t particles = 0;
    int replicas = 0, threads = 0;
    std::int64_t window_blocks = 0;  // blocks pooled for the averages (all replicas)
    RowStats rows_;
    Stat slip_bottom, slip_top;           // 1 - u(row 0), u(row H-1), over U (§4.3)
    Stat slip_bottom_fit, slip_top_fit;   // wall-plane extrapolations of a line through rows 1..H-2
    bool has_fit = false;                 // needs rows >= 4
    Stat tangential_bottom, tangential_top, normal_bottom, normal_top;  // per step per column
    Stat mean_up;
    Stat moves, pp, wall_bottom, wall_top, exhausted;                    // per grain-step
    Counters totals;                      // summed over replicas
    SteadyState steady;
    RunsProtocol runs;
    std::vector<TimePoint> timeseries;    // ensemble mean
    double wall_seconds = 0;
    double updates_per_second = 0;        // particle updates / wall second, all threads
};

struct Observer {
    // Called on the calling thread about 5 times a second: steps done over all replicas.
    std::function<void(std::uint64_t done, std::uint64_t total)> progress;
    // Called from replica 0's thread every run.snapshot_every steps (and at step 0).
    std::function<void(std::int64_t step, const Lattice& lattice)> snapshot;
};

EnsembleResult run_ensemble(const Params& p, const Observer& observer = {});

// Pools the replicas' blocks (exposed for tests of the statistics).
EnsembleResult pool(const Params& p, const std::vector<std::vector<Block>>& blocks);
SteadyState steady_state(const RunSpec& run, const std::vector<Block>& blocks);

// §4.5: throws SolverError when the runs protocol reached runs_max_steps without two agreeing
// runs, naming the point, the run lengths, the last differences (and rows) and what to try.
void require_converged(const std::string& point, const Params& p, const RunsProtocol& rp);

}  // namespace granlub::automaton
