// The friction coefficient mu = tau / P and the mean solid fraction against the inertial number I,
// with the glass-bead mu(I) law of Jop, Forterre & Pouliquen 2006 as the reference line.
//
// mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1)   (Jop, Forterre & Pouliquen 2006, Nature 441:727:
// their mu(I) law, written out here; its equation number there is not checked), with the values
// they give for glass beads:
//   mu_s = tan 20.9 deg ~ 0.38, mu_2 = tan 32.76 deg ~ 0.64, I_0 = 0.279.
// I = gamma_dot d / sqrt(P / rho_p) (GDR MiDi 2004, eq. 1), gamma_dot either U/H ("nominal") or the
// measured mid-gap shear rate (core granlub/flow_regime.h, run.flow_regime).
#pragma once
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "formats/figure_model.h"
#include "results/collect.h"
#include "statistics/speed_load_grid.h"

namespace granlub::postproc {

inline const double kJopMuS = std::tan(20.9 * std::numbers::pi / 180.0);   // Jop et al. 2006
inline const double kJopMu2 = std::tan(32.76 * std::numbers::pi / 180.0);  // Jop et al. 2006
inline constexpr double kJopI0 = 0.279;                                     // Jop et al. 2006
double jop_mu(double inertial_number);  // mu(I) above; mu_s at I = 0

// A run's two inertial numbers: from run.flow_regime when the solver wrote one (the particle
// solvers), else from its profile and wall stresses as core computes them (set_inertial_numbers:
// P the mean wall normal stress, H the run's mean gap or the case's). Nothing for the automaton,
// whose stresses are lattice analogues without a pressure in Pa.
struct RunInertia {
    std::optional<double> nominal, mid_gap;
};
RunInertia run_inertia(const Case& c, const Run& r);

// mu against I (mid-gap), mu against I (U/H), nu-bar against I: every solver with an I.
std::vector<Figure> mu_of_i_figures(const Case& c, const Collection& col, const SpeedLoadGrid& grid);

}  // namespace granlub::postproc
