// Renders a Figure as a standalone SVG document (valid XML, no external resources), sized for a
// paper figure: 540 x 380 px, 13 px text.
#pragma once
#include <string>
#include <vector>

#include "formats/figure_model.h"

namespace granlub::postproc {

std::string render_svg(const Figure& f);

// Axis limits and legend corner as render_svg chooses them (0 top right, 1 top left, 2 bottom
// right, 3 bottom left: the first corner free of data points; kLegendBelow when none is, the
// legend then below the frame); the gnuplot export takes its axis limits and key corner from here.
inline constexpr int kLegendBelow = 4;
struct Layout {
    double xlo, xhi, ylo, yhi;
    int legend_corner;
};
Layout layout(const Figure& f);

// Tick positions and labels for an axis from lo to hi ("nice" 1-2-5 steps, or decades on log
// axes). Exposed for the tests.
struct Tick {
    double value;
    std::string label;  // empty: minor tick
};
std::vector<Tick> linear_ticks(double lo, double hi);
std::vector<Tick> log_ticks(double lo, double hi);

}  // namespace granlub::postproc
