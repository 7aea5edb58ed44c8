#include "tables/twin_core_table.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "granlub/error.h"

#include "formats/format.h"

namespace granlub::postproc {

namespace {

// "0.244 ± 0.003" of a measured run (the DEM's); the value alone of an exact one (a continuum's profile has no
// standard errors: its line's scatter is its curvature, not an error)
std::string value(const Measured& m, bool exact) {
    return value_pm(m.value, exact ? std::nullopt : std::optional<double>(m.error), 3);
}

TwinCore read_core(const Case& c, const Run& r) {
    TwinCore k;
    k.run = &r;
    k.exact = !r.profile->has("u_over_U_stderr");
    try {
        k.core = run_core(c, *r.point, *r.profile, r.summary->outputs, r.summary->run, (r.dir / "summary.json").string());
        const Measured &mu = k.core->friction, &ts = k.core->temperature_scaled;
        const double f = mu.value * std::sqrt(ts.value);
        k.f2_over_f1 = {f, f * std::hypot(mu.error / mu.value, 0.5 * ts.error / ts.value)};
    } catch (const Error& e) {
        k.why = e.what();
    }
    return k;
}

std::string percent(double x) { return fmt::format("{:.0f} %", 100 * x); }

}  // namespace

std::vector<TwinCore> twin_cores(const Case& c, const Collection& col, const TwinTargets& t) {
    std::vector<TwinCore> out;
    for (const TwinPoint& p : t.points) {
        if (!p.judged) continue;
        for (const std::string& s : {t.solvers.particles, t.solvers.model})
            if (const Run& r = col.run(s, p.point->id); r.usable()) out.push_back(read_core(c, r));
    }
    return out;
}

Table twin_core_table(const std::vector<TwinCore>& cores) {
    Table table;
    table.header = {"point", "solver", "I", "μ", "ν", "T/(dγ̇)²", "μ √(T/(dγ̇)²)"};
    for (const TwinCore& k : cores) {
        std::vector<Cell> row{{k.run->point->id, ""}, {k.run->solver, ""}};
        if (!k.core) {
            row.push_back({fmt::format("core not read: {}", k.why), "unknown"});
            row.resize(table.header.size(), {"", "unknown"});
        } else {
            for (const Measured& m : {k.core->inertial_number, k.core->friction, k.core->solid_fraction,
                                      k.core->temperature_scaled, k.f2_over_f1})
                row.push_back({value(m, k.exact), ""});
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

std::string twin_core_summary(const std::vector<TwinCore>& cores) {
    struct Range {
        double lo = INFINITY, hi = -INFINITY;
        void add(double x) { lo = std::min(lo, x), hi = std::max(hi, x); }
        double largest() const { return std::max(std::abs(lo), std::abs(hi)); }
    } dI, dmu, model, dem, df, z;  // relative differences (model/DEM - 1), the two f2/f1, and |difference|/DEM error
    int n = 0;
    for (std::size_t i = 0; i + 1 < cores.size(); ++i) {
        const TwinCore &a = cores[i], &b = cores[i + 1];  // the DEM's, then the continuum's, at one point
        if (a.run->point != b.run->point || !a.core || !b.core) continue;
        ++n, ++i;
        dI.add(b.core->inertial_number.value / a.core->inertial_number.value - 1);
        dmu.add(b.core->friction.value / a.core->friction.value - 1);
        model.add(b.f2_over_f1.value), dem.add(a.f2_over_f1.value);
        df.add(b.f2_over_f1.value / a.f2_over_f1.value - 1);
        const double e = a.f2_over_f1.error;
        z.add(e > 0 ? std::abs(b.f2_over_f1.value - a.f2_over_f1.value) / e : INFINITY);
    }
    if (n == 0) return "";
    // the verdict on T only where the bed agrees and f2/f1 differs beyond the DEM's own error at every point
    const bool bed_agrees = dI.largest() <= 0.1 && dmu.largest() <= 0.1;
    const char* verdict = !bed_agrees || df.largest() <= 0.1 ? "."
                          : z.lo > 2.0 ? ": the bed's shear and stress ratio agree, its T does not, for the closures' "
                                         "f2/f1 and not the walls."
                                       : ": the bed's shear and stress ratio agree; f2/f1 differs by less than 2 of the "
                                         "DEM's standard errors at some point, so these points alone do not show its T "
                                         "differing.";
    return fmt::format(
        "At the {} point{} where both cores were read, the continuum's core is within {} of the DEM's in I and {} in "
        "μ; its μ √(T/(dγ̇)²) is {}–{} against the DEM's {}–{} ({:+.0f} … {:+.0f} %{}){}",
        n, n == 1 ? "" : "s", percent(dI.largest()), percent(dmu.largest()), num(model.lo, 3), num(model.hi, 3),
        num(dem.lo, 3), num(dem.hi, 3), 100 * df.lo, 100 * df.hi,
        std::isfinite(z.hi) ? fmt::format(", {:.1f}–{:.1f} of the DEM's standard errors", z.lo, z.hi) : "", verdict);
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
