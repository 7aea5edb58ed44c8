#include "figures/registry.h"

#include <algorithm>

#include "figures/figures.h"
#include "figures/cross_section_map.h"

namespace granlub::postproc {

const std::vector<FigureRow>& figure_registry() {
    static const std::vector<FigureRow> rows = {
        {kProfilesHeading, true, [](const FigureInput& in) { return profile_figures(in.col, in.point); }},
        {kCrossSectionHeading, true, nullptr,
         [](const FigureInput& in) { return cross_section_figures(in.col, in.point, in.plots); }},
        {kStressHeading, false, [](const FigureInput& in) { return stress_figures(in.col); }},
        {kSlipHeading, false, [](const FigureInput& in) { return slip_figures(in.col); }},
        {kSolidFractionHeading, false,
         [](const FigureInput& in) { return std::vector{solid_fraction_figure(in.col, in.c.cell.max_solid_fraction)}; }},
    };
    return rows;
}

std::vector<std::string> figure_headings() {
    std::vector<std::string> h;
    for (const auto& r : figure_registry())
        if (std::find(h.begin(), h.end(), r.heading) == h.end()) h.emplace_back(r.heading);
    return h;
}

}  // namespace granlub::postproc
