// `granlub dem CASE [--point ID] [--np N]`: the particle simulation of a case in LIGGGHTS with
// granlub's impulse contact models (or LIGGGHTS' Hertz-Mindlin as the soft-sphere reference).
// For each operating point: writes a readable LIGGGHTS deck and the initial grains into the
// point's result folder, runs granlub-liggghts (under mpirun with --np > 1), detects the steady
// state on the wall stresses, coarse-grains nu(y), u(y), T(y) and writes profile.csv and
// summary.json. Details: plugins/liggghts/README.md.
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/solver_info.h"
#include "granlub/run/sweep.h"

namespace granlub::dem {

// What the solver is (granlub/run/solver_info.h).
inline constexpr SolverInfo kSolver{.name = "dem", .description = "particle simulation in LIGGGHTS with granlub's contact models",
                                    .kind = SolverKind::Particles, .engine = true, .seeded = true, .ranks = true,
                                    .whole_ring = true, .bulk_rheology = true};

// The functions every solver module has (granlub/run/solver_info.h).
SectionSpec section();
int run(const Case& c, const RunOptions& o);
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::dem
