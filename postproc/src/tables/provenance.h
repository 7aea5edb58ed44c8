// Who computed what: one row per run (version, time, seed, hashes), then each solver's settings
// as a key-value table (folded), a value that differs between points given per point.
#pragma once
#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

void provenance_part(Report& rep, const Collection& col);

}  // namespace granlub::postproc
