// `granlub yade CASE [--point ID]`: the cross-check of `granlub dem` in YADE 2023.02a.
// Each point: the shared initial configuration (granlub/particles/particles.h), a JSON parameter file,
// the project's driver script granlub_yade.py run by `yade -n -j1 -x` (timeout, exit code
// checked, log kept), then the shared coarse-graining (granlub/particles/coarse_grain.h) into
// results/yade/<point>/{profile.csv, summary.json}. See plugins/yade/README.md.
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/sweep.h"

namespace granlub::yade {

SectionSpec section();                          // the [yade] case section
int run(const Case& c, const RunOptions& o);    // all selected points, via run_sweep()
// What run() would reject for the selected points (quick and --full run lengths), without
// running: CaseError for bad input, SolverError for a case this solver cannot run.
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::yade
