#include "tables/run_tables.h"

#include <algorithm>

#include <fmt/format.h>

#include "formats/format.h"
#include "granlub/statistics/flow_regime.h"
#include "results/scope.h"
#include "tables/metric_lookup.h"

namespace granlub::postproc {

std::string state_name(ResultState s) {
    switch (s) {
        case ResultState::Complete: return "complete";
        case ResultState::Missing: return "missing";
        case ResultState::Stale: return "stale";
        case ResultState::Corrupt: return "corrupt";
    }
    return "";
}

Table status_table(const Collection& col) {
    Table t;
    t.header = {"solver"};
    for (const OperatingPoint* p : col.points) t.header.push_back(p->id);
    for (const auto& s : col.solvers) {
        std::vector<Cell> row{{s, ""}};
        for (const OperatingPoint* p : col.points) {
            const Run& r = col.run(s, p->id);
            row.push_back({r.state_name(), r.state_class()});
        }
        t.rows.push_back(std::move(row));
    }
    for (const auto& s : col.missing_solvers) {
        std::vector<Cell> row{{s, ""}};
        for (std::size_t i = 0; i < col.points.size(); ++i) row.push_back({"no results", "missing"});
        t.rows.push_back(std::move(row));
    }
    return t;
}

Table state_reasons(const Collection& col) {
    Table problems;
    problems.header = {"solver", "point", "state", "why"};
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (const std::string why = r.state_reason(); !why.empty())
                problems.rows.push_back({{r.solver, ""}, {p->id, ""}, {r.state_name(), r.state_class()}, {why, ""}});
        }
    return problems;
}

namespace {

// value ± standard error, and for a value checked at half the time step its time-step error
std::string value_cell(const Run& r, const std::string& q, double scale = 1.0, int digits = 4) {
    std::string v = value_pm(scaled(r.scalar(q), scale), scaled(r.scalar_stderr(q), scale), digits);
    if (const auto e = r.scalar_dt_error(q); e && !v.empty()) v += " [Δt " + num(*e * scale, 2) + "]";
    return v;
}

}  // namespace

Table key_numbers(const Case& c, const Collection& col) {
    // Under load control the gap and the solid fraction are results and P_top is held at the target: the
    // table shows them (a bottom-wall σ_yy alone would read as if the fill were fixed).
    const bool load = std::any_of(col.points.begin(), col.points.end(),
                                  [](const OperatingPoint* p) { return p->control == Control::Load; });
    Table t;
    t.header = {"solver", "point", "status", "ν̄/ν_max"};
    if (load) t.header.insert(t.header.end(), {"gap (mm)", "P_top / target"});
    t.header.insert(t.header.end(), {"σ_yy bottom (Pa)", "τ_xy bottom (Pa)", "τ_xy top (Pa)", "slip bottom / U",
                                     "slip top / U", "wall clock (s)"});
    for (const OperatingPoint* p : col.points) {
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (!r.usable()) continue;
            // Values of a result that is not steady are shown greyed, never as results.
            const std::string cls = r.steady() ? "" : r.state_class();
            std::vector<Cell> row{{s, ""}, {p->id, ""}, {r.state_name(), r.state_class()}};
            row.push_back({value_cell(r, "nu_bar_over_numax"), cls});
            if (load) {
                // A solver with a fixed gap (no "gap" output) solves for ν̄ at the case's gap.
                const bool moving = r.scalar("gap").has_value();
                row.push_back({moving ? value_cell(r, "gap", 1e3) : num(c.cell.gap * 1e3) + " (fixed)", cls});
                const double per = p->control == Control::Load && p->normal_stress > 0 ? 1 / p->normal_stress : 0;
                row.push_back({lattice_stresses(r) ? "— (lattice, fixed fill)"
                               : per > 0 ? value_pm(scaled(r.scalar("normal_stress_top"), per),
                                                  scaled(r.scalar_stderr("normal_stress_top"), per), 3)
                                       : "",
                               cls});
            }
            // The automaton's stresses are lattice analogues: marked in every cell, not only in a footnote.
            const char* lattice = lattice_stresses(r) ? " (lattice)" : "";
            for (const char* q : {"normal_stress_bottom", "shear_stress_bottom", "shear_stress_top"}) {
                const std::string v = value_cell(r, q);
                row.push_back({v.empty() ? v : v + lattice, cls});
            }
            for (const char* q : {"slip_bottom_over_U", "slip_top_over_U"}) row.push_back({value_cell(r, q), cls});
            const auto& run = r.summary->run;
            row.push_back({run.is_object() && run.contains("wall_clock_s") && run["wall_clock_s"].is_number()
                               ? num(run["wall_clock_s"].get<double>(), 3)
                               : "",
                           ""});
            t.rows.push_back(std::move(row));
        }
    }
    return t;
}

bool any_dt_checked(const Collection& col) {
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers)
            if (col.run(s, p->id).scalar_dt_error("shear_stress_bottom")) return true;
    return false;
}

int dense_step_halvings(const Collection& col) {
    int most = 0;
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (r.usable()) most = std::max(most, dense_step_halvings(r));
        }
    return most;
}

Table scope_table(const Case& c, const Collection& col) {
    Table t;
    t.header = {"solver", "grains and walls", "body forces", "wall stresses", "run length and start"};
    for (const auto& s : col.solvers) {
        if (!col.any_usable(s)) continue;
        const SolverScope sc = solver_scope(c, col, s);
        t.rows.push_back({{s, ""}, {sc.grains_walls, ""}, {sc.body_forces, ""}, {sc.stresses, ""},
                          {sc.run_length, ""}});
    }
    return t;
}

// The packing's order and contacts of the particle solvers (run.order, run.flow_regime): how far
// the grains crystallised, which the continuum does not describe.
Table order_table(const Collection& col) {
    Table t;
    t.header = {"solver", "point", "status", "q6", "Q6", "layer order Λ", "layering of ν(y)", "coordination Z", "regime"};
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (!r.usable() || !r.summary->run.is_object() || !r.summary->run.contains("order")) continue;
            const auto& run = r.summary->run;
            const auto& o = run["order"];
            const std::string cls = r.steady() ? "" : r.state_class();
            auto number = [](const nlohmann::json& j, const char* k, int digits = 3) {
                return j.contains(k) && j[k].is_number() ? num(j[k].get<double>(), digits) : std::string("—");
            };
            const nlohmann::json fr = run.value("flow_regime", nlohmann::json::object());
            t.rows.push_back({{s, ""},
                              {p->id, ""},
                              {r.state_name(), r.state_class()},
                              {value_pm(r.scalar("q6"), r.scalar_stderr("q6")), cls},
                              {number(o, "Q6"), cls},
                              {value_pm(r.scalar("layer_order"), r.scalar_stderr("layer_order")), cls},
                              {number(o, "layering"), cls},
                              {number(fr, "coordination_number"), cls},
                              {fr.contains("regime") ? read_flow_verdict(fr).label() : "—", cls}});
        }
    return t;
}

}  // namespace granlub::postproc
