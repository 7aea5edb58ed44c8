#include "figures/continuum_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <sstream>

#include <fmt/format.h>

#include "figures/figures.h"
#include "granlub/error.h"
#include "granlub/results/file_io.h"
#include "granlub/run/solver_info.h"
#include "figures/mu_of_i.h"

namespace granlub::postproc {

std::vector<ContinuumMapRow> read_continuum_map(const std::filesystem::path& file) {
    std::vector<ContinuumMapRow> rows;
    if (!std::filesystem::exists(file)) return rows;
    std::istringstream in(read_file(file));
    std::string line;
    int n = 0;
    bool header = false;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            header = true;  // the column names (map.h)
            continue;
        }
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
        if (f.size() < 3) throw Error(fmt::format("{}:{}: expected the map's 12 columns", file.string(), n));
        ContinuumMapRow r;
        try {
            r.speed = std::stod(f[0]);
            r.load = std::stod(f[1]);
            r.status = f[2];
            if (r.status != "failed") {
                if (f.size() < 12) throw Error("short row");
                r.nu = std::stod(f[3]);
                r.gap = std::stod(f[4]);
                r.mu_bottom = std::stod(f[5]);
                r.mu_top = std::stod(f[6]);
                r.inertial = std::stod(f[7]);
                r.collision = f[11] == "collision";
            }
        } catch (const std::exception&) {
            throw Error(fmt::format("{}:{}: not a map row (format: continuum/include/granlub/continuum/map.h)",
                                    file.string(), n));
        }
        rows.push_back(r);
    }
    return rows;
}

