// The cross-section maps (the points' section.csv, core's granlub/particles/cross_section.h): the
// particle runs' time averages and the continuum's steady solution on the trough's cross-section
// ([continuum] geometry = "cross_section", written in the particle runs' cells), solid fraction and
// u/U over y x z as heat maps, the way Sawyer & Tichy drew their Figs. 7-8. Rendered straight to SVG; there is no gnuplot script for them, the
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

// The colour bar's range: from min(0, lowest) to the highest value.
struct ColourScale {
    double lo = 0, hi = 1;
};
// The one range of every map of a quantity at a point, so that the solvers' maps read alike.
ColourScale colour_scale(const std::vector<const std::vector<double>*>& maps);

// One heat map of `values` (nu or u/U) on `scale` (null: the map's own range) with a colour bar; `what`
// (below the axis) says what the map is; a non-empty `stamp` (cross_section_stamp) is written across
// a faded map.
std::string render_cross_section_svg(const CrossSectionMap& m, const std::vector<double>& values,
                                     const std::string& title, const std::string& bar_label, const std::string& stamp,
                                     const ColourScale* scale = nullptr, const std::string& what = "");
// What a run's map is: the continuum's steady solution (run.geometry = "cross_section") or a particle
// run's time average over its steady window.
std::string cross_section_what(const Run& r);
// The stamp of a run that is not steady, naming its state ("TRANSIENT — not a result",
// "DT-UNCONVERGED — Δt changes it", "STATUS UNKNOWN — not checked"); "" for a steady run.
std::string cross_section_stamp(const Run& r);

// The maps of every usable run at a point that has a section.csv (nu and u/U each, each quantity on
// one colour scale over the point's maps), written into `plots` (<name>.svg and <name>.csv).
std::vector<FigureRef> cross_section_figures(const Collection& col, std::size_t point_index,
                                             const std::filesystem::path& plots);

}  // namespace granlub::postproc
