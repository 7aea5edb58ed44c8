// The report's first screen: the answer to the case's question, generated from the results. For
// each quantity (ν̄, gap, τ on each wall, the slips, the regime) and point, which solvers agree
// within their combined errors; the largest disagreement with its size and the cause the report
// knows; and which numbers are not answers, and why.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

// The particle engines' regime verdicts at one point as one verdict: the same verdict when they
// agree; "at the transition" with each engine's coordination number when they straddle the
// enduring-contact threshold (core granlub/statistics/flow_regime.h, Z = 4) or disagree.
struct RegimeReading {
    // "contact lubrication (dem, yade)", "at the transition (engines disagree): dem Z = 4.17 (contact), …"
    std::string text;
    bool uncertain = false;
};
std::optional<RegimeReading> regime_reading(const Collection& col, const std::string& point);

struct CaseSummary {
    Table table;                         // quantity × point: who agrees, who differs by how much
    std::vector<std::string> sentences;  // the largest disagreement, the numbers that are not answers
    bool all_agree = false;              // one line says so
};
// equal_grains: the case's [grains] size_spread is 0, so the particle runs order into layers and the
// continuum's difference from them is named as outside its scope, not as a model difference.
CaseSummary case_summary(const Collection& col, bool equal_grains = false);

}  // namespace granlub::postproc
