// The bulk rheology of a wide plane-shear cell, read in its core (cases/bulk_shear): the GDR MiDi
// (Eur. Phys. J. E 14 (2004) 341) and da Cruz et al. (Phys. Rev. E 72 (2005) 021309) method. Without
// gravity and side walls the shear and normal stresses are uniform across the gap (momentum
// balance), so the walls' mean stresses are the core's; the shear rate is the slope of a straight
// line fitted to u(y) over the core, where the inertial number is uniform, away from the walls'
// layers; the solid fraction, temperature and coordination number are the core's means.
//
// The core is the middle third of the gap between the walls' planes (kCoreFrom..kCoreTo of the
// profile's y/H): 10 grain diameters of a 30-diameter gap, at least 10 d from the bumps' centres
// [ASSUMPTION: our choice; GDR MiDi read the central part of a wider cell]. The reduction reports
// how uniform the shear rate is over it (the two halves' slopes) rather than choosing the band.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "granlub/results/results.h"

namespace granlub {

inline constexpr double kCoreFrom = 1.0 / 3.0;  // y/H
inline constexpr double kCoreTo = 2.0 / 3.0;

// A value with its standard error (0 when not known).
struct Measured {
    double value = 0;
    double error = 0;
};

// A weighted least-squares line u = a + b y. slope_error is the larger of the error propagated
// from the points' standard errors and the scatter of the points about the line (their residuals'
// variance, n - 2 degrees of freedom): a profile whose block errors understate its scatter (or that
// is not straight) gets the larger error.
struct LineFit {
    double intercept = 0, slope = 0, slope_error = 0;
    std::size_t points = 0;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& y_error);

// One run of a point (the answer, or the run it was Delta-t-checked against), as the reduction
// needs it: its profile (profile.csv columns y_over_H, u_over_U, solid_fraction,
// temperature_over_U2 and their _stderr), the walls' stresses, the gap, and Z.
struct CoreRun {
    const Profile* profile = nullptr;
    double speed = 0;               // U, m/s
    double gap = 0;                 // m, the mean gap (the profile's H)
    Measured normal_bottom, normal_top, shear_bottom, shear_top;  // Pa
    std::optional<Measured> z_core;  // the core's coordination number (flow_regime), when recorded
    std::optional<Measured> z_bulk;  // every grain's
};

// The core's rheology. Errors: of a mean over the core's stations, the mean of their standard errors
// (neighbouring stations share grains and blocks, so their errors are not independent: this is the
// fully correlated, larger, bound); of a ratio, the relative errors added in quadrature.
struct CoreRheology {
    std::size_t stations = 0;         // profile stations whose centres lie in the core
    double core_from = kCoreFrom, core_to = kCoreTo;
    Measured shear_rate;              // 1/s, the fit's slope times U / H
    double shear_rate_halves = 0;     // (slope of the core's upper half - lower half) / slope of the core
    Measured pressure;                // Pa, mean of the two walls' normal stresses
    Measured shear_stress;            // Pa, mean of the two walls' shear stresses
    double wall_shear_imbalance = 0;  // (tau_top - tau_bottom) / tau: 0 by momentum balance
    double wall_normal_imbalance = 0; // (P_top - P_bottom) / P: 0 without gravity
    Measured inertial_number;         // gamma_dot d / sqrt(P / rho_p)
    Measured friction;                // mu = tau / P
    Measured solid_fraction;          // nu
    Measured temperature_scaled;      // T / (d gamma_dot)^2
    std::optional<Measured> coordination;  // Z: the core's, else every grain's; none when not recorded
    bool coordination_core = false;        // whether Z is the core's
};

// The time-step rule of the particle pipeline (granlub/results/run_status.h), which judges a point by
// its mean solid fraction and its walls' shear stresses, applied to the core: nu may move by
// kDtMaxSolidFractionChange; mu and I each by kDtMaxRelativeStressChange, or by more when within
// kDtMaxStressZ combined standard errors. The names of the quantities that moved more ("I", "mu",
// "nu"), empty when the core is converged. I is not in the pipeline's rule: the walls' slips can move
// with the step while the stresses do not, and I moves with them.
std::vector<std::string> core_dt_unconverged(const CoreRheology& answer, const CoreRheology& check);

// Throws Error naming what is missing (a profile column, fewer than 3 stations in the core, a
// non-positive shear rate or pressure).
CoreRheology core_rheology(const CoreRun& run, double diameter, double density);

}  // namespace granlub
