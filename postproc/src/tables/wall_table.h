// Every wall's shear stress, one row per solver and point: floor, top, outer and inner side walls and
// the side walls' share of the drag. The one reader of the names the solvers give the side walls'
// stresses in summary.json: the particle pipeline (granlub dem and yade, core particle_reduction.h:
// shear_stress_{outer,inner}) and the continuum on the cross-section (continuum
// cross_section_setup.cpp: the same, plus side_wall_drag_share). A solver without a wall shows "—"
// and why.
#pragma once
#include <optional>
#include <string>

#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

// The walls in the table's order: summary output, column label.
struct WallColumn {
    const char* output;
    const char* label;
};
inline constexpr WallColumn kWallColumns[] = {{"shear_stress_bottom", "τ floor (Pa)"},
                                  {"shear_stress_top", "τ top (Pa)"},
                                  {"shear_stress_outer", "τ outer side wall (Pa)"},
                                  {"shear_stress_inner", "τ inner side wall (Pa)"}};

// The side walls' drag over the top's: the solver's side_wall_drag_share when it writes one (the
// continuum), else 2 τ_side H / (τ_top W) over the particle box's side and top areas (core
// particle_box.h; the box the particle pipeline divides the forces by); nothing without side walls.
std::optional<double> side_wall_drag_share(const Case& c, const Run& r);

// Why a usable run has no side-wall stresses ("" when it has them).
std::string why_no_side_walls(const Case& c, const Run& r);

// Rows for every usable run; empty when no run at any point has side walls (the case's walls are
// then the floor and top of the key numbers).
Table wall_stress_table(const Case& c, const Collection& col);

}  // namespace granlub::postproc
