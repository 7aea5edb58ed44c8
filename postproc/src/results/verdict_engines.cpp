#include "results/verdict_engines.h"

namespace granlub::postproc {

std::vector<EngineRegime> verdict_engines(const Collection& col, const std::string& point) {
    std::vector<EngineRegime> engines;
    for (const Run* r : col.usable(point)) {
        const auto& run = r->summary->run;
        if (!r->steady() || !run.is_object() || !run.contains("flow_regime") || !run["flow_regime"].contains("regime"))
            continue;
        engines.push_back(engine_regime(r->solver, run));
    }
    return engines;
}

}  // namespace granlub::postproc
