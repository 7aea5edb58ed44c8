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
// `granlub continuum CASE --map [--map-grid SPEEDS,LOADS]`: the case's (U, P) map (map.h) written to
// <results>/continuum/map.csv under its lock (run_lock.h: continuum/map.csv), and one line with its cost. Returns 0,
// or 1 when no point of the grid could be solved (the file is written either way).
int run_map(const Case& c, const RunOptions& o, int speeds, int loads);

}  // namespace granlub::continuum
