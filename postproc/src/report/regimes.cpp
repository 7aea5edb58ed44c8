#include "report/regimes.h"

#include <fmt/format.h>

#include "figures/continuum_map.h"
#include "figures/mu_of_i.h"
#include "figures/regime_map.h"
#include "figures/shear_power_law.h"
#include "formats/format.h"

namespace granlub::postproc {

RegimePart regime_part(const Case& c, const Collection& col) {
    RegimePart out;
    out.grid = speed_load_grid(col.points);
    if (!out.grid.drawn()) return out;
    for (auto&& f : regime_map_figures(c, col, out.grid)) out.figures.push_back(std::move(f));
    for (auto&& f : liftoff_figures(c, col, out.grid)) out.figures.push_back(std::move(f));
    for (auto&& f : mu_of_i_figures(c, col, out.grid)) out.figures.push_back(std::move(f));
    for (auto&& f : continuum_map_figures(c, col)) out.figures.push_back(std::move(f));
    for (auto&& f : shear_power_law_figures(col, out.grid)) out.figures.push_back(std::move(f));
    out.verdicts = regime_table(c, col, out.grid);
    out.exponents = shear_exponent_table(col, out.grid);
    const std::size_t cells = out.grid.speeds.size() * out.grid.loads.size();
    std::size_t points = 0;
    for (const auto& g : out.grid.per_load) points += g.points.size();
    if (points < cells)
        out.notes.push_back(fmt::format("The case has {} of the {} (speed, load) pairs of a full grid: the others are "
                                        "holes in the map, not results.",
                                        points, cells));
    for (const auto& s : col.solvers)
        for (const auto& g : out.grid.per_load)
            for (const OperatingPoint* p : g.points) {
                const Run& r = col.run(s, p->id);
                if (!r.usable() && r.status.state != ResultState::Missing && col.any_usable(s))
                    out.notes.push_back(fmt::format("{} {} ({}): {}", s, p->id, r.state_name(), r.state_reason()));
            }
    return out;
}

void add_regime_part(Report& rep, const RegimePart& s, const std::vector<FigureRef>& refs) {
    rep.heading("Regimes over speed and load");
    if (!s.grid.drawn()) {
        rep.text(fmt::format("No regime map: {}.", s.grid.why_not));
        return;
    }
    rep.text(fmt::format(
        "Sawyer & Tichy 2001 saw two regimes in their cell: granular contact lubrication (the beads compacted in "
        "enduring contacts) at low speed, and granular collision lubrication (the upper surface lifted off, "
        "collisions carrying the load) above a shear rate of about {} 1/s. This case sweeps {} speeds × {} loads "
        "({}–{} m/s, {}–{} Pa). Each particle point's verdict is decided by its contacts alone (the coordination "
        "number Z and the contact persistence); the inertial-number class stands beside it as a separate "
        "measure. Steady points only are fitted.",
        num(kSawyerCriticalShearRate), s.grid.speeds.size(), s.grid.loads.size(), num(s.grid.speeds.front()),
        num(s.grid.speeds.back()), num(s.grid.loads.front()), num(s.grid.loads.back())));
    for (const auto& n : s.notes) rep.text(n);
    rep.figures(refs);
    rep.heading("Verdict at each point and what decided it", 3);
    rep.table(s.verdicts);
    rep.heading("Shear stress–speed exponent per load", 3);
    if (s.exponents.rows.empty())
        rep.text("No exponent: no solver has results at these points.");
    else
        rep.table(s.exponents);
    rep.text(fmt::format("Reading [ours]: Bagnold (collisional) when n ≥ {} or within two standard errors of 2; "
                         "quasi-static when n ≤ {} or within two standard errors of 0.",
                         num(kBagnoldMinExponent), num(kQuasiStaticMaxExponent)));
}

}  // namespace granlub::postproc
