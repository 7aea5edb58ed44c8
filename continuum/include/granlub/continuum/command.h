// `granlub continuum CASE [--point ID]`: the GKL continuum solver on every operating point.
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/sweep.h"

namespace granlub::continuum {

SectionSpec section();                          // the [continuum] case section
int run(const Case& c, const RunOptions& o);    // solves the selected points through run_sweep()
// What run() would reject for the selected points (quick and --full run lengths), without
// running: CaseError for bad input, SolverError for a case this solver cannot run.
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::continuum
