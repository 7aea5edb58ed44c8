// A solver's points in one figure, split by result state: the steady ones under `label`, then one
// series per other state ("dem: transient"), drawn hollow and faded and left out of every fit (as
// figures.cpp draws them). Used by the regime figures (regimes.h) and figures.cpp.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "formats/figure_model.h"
#include "results/collect.h"

namespace granlub::postproc {

// The split itself, shared with figures.cpp: the steady points in the first series, then one per
// other state; add(run, point, series) appends the point to its series (or not).
template <class Add>
std::vector<Series> split_by_state(const Collection& col, const std::string& solver,
                                   const std::vector<const OperatingPoint*>& points, const std::string& label,
                                   Add add) {
    std::vector<Series> out(1);
    out[0].label = label;
    for (const OperatingPoint* p : points) {
        const Run& r = col.run(solver, p->id);
        if (!r.usable()) continue;
        std::size_t k = 0;
        if (!r.steady()) {
            const std::string l = fmt::format("{}: {}", label, r.state_name());
            k = 1;
            while (k < out.size() && out[k].label != l) ++k;
            if (k == out.size()) out.emplace_back().label = l, out.back().unsteady = true;
        }
        add(r, *p, out[k]);
    }
    return out;
}

// xy(run, point) gives the point's (x, y), or nothing to leave it out.
template <class XY>
std::vector<Series> series_by_state(const Collection& col, const std::string& solver,
                                    const std::vector<const OperatingPoint*>& points, const std::string& label,
                                    int style, XY xy) {
    std::vector<Series> out = split_by_state(col, solver, points, label, [&](const Run& r, const OperatingPoint& p, Series& s) {
        if (const std::optional<std::pair<double, double>> v = xy(r, p)) {
            s.x.push_back(v->first);
            s.y.push_back(v->second);
        }
    });
    std::vector<Series> kept;
    for (auto& s : out)
        if (!s.x.empty()) s.style = style, s.mark = Mark::Points, kept.push_back(std::move(s));
    return kept;
}

}  // namespace granlub::postproc
