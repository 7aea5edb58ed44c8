// `granlub automaton CASE [--point ID] [--seed N] [--vtk] [--full]`: the Jasti-Higgs lattice
// cellular automaton on every operating point of a case (docs/automaton-model.md; automaton/README.md).
#pragma once
#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/solver_info.h"
#include "granlub/run/sweep.h"

namespace granlub::automaton {

// What the solver is (granlub/run/solver_info.h).
inline constexpr SolverInfo kSolver{.name = "automaton", .description = "lattice cellular automaton (Jasti & Higgs 2006)",
                                    .kind = SolverKind::Lattice, .seeded = true};

// The functions every solver module has (granlub/run/solver_info.h).
SectionSpec section();
int run(const Case& c, const RunOptions& o);
void check(const Case& c, const RunOptions& o);

}  // namespace granlub::automaton
