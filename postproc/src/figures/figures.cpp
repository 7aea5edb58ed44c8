#include "figures/figures.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "figures/state_series.h"
#include "formats/format.h"
#include "results/scope.h"
#include "statistics/metrics.h"
#include "statistics/stats.h"

namespace granlub::postproc {
namespace {

const char* stress_label(const std::string& q) {
    for (const auto& s : kScalarQuantities)
        if (q == s.key) return s.label;
    return "";
}

const char* stress_title(const std::string& q) {
    if (q == "normal_stress_bottom") return "Normal stress on the moving wall";
    if (q == "normal_stress_top") return "Normal stress on the stationary wall";
    if (q == "shear_stress_bottom") return "Shear stress on the moving wall";
    return "Shear stress on the stationary wall";
}

std::string with_group(const std::string& solver, const std::string& group) {
    return group.empty() ? solver : fmt::format("{}, {}", solver, group);
}

void sort_by_x(Series& s) {
    std::vector<std::size_t> idx(s.x.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
    Series t = s;
    for (std::size_t i = 0; i < idx.size(); ++i) {
        t.x[i] = s.x[idx[i]];
        t.y[i] = s.y[idx[i]];
        if (!s.err.empty()) t.err[i] = s.err[idx[i]];
    }
    s = std::move(t);
}

// A solver's points in one figure, split by state (state_series.h) in the solver's style.
template <class Add>
std::vector<Series> points_by_state(const Collection& col, const std::string& solver,
                                    const std::vector<const OperatingPoint*>& points, const std::string& label,
                                    Add add) {
    std::vector<Series> out = split_by_state(col, solver, points, label, add);
    for (auto& s : out) s.style = solver_style(col, solver), s.mark = Mark::Points;
    return out;
}

// Under load control the top plate is held at the target stress: drawn as a black dotted line at
// the target over the speeds of the load-controlled points (one line per target value).
void add_load_target(const Collection& col, Figure& f) {
    std::map<double, std::vector<double>> speeds;
    for (const OperatingPoint* p : col.points)
        if (p->control == Control::Load && p->normal_stress > 0) speeds[p->normal_stress].push_back(p->speed);
    for (const auto& [target, u] : speeds) {
        Series line;
        line.style = 6;  // black
        line.dashed = true;
        line.label = speeds.size() == 1 ? "load target" : fmt::format("load target {} Pa", num(target));
        const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
        line.x = {*lo / 1.1, *hi * 1.1};
        line.y = {target, target};
        f.series.push_back(std::move(line));
    }
    if (!speeds.empty()) f.caption += " Black dashed: the load target of the case.";
}

}  // namespace

int solver_style(const Collection& col, const std::string& solver) {
    const auto known = std::find(col.known.begin(), col.known.end(), solver);
    if (known != col.known.end()) return static_cast<int>(known - col.known.begin());
    int k = static_cast<int>(col.known.size());
    for (const auto& s : col.solvers) {
        if (s == solver) return k;
        if (std::find(col.known.begin(), col.known.end(), s) == col.known.end()) ++k;
    }
    return k;
}

std::string point_slug(const OperatingPoint& p) {
    std::string s;
    for (char ch : p.id) s += std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(ch)) : ch == '_' ? '_' : '-';
    return s;
}

std::string name_slug(const std::string& s) {
    std::string out;
    for (char ch : s) out += std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(ch)) : '-';
    return out;
}

std::vector<Figure> profile_figures(const Collection& col, std::size_t point_index) {
    const OperatingPoint& p = *col.points.at(point_index);
    const auto runs = col.usable(p.id);
    const std::string stem = fmt::format("profile_{}", point_slug(p));
    const char* suffix[] = {"u", "nu", "T"};
    const char* what[] = {"Velocity", "Solid fraction", "Granular temperature"};
    std::vector<Figure> figs;
    for (std::size_t k = 0; k < std::size(kProfileQuantities); ++k) {
        const auto& q = kProfileQuantities[k];
        Figure f;
        f.name = fmt::format("{}_{}", stem, suffix[k]);
        f.title = fmt::format("{}, {} (U = {} m/s)", what[k], p.id, num(p.speed));
        f.caption = fmt::format("{} across the gap at point {}.", q.label, p.id);
        if (std::any_of(runs.begin(), runs.end(), [](const Run* r) { return run_text(*r, "geometry") == "cross_section"; }))
            f.caption += " The continuum on the cross-section: its mid-width column; a particle run's profile is its "
                         "average over the width.";
        f.x.label = "y/H (0: moving wall, 1: stationary wall)";
        f.x.lo = 0;
        f.x.hi = 1;
        f.y.label = q.label;
        if (k > 0) f.y.lo = 0;  // nu and T are non-negative: show the zero
        for (const Run* r : runs) {
            Series s;
            s.unsteady = !r->steady();
            // The continuum on the trough's cross-section writes its mid-width column as profile.csv.
            const std::string name = run_text(*r, "geometry") == "cross_section" ? r->solver + " (mid-width)" : r->solver;
            s.label = s.unsteady ? fmt::format("{}: {}", name, r->state_name()) : name;
            s.x = r->y();
            s.y = r->column(q.key);
            s.err = r->column_stderr(q.key);
            s.style = solver_style(col, r->solver);
            f.series.push_back(std::move(s));
        }
        figs.push_back(std::move(f));
    }
    return figs;
}

