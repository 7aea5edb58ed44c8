#include "figures.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "metrics.h"
#include "stats.h"
#include "text.h"

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

}  // namespace

int solver_style(const Collection& col, const std::string& solver) {
    const auto known = std::find(std::begin(kKnownSolvers), std::end(kKnownSolvers), solver);
    if (known != std::end(kKnownSolvers)) return static_cast<int>(known - std::begin(kKnownSolvers));
    int k = 4;
    for (const auto& s : col.solvers) {
        if (s == solver) return k;
        if (std::find(std::begin(kKnownSolvers), std::end(kKnownSolvers), s) == std::end(kKnownSolvers)) ++k;
    }
    return k;
}

std::string point_slug(const OperatingPoint& p) {
    std::string s;
    for (char ch : p.id) s += std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(ch)) : ch == '_' ? '_' : '-';
    return s;
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
        f.caption = fmt::format("{} across the gap at point {}; shaded bands are ±1 standard error.", q.label, p.id);
        f.x.label = "y/H (0: moving wall, 1: stationary wall)";
        f.x.lo = 0;
        f.x.hi = 1;
        f.y.label = q.label;
        if (k > 0) f.y.lo = 0;  // nu and T are non-negative: show the zero
        for (const Run* r : runs) {
            Series s;
            s.label = r->solver;
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
        f.caption = "Log–log; markers are the results (bars ±1 standard error), dashed lines the fitted "
                    "power law σ = c Uⁿ per solver.";
        f.x.label = "wall speed U (m/s)";
        f.x.log = true;
        f.y.label = stress_label(q);
        f.y.log = true;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const auto& solver : col.solvers) {
                Series pts;
                std::vector<std::optional<double>> se;
                for (const OperatingPoint* p : groups[g].points) {
                    const Run& r = col.run(solver, p->id);
                    if (!r.usable()) continue;
                    pts.x.push_back(p->speed);
                    pts.y.push_back(*r.scalar(q));
                    se.push_back(r.scalar_stderr(q));
                    pts.err.push_back(se.back().value_or(0.0));
                }
                if (pts.x.empty()) continue;
                pts.label = with_group(solver, groups[g].label);
                pts.style = solver_style(col, solver);
                pts.mark = Mark::Points;
                pts.open = g % 2 == 1;
                if (const auto fit = power_fit(pts.x, pts.y, se)) {
                    Series line;
                    line.style = pts.style;
                    line.dashed = true;
                    line.label = fit->exponent_stderr
                                     ? fmt::format("n = {:.2f} ± {:.2f}", fit->exponent, *fit->exponent_stderr)
                                     : fmt::format("n = {:.2f}", fit->exponent);
                    const auto [lo, hi] = std::minmax_element(pts.x.begin(), pts.x.end());
                    for (double u : {*lo / 1.1, *hi * 1.1}) {
                        line.x.push_back(u);
                        line.y.push_back(fit->prefactor * std::pow(u, fit->exponent));
                    }
                    f.series.push_back(std::move(pts));
                    f.series.push_back(std::move(line));
                } else {
                    f.series.push_back(std::move(pts));
                }
            }
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
        f.title = "Slip at the " + wall;
        f.caption = (bottom ? "Slip (U − u(0)) / U" : "Slip u(H) / U") +
                    (swept ? std::string(" against the ") + wall + "'s roughness R"
                           : fmt::format(" against U (the case has one roughness, R = {})",
                                         col.points.empty() ? std::string("?") : num(R(*col.points.front())))) +
                    "; bars ±1 standard error.";
        f.x.label = swept ? "roughness R of the " + wall : std::string("wall speed U (m/s)");
        f.y.label = "slip / U at the " + wall;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const auto& solver : col.solvers) {
                Series pts;
                for (const OperatingPoint* p : groups[g].points) {
                    const Run& r = col.run(solver, p->id);
                    if (!r.usable()) continue;
                    pts.x.push_back(swept ? R(*p) : p->speed);
                    pts.y.push_back(*r.scalar(q));
                    pts.err.push_back(r.scalar_stderr(q).value_or(0.0));
                }
                if (pts.x.empty()) continue;
                sort_by_x(pts);
                pts.label = with_group(solver, groups[g].label);
                pts.style = solver_style(col, solver);
                pts.mark = Mark::Points;
                pts.open = g % 2 == 1;
                if (pts.x.size() > 1) {
                    Series line;
                    line.style = pts.style;
                    line.x = pts.x;
                    line.y = pts.y;
                    f.series.push_back(std::move(line));
                }
                f.series.push_back(std::move(pts));
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
    f.caption = "Mean solid fraction over the gap divided by each model's own ν_max, per point "
                "(bars ±1 standard error); black: the fill target ν/ν_max of the case.";
    f.x.label = "operating point";
    f.y.label = "mean ν / ν_max";
    const std::size_t n = col.solvers.size();
    for (std::size_t i = 0; i < col.points.size(); ++i) f.x.categories.emplace_back(static_cast<double>(i), col.points[i]->id);
    for (std::size_t k = 0; k < n; ++k) {
        Series s;
        s.label = col.solvers[k];
        s.style = solver_style(col, col.solvers[k]);
        s.mark = Mark::Points;
        const double offset = n > 1 ? -0.25 + 0.5 * static_cast<double>(k) / static_cast<double>(n - 1) : 0.0;
        for (std::size_t i = 0; i < col.points.size(); ++i) {
            const Run& r = col.run(col.solvers[k], col.points[i]->id);
            if (!r.usable()) continue;
            s.x.push_back(static_cast<double>(i) + offset);
            s.y.push_back(*r.scalar("nu_bar_over_numax"));
            s.err.push_back(r.scalar_stderr("nu_bar_over_numax").value_or(0.0));
        }
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
    if (!target.x.empty()) f.series.push_back(std::move(target));
    return f;
}

}  // namespace granlub::postproc
