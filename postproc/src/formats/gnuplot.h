// Plot sources for the user: each Figure as <name>.dat (one gnuplot `index` block per series)
// plus <name>.gp, a plain gnuplot script that plots that data with the report's axis limits and
// labels (to <name>.gnuplot.svg by default). The report never runs gnuplot, and the script does
// not promise to reproduce the report's figure: the report's one renderer is svg_plot.h.
#pragma once
#include <filesystem>

#include "formats/figure_model.h"

namespace granlub::postproc {

std::string gnuplot_data(const Figure& f);
std::string gnuplot_script(const Figure& f);
// Writes both files (atomically) into dir.
void write_gnuplot(const Figure& f, const std::filesystem::path& dir);

}  // namespace granlub::postproc
