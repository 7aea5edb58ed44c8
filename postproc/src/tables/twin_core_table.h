// The bed between the twin's walls: each run's core (the middle third of the gap) read as `granlub bulk-rheology`
// reads cases/bulk_shear's (core_rheology, granlub/particles/bulk_rheology.h: one reduction for every solver), so
// that the continuum's bulk closures are seen apart from its walls: I, μ, ν, T/(dγ̇)² and μ √(T/(dγ̇)²), kinetic
// theory's f2/f1 at the core's ν.
#pragma once
#include "formats/report.h"
#include "results/collect.h"
#include "tables/twin_targets.h"

namespace granlub::postproc {

// One row per judged point and twin solver (the DEM, then the continuum); a run whose core cannot be read (it does
// not shear, too few stations) says why. Empty when no point is judged.
Table twin_core_table(const Case& c, const Collection& col, const TwinTargets& t);

// The table's note: what the core is and what its last column tells.
std::string twin_core_note();

}  // namespace granlub::postproc
