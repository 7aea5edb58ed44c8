// The report's part "The continuum against its particle twin" (tables/twin_targets.h): drawn only for a
// case whose particle cell is periodic across the width and that has continuum and DEM results.
#pragma once
#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

inline constexpr const char* kTwinHeading = "The continuum against its particle twin";

// Adds the part (heading, how it judges, the count per model, μ's rises, a folded table per point);
// nothing when twin_applies is false.
void add_twin_part(Report& rep, const Case& c, const Collection& col);

}  // namespace granlub::postproc
