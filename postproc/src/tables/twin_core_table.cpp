#include "tables/twin_core_table.h"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "granlub/case/wall_bumps.h"
#include "granlub/error.h"
#include "granlub/particles/bulk_rheology.h"

#include "formats/format.h"

namespace granlub::postproc {

namespace {

// "0.244 ± 0.003" of a measured run (the DEM's); the value alone of an exact one (a continuum's profile has no
// standard errors: its line's scatter is its curvature, not an error)
std::string value(const Measured& m, bool exact) {
    return value_pm(m.value, exact ? std::nullopt : std::optional<double>(m.error), 3);
}

std::vector<Cell> core_row(const Case& c, const Run& r) {
    std::vector<Cell> row{{r.point->id, ""}, {r.solver, ""}};
    const nlohmann::json none = nlohmann::json::object();
    const nlohmann::json& fr = r.summary->run.contains("flow_regime") ? r.summary->run.at("flow_regime") : none;
    try {
        const OperatingPoint& p = *r.point;
        const CoreRun run = core_run(*r.profile, p.speed, r.summary->outputs, fr, c.cell.gap,
                                     bump_protrusion(c, p.bottom), bump_protrusion(c, p.top),
                                     (r.dir / "summary.json").string());
        const CoreRheology k = core_rheology(run, c.grains.diameter, c.grains.density);
        // mu sqrt(T~): relative errors of mu and half that of T~, in quadrature
        const double ts = k.temperature_scaled.value, f = k.friction.value * std::sqrt(ts);
        const double fe = f * std::hypot(k.friction.error / k.friction.value, 0.5 * k.temperature_scaled.error / ts);
        const bool exact = !r.profile->has("u_over_U_stderr");
        for (const Measured& m :
             {k.inertial_number, k.friction, k.solid_fraction, k.temperature_scaled, Measured{f, fe}})
            row.push_back({value(m, exact), ""});
    } catch (const Error& e) {
        row.push_back({fmt::format("core not read: {}", e.what()), "unknown"});
    }
    return row;
}

}  // namespace

Table twin_core_table(const Case& c, const Collection& col, const TwinTargets& t) {
    Table table;
    table.header = {"point", "solver", "I", "μ", "ν", "T/(dγ̇)²", "μ √(T/(dγ̇)²)"};
    for (const TwinPoint& p : t.points) {
        if (!p.judged) continue;
        for (const std::string& s : {t.solvers.particles, t.solvers.model}) {
            const Run& r = col.run(s, p.point->id);
            if (!r.usable()) continue;
            auto row = core_row(c, r);
            row.resize(table.header.size(), {"", row.back().cls});
            table.rows.push_back(std::move(row));
        }
    }
    return table;
}

std::string twin_core_note() {
    return fmt::format(
        "Each run's core, the middle third of the gap (y/H {:.3g} to {:.3g}), read as granlub bulk-rheology reads "
        "cases/bulk_shear's homogeneous shear: γ̇ from a straight line through u(y) there, τ and P the means of the two "
        "walls' stresses, ν and T the core's means, I = γ̇ d/√(P/ρ_p) with d the mean diameter. The walls' layers are "
        "outside it, so a difference here is the bulk closures', not the walls'. μ √(T/(dγ̇)²) is kinetic theory's "
        "f2/f1 at the core's ν (the shear stress ρ_p d f2 √T γ̇ over the pressure ρ_p f1 T): where the solvers agree on "
        "μ and not on it, they disagree on T. The DEM's errors are one standard error (its means' fully correlated "
        "bound); the continuum's values are exact.",
        kCoreFrom, kCoreTo);
}

}  // namespace granlub::postproc
