#include "report/twin_part.h"

#include <fmt/format.h>

#include "granlub/results/results.h"

#include "formats/format.h"
#include "tables/twin_core_table.h"
#include "tables/twin_targets.h"
#include "tables/twin_thresholds.h"

namespace granlub::postproc {

namespace {

std::string how_judged() {
    return fmt::format(
        "This case's particle cell is periodic across the width ([cell] width = 0: no side walls), so granlub dem "
        "solves the continuum's 1-D problem: the continuum's twin. The targets are ones a constant μ cannot meet "
        "together (it has no slip, ν, gap or T, and its μ does not rise with speed): μ = |τ|/σ_yy at each wall within {:g} % of the DEM's; μ's rise from the slowest to the fastest speed "
        "at each load and wall within {:g} % of the DEM's rise; the slip at each wall within {:g} U; the solid "
        "fraction ν(y) (not ν/ν_max: the models' ν_max differ) within {:g} in RMS over {:g} ≤ y/H ≤ {:g}, the "
        "continuum's profile interpolated linearly onto the DEM's stations and the DEM's ν the mean over {:g} grain "
        "diameter about each (a continuum's ν is a coarse-grained field; the stations also resolve the walls' "
        "layers [ASSUMPTION, ours]); the gap within {:g} mm; T(y) within a "
        "factor {:g} at every station where the DEM resolves it (a finite T > 0 whose standard error is below {:g} % "
        "of it [ASSUMPTION, ours]). A model meets the case when it meets every target at ≥ {:g} % of the judged "
        "points (all of them when the case has {} points or fewer) and every rise.",
        100 * kTwinMuRelative, 100 * kTwinRiseRelative, kTwinSlipOverU, kTwinNuCoreRms, kTwinCoreLo, kTwinCoreHi,
        kTwinNuGrainWindow, kTwinGap * 1e3, kTwinTemperatureFactor, 100 * kTwinTemperatureMaxRelativeError, 100 * kTwinPointsFraction,
        kTwinAllPointsUpTo);
}

std::string constant_and_rules(const TwinTargets& t) {
    int checked = 0, judged = 0;
    for (const auto& p : t.points)
        if (p.judged) ++judged, checked += p.dt_checked;
    return fmt::format(
        "The constant μ is the most favourable constant for these targets: at each wall the value that meets the μ "
        "target at the most judged points (floor and top together), ties broken by the smallest sum of squared "
        "relative deviations from the DEM's μ; here floor {}, top {}. It has no slip, ν, gap or T, so it is judged on "
        "μ only, and its rise is 0. Only steady DEM points are judged: a transient, dt-unconverged or status-unknown "
        "DEM point is listed and not judged, and the count's denominator says so; {} of the {} judged points carry a "
        "half-time-step check (the others are steady but their Δt error is unmeasured). μ's standard error combines "
        "τ's and σ's as independent. A miss by less than {:g} of the DEM's standard errors beyond the band is a miss "
        "by the target's rule; its verdict says so. Profiles are compared on the one y/H every profile.csv is "
        "written on ({}); the gap: each solver's gap output (the case's gap for a solver that keeps it fixed).",
        num(t.constant_floor, 3), num(t.constant_top, 3), checked, judged, kTwinDemErrorZ, kProfileYDefinition);
}

}  // namespace

void add_twin_part(Report& rep, const Case& c, const Collection& col) {
    if (!twin_applies(c, col)) return;
    const TwinTargets t = twin_targets(c, col);
    rep.heading(kTwinHeading);
    rep.text(how_judged());
    if (t.equal_grains)
        rep.text("The grains are equal ([grains] size_spread = 0): in the particle runs they order into layers (“How "
                 "ordered the particle packings are”), a crystal that no kinetic theory describes. The verdicts below "
                 "are outside the continuum's scope: shown, not a test of its model.");
    rep.table(twin_count_table(t));
    rep.table(twin_by_target_table(t));
    rep.note(constant_and_rules(t));
    if (!t.rises.empty()) {
        rep.heading("μ's rise with speed", 3);
        rep.table(twin_rise_table(t));
    }
    if (const auto cores = twin_cores(c, col, t); !cores.empty()) {
        rep.heading("The bed between the walls", 3);
        if (const std::string answer = twin_core_summary(cores); !answer.empty()) rep.text(answer);
        rep.table(twin_core_table(cores));
        rep.note(twin_core_note());
    }
    for (const auto& p : t.points) {
        if (!p.judged) continue;
        rep.fold(fmt::format("Targets at {}", p.point->id));
        rep.table(twin_point_table(p));
        if (!p.dt_checked) rep.note("The DEM's point is steady; its Δt error was not measured (no half-step run).");
        rep.end_fold();
    }
}

}  // namespace granlub::postproc
