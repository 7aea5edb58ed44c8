// `granlub dem CASE [--point ID] [--np N]`: the particle simulation of a case in LIGGGHTS with
// granlub's impulse contact models (or LIGGGHTS' Hertz-Mindlin as the soft-sphere reference).
// For each operating point: writes a readable LIGGGHTS deck and the initial grains into the
// point's result folder, runs granlub-liggghts (under mpirun with --np > 1), detects the steady
// state on the wall stresses, coarse-grains nu(y), u(y), T(y) and writes profile.csv and
// summary.json. Details: plugins/liggghts/README.md.
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/sweep.h"

namespace granlub::dem {

// The [dem] case section, one line per key.
SectionSpec section();

// Runs the selected points through run_sweep(); returns the process exit code.
int run(const Case& c, const RunOptions& o);
// What run() would reject for the selected points (quick and --full run lengths), without
// running: CaseError for bad input, SolverError for a case this solver cannot run.
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::dem
