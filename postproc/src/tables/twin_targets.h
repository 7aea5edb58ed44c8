// The continuum against its particle twin (issue 73, item 5): on a case whose particle cell is periodic
// across the width ([cell] width = 0: no side walls, so granlub dem solves the continuum's 1-D problem),
// targets a constant μ cannot meet, judged per point against the DEM: μ at each wall, slip at each wall,
// ν(y) in the core, the gap, T(y) where the DEM resolves it; and per load μ's rise from the slowest to the
// fastest speed. Two models are judged: the continuum as run (its closures as the case configures them)
// and the constant μ that fits the DEM best (twin_constant_mu), which has only μ and rises by 0.
// Thresholds: tables/twin_thresholds.h. Only steady (so Δt-converged where checked) DEM points are judged.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

// The twin's two solvers, from the solvers' declarations (SolverInfo::kind): the first continuum and the
// first particle engine, in declared order (granlub dem before yade), with usable results; "" where none.
struct TwinSolvers {
    std::string model, particles;
};
TwinSolvers twin_solvers(const Case& c, const Collection& col);

// The one definition of the gap the twin targets use: the run's `gap` output (m), else the case's
// [cell] gap (a solver that keeps the gap fixed); `fixed` says which.
double twin_gap(const Case& c, const Run& r, bool* fixed = nullptr);

// One target at one point (or one load) for one model.
struct TargetCheck {
    std::string target;  // "μ floor", "slip top / U", ...
    std::string rule;    // "within 7 %"
    std::optional<double> dem, dem_se;   // the DEM's value and standard error
    std::optional<double> model;         // the model's value
    std::optional<double> difference;    // as the rule measures it (relative, in U, RMS, ratio ...)
    bool judged = false;                 // false: the model has no such quantity, or the DEM none
    bool met = false;
    bool within_dem_error = false;  // missed by less than kTwinDemErrorZ DEM standard errors beyond the band
    std::string note;               // why not judged, or what was measured ("12 stations")
};

struct TwinPoint {
    const OperatingPoint* point = nullptr;
    bool judged = false;       // the DEM's result is steady
    std::string dem_state;     // the DEM's state (Run::state_name) when not judged
    bool dt_checked = false;   // the DEM's point carries a half-step record (run.dt_refinement)
    std::vector<TargetCheck> continuum, constant;  // the same targets, in the same order
    bool continuum_met = false, constant_met = false;  // every judged target met (at a judged point)
};

// μ's rise over one load's speeds at one wall.
struct TwinRise {
    std::string group;  // "P = 2250 Pa" (or "every point")
    std::string wall;   // "floor", "top"
    double slow = 0, fast = 0;  // the speeds it spans (the slowest and fastest judged DEM points)
    TargetCheck continuum, constant;
};

struct ModelCount {
    int met = 0, judged = 0, listed = 0, required = 0;  // points
    int rises_met = 0, rises = 0;
    bool overall = false;  // met >= required and every rise met (at least one judged point)
};

struct TwinTargets {
    TwinSolvers solvers;
    std::string closures;       // the continuum as run: its closures named from its summary
    double constant_floor = 0, constant_top = 0;  // the constant μ at each wall (twin_constant_mu)
    bool equal_grains = false;  // [grains] size_spread = 0: the particle runs order into layers
    std::vector<TwinPoint> points;
    std::vector<TwinRise> rises;
    ModelCount continuum, constant;
};

// Whether the case has a twin to judge: periodic across the width, not a ring, with usable results of
// both the continuum and the DEM.
bool twin_applies(const Case& c, const Collection& col);

// The constant μ0 per wall over the DEM's μ_i at the judged points: the one that meets the μ target
// (|μ0 − μ_i| ≤ kTwinMuRelative μ_i) at the most points, floor and top together; among those the
// one with the smallest sum of squared relative deviations. The most favourable constant for the
// table, so that its failure is the constant's, not the fit's. floor and top: {μ_i}, in point order.
std::pair<double, double> twin_constant_mu(const std::vector<double>& floor, const std::vector<double>& top);

TwinTargets twin_targets(const Case& c, const Collection& col);

// The count per model against the rule; μ's rises; one point's targets.
Table twin_count_table(const TwinTargets& t);
Table twin_rise_table(const TwinTargets& t);
// Per target, at how many judged points each model meets it: what the models miss, at a glance.
Table twin_by_target_table(const TwinTargets& t);
Table twin_point_table(const TwinPoint& p);

}  // namespace granlub::postproc
