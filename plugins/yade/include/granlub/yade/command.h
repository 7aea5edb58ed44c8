// `granlub yade CASE [--point ID]`: the cross-check of `granlub dem` in YADE 2023.02a.
// Each point: the shared initial configuration (granlub/particles/particles.h), a JSON parameter file,
// the project's driver script granlub_yade.py run by `yade -n -j1 -x` (timeout, exit code
// checked, log kept), then the shared coarse-graining (granlub/particles/coarse_grain.h) into
// results/yade/<point>/{profile.csv, summary.json}. See plugins/yade/README.md.
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/solver_info.h"
#include "granlub/run/sweep.h"

namespace granlub::yade {

// What the solver is (granlub/run/solver_info.h).
inline constexpr SolverInfo kSolver{.name = "yade", .description = "particle simulation in YADE (cross-check)",
                                    .kind = SolverKind::Particles, .engine = true, .seeded = true,
                                    .warm_from = "dem"};

// The functions every solver module has (granlub/run/solver_info.h).
SectionSpec section();
int run(const Case& c, const RunOptions& o);
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::yade
