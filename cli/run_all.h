#pragma once
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/run/sweep.h"

namespace granlub::cli {
// `granlub run`: the selected solvers (all when empty), then compare; one overall progress line
// per stage and a closing table. Returns 0 if every stage succeeded. The engines (dem, yade;
// the generated solvers.h) are one stage, their sweeps side by side under one SweepPipeline (pipeline.h), so a
// YADE point starts once the DEM point it reads is done; with --np > 1 (ranks busy-wait) or
// --threads (a core budget) they run one after the other. Each stage takes and frees its own locks
// (run_lock.h); none is held from one stage into the next, so a run cannot wait on itself. With
// --no-wait, a stage whose results another run holds ends the run (ResultsInUse).
int run_all(const Case& c, const RunOptions& o, const std::vector<std::string>& solvers);
}
