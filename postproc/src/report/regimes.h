// The report's part on Sawyer & Tichy's two regimes, for a case that sweeps speed and load
// (speed_load_grid.h): mu and nu-bar against I with the mu(I) law (mu_of_i.h), the regime map and
// the lift-off (regime_map.h), tau against U per load with its exponent (shear_power_law.h).
// Without a grid the part is one sentence saying why no map is drawn.
#pragma once
#include <string>
#include <vector>

#include "formats/figure_model.h"
#include "formats/report.h"
#include "results/collect.h"
#include "statistics/speed_load_grid.h"

namespace granlub::postproc {

struct RegimePart {
    SpeedLoadGrid grid;
    std::vector<Figure> figures;  // empty without a grid
    Table verdicts, exponents;
    std::vector<std::string> notes;  // what a reader must know: holes in the grid, solvers without a verdict
};

RegimePart regime_part(const Case& c, const Collection& col);

// The part's blocks (heading included) into the report, figures from `refs` (emitted from
// part.figures, same order).
void add_regime_part(Report& rep, const RegimePart& part, const std::vector<FigureRef>& refs);

}  // namespace granlub::postproc
