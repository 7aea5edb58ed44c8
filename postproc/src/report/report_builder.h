// What the report says, in order: what was found, the figures, the metric tables, provenance of
// every run and the case itself.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "formats/report.h"
#include "results/collect.h"
#include "statistics/metrics.h"

namespace granlub::postproc {

struct ReportFigures {
    std::map<std::string, std::vector<FigureRef>> profiles;  // by point id
    std::vector<FigureRef> stress, slip, solid_fraction;
    std::vector<FigureRef> ring_slice;  // ring_slice.h
    std::vector<FigureRef> regime;      // regime_section.h
};

struct RingSliceSection;
struct RegimeSection;

Report build_report(const Case& c, const Collection& col, const std::vector<MetricRow>& metrics,
                    const ReportFigures& figs, const std::vector<std::filesystem::path>& paraview_files,
                    const RingSliceSection* ring = nullptr, const RegimeSection* regime = nullptr);

// Key numbers per solver and point (nu_bar/nu_max, wall stresses, slip/U, wall clock; under load
// control also the gap and P_top / target); used by the report and by summary_table().
Table key_numbers(const Case& c, const Collection& col);
// Per solver: the body forces it models, what its wall stresses are, how long it ran (scope.h).
Table scope_table(const Case& c, const Collection& col);
// Result state per solver (rows, missing solvers included) and point (columns).
Table status_table(const Collection& col);

std::string state_name(ResultState s);

}  // namespace granlub::postproc
