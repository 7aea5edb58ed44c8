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
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granlub/case/case.h"
#include "granlub/results/results.h"

namespace granlub {

inline constexpr double kCoreFrom = 1.0 / 3.0;  // y/H
inline constexpr double kCoreTo = 2.0 / 3.0;
// The walls' layers, where the continuum's wall constants are calibrated (continuum-fit --free slip_dissipation):
// the stations within kNearWallBand grain diameters of each wall's bump tops (d_w/2 inside its plane, as
// bump_protrusion gives it) [ASSUMPTION: our choice; two diameters hold the layer T falls across toward a bumpy
// wall in the DEM, and four to five profile stations].
inline constexpr double kNearWallBand = 2.0;  // grain diameters

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
    std::optional<Measured> slip_bottom, slip_top;  // m/s, the summary's slips (results.h), when recorded
    double protrusion_bottom = 0, protrusion_top = 0;  // m, how far each wall's bumps reach into the gap
};

// The mean of profile.csv's temperature_over_U2 over the stations whose y/H lies within kNearWallBand diameters
// above the floor's bump tops and below the top's, on the profile's one y/H scale (kProfileYDefinition: y from
// the floor's plane, H = gap between the planes). Errors: the mean of the stations' temperature_over_U2_stderr (the
// fully correlated bound, as the core's means), 0 when the profile has no such column (the continuum's).
// A particle profile's stations are slabs (each already a mean over its height): the mean of those whose centres lie
// in the band. A continuum's are the nodes of a solution: the band's mean of the straight lines between them
// (BandMean::Interpolated), which moves continuously as the solved gap moves the nodes across the band's edges (a
// fit's finite differences need that; the stations' mean jumps when a node enters the band).
// Throws Error when a band holds no station.
enum class BandMean { Stations, Interpolated };
struct NearWallTemperature {
    Measured bottom, top;  // T/U^2
    std::size_t stations_bottom = 0, stations_top = 0;
};
NearWallTemperature near_wall_temperature(const Profile& p, double gap, double diameter, double protrusion_bottom,
                                          double protrusion_top, BandMean how = BandMean::Stations);

// What the walls' layers give the wall constants' fit: the slips over U and the near-wall T over U^2.
struct WallLayers {
    Measured slip_bottom, slip_top;  // slip/U, errors from the summary's stderr
    Measured T_bottom, T_top;        // near_wall_temperature
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
    std::optional<WallLayers> walls;       // when the run recorded both slips
};

// A run's CoreRun from its result files: its profile, U, its summary's outputs (`gap`, else case_gap for a solver
// that keeps the gap fixed; the walls' stresses and, when both are there, slips, each with its standard error, 0
// when it has none), its run.flow_regime record (Z; an empty object when it has none) and each wall's bump
// protrusion (bump_protrusion, wall_bumps.h). Every solver's results read alike: the bulk table's DEM runs, and the
// report's twin (the continuum's too). Throws Error naming `source` and a missing output.
CoreRun core_run(const Profile& profile, double U, const std::map<std::string, Scalar>& outputs,
                 const nlohmann::json& flow_regime, double case_gap, double protrusion_bottom, double protrusion_top,
                 const std::string& source);

// The core of one run of point p of case c, as every reader takes it (the bulk table's answers and their Delta-t checks,
// the report's twins): core_run on the run's profile and outputs, its record's `flow_regime` (none: no Z) and the
// case's bump protrusions, then core_rheology at the grains' mean diameter and density. `record` is the run's
// summary.run, or a check's record in run.dt_refinement.
CoreRheology run_core(const Case& c, const OperatingPoint& p, const Profile& profile,
                      const std::map<std::string, Scalar>& outputs, const nlohmann::json& record,
                      const std::string& source);

// The time-step rule of the particle pipeline (granlub/results/run_status.h), which judges a point by
// its mean solid fraction and its walls' shear stresses, applied to the core: nu may move by
// kDtMaxSolidFractionChange; mu and I each by kDtMaxRelativeStressChange, or by more when within
// kDtMaxStressZ combined standard errors. The names of the quantities that moved more ("I", "mu",
// "nu"), empty when the core is converged. I is not in the pipeline's rule: the walls' slips can move
// with the step while the stresses do not, and I moves with them.
std::vector<std::string> core_dt_unconverged(const CoreRheology& answer, const CoreRheology& check);

// A profile without the _stderr columns (a continuum's) reads with zero errors: its means exact, its line fitted
// unweighted (the scatter about it the slope's error). Throws Error naming what is missing (a profile column, fewer
// than 6 stations in the core, a non-positive shear rate or pressure).
CoreRheology core_rheology(const CoreRun& run, double diameter, double density);

// The cores of a point's seeds (seeds.h), each reduced alone by core_rheology, as one: every measured quantity the
// mean over the members (seed_mean.h), its error the larger of the seeds' standard error and the members' own errors
// combined. Our choice, not the seeds' pool's (which keeps the seeds' standard error): the core's I wanders over a
// run more slowly than a run's blocks see (cases/bulk_shear/README.md), so only the seeds' scatter shows it, but
// the scatter of a few seeds can be small by chance. Z and the walls' layers pooled when every member has them.
// Throws Error when members is empty or their cores differ in stations.
CoreRheology pool_core_rheology(const std::vector<CoreRheology>& members);

}  // namespace granlub
