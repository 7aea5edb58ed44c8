// The regime map over (U, P) and the lift-off: each point's verdict (core granlub/flow_regime.h:
// contact or collision lubrication in Sawyer & Tichy's sense, the criterion that decided, the
// inertial class beside it), and the gap and mean solid fraction against U at each load, with the
// experiment's critical shear rate marked.
//
// Sawyer & Tichy 2001 (J. Tribol. 123:777) saw the upper surface lift off above a shear rate of
// about 100 1/s in their cell (loads 2.25-5.55 kPa, speeds 0.4-2.8 m/s): drawn at U = 100 1/s x H,
// H the case's gap. [ASSUMPTION] The nominal gap H of the case sets the line; under load control
// each run's gap moves, so the line marks the experiment's rate, not each run's.
#pragma once
#include <vector>

#include "formats/figure_model.h"
#include "formats/report.h"
#include "results/collect.h"
#include "statistics/speed_load_grid.h"

namespace granlub::postproc {

inline constexpr double kSawyerCriticalShearRate = 100.0;  // 1/s, Sawyer & Tichy 2001: lift-off above it

// One map per solver that recorded a verdict (run.flow_regime): U across, P up.
std::vector<Figure> regime_map_figures(const Case& c, const Collection& col, const SpeedLoadGrid& grid);
// The gap (load-controlled solvers that report one) and the mean solid fraction against U, per load:
// one figure per solver and quantity (not the lattice solvers, named in the caption).
std::vector<Figure> liftoff_figures(const Case& c, const Collection& col, const SpeedLoadGrid& grid);
// Per solver and point: U, P, state, the solver's own verdict and the criterion that decided it (a
// particle engine's contacts, the continuum's I/nu; "—" without one), I (U/H), I (mid-gap), gap; per
// point the particle engines' combined verdict.
Table regime_table(const Case& c, const Collection& col, const SpeedLoadGrid& grid);

}  // namespace granlub::postproc
