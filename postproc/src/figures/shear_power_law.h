// The wall shear stress against U at each load, with the power law tau = c U^n fitted per solver
// and load over the steady points only (metrics.h stress_fit: the same fit as the stress figures),
// and what the exponent says: n = 2 is Bagnold's rapid, collisional scaling at a fixed solid
// fraction (Bagnold 1954, Proc. R. Soc. A 225:49, tau ~ rho_p d^2 gamma_dot^2), n = 0 the
// rate-independent friction of quasi-static flow (GDR MiDi 2004: mu -> mu_s as I -> 0).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "formats/figure_model.h"
#include "formats/report.h"
#include "results/collect.h"
#include "statistics/speed_load_grid.h"
#include "statistics/stats.h"

namespace granlub::postproc {

// [ASSUMPTION] ours: how a fitted exponent reads. "Bagnold (collisional)" when n is within two
// standard errors of 2 or n >= kBagnoldMinExponent; "quasi-static" when within two standard errors
// of 0 or n <= kQuasiStaticMaxExponent; "between" otherwise. Both bands are ours.
inline constexpr double kBagnoldMinExponent = 1.5;
inline constexpr double kQuasiStaticMaxExponent = 0.5;
std::string exponent_reading(const PowerFit& fit);

// One figure per solver and wall: tau against U on log-log axes, a style per load (not the
// automaton: lattice stresses, one fill at every load); the fits dashed, and
// the slopes n = 2 and n = 0 as black dotted guides through the geometric mean of the data.
std::vector<Figure> shear_power_law_figures(const Collection& col, const SpeedLoadGrid& grid);
// solver, load, wall, n +- se (steady points), reading; or why there is no fit.
Table shear_exponent_table(const Collection& col, const SpeedLoadGrid& grid);

}  // namespace granlub::postproc
