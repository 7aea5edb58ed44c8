// A solver's points in one figure, split by result state: the steady ones under `label`, then one
// series per other state ("dem: transient"), drawn hollow and faded and left out of every fit (as
// figures.cpp draws them). Used by the regime figures (regime_section.h).
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "collect.h"
#include "figure_model.h"

namespace granlub::postproc {

// xy(run, point) gives the point's (x, y), or nothing to leave it out.
template <class XY>
std::vector<Series> series_by_state(const Collection& col, const std::string& solver,
                                    const std::vector<const OperatingPoint*>& points, const std::string& label,
                                    int style, XY xy) {
    std::vector<Series> out(1);
    out[0].label = label;
    for (const OperatingPoint* p : points) {
        const Run& r = col.run(solver, p->id);
        if (!r.usable()) continue;
        const std::optional<std::pair<double, double>> v = xy(r, *p);
        if (!v) continue;
        std::size_t k = 0;
        if (!r.steady()) {
            const std::string l = fmt::format("{}: {}", label, r.state_name());
            k = 1;
            while (k < out.size() && out[k].label != l) ++k;
            if (k == out.size()) out.emplace_back().label = l, out.back().unsteady = true;
        }
        out[k].x.push_back(v->first);
        out[k].y.push_back(v->second);
    }
    std::vector<Series> kept;
    for (auto& s : out)
        if (!s.x.empty()) s.style = style, s.mark = Mark::Points, kept.push_back(std::move(s));
    return kept;
}

// The caption's sentence for the hollow, faded series, when the figure has any.
inline void say_unsteady(Figure& f) {
    for (const Series& s : f.series)
        if (s.unsteady && !s.x.empty()) {
            f.caption += " Hollow faded markers are results that are NOT steady (the legend says which); shown for "
                         "information only, left out of every fit.";
            return;
        }
}

}  // namespace granlub::postproc
