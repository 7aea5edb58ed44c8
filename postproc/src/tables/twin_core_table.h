// The bed between the twin's walls: each run's core (the middle third of the gap) read as `granlub bulk-rheology`
// reads cases/bulk_shear's (core_rheology, granlub/particles/bulk_rheology.h: one reduction for every solver), so
// that the continuum's bulk closures are seen apart from its walls: I, μ, ν, T/(dγ̇)² and μ √(T/(dγ̇)²), kinetic
// theory's f2/f1 at the core's ν.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "granlub/particles/bulk_rheology.h"

#include "formats/report.h"
#include "results/collect.h"
#include "tables/twin_targets.h"

namespace granlub::postproc {

// One run's core: its rheology, or why it could not be read (it does not shear, too few stations).
struct TwinCore {
    const Run* run = nullptr;
    std::optional<CoreRheology> core;
    Measured f2_over_f1;  // μ √(T/(dγ̇)²), its error from μ's and half T/(dγ̇)²'s in quadrature
    bool exact = false;   // a profile without standard errors (a continuum's)
    std::string why;      // when core is empty
};

// The DEM's and the continuum's core at each judged point, in that order; runs without a usable result left out.
std::vector<TwinCore> twin_cores(const Case& c, const Collection& col, const TwinTargets& t);

// One row per core; empty when there is none.
Table twin_core_table(const std::vector<TwinCore>& cores);

// The answer first, from the points where both cores were read: how far the continuum's I and μ lie from the DEM's
// (the largest relative difference), its μ √(T/(dγ̇)²) against theirs and in the DEM's standard errors, and a
// verdict on T where the bed agrees (I and μ within 10 %) and f2/f1 does not (beyond 10 % and 2 of the DEM's
// standard errors at every point); "" when no point has both.
std::string twin_core_summary(const std::vector<TwinCore>& cores);

// The table's note: what the core is and what its last column tells.
std::string twin_core_note();

}  // namespace granlub::postproc
