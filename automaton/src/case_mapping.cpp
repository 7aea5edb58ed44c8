#include "granlub/automaton/case_mapping.h"

#include <cmath>

#include <fmt/format.h>

#include "granlub/automaton/variants.h"
#include "granlub/error.h"

namespace granlub::automaton {

namespace {

// Memory of the lattice and its grains (a few tens of bytes per cell) and int indices bound it.
constexpr double kMaxLatticeCells = 5e7;

// The variant the case names for `key` (the schema has checked that it is one).
template <class E>
E pick(const Section& s, const char* key) {
    return variant<E>(s.string(key), key);
}

}  // namespace

Mapping map_point(const Case& c, const OperatingPoint& p, const RunOptions& o) {
    const Section& s = c.section("automaton");
    const std::string src = c.file.string();
    const double d = c.grains.diameter;
    Mapping m;
    Params& prm = m.params;

    // Lattice: one cell per grain diameter [JH06 §CA].
    const double rows = std::round(c.cell.gap / d), cols = std::round(c.cell.length / d);
    if (rows < 3)
        throw CaseError(fmt::format("{}: [cell] gap = {} m is {:.2f} grain diameters: the lattice has {} rows "
                                    "(allowed: gap >= 2.5 diameters, i.e. at least 3 rows)",
                                    src, c.cell.gap, c.cell.gap / d, rows));
    if (cols < 3)
        throw CaseError(fmt::format("{}: [cell] length = {} m is {:.2f} grain diameters: the lattice has {} "
                                    "columns (allowed: length >= 2.5 diameters)",
                                    src, c.cell.length, c.cell.length / d, cols));
    if (!(rows * cols <= kMaxLatticeCells))
        throw CaseError(fmt::format("{}: [cell] length = {} m and gap = {} m make a lattice of {:.3g} x {:.3g} cells of "
                                    "one grain diameter; at most {:g} cells are allowed",
                                    src, c.cell.length, c.cell.gap, cols, rows, kMaxLatticeCells));
    prm.lattice.rows = static_cast<int>(rows);
    prm.lattice.columns = static_cast<int>(cols);

    // Fill: [automaton] fill, else the point's solid fraction over the model maximum [ASSUMPTION].
    if (const auto f = s.maybe_real("fill")) {
        prm.lattice.fill = *f;
        m.fill_source = "[automaton] fill";
    } else {
        if (p.control == Control::Load)
            throw NoAnswer(fmt::format(
                "point {}: the cellular automaton holds a fixed number of grains and cannot follow "
                "control = \"load\"; set [automaton] fill (fraction of cells occupied) or use control = \"fill\"",
                p.id));
        if (!(c.cell.max_solid_fraction > 0))
            throw CaseError(fmt::format("{}: [cell] max_solid_fraction = {} (allowed: > 0; the CA maps "
                                        "solid_fraction / max_solid_fraction to its fill)",
                                        src, c.cell.max_solid_fraction));
        prm.lattice.fill = p.solid_fraction / c.cell.max_solid_fraction;
        m.fill_source = "[operating] solid_fraction / [cell] max_solid_fraction";
        if (!(prm.lattice.fill > 0 && prm.lattice.fill <= 1))
            throw CaseError(fmt::format(
                "{}: point {}: [operating] solid_fraction = {} over [cell] max_solid_fraction = {} gives a lattice "
                "fill of {:.4f} (allowed: (0, 1]; set [automaton] fill to override)",
                src, p.id, p.solid_fraction, c.cell.max_solid_fraction, prm.lattice.fill));
    }
    prm.lattice.s0_max = s.real("s0_max");

    // Rules.
    Rules& r = prm.rules;
    r.mode = pick<Mode>(s, "mode");
    r.e_p = c.grains.restitution;
    r.e_w_bottom = p.bottom.restitution;
    r.e_w_top = p.top.restitution;
    r.R_bottom = p.bottom.roughness;
    r.R_top = p.top.roughness;
    r.p_drag = s.maybe_real("p_drag").value_or(r.R_bottom);
    r.tf_max = static_cast<int>(s.integer("tf_max"));
    r.tf_rounding = pick<TfRounding>(s, "tf_rounding");
    r.wall_speed = pick<WallSpeed>(s, "wall_speed");
    r.pp_deflect = static_cast<int>(s.integer("pp_deflect"));
    r.struck_dir = pick<StruckDir>(s, "struck_dir");
    r.pp_jitter_deg = s.real("pp_jitter");
    r.vec_blocked = pick<VecBlocked>(s, "vec_blocked");

    // Run.
    RunSpec& run = prm.run;
    run.steps = s.integer(o.full ? "steps_full" : "steps");
    run.replicas = static_cast<int>(s.integer(o.full ? "replicas_full" : "replicas"));
    run.t_avg_start = s.integer("t_avg_start");
    run.block = s.integer("block");
    run.sample_every = s.integer("sample_every");
    run.timeseries_every = s.integer("timeseries_every");
    run.threads = o.threads > 0 ? o.threads : static_cast<int>(s.integer("threads"));
    run.seed = o.seed ? *o.seed : static_cast<std::uint64_t>(s.integer("seed"));
    run.steady_tol_u = s.real("steady_tol_u");
    run.steady_tol_nu = s.real("steady_tol_nu");
    run.steady_protocol = pick<SteadyProtocol>(s, "steady_state");
    run.runs_start = s.integer("runs_start");
    run.runs_max_steps = s.integer("runs_max_steps");
    run.runs_tol_u = s.real("runs_tol_u");
    run.runs_tol_nu = s.real("runs_tol_nu");
    run.snapshot_every = o.vtk ? s.integer("vtk_every") : 0;
    try {
        validate(prm);
    } catch (const Error& e) {
        throw CaseError(fmt::format("{}: point {}: {}", src, p.id, e.what()));
    }
    return m;
}

}  // namespace granlub::automaton
