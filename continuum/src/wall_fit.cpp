// The wall constants' model of continuum-fit (wall_fit.h).
#include "wall_fit.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "granlub/case/wall_bumps.h"
#include "granlub/error.h"

namespace granlub::continuum::detail {

bool is_wall_key(const std::string& key) { return key == "slip_dissipation" || key == "r5"; }

void check_wall_columns(const std::vector<std::string>& missing_columns, const std::vector<std::string>& wall_keys,
                        const std::string& source) {
    if (!missing_columns.empty())
        throw CaseError(fmt::format("{}: no column(s) {}: --free {} fits the walls' slips and near-wall T, which a "
                                    "table written before `granlub bulk-rheology` recorded them lacks; allowed: a "
                                    "table rewritten by this granlub's bulk-rheology, or no wall key in --free",
                                    source, fmt::join(missing_columns, ", "), fmt::join(wall_keys, ", ")));
}

std::vector<const OperatingPoint*> wall_points(const Settings& s, const Case& bulk, const std::vector<BulkRow>& answers,
                                               const std::vector<std::string>& wall_keys, const std::string& source) {
    const std::string keys = fmt::format("{}", fmt::join(wall_keys, ", "));
    if (s.cross_section)
        throw CaseError(fmt::format("continuum-fit --free {}: the case's [continuum] geometry = \"cross_section\"; the "
                                    "wall fit solves the bulk case in 1-D (allowed: geometry = \"gap\")",
                                    keys));
    std::vector<const OperatingPoint*> points;
    for (const BulkRow& r : answers) {
        const auto it = std::find_if(bulk.points.begin(), bulk.points.end(),
                                     [&](const OperatingPoint& p) { return p.id == r.point; });
        if (it == bulk.points.end())
            throw CaseError(fmt::format("{}:{}: point {}: the bulk case {} has no such point (allowed: the table of "
                                        "that case, --bulk-case naming the case the table was written from)",
                                        source, r.line, r.point, bulk.file.string()));
        const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
        if (!same(r.load, it->normal_stress) || (std::isfinite(r.speed) && !same(r.speed, it->speed)))
            throw CaseError(fmt::format("{}:{}: point {} at U = {} m/s, P = {} Pa; the bulk case {} holds it at U = {} "
                                        "m/s, P = {} Pa (allowed: --bulk-case naming the case the table was written "
                                        "from)",
                                        source, r.line, r.point, r.speed, r.load, bulk.file.string(), it->speed,
                                        it->normal_stress));
        if (it->control != Control::Load)
            throw CaseError(fmt::format("{}:{}: point {} of the bulk case {} is fill-controlled; the wall fit solves "
                                        "it under its load (allowed: [operating] control = \"load\")",
                                        source, r.line, r.point, bulk.file.string()));
        const std::pair<const char*, const Measured*> cells[] = {{"slip_bottom", &r.slip_bottom},
                                                                 {"slip_top", &r.slip_top},
                                                                 {"T_wall_bottom", &r.T_wall_bottom},
                                                                 {"T_wall_top", &r.T_wall_top}};
        for (const auto& [name, m] : cells)
            if (!std::isfinite(m->value) || !(m->error > 0) || !std::isfinite(m->error))
                throw CaseError(fmt::format("{}:{}: point {}: {} = {} +- {} cannot weight a wall fit (the residuals "
                                            "are in units of the row's own error; allowed: a finite value with an "
                                            "error > 0)",
                                            source, r.line, r.point, name, m->value, m->error));
        points.push_back(&*it);
    }
    // f_t enters the energy condition as R7 b7 (wall_condition.h): with R7 = 0 at both walls no residual feels it
    const bool ft = std::find(wall_keys.begin(), wall_keys.end(), "slip_dissipation") != wall_keys.end();
    if (!points.empty() && ft) {
        const Problem q = problem_for(bulk, s, *points.front());
        if (q.bottom.params.r7 == 0 && q.top.params.r7 == 0)
            throw CaseError(fmt::format("continuum-fit --free {}: R7 = 0 at both walls of the bulk case ([continuum] "
                                        "r7, r7_bottom, r7_top): the slip dissipation f_t acts through R7 b7 and "
                                        "would change nothing (allowed: R7 > 0 at a wall)",
                                        keys));
    }
    // one R5 for both walls: a case that sets them apart has no one value to start from or to write back
    const Section& sec = bulk.section("continuum");
    if (std::find(wall_keys.begin(), wall_keys.end(), "r5") != wall_keys.end())
        for (const char* k : {"r5_bottom", "r5_top"})
            if (sec.has(k))
                throw CaseError(fmt::format("continuum-fit --free r5: the case sets {} (the fit's R5 is one value at "
                                            "both walls, written back as r5); allowed: remove r5_bottom, r5_top",
                                            k));
    return points;
}

double case_r5(const Case& bulk, const Settings& s, const OperatingPoint& p) {
    const Problem q = problem_for(bulk, s, p);
    if (q.bottom.params.r5 != q.top.params.r5)
        throw CaseError(fmt::format("continuum-fit --free r5: the bulk case's walls have R5 = {} and {} at point {} "
                                    "(the fit's R5 is one value at both walls); allowed: walls of one roughness",
                                    q.bottom.params.r5, q.top.params.r5, p.id));
    return q.bottom.params.r5;
}

WallLayers wall_model(const Case& bulk, const Settings& s, const OperatingPoint& p) {
    const PointResult r = solve_point(bulk, p, s);
    const auto& o = r.summary.outputs;
    const double gap = o.count("gap") ? o.at("gap").value : bulk.cell.gap;  // the profile's H
    const NearWallTemperature nw = near_wall_temperature(r.profile, gap, bulk.grains.diameter,
                                                         bump_protrusion(bulk, p.bottom), bump_protrusion(bulk, p.top),
                                                         BandMean::Interpolated);
    return {{o.at("slip_bottom").value / p.speed, 0}, {o.at("slip_top").value / p.speed, 0}, nw.bottom, nw.top};
}

void wall_residuals(const WallLayers& m, const BulkRow& r, double* f) {
    f[0] = (m.slip_bottom.value - r.slip_bottom.value) / r.slip_bottom.error;
    f[1] = (m.slip_top.value - r.slip_top.value) / r.slip_top.error;
    f[2] = (m.T_bottom.value - r.T_wall_bottom.value) / r.T_wall_bottom.error;
    f[3] = (m.T_top.value - r.T_wall_top.value) / r.T_wall_top.error;
}

}  // namespace granlub::continuum::detail
