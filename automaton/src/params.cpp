#include "granlub/automaton/params.h"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "granlub/automaton/directions.h"
#include "granlub/automaton/keys.h"
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

// Each bound field within its key's range (the schema's, keys.h).
void check_ranges(const Params& p) {
    const BoundKeys<Params>& keys = automaton_keys();
    for (const auto& b : keys.bindings()) {
        const Value v = b.get(p);
        double x;
        if (const auto* i = std::get_if<std::int64_t>(&v)) x = static_cast<double>(*i);
        else if (const auto* d = std::get_if<double>(&v)) x = *d;
        else continue;  // a switch: its enum holds one of its variants
        if (b.only_with_vtk && x == 0) continue;  // 0: no snapshots
        const KeySpec& k = *keys.spec.find(b.key);
        if (!k.range.contains(x)) bad(b.key, value_text(v), k.allowed_text());
    }
}

// The value of the field `key` sets, as the case file writes it.
std::string field_text(const Params& p, const std::string& key) {
    for (const auto& b : automaton_keys().bindings())
        if (b.key == key) return value_text(b.get(p));
    throw Error("internal: no [automaton] key " + key);
}

}  // namespace

std::optional<KeyProblem> broken_key_rule(const Params& p) {
    const auto& run = p.run;
    const std::string block = std::to_string(run.block);
    if (p.rules.pp_deflect != 90 && p.rules.pp_deflect != 45) return KeyProblem{"pp_deflect", "90 or 45 (degrees)"};
    if (run.t_avg_start % run.block != 0)
        return KeyProblem{"t_avg_start", "a non-negative multiple of block = " + block};
    if (run.sample_every > run.block) return KeyProblem{"sample_every", "an integer in [1, block = " + block + "]"};
    const std::int64_t window_blocks = (run.steps - run.t_avg_start) / run.block;
    if (run.steps < run.t_avg_start + run.block || window_blocks * run.replicas < 2)
        return KeyProblem{"steps", "at least t_avg_start + block = " + std::to_string(run.t_avg_start + run.block) +
                                       ", and 2 blocks of " + block + " steps after t_avg_start over all replicas, " +
                                       "for a standard error"};
    if (run.steady_protocol == SteadyProtocol::Runs) {
        if (run.runs_start % (2 * run.block) != 0)
            return KeyProblem{"runs_start", "a positive multiple of 2 x block = " + std::to_string(2 * run.block) +
                                                " (each run is read over its second half, in whole blocks)"};
        if (run.runs_max_steps < 2 * run.runs_start)
            return KeyProblem{"runs_max_steps", "at least 2 x runs_start = " + std::to_string(2 * run.runs_start) +
                                                    " (two runs to compare)"};
    }
    return std::nullopt;
}

void validate(const Params& p) {
    const auto& l = p.lattice;
    const auto& r = p.rules;
    if (l.rows < kMinCells)
        bad("rows", l.rows, "at least 3 particle rows between the walls (gap >= 2.5 grain diameters)");
    if (l.columns < kMinCells) bad("columns", l.columns, "at least 3 columns (length >= 2.5 grain diameters)");
    const double cells = static_cast<double>(l.rows) * l.columns;
    if (cells > kMaxLatticeCells) bad("rows x columns", cells, fmt::format("at most {:g} cells", kMaxLatticeCells));
    unit_interval("e_p (grains.restitution)", r.e_p);
    unit_interval("e_w at the bottom wall", r.e_w_bottom);
    unit_interval("e_w at the top wall", r.e_w_top);
    unit_interval("roughness of the bottom wall", r.R_bottom);
    unit_interval("roughness of the top wall", r.R_top);
    check_ranges(p);
    if (l.particles() < 1) bad("fill", l.fill, "a fill that puts at least one grain on the lattice");
    if (const auto k = broken_key_rule(p)) bad(k->key, field_text(p, k->key), k->allowed);
    if (p.run.steady_pairs < 1) bad("steady_pairs", p.run.steady_pairs, "an integer >= 1");
}

const char* dir_name(int d) {
    static const char* names[8] = {"E", "NE", "N", "NW", "W", "SW", "S", "SE"};
    return names[d & 7];
}

}  // namespace granlub::automaton
