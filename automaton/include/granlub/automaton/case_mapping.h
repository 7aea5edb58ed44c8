// From a case and an operating point to the lattice parameters (automaton/README.md, "Mapping"):
// rows = round(gap/d), columns = round(length/d), fill = [automaton] fill or
// solid_fraction / max_solid_fraction [ASSUMPTION], e_p from the grains, e_w and R from the point's
// walls, the rule switches and run lengths from [automaton].
#pragma once
#include <string>

#include "granlub/automaton/params.h"
#include "granlub/case/case.h"
#include "granlub/run/sweep.h"

namespace granlub::automaton {

struct Mapping {
    Params params;
    std::string fill_source;  // where the fill came from, for the summary
};

// Throws CaseError / SolverError naming the key and what is allowed.
Mapping resolve_settings(const Case& c, const OperatingPoint& p, const RunOptions& o);

}  // namespace granlub::automaton