std::vector<Figure> stress_figures(const Collection& col) {
    std::vector<Figure> figs;
    const auto groups = speed_groups(col.points);
    for (const char* q : kStressOutputs) {
        Figure f;
        f.name = std::string("stress_") + q;
        f.title = stress_title(q);
        f.caption = "Log–log; dashed: the fitted power law σ = c Uⁿ per solver.";
        f.x.label = "wall speed U (m/s)";
        f.x.log = true;
        f.y.label = stress_label(q);
        f.y.log = true;
        std::vector<std::string> not_fitted;
        bool controlled = false;
        std::size_t short_groups = 0;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const auto& solver : col.solvers) {
                // The automaton's "stresses" are lattice analogues: said in the legend, beside the markers.
                const std::string label = with_group(lattice_stresses(col, solver) ? solver + " (lattice analogue)" : solver,
                                                     groups[g].label);
                auto series = points_by_state(col, solver, groups[g].points, label,
                                              [&](const Run& r, const OperatingPoint& p, Series& s) {
                                                  s.x.push_back(p.speed);
                                                  s.y.push_back(*r.scalar(q));
                                                  s.err.push_back(r.scalar_stderr(q).value_or(0.0));
                                              });
                for (auto& s : series) s.open = s.open || g % 2 == 1;
                const StressFit fit = stress_fit(col, groups[g], solver, q);
                if (controlled_stress(groups[g], q))
                    controlled = true;
                else if (groups[g].points.size() < static_cast<std::size_t>(kMinFitPoints))
                    ++short_groups;  // one sentence for all of them, not one per solver
                else if (fit.steady_points + fit.other_points > 0 && !fit.fit)
                    not_fitted.push_back(fit.steady_points < kMinFitPoints
                                             ? fmt::format("{} has {} steady point{} (a fit needs {})",
                                                           with_group(solver, groups[g].label), fit.steady_points,
                                                           fit.steady_points == 1 ? "" : "s", kMinFitPoints)
                                             : fmt::format("{}: {}", with_group(solver, groups[g].label), fit.why_not));
                Series line;
                if (fit.fit) {
                    line.style = series[0].style;
                    line.dashed = true;
                    line.label = fit.fit->exponent_stderr
                                     ? fmt::format("n = {:.2f} ± {:.2f}", fit.fit->exponent, *fit.fit->exponent_stderr)
                                     : fmt::format("n = {:.2f}", fit.fit->exponent);
                    const auto [lo, hi] = std::minmax_element(series[0].x.begin(), series[0].x.end());
                    for (double u : {*lo / 1.1, *hi * 1.1}) {
                        line.x.push_back(u);
                        line.y.push_back(fit.fit->prefactor * std::pow(u, fit.fit->exponent));
                    }
                }
                for (auto& s : series)
                    if (!s.x.empty()) f.series.push_back(std::move(s));
                if (!line.x.empty()) f.series.push_back(std::move(line));
            }
        }
        if (controlled)
            f.caption += " Under load control this normal stress follows the load (the control variable): not fitted.";
        if (q == std::string("normal_stress_top")) add_load_target(col, f);
        const std::size_t short_count = short_groups / std::max<std::size_t>(1, col.solvers.size());
        if (short_count == groups.size())
            f.caption += fmt::format(" No power law: no group of points that differ only in speed has {} speeds.",
                                     kMinFitPoints);
        else if (short_count > 0)
            f.caption += fmt::format(" No power law for {} of the {} speed groups (fewer than {} speeds).", short_count,
                                     groups.size(), kMinFitPoints);
        if (!not_fitted.empty()) {
            f.caption += " No power law:";
            for (std::size_t i = 0; i < not_fitted.size(); ++i) f.caption += (i ? "; " : " ") + not_fitted[i];
            f.caption += ".";
        }
        figs.push_back(std::move(f));
    }
    return figs;
}

