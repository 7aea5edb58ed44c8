// A line-and-point plot described once (the report's figures are built in figures.h). One
// renderer draws it in the report: svg_plot.h. The gnuplot export (gnuplot.h) hands the same
// data, limits and labels to a user who wants their own figure; it is a starting point, not a
// second drawing of the report's figure. Colours and dashes per style: figure_style.h.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace granlub::postproc {

enum class Mark { Line, Points };

struct Series {
    std::string label;            // legend entry; empty = not in the legend
    std::vector<double> x, y;
    std::vector<double> err;      // +- error per point (empty: none): a band for lines, bars for points
    int style = 0;                // colour, dash and marker index (one per solver, see style_of)
    Mark mark = Mark::Line;
    bool dashed = false;          // lines: dashed instead of the style's own pattern (fits)
    bool open = false;            // points: open marker (e.g. the top wall)
    bool unsteady = false;        // not a steady result (transient, ...): hollow, faded, dotted; label says so
};

struct Axis {
    std::string label;            // with unit, e.g. "U (m/s)"
    bool log = false;
    std::optional<double> lo, hi;  // fixed limits; otherwise from the data
    std::vector<std::pair<double, std::string>> categories;  // categorical tick labels
};

struct Figure {
    std::string name;     // file stem and SVG id prefix: [a-z0-9_-]
    std::string title;
    std::string caption;  // one sentence under the figure in the report
    Axis x, y;
    std::vector<Series> series;
};

}  // namespace granlub::postproc
