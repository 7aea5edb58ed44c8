#include "statistics/speed_load_grid.h"

#include <algorithm>

#include <fmt/format.h>

#include "formats/format.h"

namespace granlub::postproc {

SpeedLoadGrid speed_load_grid(const std::vector<const OperatingPoint*>& points) {
    SpeedLoadGrid g;
    if (points.empty()) {
        g.why_not = "the case has no operating points";
        return g;
    }
    if (points.size() == 1) {
        g.why_not = fmt::format("the case has one operating point ({}): a map over speed and load needs at least two "
                                "speeds and two loads",
                                points.front()->id);
        return g;
    }
    for (const OperatingPoint* p : points) {
        if (p->control != Control::Load) {
            g.why_not = fmt::format("point {} is under fill control ([operating] control = \"fill\"): the normal "
                                    "stress is a result there, not a load the map can be drawn over",
                                    p->id);
            return g;
        }
        g.speeds.push_back(p->speed);
        g.loads.push_back(p->normal_stress);
    }
    for (auto* v : {&g.speeds, &g.loads}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    const auto groups = speed_groups(points);  // same everything but the speed
    if (groups.size() != g.loads.size()) {
        g.why_not = "the points differ in more than speed and load (roughness, walls or fill): the map would mix them";
        return g;
    }
    if (g.loads.size() < 2)
        g.why_not = fmt::format("one load (P = {} Pa): the sweep is over speed only; the map needs at least two "
                                "normal stresses ([operating] normal_stress = [...])",
                                num(g.loads.front()));
    else if (g.speeds.size() < 2)
        g.why_not = fmt::format("one speed (U = {} m/s): the sweep is over load only; the map needs at least two "
                                "speeds ([operating] speed = [...])",
                                num(g.speeds.front()));
    g.per_load = groups;
    std::sort(g.per_load.begin(), g.per_load.end(), [](const PointGroup& a, const PointGroup& b) {
        return a.points.front()->normal_stress < b.points.front()->normal_stress;
    });
    for (auto& grp : g.per_load) grp.label = fmt::format("P = {} Pa", num(grp.points.front()->normal_stress));
    return g;
}

}  // namespace granlub::postproc
