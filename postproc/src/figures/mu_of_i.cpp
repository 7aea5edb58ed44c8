#include "figures/mu_of_i.h"

#include <algorithm>

#include <fmt/format.h>

#include "figures/figures.h"
#include "figures/state_series.h"
#include "formats/format.h"
#include "granlub/statistics/flow_regime.h"
#include "results/scope.h"

namespace granlub::postproc {

double jop_mu(double I) { return I > 0 ? kJopMuS + (kJopMu2 - kJopMuS) / (kJopI0 / I + 1.0) : kJopMuS; }

RunInertia run_inertia(const Case& c, const Run& r) {
    RunInertia out;
    if (!r.usable()) return out;
    const auto& run = r.summary->run;
    if (run.is_object() && run.contains("flow_regime")) {
        const FlowVerdict v = read_flow_verdict(run["flow_regime"]);
        out.nominal = v.inertial_nominal;
        out.mid_gap = v.inertial_mid_gap;
        return out;
    }
    if (lattice_stresses(r)) return out;  // no pressure in Pa
    const auto sb = r.scalar("normal_stress_bottom"), st = r.scalar("normal_stress_top");
    if (!sb || !st) return out;
    const double H = r.scalar("gap").value_or(c.cell.gap);
    FlowDiagnostics d;
    try {
        set_inertial_numbers(d, *r.profile, r.point->speed, H, 0.5 * (*sb + *st), c.grains.diameter, c.grains.density);
    } catch (const std::exception&) {
        return out;  // a profile without y_over_H / u_over_U: no I, the figure says who is missing
    }
    out.nominal = d.inertial_nominal;
    out.mid_gap = d.inertial_mid_gap;
    return out;
}

namespace {

std::optional<double> friction(const Run& r, bool bottom) {
    const auto tau = r.scalar(bottom ? "shear_stress_bottom" : "shear_stress_top");
    const auto sigma = r.scalar(bottom ? "normal_stress_bottom" : "normal_stress_top");
    if (!tau || !sigma || !(*sigma > 0)) return std::nullopt;
    return std::abs(*tau) / *sigma;
}

void add_jop_line(Figure& f) {
    double lo = 0, hi = 0;
    for (const Series& s : f.series)
        for (double x : s.x)
            if (x > 0) lo = lo > 0 ? std::min(lo, x) : x, hi = std::max(hi, x);
    if (!(lo > 0)) lo = 1e-3, hi = 1.0;
    lo /= 2, hi *= 2;
    Series line;
    line.label = "μ(I), glass beads (Jop et al. 2006)";
    line.style = 6;  // black
    line.dashed = true;
    for (int k = 0; k <= 60; ++k) {
        const double I = lo * std::pow(hi / lo, k / 60.0);
        line.x.push_back(I);
        line.y.push_back(jop_mu(I));
    }
    f.series.push_back(std::move(line));
}

}  // namespace

std::vector<Figure> mu_of_i_figures(const Case& c, const Collection& col, const SpeedLoadGrid& grid) {
    std::vector<const OperatingPoint*> points;
    for (const auto& g : grid.per_load) points.insert(points.end(), g.points.begin(), g.points.end());
    std::vector<std::string> without;  // solvers with results but no I
    for (const auto& s : col.solvers) {
        bool any = false, any_i = false;
        for (const OperatingPoint* p : points) {
            const Run& r = col.run(s, p->id);
            if (!r.usable()) continue;
            any = true;
            any_i = any_i || run_inertia(c, r).nominal.has_value();
        }
        if (any && !any_i) without.push_back(s);
    }
    const std::string missing =
        without.empty() ? ""
                        : fmt::format(" Not drawn: {} (no inertial number: the automaton's stresses are lattice "
                                      "analogues with no pressure in Pa).",
                                      list_text(without));
    const std::string law = fmt::format(
        " Black dashed: μ(I) = μ_s + (μ_2 − μ_s)/(I_0/I + 1) of Jop, Forterre & Pouliquen 2006 (Nature 441:727) "
        "for glass beads, μ_s = tan 20.9° = {:.3f}, μ_2 = tan 32.76° = {:.3f}, I_0 = {}: a reference for "
        "dense flow, not a fit.",
        kJopMuS, kJopMu2, kJopI0);
    std::vector<Figure> figs;
    for (const bool mid : {true, false}) {
        Figure f;
        f.name = mid ? "regime_mu_of_i_mid_gap" : "regime_mu_of_i_nominal";
        f.title = mid ? "μ = τ/P against I (mid-gap shear rate)" : "μ = τ/P against I (U/H)";
        f.caption = fmt::format("The wall friction coefficient μ = |τ|/σ_yy of each wall against the inertial number "
                                "I = γ̇ d / √(P/ρ_p) (GDR MiDi 2004, eq. 1), γ̇ {}; filled markers the moving wall, "
                                "open the stationary one; every point of every load.",
                                mid ? "the measured shear rate at mid-gap (run.flow_regime)" : "= U/H");
        f.caption += law + missing;
        f.x.label = mid ? "I (mid-gap γ̇)" : "I (γ̇ = U/H)";
        f.x.log = true;
        f.y.label = "μ = |τ| / σ_yy";
        f.y.lo = 0;
        for (const auto& s : col.solvers)
            for (const bool bottom : {true, false}) {
                auto series = series_by_state(
                    col, s, points, fmt::format("{}, {}", s, bottom ? "moving wall" : "stationary wall"),
                    solver_style(col, s), [&](const Run& r, const OperatingPoint&) {
                        const RunInertia I = run_inertia(c, r);
                        const auto x = mid ? I.mid_gap : I.nominal;
                        const auto y = friction(r, bottom);
                        return x && *x > 0 && y ? std::optional(std::pair(*x, *y)) : std::nullopt;
                    });
                for (auto& ser : series) ser.open = ser.open || !bottom, f.series.push_back(std::move(ser));
            }
        add_jop_line(f);
        figs.push_back(std::move(f));
    }
    Figure f;
    f.name = "regime_nu_of_i";
    f.title = "Mean solid fraction against I";
    f.caption = "The mean solid fraction ν̄ over the gap against the inertial number: filled markers with I from the "
                "mid-gap shear rate, open with I from U/H. In dense flow ν̄ falls roughly linearly with I from its "
                "quasi-static value (GDR MiDi 2004; da Cruz et al. 2005); a bed lifting off into collisional flow "
                "loses ν̄ fast." +
                missing;
    f.x.label = "I";
    f.x.log = true;
    f.y.label = "ν̄ (mean solid fraction)";
    for (const auto& s : col.solvers)
        for (const bool mid : {true, false}) {
            auto series = series_by_state(col, s, points, fmt::format("{}, I {}", s, mid ? "mid-gap" : "U/H"),
                                          solver_style(col, s), [&](const Run& r, const OperatingPoint&) {
                                              const RunInertia I = run_inertia(c, r);
                                              const auto x = mid ? I.mid_gap : I.nominal;
                                              const auto y = r.scalar("mean_solid_fraction");
                                              return x && *x > 0 && y ? std::optional(std::pair(*x, *y))
                                                                      : std::nullopt;
                                          });
            for (auto& ser : series) ser.open = ser.open || !mid, f.series.push_back(std::move(ser));
        }
    figs.push_back(std::move(f));
    return figs;
}

}  // namespace granlub::postproc
