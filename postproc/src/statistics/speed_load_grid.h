// Which operating points form a (speed, load) grid: the question of Sawyer & Tichy's two
// regimes (contact and collision lubrication) is asked over U and P, so the regime figures
// (regimes.h) are drawn only for a case whose points sweep both. Otherwise the report says
// why not, in one sentence.
#pragma once
#include <string>
#include <vector>

#include "statistics/metrics.h"

namespace granlub::postproc {

struct SpeedLoadGrid {
    std::vector<double> speeds, loads;  // distinct values, ascending
    std::vector<PointGroup> per_load;   // the points at each load (speed_groups), ascending load
    std::string why_not;                // empty when the grid can be drawn
    bool drawn() const { return why_not.empty(); }
};

// At least two speeds and two normal stresses among load-controlled points ([operating] control =
// "load", speed and normal_stress lists) that differ in nothing else. The grid need not be full:
// a point a solver could not run is a hole, drawn as one.
SpeedLoadGrid speed_load_grid(const std::vector<const OperatingPoint*>& points);

// The style (colour, dash, marker) of the g-th load in a figure of one solver's points per load:
// styles 5 (sky blue) and 6 (black) stay for the figures' reference lines. Open markers are not
// used for loads: they mean a result that is not steady.
inline int load_style(std::size_t g) { return static_cast<int>(g % 5); }

}  // namespace granlub::postproc
