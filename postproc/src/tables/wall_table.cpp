#include "tables/wall_table.h"

#include <algorithm>

#include <fmt/format.h>

#include "formats/format.h"
#include "granlub/case/particle_box.h"
#include "results/scope.h"

namespace granlub::postproc {

namespace {

bool has_side_walls(const Run& r) {
    return r.usable() && r.scalar("shear_stress_outer") && r.scalar("shear_stress_inner");
}

}  // namespace

std::optional<double> side_wall_drag_share(const Case& c, const Run& r) {
    if (!has_side_walls(r)) return std::nullopt;
    if (const auto share = r.scalar("side_wall_drag_share")) return share;
    const auto top = r.scalar("shear_stress_top");
    const ParticleBox box = particle_box(c);
    if (!top || *top == 0 || box.periodic_z) return std::nullopt;
    const double sides = *r.scalar("shear_stress_outer") + *r.scalar("shear_stress_inner");
    return sides * box.gap / (*top * box.width);
}

std::string why_no_side_walls(const Case& c, const Run& r) {
    if (has_side_walls(r)) return "";
    if (lattice_stresses(r)) return "the lattice has no side walls";
    if (run_text(r, "geometry") == "cross_section") return "not in this result";
    if (r.kind() == SolverKind::Continuum) return "1-D gap: no side walls ([continuum] geometry = \"gap\")";
    if (c.cell.width <= 0) return "periodic across the width: no side walls";
    return "not recorded by this run";
}

Table wall_stress_table(const Case& c, const Collection& col) {
    Table t;
    bool any = false;
    t.header = {"solver", "point", "status"};
    for (const WallColumn& w : kWallColumns) t.header.emplace_back(w.label);
    t.header.emplace_back("side walls' drag / top's");
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (!r.usable()) continue;
            any = any || has_side_walls(r);
            const std::string cls = r.steady() ? "" : r.state_class();
            const char* lattice = lattice_stresses(r) ? " (lattice)" : "";
            const std::string why = why_no_side_walls(c, r);
            std::vector<Cell> row{{s, ""}, {p->id, ""}, {r.state_name(), r.state_class()}};
            for (const WallColumn& w : kWallColumns) {
                const std::string v = value_pm(r.scalar(w.output), r.scalar_stderr(w.output));
                row.push_back({!v.empty() ? v + lattice : fmt::format("— ({})", why.empty() ? "not recorded" : why), cls});
            }
            const auto share = side_wall_drag_share(c, r);
            row.push_back({share ? num(*share, 3) : fmt::format("— ({})", why.empty() ? "no top-wall stress" : why), cls});
            t.rows.push_back(std::move(row));
        }
    if (!any) t.rows.clear();
    return t;
}

}  // namespace granlub::postproc
