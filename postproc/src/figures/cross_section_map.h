// The cross-section maps of the particle solvers (the points' section.csv, core's
// granlub/particles/cross_section.h): solid fraction and u/U over y x z as heat maps, the way Sawyer &
// Tichy drew their Figs. 7-8. Rendered straight to SVG; there is no gnuplot script for them, the
// CSV beside each map holds the numbers.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

struct CrossSectionMap {
    std::size_t ny = 0, nz = 0;             // cells across the gap and the width
    std::vector<double> y, z, nu, u;        // per cell, row-major over (y, z): y/H, z/W, nu, u/U
};

// The run's section.csv, or nothing when the run has none (older results, solvers without one).
// A file that is there but malformed throws Error naming it.
std::optional<CrossSectionMap> read_cross_section(const Run& r);

// One heat map of `values` (nu or u/U) with a colour bar; a non-empty `stamp` (cross_section_stamp) is
// written across a faded map.
std::string render_cross_section_svg(const CrossSectionMap& m, const std::vector<double>& values,
                                     const std::string& title, const std::string& bar_label, const std::string& stamp);
// The stamp of a run that is not steady, naming its state ("TRANSIENT — not a result",
// "DT-UNCONVERGED — Δt changes it", "STATUS UNKNOWN — not checked"); "" for a steady run.
std::string cross_section_stamp(const Run& r);

// The maps of every usable particle run at a point that has a section.csv (nu and u/U each),
// written into `plots` (<name>.svg and <name>.csv).
std::vector<FigureRef> cross_section_figures(const Collection& col, std::size_t point_index,
                                             const std::filesystem::path& plots);

}  // namespace granlub::postproc
