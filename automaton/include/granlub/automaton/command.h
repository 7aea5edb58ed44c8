// `granlub automaton CASE [--point ID] [--seed N] [--vtk] [--full]`: the Jasti-Higgs lattice
// cellular automaton on every operating point of a case (docs/automaton-model.md; automaton/README.md).
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/sweep.h"

namespace granlub::automaton {

// The [automaton] case section, one line per key.
SectionSpec section();

// Runs the selected points through run_sweep(); returns the exit code.
int run(const Case& c, const RunOptions& o);
// What run() would reject for the selected points (quick and --full run lengths), without
// running: CaseError for bad input, SolverError for a case this solver cannot run.
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::automaton
