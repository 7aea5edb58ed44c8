// `granlub continuum CASE [--point ID]`: the GKL continuum solver on every operating point.
#pragma once
#include "granlub/case.h"
#include "granlub/schema.h"
#include "granlub/sweep.h"

namespace granlub::continuum {

SectionSpec section();                          // the [continuum] case section
int run(const Case& c, const RunOptions& o);    // solves the selected points through run_sweep()

}  // namespace granlub::continuum
