// The grains beside each wall: how far they lag it, how much of that their spin carries back, and the slip left
// at their contact points. The one reader of the particle summaries' run.wall_layer (core
// granlub/particles/wall_layer.h, both engines through the shared pipeline, from each run's final state).
#pragma once
#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

// One row per usable particle run and wall with the record; empty when no run has it. A wall the run did not
// measure shows why.
Table wall_layer_table(const Collection& col);

}  // namespace granlub::postproc
