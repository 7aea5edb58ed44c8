#include "granlub/automaton/params.h"

#include <cmath>
#include <sstream>

#include "granlub/automaton/directions.h"
#include "granlub/error.h"

namespace granlub::automaton {

std::int64_t LatticeSpec::particles() const {
    return std::llround(fill * static_cast<double>(columns) * static_cast<double>(rows));
}

namespace {

template <class T>
[[noreturn]] void bad(const std::string& name, T value, const std::string& allowed) {
    std::ostringstream os;
    os << "automaton: " << name << " = " << value << " is not allowed (allowed: " << allowed << ")";
    throw Error(os.str());
}

void unit_interval(const std::string& name, double v) {
    if (!(v >= 0.0 && v <= 1.0)) bad(name, v, "a real number in [0, 1]");
}

}  // namespace

void validate(const Params& p) {
    const auto& l = p.lattice;
    const auto& r = p.rules;
    const auto& run = p.run;
    if (l.rows < 3) bad("rows", l.rows, "at least 3 particle rows between the walls (gap >= 2.5 grain diameters)");
    if (l.columns < 3) bad("columns", l.columns, "at least 3 columns (length >= 2.5 grain diameters)");
    if (static_cast<double>(l.rows) * l.columns > 2.0e9) bad("rows x columns", static_cast<double>(l.rows) * l.columns, "at most 2e9 cells");
    if (!(l.fill > 0.0 && l.fill <= 1.0))
        bad("fill", l.fill, "(0, 1]: the fraction of lattice cells holding a grain (solid_fraction / max_solid_fraction)");
    if (l.particles() < 1) bad("fill", l.fill, "a fill that puts at least one grain on the lattice");
    if (!(l.s0_max > 0.0 && l.s0_max <= 1.0)) bad("s0_max", l.s0_max, "(0, 1]");
    unit_interval("e_p (grains.restitution)", r.e_p);
    unit_interval("e_w at the bottom wall", r.e_w_bottom);
    unit_interval("e_w at the top wall", r.e_w_top);
    unit_interval("roughness of the bottom wall", r.R_bottom);
    unit_interval("roughness of the top wall", r.R_top);
    unit_interval("p_drag", r.p_drag);
    if (r.tf_max < 1 || r.tf_max > 65535) bad("tf_max", r.tf_max, "an integer in [1, 65535] (the clock is 16 bits)");
    if (r.pp_deflect != 90 && r.pp_deflect != 45) bad("pp_deflect", r.pp_deflect, "90 or 45 (degrees)");
    if (!(r.pp_jitter_deg >= 0.0 && r.pp_jitter_deg <= 90.0)) bad("pp_jitter", r.pp_jitter_deg, "[0, 90] degrees");
    if (run.steps < 1) bad("steps", run.steps, "an integer >= 1");
    if (run.block < 1) bad("block", run.block, "an integer >= 1");
    if (run.sample_every < 1 || run.sample_every > run.block)
        bad("sample_every", run.sample_every, "an integer in [1, block = " + std::to_string(run.block) + "]");
    if (run.timeseries_every < 0) bad("timeseries_every", run.timeseries_every, "an integer >= 0 (0 = none)");
    if (run.t_avg_start < 0 || run.t_avg_start % run.block != 0)
        bad("t_avg_start", run.t_avg_start, "a non-negative multiple of block = " + std::to_string(run.block));
    if (run.replicas < 1) bad("replicas", run.replicas, "an integer >= 1");
    if (run.threads < 0) bad("threads", run.threads, "an integer >= 0 (0 = one per replica, up to the cores)");
    const std::int64_t window_blocks = (run.steps - run.t_avg_start) / run.block;
    if (window_blocks * run.replicas < 2)
        bad("steps", run.steps,
            "at least 2 blocks of " + std::to_string(run.block) + " steps after t_avg_start = " +
                std::to_string(run.t_avg_start) + " over all replicas, for a standard error");
    if (!(run.steady_tol_u > 0)) bad("steady_tol_u", run.steady_tol_u, "> 0");
    if (!(run.steady_tol_nu > 0)) bad("steady_tol_nu", run.steady_tol_nu, "> 0");
    if (run.steady_pairs < 1) bad("steady_pairs", run.steady_pairs, "an integer >= 1");
    if (run.steady_protocol == SteadyProtocol::Runs) {
        if (run.runs_start < 2 * run.block || run.runs_start % (2 * run.block) != 0)
            bad("runs_start", run.runs_start,
                "a positive multiple of 2 x block = " + std::to_string(2 * run.block) +
                    " (each run is read over its second half, in whole blocks)");
        if (run.runs_max_steps < 2 * run.runs_start)
            bad("runs_max_steps", run.runs_max_steps,
                "at least 2 x runs_start = " + std::to_string(2 * run.runs_start) + " (two runs to compare)");
        if (!(run.runs_tol_u > 0)) bad("runs_tol_u", run.runs_tol_u, "> 0");
        if (!(run.runs_tol_nu > 0)) bad("runs_tol_nu", run.runs_tol_nu, "> 0");
    }
    if (run.snapshot_every < 0) bad("snapshot_every", run.snapshot_every, "an integer >= 0 (0 = none)");
}

const char* dir_name(int d) {
    static const char* names[8] = {"E", "NE", "N", "NW", "W", "SW", "S", "SE"};
    return names[d & 7];
}

}  // namespace granlub::automaton
