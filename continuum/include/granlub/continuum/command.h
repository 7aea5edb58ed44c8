// `granlub continuum CASE [--point ID]`: the GKL continuum solver on every operating point.
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/solver_info.h"
#include "granlub/run/sweep.h"

namespace granlub::continuum {

// The functions every solver module has (granlub/run/solver_info.h).
SectionSpec section();
int run(const Case& c, const RunOptions& o);
void check(const Case& c, const RunOptions& o);
// `granlub continuum CASE --map [--map-grid SPEEDS,LOADS]`: the case's (U, P) map (map.h) written to
// <results>/continuum/map.csv under the continuum's results lock, and one line with its cost. Returns 0,
// or 1 when no point of the grid could be solved (the file is written either way).
int run_map(const Case& c, const RunOptions& o, int speeds, int loads);

// What the solver is (granlub/run/solver_info.h).
inline constexpr SolverInfo kSolver{.name = "continuum", .description = "granular kinetic lubrication (GKL) continuum solver",
                                    .kind = SolverKind::Continuum, .map = &run_map};

}  // namespace granlub::continuum
