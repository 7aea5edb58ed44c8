// The [automaton] section: every switch of the model (docs/automaton-model.md) with its default.
#include "granlub/automaton/command.h"
#include "granlub/automaton/variants.h"

namespace granlub::automaton {

// Upper bounds on counts keep a typo from exhausting memory (the sampler keeps per-block and
// time-series rows) or overflowing an int: 1e8 steps of the JH06 lattice is about an hour.
constexpr double kMaxSteps = 1e8;

namespace {
// A switch: its choices and its default (the default Params) from its variant table.
template <class E>
void variant_key(SectionSpec& s, const char* key, E def, const char* doc) {
    s.choice(key, variant_name(def), variant_names<E>(), doc);
}
}  // namespace

SectionSpec section() {
    SectionSpec s("automaton", "lattice cellular automaton (Jasti & Higgs 2006)");
    const Params def;
    variant_key(s, "mode", def.rules.mode,
             "rules: jh = JH06 as specified (scalar u_p); vector = momentum-consistent variant [ASSUMPTION]");
    s.real_optional("fill", Range::open_closed(0, 1), "",
                    "fraction of lattice cells holding a grain; default solid_fraction / max_solid_fraction [ASSUMPTION]");
    s.integer("steps", 10000, Range::closed(1, kMaxSteps), "time steps per replica (quick runs; JH06 used 10 000)");
    s.integer("steps_full", 50000, Range::closed(1, kMaxSteps), "time steps per replica with --full");
    s.integer("t_avg_start", 2000, Range::closed(0, kMaxSteps), "first step of the sampling window (a multiple of block)");
    s.integer("block", 500, Range::closed(1, kMaxSteps), "block length (steps) for the steady-state test and standard errors");
    s.integer("sample_every", 1, Range::closed(1, kMaxSteps), "sample the rows every this many steps");
    s.integer("replicas", 4, Range::closed(1, 1024), "independent replicas averaged (quick runs)");
    s.integer("replicas_full", 16, Range::closed(1, 1024), "independent replicas with --full");
    s.integer("threads", 0, Range::closed(0, 1024), "threads for the replicas; 0 = one per core (--threads overrides)");
    s.integer("seed", 1, Range::at_least(0), "random seed (--seed overrides); same seed = same numbers");
    s.real("s0_max", 0.1, Range::open_closed(0, 1), "", "initial u_p/U uniform on (0, s0_max] [ASSUMPTION]");
    // 65535: the 16-bit clock of the round and ceil rules (Engine::kTfMaxLimit)
    s.integer("tf_max", 50, Range::closed(1, 65535),
              "slowest time factor; grains with u_p < U/tf_max are at rest [ASSUMPTION]");
    variant_key(s, "tf_rounding", def.rules.tf_rounding,
             "time factor from u_p: round(U/u_p), ceil(U/u_p), or a continuous progress counter [ASSUMPTION]");
    variant_key(s, "wall_speed", def.rules.wall_speed,
             "wall speed law: Eq. 6 then Eq. 7, or Eq. 7 for normal / Eq. 6 for oblique impacts [ASSUMPTION]");
    s.real_optional("p_drag", Range::unit(), "",
                    "probability of the +x drag notch at the moving wall; default = bottom-wall roughness [ASSUMPTION]");
    s.integer("pp_deflect", 90, Range::closed(45, 90), "mover deflection at a grain hit: 90 (billiard) or 45 degrees [RECON]");
    variant_key(s, "struck_dir", def.rules.struck_dir,
             "struck grain's new direction: along the line of centres, or unchanged [ASSUMPTION]");
    s.real("pp_jitter", 22.5, Range::closed(0, 90), "deg", "vector mode: spread of the line of centres [ASSUMPTION]");
    variant_key(s, "vec_blocked", def.rules.vec_blocked,
             "vector mode, grains not approaching: deflect the mover by 45 degrees, or end its update [ASSUMPTION]");
    s.real("steady_tol_u", 0.02, Range::positive(), "", "block test: max |change of u/U| between consecutive blocks");
    s.real("steady_tol_nu", 0.02, Range::positive(), "", "block test: max |change of occupancy| between blocks");
    variant_key(s, "steady_state", def.run.steady_protocol,
             "steady-state protocol: blocks = block test over `steps` (docs/automaton-model.md §4.4); runs = JH06's "
             "literal protocol (§4.5): runs of runs_start, 2 runs_start, ... steps until consecutive runs agree");
    s.integer("runs_start", 1000, Range::closed(1, kMaxSteps),
              "steady_state = \"runs\": first run length T_1 (a multiple of 2 x block); each run doubles it");
    s.integer("runs_max_steps", 16000, Range::closed(1, kMaxSteps),
              "steady_state = \"runs\": step limit; the point fails if runs up to this length never agree");
    s.real("runs_tol_u", 0.01, Range::positive(), "",
           "steady_state = \"runs\": max |change of u/U| between consecutive runs (JH06)");
    s.real("runs_tol_nu", 0.01, Range::positive(), "",
           "steady_state = \"runs\": max |change of occupancy| between consecutive runs");
    s.integer("timeseries_every", 10, Range::closed(0, kMaxSteps), "write <u_p>, u(row 0), u(top row) every this many steps (0 = none)");
    s.integer("vtk_every", 100, Range::closed(1, kMaxSteps), "lattice snapshot interval (steps) with --vtk");
    s.validate = [](const Section& sec) {
        const auto deflect = sec.integer("pp_deflect");
        if (deflect != 45 && deflect != 90) sec.fail("pp_deflect", "allowed: 45 or 90");
        const auto block = sec.integer("block");
        if (sec.integer("t_avg_start") % block != 0)
            sec.fail("t_avg_start", "must be a multiple of block = " + std::to_string(block));
        for (const char* steps : {"steps", "steps_full"})
            if (sec.integer(steps) < sec.integer("t_avg_start") + block)
                sec.fail(steps, "must be at least t_avg_start + block = " +
                                    std::to_string(sec.integer("t_avg_start") + block) +
                                    " so that the sampling window holds a block");
        if (variant<SteadyProtocol>(sec.string("steady_state"), "steady_state") == SteadyProtocol::Runs) {
            const auto start = sec.integer("runs_start");
            if (start % (2 * block) != 0)
                sec.fail("runs_start", "allowed: a positive multiple of 2 x block = " + std::to_string(2 * block) +
                                           " (each run is read over its second half, in whole blocks)");
            if (sec.integer("runs_max_steps") < 2 * start)
                sec.fail("runs_max_steps", "allowed: at least 2 x runs_start = " + std::to_string(2 * start) +
                                               " (two runs to compare)");
        }
        if (sec.integer("sample_every") > block)
            sec.fail("sample_every", "must not exceed block = " + std::to_string(block));
    };
    return s;
}

}  // namespace granlub::automaton
