// What the report says, in order: what was found, the figures, the metric tables, provenance of
// every run and the case itself.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "formats/report.h"
#include "results/collect.h"
#include "statistics/metrics.h"
#include "tables/run_tables.h"

namespace granlub::postproc {

// The figures of one figure_registry() row under its heading, for one point ("" for the case).
struct FigureGroup {
    std::string heading, point;
    std::vector<FigureRef> refs;
};

struct ReportFigures {
    std::vector<FigureGroup> groups;    // the registry's rows drawn, in its order (figures/registry.h)
    std::vector<FigureRef> ring_slice;  // ring_slice.h
    std::vector<FigureRef> regime;      // regimes.h
    bool pdf = true;                    // each figure also as a PDF (formats/pdf.h)
    std::vector<FigureRef> of(const std::string& heading, const std::string& point = "") const;
};

struct RingSlicePart;
struct RegimePart;

Report build_report(const Case& c, const Collection& col, const std::vector<MetricRow>& metrics,
                    const ReportFigures& figs, const std::vector<std::filesystem::path>& paraview_files,
                    const RingSlicePart* ring = nullptr, const RegimePart* regime = nullptr);

}  // namespace granlub::postproc
