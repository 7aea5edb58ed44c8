// The [automaton] section: every switch of the model (docs/automaton-model.md), each key once with
// its default, range, doc and the Params field it sets (keys.h).
#include <type_traits>

#include "granlub/automaton/command.h"
#include "granlub/automaton/keys.h"
#include "granlub/automaton/variants.h"

namespace granlub::automaton {

// Upper bounds on counts keep a typo from exhausting memory (the sampler keeps per-block and
// time-series rows) or overflowing an int: 1e8 steps of the JH06 lattice is about an hour.
constexpr double kMaxSteps = 1e8;

namespace {

// A field of Params: which part, which member.
template <class S, class T>
struct Field {
    S Params::*part;
    T S::*member;
    T& of(Params& p) const { return p.*part.*member; }
    const T& of(const Params& p) const { return p.*part.*member; }
};
template <class T>
Field<LatticeSpec, T> lattice(T LatticeSpec::*m) { return {&Params::lattice, m}; }
template <class T>
Field<Rules, T> rule(T Rules::*m) { return {&Params::rules, m}; }
template <class T>
Field<RunSpec, T> run(T RunSpec::*m) { return {&Params::run, m}; }

// Declares a key in the section and binds it to its field, one call per key. The setters read the
// value the schema has checked; a switch's values come from its variant table (variants.h).
class KeyTable {
public:
    explicit KeyTable(AutomatonKeys& k) : k_(k) {}

    template <class S, class T>
    KeyTable& integer(const char* key, Field<S, T> f, std::int64_t def, Range r, const char* doc) {
        k_.spec.integer(key, def, r, doc);
        return bind(key, f);
    }
    template <class S>
    KeyTable& real(const char* key, Field<S, double> f, double def, Range r, const char* unit, const char* doc) {
        k_.spec.real(key, def, r, unit, doc);
        return bind(key, f);
    }
    template <class S>
    KeyTable& real_optional(const char* key, Field<S, double> f, Range r, const char* doc) {
        k_.spec.real_optional(key, r, "", doc);
        return bind(key, f);
    }
    template <class S, class E>
    KeyTable& choice(const char* key, Field<S, E> f, E def, const char* doc) {
        k_.spec.choice(key, variant_name(def), variant_names<E>(), doc);
        return bind(key, f);
    }
    // The key read instead with --full: declared next, with the same range.
    KeyTable& full(const char* key, std::int64_t def, const char* doc) {
        k_.spec.integer(key, def, k_.spec.keys.back().range, doc);
        k_.bindings.back().full_key = key;
        return *this;
    }
    KeyTable& only_with_vtk() {
        k_.bindings.back().only_with_vtk = true;
        return *this;
    }
    KeyTable& output_only() {
        k_.bindings.back().output_only = true;
        return *this;
    }
    KeyTable& old_names(std::vector<std::string> names) {
        k_.spec.old_names(std::move(names));
        return *this;
    }

private:
    template <class S, class T>
    KeyTable& bind(const char* key, Field<S, T> f) {
        KeyBinding b;
        b.key = key;
        if constexpr (std::is_enum_v<T>) {
            b.set = [f, key = std::string(key)](Params& p, const Value& v) {
                f.of(p) = variant<T>(std::get<std::string>(v), key);
            };
            b.get = [f](const Params& p) { return Value{std::string(variant_name(f.of(p)))}; };
        } else if constexpr (std::is_integral_v<T>) {
            b.set = [f](Params& p, const Value& v) { f.of(p) = static_cast<T>(std::get<std::int64_t>(v)); };
            b.get = [f](const Params& p) { return Value{static_cast<std::int64_t>(f.of(p))}; };
        } else {
            b.set = [f](Params& p, const Value& v) { f.of(p) = std::get<double>(v); };
            b.get = [f](const Params& p) { return Value{f.of(p)}; };
        }
        k_.bindings.push_back(std::move(b));
        return *this;
    }
    AutomatonKeys& k_;
};

AutomatonKeys declare() {
    AutomatonKeys keys{SectionSpec("automaton", "lattice cellular automaton (Jasti & Higgs 2006)"), {}};
    KeyTable k(keys);
    k.choice("mode", rule(&Rules::mode), Mode::JH,
             "rules: jh = JH06 as specified (scalar u_p); vector = momentum-consistent variant [ASSUMPTION]");
    k.real_optional("fill", lattice(&LatticeSpec::fill), Range::open_closed(0, 1),
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
    k.choice("tf_rounding", rule(&Rules::tf_rounding), TfRounding::Round,
             "time factor from u_p: round(U/u_p), ceil(U/u_p), or a continuous progress counter [ASSUMPTION]");
    k.choice("wall_speed", rule(&Rules::wall_speed), WallSpeed::Sequential,
             "wall speed law: Eq. 6 then Eq. 7, or Eq. 7 for normal / Eq. 6 for oblique impacts [ASSUMPTION]");
    k.real_optional("p_drag", rule(&Rules::p_drag), Range::unit(),
                    "probability of the +x drag notch at the moving wall; default = bottom-wall roughness [ASSUMPTION]");
    k.integer("pp_deflect", rule(&Rules::pp_deflect), 90, Range::closed(45, 90),
              "mover deflection at a grain hit: 90 (billiard) or 45 degrees [RECON]");
    k.choice("struck_dir", rule(&Rules::struck_dir), StruckDir::Line,
             "struck grain's new direction: along the line of centres, or unchanged [ASSUMPTION]");
    k.real("pp_jitter", rule(&Rules::pp_jitter_deg), 22.5, Range::closed(0, 90), "deg",
           "vector mode: spread of the line of centres [ASSUMPTION]");
    k.choice("vec_blocked", rule(&Rules::vec_blocked), VecBlocked::Deflect,
             "vector mode, grains not approaching: deflect the mover by 45 degrees, or end its update [ASSUMPTION]");
    k.real("steady_tol_u", run(&RunSpec::steady_tol_u), 0.02, Range::positive(), "",
           "block test: max |change of u/U| between consecutive blocks");
    k.real("steady_tol_nu", run(&RunSpec::steady_tol_nu), 0.02, Range::positive(), "",
           "block test: max |change of occupancy| between blocks");
    k.choice("steady_state", run(&RunSpec::steady_protocol), SteadyProtocol::Blocks,
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
    keys.spec.validate = [](const Section& sec) {
        for (const bool full : {false, true}) {
            Params p;
            read_keys(p, sec, {full, false});
            if (const auto bad = broken_key_rule(p))
                sec.fail(key_name(bad->key, {full, false}), "allowed: " + bad->allowed);
        }
    };
    return keys;
}

}  // namespace

const AutomatonKeys& automaton_keys() {
    static const AutomatonKeys keys = declare();
    return keys;
}

SectionSpec section() { return automaton_keys().spec; }

Params::Params() {
    for (const auto& b : automaton_keys().bindings) {
        const KeySpec* k = automaton_keys().spec.find(b.key);
        if (k->default_value && !b.only_with_vtk) b.set(*this, *k->default_value);
    }
}

void read_keys(Params& p, const Section& s, KeyUse use) {
    for (const auto& b : automaton_keys().bindings) {
        if (b.only_with_vtk && !use.vtk) continue;
        const std::string key = key_name(b.key, use);
        if (s.has(key)) b.set(p, s.values().at(key));
    }
}

std::string key_name(const std::string& key, KeyUse use) {
    if (use.full)
        for (const auto& b : automaton_keys().bindings)
            if (b.key == key && !b.full_key.empty()) return b.full_key;
    return key;
}

}  // namespace granlub::automaton
