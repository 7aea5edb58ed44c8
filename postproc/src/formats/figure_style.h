// The look of a Series' style index (figure_model.h), the same in the report's SVG and the gnuplot
// export: Okabe & Ito (2008) colour-blind-safe palette, with dash patterns and markers so figures
// also read in greyscale.
#pragma once

namespace granlub::postproc {

const char* style_colour(int style);
const char* style_dash(int style);      // SVG stroke-dasharray ("" = solid)
int style_gnuplot_dashtype(int style);  // gnuplot dt
int style_gnuplot_pointtype(int style, bool open);

}  // namespace granlub::postproc