namespace {

// The grid: speeds and loads in order, value(i, j) at speed i and load j (NaN where not steady).
struct Grid {
    std::vector<double> speeds, loads;
    std::map<std::pair<double, double>, const ContinuumMapRow*> at;
    const ContinuumMapRow* row(std::size_t i, std::size_t j) const {
        const auto it = at.find({speeds[i], loads[j]});
        return it == at.end() || it->second->status != "steady" ? nullptr : it->second;
    }
};

Grid grid_of(const std::vector<ContinuumMapRow>& rows) {
    Grid g;
    for (const auto& r : rows) {
        g.speeds.push_back(r.speed);
        g.loads.push_back(r.load);
        g.at[{r.speed, r.load}] = &r;
    }
    for (auto* v : {&g.speeds, &g.loads}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    return g;
}

// The line where value = level: for each speed, the first load (log-interpolated) where it crosses.
template <class F>
Series contour(const Grid& g, double level, F value) {
    Series s;
    for (std::size_t i = 0; i < g.speeds.size(); ++i)
        for (std::size_t j = 0; j + 1 < g.loads.size(); ++j) {
            const auto *a = g.row(i, j), *b = g.row(i, j + 1);
            if (!a || !b) continue;
            const double va = value(*a) - level, vb = value(*b) - level;
            if ((va > 0) == (vb > 0)) continue;
            const double t = va / (va - vb);
            s.x.push_back(g.speeds[i]);
            s.y.push_back(std::exp((1 - t) * std::log(g.loads[j]) + t * std::log(g.loads[j + 1])));
            break;
        }
    return s;
}

// Each particle solver's points, in its style: xy(run, point) gives a point's (x, y) or nothing.
template <class XY>
void add_particle_points(Figure& f, const Collection& col, const std::string& what, XY xy) {
    for (const auto& s : col.solvers) {
        if (col.kind(s) == SolverKind::Continuum) continue;
        Series pts;
        pts.label = s + what;
        pts.mark = Mark::Points;
        pts.style = solver_style(col, s);
        for (const OperatingPoint* p : col.points)
            if (const auto v = xy(col.run(s, p->id), *p)) {
                pts.x.push_back(v->first);
                pts.y.push_back(v->second);
            }
        if (!pts.x.empty()) f.series.push_back(std::move(pts));
    }
}

// The particle solvers' points at their (U, P).
void add_points(Figure& f, const Collection& col) {
    add_particle_points(f, col, " points", [](const Run& r, const OperatingPoint& p) {
        return r.usable() ? std::optional(std::pair(p.speed, p.normal_stress)) : std::nullopt;
    });
}

Figure field_figure(const Grid& g, const Collection& col, const std::string& name, const std::string& what,
                    const std::vector<double>& levels, double (*value)(const ContinuumMapRow&)) {
    Figure f;
    f.name = name;
    f.title = fmt::format("Continuum {} over speed and load", what);
    f.caption = fmt::format("Contour lines of the continuum's {} on its {} × {} (U, P) map (results/continuum/map.csv), "
                            "the dashed black line its contact/collision boundary (I/ν = 0.2, Chialvo & Sundaresan "
                            "2013), and the particle solvers' points; the points' own values are in the tables.",
                            what, g.speeds.size(), g.loads.size());
    f.x.label = "U (m/s)";
    f.y.label = "P (Pa)";
    f.y.log = true;
    int k = 0;
    for (double level : levels) {
        Series s = contour(g, level, value);
        if (s.x.empty()) continue;
        s.label = fmt::format("{} = {:.2f}", what, level);
        s.style = k++ % 6;
        f.series.push_back(std::move(s));
    }
    Series edge = contour(g, 0.5, [](const ContinuumMapRow& r) { return r.collision ? 1.0 : 0.0; });
    if (!edge.x.empty()) {
        edge.label = "contact | collision";
        edge.style = 6;
        edge.dashed = true;
        f.series.push_back(std::move(edge));
    }
    add_points(f, col);
    return f;
}

}  // namespace

std::vector<Figure> continuum_map_figures(const Case& c, const Collection& col) {
    // the map of the solver declared with one (SolverInfo::map), under its results folder
    std::filesystem::path file;
    if (c.schema)
        for (const SolverInfo* s : declared_solvers(*c.schema))
            if (s->map && file.empty()) file = col.root / s->name / kMapFile;
    if (file.empty()) return {};
    const auto rows = read_continuum_map(file);
    if (rows.empty()) return {};
    const Grid g = grid_of(rows);
    std::vector<Figure> figs;
    figs.push_back(field_figure(g, col, "continuum_map_mu", "μ (top wall)", {0.25, 0.30, 0.35, 0.40, 0.45},
                                [](const ContinuumMapRow& r) { return r.mu_top; }));
    figs.push_back(field_figure(g, col, "continuum_map_nu", "ν̄", {0.44, 0.46, 0.48, 0.50},
                                [](const ContinuumMapRow& r) { return r.nu; }));
    // mu(I): the continuum's line at each of the case's loads (the map's nearest), and the particle points
    Figure f;
    f.name = "continuum_map_mu_of_i";
    f.title = "μ against I: the continuum's lines and the particle points";
    f.caption = "The continuum's μ on the top wall against its mid-gap inertial number along the map's speeds at "
                "the case's loads (lines), the particle solvers' top-wall μ against their mid-gap I (points), and "
                "Jop, Forterre & Pouliquen's (2006) μ(I) for glass beads.";
    f.x.label = "I (mid-gap γ̇)";
    f.x.log = true;
    f.y.label = "μ = |τ| / σ_yy";
    f.y.lo = 0;
    std::vector<double> loads;
    for (const OperatingPoint* p : col.points) loads.push_back(p->normal_stress);
    std::sort(loads.begin(), loads.end());
    loads.erase(std::unique(loads.begin(), loads.end()), loads.end());
    int k = 0;
    for (double P : loads) {
        const auto j = static_cast<std::size_t>(
            std::min_element(g.loads.begin(), g.loads.end(),
                             [&](double a, double b) { return std::abs(std::log(a / P)) < std::abs(std::log(b / P)); }) -
            g.loads.begin());
        Series s;
        s.label = fmt::format("continuum, {:.0f} Pa", g.loads[j]);
        s.style = k++ % 6;
        for (std::size_t i = 0; i < g.speeds.size(); ++i)
            if (const auto* r = g.row(i, j); r && r->inertial > 0) {
                s.x.push_back(r->inertial);
                s.y.push_back(r->mu_top);
            }
        if (!s.x.empty()) f.series.push_back(std::move(s));
    }
    add_particle_points(f, col, ", top wall", [&](const Run& r, const OperatingPoint&) {
        std::optional<std::pair<double, double>> v;
        if (!r.steady()) return v;
        const auto I = run_inertia(c, r).mid_gap;
        const auto tau = r.scalar("shear_stress_top"), P = r.scalar("normal_stress_top");
        if (I && *I > 0 && tau && P && *P > 0) v = std::pair(*I, *tau / *P);
        return v;
    });
    Series jop;
    jop.label = "Jop et al. 2006";
    jop.style = 6;
    jop.dashed = true;
    for (int i = 0; i <= 40; ++i) {
        const double I = 0.01 * std::pow(50.0, i / 40.0);
        jop.x.push_back(I);
        jop.y.push_back(jop_mu(I));
    }
    f.series.push_back(std::move(jop));
    figs.push_back(std::move(f));
    return figs;
}

}  // namespace granlub::postproc