std::vector<Figure> slip_figures(const Collection& col) {
    std::vector<Figure> figs;
    for (const bool bottom : {true, false}) {
        const auto R = [bottom](const OperatingPoint& p) { return bottom ? p.bottom.roughness : p.top.roughness; };
        // Against roughness when the case sweeps it; otherwise (one roughness) against U, which
        // is then the only thing that varies.
        const bool swept = std::any_of(col.points.begin(), col.points.end(),
                                       [&](const OperatingPoint* p) { return R(*p) != R(*col.points.front()); });
        const auto groups = swept ? roughness_groups(col.points) : speed_groups(col.points);
        const std::string q = bottom ? "slip_bottom_over_U" : "slip_top_over_U";
        const std::string wall = bottom ? "moving wall" : "stationary wall";
        Figure f;
        f.name = bottom ? "slip_bottom" : "slip_top";
        f.title = "Slip at the " + wall + (swept ? " against roughness" : " against wall speed");
        // which solvers had which wall: R for the continuum and the automaton, the bumps' R for a
        // rough particle wall, no R at all for a particle solver's plane
        std::vector<std::string> planes, bumps;
        for (const auto& solver : col.solvers)
            for (const OperatingPoint* p : col.points) {
                const std::string surface = col.run(solver, p->id).wall_surface(bottom);
                auto& list = surface == "plane" ? planes : bumps;
                if (!surface.empty() && std::find(list.begin(), list.end(), solver) == list.end()) list.push_back(solver);
            }
        std::string walls;
        if (!planes.empty())
            walls += fmt::format(" {} had a frictional plane here, which has no R{}.", list_text(planes),
                                 swept ? ": not drawn" : "");
        if (!bumps.empty())
            walls += fmt::format(" {} had a layer of bumps built to the point's R (drawn at the R they give); "
                                 "their slip is the wall's speed against the grains' mean velocity in the first "
                                 "coarse-graining station clear of the bumps (half a bump diameter from the "
                                 "plane through their centres), not at the plane.",
                                 list_text(bumps));
        f.caption = (bottom ? "Slip (U − u(0)) / U" : "Slip u(H) / U") +
                    (swept ? std::string(" against the ") + wall + "'s roughness R"
                           : fmt::format(" against U (one roughness, R = {})",
                                         col.points.empty() ? std::string("?") : num(R(*col.points.front())))) +
                    "." + walls;
        f.x.label = swept ? "roughness R of the " + wall : std::string("wall speed U (m/s)");
        f.y.label = "slip / U at the " + wall;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const auto& solver : col.solvers) {
                auto series = points_by_state(col, solver, groups[g].points, with_group(solver, groups[g].label),
                                              [&](const Run& r, const OperatingPoint& p, Series& s) {
                                                  const std::optional<double> rough = r.wall_roughness(bottom);
                                                  if (swept && !rough) return;  // a plane: no R to draw it at
                                                  s.x.push_back(swept ? *rough : p.speed);
                                                  s.y.push_back(*r.scalar(q));
                                                  s.err.push_back(r.scalar_stderr(q).value_or(0.0));
                                              });
                for (auto& s : series) sort_by_x(s), s.open = s.open || g % 2 == 1;
                if (series[0].x.size() > 1) {  // a line through the steady points only
                    Series line;
                    line.style = series[0].style;
                    line.x = series[0].x;
                    line.y = series[0].y;
                    f.series.push_back(std::move(line));
                }
                for (auto& s : series)
                    if (!s.x.empty()) f.series.push_back(std::move(s));
            }
        }
        figs.push_back(std::move(f));
    }
    return figs;
}

Figure solid_fraction_figure(const Collection& col, double case_nu_max) {
    Figure f;
    f.name = "solid_fraction";
    f.title = "Mean solid fraction";
    f.caption = "Mean solid fraction over the gap divided by each model's own ν_max, per point.";
    f.x.label = "operating point";
    f.y.label = "mean ν / ν_max";
    const std::size_t n = col.solvers.size();
    for (std::size_t i = 0; i < col.points.size(); ++i) f.x.categories.emplace_back(static_cast<double>(i), col.points[i]->id);
    for (std::size_t k = 0; k < n; ++k) {
        const double offset = n > 1 ? -0.25 + 0.5 * static_cast<double>(k) / static_cast<double>(n - 1) : 0.0;
        auto series = points_by_state(col, col.solvers[k], col.points, col.solvers[k],
                                      [&](const Run& r, const OperatingPoint& p, Series& s) {
                                          const auto i = static_cast<std::size_t>(
                                              std::find(col.points.begin(), col.points.end(), &p) - col.points.begin());
                                          s.x.push_back(static_cast<double>(i) + offset);
                                          s.y.push_back(*r.scalar("nu_bar_over_numax"));
                                          s.err.push_back(r.scalar_stderr("nu_bar_over_numax").value_or(0.0));
                                      });
        for (auto& s : series)
            if (!s.x.empty()) f.series.push_back(std::move(s));
    }
    Series target;
    target.label = "fill target";
    target.style = 6;  // black
    target.mark = Mark::Points;
    target.open = true;
    for (std::size_t i = 0; i < col.points.size(); ++i) {
        if (col.points[i]->control != Control::Fill || !(case_nu_max > 0)) continue;
        target.x.push_back(static_cast<double>(i));
        target.y.push_back(col.points[i]->solid_fraction / case_nu_max);
    }
    // Only the points under fill control have a target; under load control ν̄ is a result.
    if (!target.x.empty()) {
        f.series.push_back(std::move(target));
        f.caption += " Black hollow triangles: the fill target ν/ν_max of the case.";
    }
    const auto load = [](const OperatingPoint* p) { return p->control == Control::Load; };
    if (std::any_of(col.points.begin(), col.points.end(), load))
        f.caption += " Under load control ν̄ is a result (the gap moves or the model solves for it), not a target.";
    return f;
}

}  // namespace granlub::postproc
