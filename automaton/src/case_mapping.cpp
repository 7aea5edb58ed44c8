#include "granlub/automaton/case_mapping.h"

#include <cmath>

#include <fmt/format.h>

#include "granlub/automaton/command.h"
#include "granlub/automaton/keys.h"
#include "granlub/error.h"

namespace granlub::automaton {

Mapping resolve_settings(const Case& c, const OperatingPoint& p, const RunOptions& o) {
    const Section& s = c.section(kSolver.name);
    const std::string src = c.file.string();
    const double d = c.grains.diameter;
    Mapping m;
    Params& prm = m.params;

    // Lattice: one cell per grain diameter [JH06 §CA].
    const double rows = std::round(c.cell.gap / d), cols = std::round(c.cell.length / d);
    if (rows < kMinCells)
        throw CaseError(fmt::format("{}: [cell] gap = {} m is {:.2f} grain diameters: the lattice has {} rows "
                                    "(allowed: gap >= 2.5 diameters, i.e. at least 3 rows)",
                                    src, c.cell.gap, c.cell.gap / d, rows));
    if (cols < kMinCells)
        throw CaseError(fmt::format("{}: [cell] length = {} m is {:.2f} grain diameters: the lattice has {} "
                                    "columns (allowed: length >= 2.5 diameters)",
                                    src, c.cell.length, c.cell.length / d, cols));
    if (!(rows * cols <= kMaxLatticeCells))
        throw CaseError(fmt::format("{}: [cell] length = {} m and gap = {} m make a lattice of {:.3g} x {:.3g} cells of "
                                    "one grain diameter; at most {:g} cells are allowed",
                                    src, c.cell.length, c.cell.gap, cols, rows, kMaxLatticeCells));
    prm.lattice.rows = static_cast<int>(rows);
    prm.lattice.columns = static_cast<int>(cols);

    // Fill: [automaton] fill (read with the keys below), else the point's solid fraction over the
    // model maximum [ASSUMPTION].
    if (s.has("fill")) {
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

    // Grains and walls; p_drag is the bottom wall's roughness unless [automaton] p_drag is set.
    Rules& r = prm.rules;
    r.e_p = c.grains.restitution;
    r.e_w_bottom = p.bottom.restitution;
    r.e_w_top = p.top.restitution;
    r.R_bottom = p.bottom.roughness;
    r.R_top = p.top.roughness;
    r.p_drag = r.R_bottom;

    // The [automaton] keys, then the command line's overrides.
    automaton_keys().read(prm, s, {o.full, o.vtk});
    if (o.threads > 0) prm.run.threads = o.threads;
    if (o.seed) prm.run.seed = *o.seed;
    try {
        validate(prm);
    } catch (const Error& e) {
        throw CaseError(fmt::format("{}: point {}: {}", src, p.id, e.what()));
    }
    return m;
}

}  // namespace granlub::automaton
