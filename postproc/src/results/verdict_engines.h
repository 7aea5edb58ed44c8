// The particle engines whose flow-regime verdict counts at a point: the steady runs (a result: not a
// transient, not dt-unconverged) with a contact record (run.flow_regime), each with its Δt check's
// record (core point_verdict.h). The summary's regime row and the regime table's point rows both
// combine these and nothing else.
#pragma once
#include <string>
#include <vector>

#include "granlub/statistics/point_verdict.h"
#include "results/collect.h"

namespace granlub::postproc {

std::vector<EngineRegime> verdict_engines(const Collection& col, const std::string& point);

}  // namespace granlub::postproc
