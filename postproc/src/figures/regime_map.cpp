#include "figures/regime_map.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "figures/figures.h"
#include "figures/mu_of_i.h"
#include "figures/state_series.h"
#include "formats/format.h"
#include "granlub/statistics/flow_regime.h"
#include "granlub/statistics/point_verdict.h"
#include "results/scope.h"
#include "results/verdict_engines.h"

namespace granlub::postproc {
namespace {

std::vector<const OperatingPoint*> grid_points(const SpeedLoadGrid& grid) {
    std::vector<const OperatingPoint*> points;
    for (const auto& g : grid.per_load) points.insert(points.end(), g.points.begin(), g.points.end());
    return points;
}

bool has_verdict(const Run& r) {
    return r.usable() && r.summary->run.is_object() && r.summary->run.contains("flow_regime");
}

// A run's own regime label and what decided it: a particle engine's contact record (run.flow_regime,
// core flow_regime.h) or the continuum's I/nu against its own threshold (run.lubrication: verdict,
// criterion, inertial_number_over_solid_fraction; written by the continuum's case_setup.cpp). Read
// from the summary, whichever solver wrote it; "—" for a run with neither (the automaton).
struct OwnRegime {
    std::string label, decided_by;
};
OwnRegime own_regime(const Run& r) {
    const nlohmann::json& run = r.summary->run;
    if (has_verdict(r)) {
        const FlowVerdict v = read_flow_verdict(run["flow_regime"]);
        return {v.label(), v.criterion};
    }
    if (!run.is_object() || !run.contains("lubrication") || !run["lubrication"].is_object())
        return {"—", "no regime label of its own (its summary has neither run.flow_regime nor run.lubrication)"};
    const nlohmann::json& l = run["lubrication"];
    const auto text = [&](const char* key) { return l.contains(key) && l[key].is_string() ? l[key].get<std::string>() : ""; };
    const nlohmann::json& im = l.contains("inertial_number_over_solid_fraction") ? l["inertial_number_over_solid_fraction"]
                                                                                 : nlohmann::json();
    return {text("verdict").empty() ? "—" : text("verdict"),
            fmt::format("{}'s own criterion{}: {}", r.solver, im.is_number() ? ", I/ν = " + num(im.get<double>()) : "",
                        text("criterion").empty() ? "not recorded" : text("criterion"))};
}

// The experiment's critical shear rate as a vertical black dotted line at U = 100 1/s x H over [lo, hi].
void add_critical_rate(const Case& c, Figure& f, double lo, double hi) {
    Series line;
    line.label = fmt::format("U/H = {} 1/s (Sawyer & Tichy 2001)", num(kSawyerCriticalShearRate));
    line.style = 6;  // black
    line.dashed = true;
    const double u = kSawyerCriticalShearRate * c.cell.gap;
    line.x = {u, u};
    line.y = {lo, hi};
    f.series.push_back(std::move(line));
    f.caption += fmt::format(" Black dashed vertical: U = {} 1/s × H = {} m/s (H = {} mm, the case's gap), the shear "
                             "rate above which Sawyer & Tichy 2001 saw the upper surface lift off.",
                             num(kSawyerCriticalShearRate), num(u), num(c.cell.gap * 1e3));
}

// The y range of the figure's data (for the vertical line), padded.
std::pair<double, double> y_span(const Figure& f, bool log) {
    double lo = 0, hi = 0;
    bool any = false;
    for (const Series& s : f.series)
        for (double y : s.y) {
            if (log && !(y > 0)) continue;
            lo = any ? std::min(lo, y) : y, hi = any ? std::max(hi, y) : y, any = true;
        }
    if (!any) return {log ? 1.0 : 0.0, log ? 10.0 : 1.0};
    return log ? std::pair(lo / 1.3, hi * 1.3) : std::pair(lo - 0.05 * (hi - lo + 1e-12), hi + 0.05 * (hi - lo + 1e-12));
}

}  // namespace

std::vector<Figure> regime_map_figures(const Case& c, const Collection& col, const SpeedLoadGrid& grid) {
    const auto points = grid_points(grid);
    std::vector<Figure> figs;
    for (const auto& s : col.solvers) {
        if (std::none_of(points.begin(), points.end(), [&](const OperatingPoint* p) { return has_verdict(col.run(s, p->id)); }))
            continue;
        Figure f;
        f.name = "regime_map_" + name_slug(s);
        f.title = fmt::format("Regime map over speed and load: {}", s);
        f.caption = fmt::format(
            "{}'s verdict at each point (core flow_regime.h): contact lubrication where the contacts endure (Z ≥ {} "
            "and ≥ {:.0f} % of contacts survive a shear strain of {}), collision lubrication where they do not "
            "(Sawyer & Tichy 2001's two regimes); at the transition where Z lies within {} block errors of {} or "
            "within its time-step error (the Δt check's run at twice the step on the other side, or Z moved by more "
            "than it lies from {}); undetermined where what decides was not measured. The criterion that decided each "
            "point is in the table below. Hollow purple diamonds: points of the sweep with no usable result.",
            s, num(kEnduringMinCoordination), 100 * kEnduringMinPersistence, num(kPersistenceStrain),
            num(kTransitionSigmas), num(kEnduringMinCoordination), num(kEnduringMinCoordination));
        f.x.label = "wall speed U (m/s)";
        f.y.label = "load P (Pa)";
        f.y.log = true;
        // Each marker is this engine's own point verdict (core point_verdict.h: its Z, block error and
        // Δt check). Contact: blue circles, collision: vermillion squares, at the transition: orange
        // circles, undetermined: black triangles (formats/figure_style.cpp).
        std::map<std::string, PointRegime> verdict;  // per point id, once
        for (const OperatingPoint* p : points)
            if (const Run& r = col.run(s, p->id); has_verdict(r))
                verdict[p->id] = point_verdict({engine_regime(s, r.summary->run)}).regime;
        const std::pair<PointRegime, int> kinds[] = {{PointRegime::Contact, 0},
                                                     {PointRegime::Collision, 1},
                                                     {PointRegime::Transition, 4},
                                                     {PointRegime::Undetermined, 6}};
        for (const auto& [kind, style] : kinds) {
            auto series = series_by_state(col, s, points, to_string(kind), style,
                                          [&](const Run&, const OperatingPoint& p) {
                                              const auto v = verdict.find(p.id);
                                              if (v == verdict.end() || v->second != kind)
                                                  return std::optional<std::pair<double, double>>();
                                              return std::optional(std::pair(p.speed, p.normal_stress));
                                          });
            for (auto& ser : series) f.series.push_back(std::move(ser));
        }
        Series holes;
        holes.label = "no usable result";
        holes.style = 3;  // hollow reddish-purple diamonds
        holes.mark = Mark::Points;
        holes.open = true;
        for (const OperatingPoint* p : points)
            if (!col.run(s, p->id).usable()) holes.x.push_back(p->speed), holes.y.push_back(p->normal_stress);
        if (!holes.x.empty()) f.series.push_back(std::move(holes));
        const auto [lo, hi] = y_span(f, true);
        add_critical_rate(c, f, lo, hi);
        figs.push_back(std::move(f));
    }
    return figs;
}

// One figure per solver and quantity, the loads told apart by colour, dash and marker: with every
// solver in one figure the loads could only be told apart by open markers, which the report keeps
// for results that are not steady. A lattice solver (the automaton) runs a fixed fill at every load
// and cannot lift off; its occupancy is not a solid fraction, so it is named, not drawn.
std::vector<Figure> liftoff_figures(const Case& c, const Collection& col, const SpeedLoadGrid& grid) {
    std::vector<std::string> lattice;
    for (const auto& s : col.solvers)
        if (lattice_stresses(col, s) && col.any_usable(s)) lattice.push_back(s);
    std::vector<Figure> figs;
    for (const bool gap : {true, false})
        for (const auto& s : col.solvers) {
            if (lattice_stresses(col, s)) continue;
            Figure f;
            f.name = fmt::format("regime_liftoff_{}_{}", gap ? "gap" : "nu", name_slug(s));
            f.title = fmt::format("Lift-off: {} against speed, per load: {}", gap ? "the gap" : "mean solid fraction", s);
            f.caption = gap ? fmt::format("{}'s mean gap between the walls (the loaded plate's mean height) against U at "
                                          "each load (colour, dash and marker per load). Sky blue: the case's gap "
                                          "H = {} mm.",
                                          s, num(c.cell.gap * 1e3))
                            : fmt::format("{}'s mean solid fraction ν̄ over the gap against U at each load (colour, "
                                          "dash and marker per load): a bed that lifts off dilates.",
                                          s);
            if (!lattice.empty())
                f.caption += fmt::format(" Not drawn: {} (a lattice of fixed fill at every load: it cannot lift off, "
                                         "and its occupancy is not a solid fraction).",
                                         fmt::join(lattice, ", "));
            f.x.label = "wall speed U (m/s)";
            f.y.label = gap ? "gap (mm)" : "ν̄ (mean solid fraction)";
            for (std::size_t g = 0; g < grid.per_load.size(); ++g) {
                const int style = load_style(g);
                auto series = series_by_state(col, s, grid.per_load[g].points, grid.per_load[g].label, style,
                                              [&](const Run& r, const OperatingPoint& p) {
                                                  const auto v = r.scalar(gap ? "gap" : "mean_solid_fraction");
                                                  if (!v) return std::optional<std::pair<double, double>>();
                                                  return std::optional(std::pair(p.speed, gap ? *v * 1e3 : *v));
                                              });
                for (auto& ser : series) {
                    if (!ser.unsteady && ser.x.size() > 1) {  // a line through the steady points
                        Series line;
                        line.style = ser.style;
                        line.x = ser.x;
                        line.y = ser.y;
                        f.series.push_back(std::move(line));
                    }
                    f.series.push_back(std::move(ser));
                }
            }
            if (f.series.empty()) continue;  // this solver does not report the quantity (e.g. a fixed gap)
            if (gap) {
                Series h;
                h.label = "case gap H";
                h.style = 5;  // sky blue, its own dash: not the black dashed critical rate
                h.x = {grid.speeds.front(), grid.speeds.back()};
                h.y = {c.cell.gap * 1e3, c.cell.gap * 1e3};
                f.series.push_back(std::move(h));
            }
            const auto [lo, hi] = y_span(f, false);
            add_critical_rate(c, f, lo, hi);
            figs.push_back(std::move(f));
        }
    return figs;
}

Table regime_table(const Case& c, const Collection& col, const SpeedLoadGrid& grid) {
    Table t;
    t.header = {"solver", "point", "U (m/s)", "P (Pa)", "status", "verdict", "decided by", "I (U/H)", "I (mid-gap)",
                "gap (mm)"};
    for (const auto& g : grid.per_load)
        for (const OperatingPoint* p : g.points) {
            bool any = false;
            for (const auto& s : col.solvers) {
                const Run& r = col.run(s, p->id);
                if (!r.usable()) continue;
                any = any || has_verdict(r);
                const std::string cls = r.steady() ? "" : r.state_class();
                const OwnRegime own = own_regime(r);
                const RunInertia I = run_inertia(c, r);
                const auto gap = r.scalar("gap");
                t.rows.push_back({{s, ""},
                                  {p->id, ""},
                                  {num(p->speed), ""},
                                  {num(p->normal_stress), ""},
                                  {r.state_name(), r.state_class()},
                                  {own.label, cls},
                                  {own.decided_by, cls},
                                  {I.nominal ? num(*I.nominal, 3) : "—", cls},
                                  {I.mid_gap ? num(*I.mid_gap, 3) : "—", cls},
                                  {gap ? num(*gap * 1e3, 3) : "—", cls}});
            }
            if (!any) continue;
            // the point's one verdict (core point_verdict.h) from its steady runs only, as the summary's
            const std::vector<EngineRegime> engines = verdict_engines(col, p->id);
            if (engines.empty()) {
                t.rows.push_back({{"point", ""}, {p->id, ""}, {num(p->speed), ""}, {num(p->normal_stress), ""},
                                  {"", ""}, {"no verdict", "transient"},
                                  {"no run here is a result (the status column: a transient's contacts are still "
                                   "on their way, a dt-unconverged run's move with the step)",
                                   "transient"},
                                  {"", ""}, {"", ""}, {"", ""}});
                continue;
            }
            const PointVerdict v = point_verdict(engines);
            t.rows.push_back({{"point", ""}, {p->id, ""}, {num(p->speed), ""}, {num(p->normal_stress), ""}, {"", ""},
                              {to_string(v.regime), ""}, {v.criterion, ""}, {"", ""}, {"", ""}, {"", ""}});
        }
    return t;
}

}  // namespace granlub::postproc
