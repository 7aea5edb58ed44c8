#include "figures/shear_power_law.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "figures/figures.h"
#include "figures/state_series.h"
#include "formats/format.h"
#include "results/scope.h"
#include "statistics/metrics.h"

namespace granlub::postproc {

std::string exponent_reading(const PowerFit& fit) {
    const double n = fit.exponent;
    const double two_se = fit.exponent_stderr ? 2 * *fit.exponent_stderr : 0.0;
    if (n >= kBagnoldMinExponent || std::abs(n - 2.0) <= two_se) return "Bagnold (collisional)";
    if (n <= kQuasiStaticMaxExponent || std::abs(n) <= two_se) return "quasi-static";
    return "between quasi-static and Bagnold";
}

namespace {

constexpr const char* kShear[] = {"shear_stress_bottom", "shear_stress_top"};

// A guide of slope n through (x0, y0), over [lo, hi].
Series guide(double n, double x0, double y0, double lo, double hi) {
    Series g;
    g.label = n == 2 ? "slope 2 (Bagnold)" : "slope 0 (quasi-static)";
    g.style = n == 2 ? 6 : 5;  // black dashed; sky blue with its own dash
    g.dashed = n == 2;
    for (double x : {lo, hi}) g.x.push_back(x), g.y.push_back(y0 * std::pow(x / x0, n));
    return g;
}

}  // namespace

// One figure per solver and wall, the loads told apart by colour, dash and marker (as the lift-off
// figures, regime_map.cpp): open markers stay for results that are not steady.
std::vector<Figure> shear_power_law_figures(const Collection& col, const SpeedLoadGrid& grid) {
    std::vector<Figure> figs;
    for (const char* q : kShear)
        for (const auto& s : col.solvers) {
            if (lattice_stresses(col, s)) continue;  // no load, no exponent of its own (scope.h)
            const bool bottom = q == std::string("shear_stress_bottom");
            Figure f;
            f.name = fmt::format("regime_tau_of_u_{}_{}", bottom ? "bottom" : "top", name_slug(s));
            f.title = fmt::format("Shear stress on the {} wall against U, per load: {}", bottom ? "moving" : "stationary", s);
            f.caption = fmt::format("Log–log, {}. τ = c Uⁿ fitted per load over its steady points (at least {}; "
                                    "dashed, n in the legend); colour, dash and marker per load. Guides: slope 2, "
                                    "Bagnold's rapid collisional scaling at fixed ν (Bagnold 1954), and slope 0, the "
                                    "rate-independent friction of quasi-static flow. The automaton is not drawn: its "
                                    "stresses are lattice analogues ∝ U² by construction, and it runs one fill at "
                                    "every load.",
                                    s, kMinFitPoints);
            f.x.label = "wall speed U (m/s)";
            f.x.log = true;
            f.y.label = bottom ? "shear stress, moving wall (Pa)" : "shear stress, stationary wall (Pa)";
            f.y.log = true;
            double slog = 0;
            int count = 0;
            for (std::size_t g = 0; g < grid.per_load.size(); ++g) {
                const PointGroup& group = grid.per_load[g];
                auto series = series_by_state(col, s, group.points, group.label, load_style(g),
                                              [&](const Run& r, const OperatingPoint& p) {
                                                  const auto v = r.scalar(q);
                                                  if (!v || !(*v > 0)) return std::optional<std::pair<double, double>>();
                                                  return std::optional(std::pair(p.speed, *v));
                                              });
                for (auto& ser : series) {
                    if (!ser.unsteady)
                        for (double y : ser.y) slog += std::log(y), ++count;
                    f.series.push_back(std::move(ser));
                }
                const StressFit fit = stress_fit(col, group, s, q);
                if (!fit.fit) continue;
                Series line;
                line.style = load_style(g);
                line.dashed = true;
                line.label = fit.fit->exponent_stderr
                                 ? fmt::format("{}: n = {:.2f} ± {:.2f}", group.label, fit.fit->exponent,
                                               *fit.fit->exponent_stderr)
                                 : fmt::format("{}: n = {:.2f}", group.label, fit.fit->exponent);
                double lo = 0, hi = 0;
                for (const OperatingPoint* p : group.points) lo = lo > 0 ? std::min(lo, p->speed) : p->speed, hi = std::max(hi, p->speed);
                for (double u : {lo / 1.1, hi * 1.1})
                    line.x.push_back(u), line.y.push_back(fit.fit->prefactor * std::pow(u, fit.fit->exponent));
                f.series.push_back(std::move(line));
            }
            if (f.series.empty()) continue;  // no results of this solver at the sweep's points
            if (count > 0 && grid.speeds.front() > 0) {
                const double lo = grid.speeds.front() / 1.1, hi = grid.speeds.back() * 1.1;
                const double x0 = std::sqrt(lo * hi), y0 = std::exp(slog / count);
                f.series.push_back(guide(2, x0, y0, lo, hi));
                f.series.push_back(guide(0, x0, y0, lo, hi));
            }
            figs.push_back(std::move(f));
        }
    return figs;
}

Table shear_exponent_table(const Collection& col, const SpeedLoadGrid& grid) {
    Table t;
    t.header = {"solver", "load", "wall", "n (steady points)", "reads as"};
    for (const auto& group : grid.per_load)
        for (const auto& s : col.solvers)
            for (const char* q : kShear) {
                if (lattice_stresses(col, s)) continue;
                const StressFit fit = stress_fit(col, group, s, q);
                if (fit.steady_points + fit.other_points == 0) continue;
                const std::string wall = q == std::string("shear_stress_bottom") ? "moving" : "stationary";
                if (!fit.fit) {
                    t.rows.push_back({{s, ""}, {group.label, ""}, {wall, ""}, {fit.why_not, "transient"}, {"—", ""}});
                    continue;
                }
                t.rows.push_back({{s, ""},
                                  {group.label, ""},
                                  {wall, ""},
                                  {fmt::format("{} ({} points)", value_pm(fit.fit->exponent, fit.fit->exponent_stderr, 3),
                                               fit.fit->points),
                                   ""},
                                  {exponent_reading(*fit.fit), ""}});
            }
    return t;
}

}  // namespace granlub::postproc
