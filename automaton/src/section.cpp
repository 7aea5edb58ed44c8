// The [automaton] section: every switch of the model (docs/automaton-model.md), each key once with
// its default, range, doc and the Params field it sets (keys.h).
#include "granlub/automaton/command.h"
#include "granlub/automaton/keys.h"
#include "granlub/automaton/variants.h"

namespace granlub::automaton {

// Upper bounds on counts keep a typo from exhausting memory (the sampler keeps per-block and
// time-series rows) or overflowing an int: 1e8 steps of the JH06 lattice is about an hour.
constexpr double kMaxSteps = 1e8;

namespace {

// The parts of Params a key's field lies in.
template <class T>
PartField<Params, LatticeSpec, T> lattice(T LatticeSpec::*m) { return part(&Params::lattice, m); }
template <class T>
PartField<Params, Rules, T> rule(T Rules::*m) { return part(&Params::rules, m); }
template <class T>
PartField<Params, RunSpec, T> run(T RunSpec::*m) { return part(&Params::run, m); }

// One call per key declares it and binds it to its field; a switch's values come from its variant
// table (variants.h).
BoundKeys<Params> declare() {
    BoundKeys<Params> k(SectionSpec(kSolver.name, "lattice cellular automaton (Jasti & Higgs 2006)"));
    k.choice("mode", rule(&Rules::mode), variants<Mode>(), Mode::JH,
             "rules: jh = JH06 as specified (scalar u_p); vector = momentum-consistent variant [ASSUMPTION]");
    k.real_optional("fill", lattice(&LatticeSpec::fill), Range::open_closed(0, 1), "",
                    "fraction of lattice cells holding a grain; default solid_fraction / max_solid_fraction [ASSUMPTION]");
    k.integer("steps", run(&RunSpec::steps), 10000, Range::closed(1, kMaxSteps),
              "time steps per replica (quick runs; JH06 used 10 000)")
        .full("steps_full", 50000, "time steps per replica with --full");
    k.integer("t_avg_start", run(&RunSpec::t_avg_start), 2000, Range::closed(0, kMaxSteps),
              "first step of the sampling window (a multiple of block)");
    k.integer("block", run(&RunSpec::block), 500, Range::closed(1, kMaxSteps),
              "block length (steps) for the steady-state test and standard errors");
    k.integer("sample_every", run(&RunSpec::sample_every), 1, Range::closed(1, kMaxSteps),
              "sample the rows every this many steps");
    k.integer("replicas", run(&RunSpec::replicas), 4, Range::closed(1, 1024),
              "independent replicas averaged (quick runs)")
        .full("replicas_full", 16, "independent replicas with --full");
    k.integer("threads", run(&RunSpec::threads), 0, Range::closed(0, 1024),
              "threads for the replicas; 0 = one per core (--threads overrides)")
        .output_only();
    k.integer("seed", run(&RunSpec::seed), 1, Range::at_least(0),
              "random seed (--seed overrides); same seed = same numbers");
    k.real("s0_max", lattice(&LatticeSpec::s0_max), 0.1, Range::open_closed(0, 1), "",
           "initial u_p/U uniform on (0, s0_max] [ASSUMPTION]");
    // 65535: the 16-bit clock of the round and ceil rules (Engine::kTfMaxLimit)
    k.integer("tf_max", rule(&Rules::tf_max), 50, Range::closed(1, 65535),
              "slowest time factor; grains with u_p < U/tf_max are at rest [ASSUMPTION]");
    k.choice("tf_rounding", rule(&Rules::tf_rounding), variants<TfRounding>(), TfRounding::Round,
             "time factor from u_p: round(U/u_p), ceil(U/u_p), or a continuous progress counter [ASSUMPTION]");
    k.choice("wall_speed", rule(&Rules::wall_speed), variants<WallSpeed>(), WallSpeed::Sequential,
             "wall speed law: Eq. 6 then Eq. 7, or Eq. 7 for normal / Eq. 6 for oblique impacts [ASSUMPTION]");
    k.real_optional("p_drag", rule(&Rules::p_drag), Range::unit(), "",
                    "probability of the +x drag notch at the moving wall; default = bottom-wall roughness [ASSUMPTION]");
    k.integer("pp_deflect", rule(&Rules::pp_deflect), 90, Range::closed(45, 90),
              "mover deflection at a grain hit: 90 (billiard) or 45 degrees [RECON]");
    k.choice("struck_dir", rule(&Rules::struck_dir), variants<StruckDir>(), StruckDir::Line,
             "struck grain's new direction: along the line of centres, or unchanged [ASSUMPTION]");
    k.real("pp_jitter", rule(&Rules::pp_jitter_deg), 22.5, Range::closed(0, 90), "deg",
           "vector mode: spread of the line of centres [ASSUMPTION]");
    k.choice("vec_blocked", rule(&Rules::vec_blocked), variants<VecBlocked>(), VecBlocked::Deflect,
             "vector mode, grains not approaching: deflect the mover by 45 degrees, or end its update [ASSUMPTION]");
    k.real("steady_tol_u", run(&RunSpec::steady_tol_u), 0.02, Range::positive(), "",
           "block test: max |change of u/U| between consecutive blocks");
    k.real("steady_tol_nu", run(&RunSpec::steady_tol_nu), 0.02, Range::positive(), "",
           "block test: max |change of occupancy| between blocks");
    k.choice("steady_state", run(&RunSpec::steady_protocol), variants<SteadyProtocol>(), SteadyProtocol::Blocks,
             "steady-state protocol: blocks = block test over `steps` (docs/automaton-model.md §4.4); runs = JH06's "
             "literal protocol (§4.5): runs of runs_start, 2 runs_start, ... steps until consecutive runs agree");
    k.integer("runs_start", run(&RunSpec::runs_start), 1000, Range::closed(1, kMaxSteps),
              "steady_state = \"runs\": first run length T_1 (a multiple of 2 x block); each run doubles it");
    k.integer("runs_max_steps", run(&RunSpec::runs_max_steps), 16000, Range::closed(1, kMaxSteps),
              "steady_state = \"runs\": step limit; the point fails if runs up to this length never agree");
    k.real("runs_tol_u", run(&RunSpec::runs_tol_u), 0.01, Range::positive(), "",
           "steady_state = \"runs\": max |change of u/U| between consecutive runs (JH06)");
    k.real("runs_tol_nu", run(&RunSpec::runs_tol_nu), 0.01, Range::positive(), "",
           "steady_state = \"runs\": max |change of occupancy| between consecutive runs");
    k.integer("timeseries_every", run(&RunSpec::timeseries_every), 10, Range::closed(0, kMaxSteps),
              "write <u_p>, u(row 0), u(top row) every this many steps (0 = none)")
        .output_only();
    k.integer("snapshot_every", run(&RunSpec::snapshot_every), 100, Range::closed(1, kMaxSteps),
              "lattice snapshot interval (steps) with --vtk")
        .only_with_vtk()
        .output_only()
        .old_names({"vtk_every"});
    // The rules between keys (params.cpp), on the quick and the --full run lengths.
    k.spec.validate = [](const Section& sec) {
        for (const bool full : {false, true}) {
            Params p;
            automaton_keys().read(p, sec, {full, false});
            if (const auto bad = broken_key_rule(p))
                sec.fail(automaton_keys().key_name(bad->key, {full, false}), "allowed: " + bad->allowed);
        }
    };
    return k;
}

}  // namespace

const BoundKeys<Params>& automaton_keys() { return keys_once<Params, declare>(); }

SectionSpec section() { return automaton_keys().spec; }

Params::Params() {
    for (const auto& b : automaton_keys().bindings()) {
        const KeySpec* k = automaton_keys().spec.find(b.key);
        if (k->default_value && !b.only_with_vtk) b.set(*this, *k->default_value);
    }
}

}  // namespace granlub::automaton
