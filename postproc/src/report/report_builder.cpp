#include "report/report_builder.h"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "formats/text.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "granlub/statistics/flow_regime.h"
#include "report/regime_section.h"
#include "report/ring_slice.h"
#include "results/scope.h"

namespace granlub::postproc {
namespace {

std::optional<double> scaled(const std::optional<double>& v, double factor) {
    return v ? std::optional(*v * factor) : std::nullopt;
}

const MetricRow* find_row(const std::vector<MetricRow>& rows, const std::string& kind, const std::string& point,
                          const std::string& quantity, const std::string& a, const std::string& b) {
    for (const auto& r : rows)
        if (r.kind == kind && r.point == point && r.quantity == quantity && r.solver_a == a && r.solver_b == b) return &r;
    return nullptr;
}

const char* short_label(const std::string& key) {
    for (const auto& q : kScalarQuantities)
        if (key == q.key) return q.short_label;
    for (const auto& q : kProfileQuantities)
        if (key == q.key) return q.short_label;
    return "";
}

void difference_tables(Report& rep, const Collection& col, const std::vector<MetricRow>& metrics) {
    bool first_fold = true;  // the first point unfolded, the others one click away
    for (const OperatingPoint* p : col.points) {
        const auto runs = col.usable(p->id);
        if (runs.size() < 2) continue;
        rep.fold(fmt::format("Point {}", p->id), first_fold);
        first_fold = false;
        Table prof;
        prof.header = {"solvers (a − b)"};
        for (const auto& q : kProfileQuantities) prof.header.push_back(std::string(q.short_label) + ": RMS (max at y/H; noise)");
        Table sc;
        sc.header = {"solvers (a − b)"};
        for (const auto& q : kScalarQuantities) sc.header.push_back(q.short_label);
        for (std::size_t i = 0; i < runs.size(); ++i) {
            for (std::size_t j = i + 1; j < runs.size(); ++j) {
                const auto& a = runs[i]->solver;
                const auto& b = runs[j]->solver;
                // A pair with a result that is not steady: no number, the reason instead.
                std::string pair = a + " − " + b, unsteady;
                for (const Run* r : {runs[i], runs[j]})
                    if (!r->steady()) {
                        pair += fmt::format(" ({}: {})", r->solver, r->state_name());
                        if (unsteady.empty()) unsteady = "—, " + r->state_name();
                    }
                std::vector<Cell> prow{{pair, ""}}, srow{{pair, ""}};
                for (const auto& q : kProfileQuantities) {
                    const MetricRow* r = find_row(metrics, "profile", p->id, q.key, a, b);
                    if (!r) {
                        prow.push_back({});
                        continue;
                    }
                    if (!unsteady.empty()) {
                        prow.push_back({unsteady, "transient"});
                        continue;
                    }
                    std::string t = fmt::format("{} (max {} at {}", num(*r->rms, 3), num(*r->max, 3), num(*r->y_at_max, 2));
                    t += r->noise_rms ? fmt::format("; noise {})", num(*r->noise_rms, 2)) : ")";
                    prow.push_back({t, r->noise_rms && *r->rms > 2 * *r->noise_rms ? "significant" : ""});
                }
                for (const auto& q : kScalarQuantities) {
                    const MetricRow* r = find_row(metrics, "scalar", p->id, q.key, a, b);
                    if (!r) {
                        srow.push_back({});
                        continue;
                    }
                    if (!unsteady.empty()) {
                        srow.push_back({unsteady, "transient"});
                        continue;
                    }
                    std::string t = value_pm(r->difference, r->combined_stderr, 3);
                    if (r->z) t += fmt::format(" (z = {:.1f})", *r->z);
                    srow.push_back({t, r->significant() ? "significant" : ""});
                }
                prof.rows.push_back(std::move(prow));
                sc.rows.push_back(std::move(srow));
            }
        }
        rep.text("Normalised profiles: RMS and max |a − b| over the y/H range both solvers cover; noise = RMS of the "
                 "combined standard error (bold: RMS > 2 × noise).");
        rep.table(std::move(prof));
        rep.text("Scalars: a − b ± combined standard error, stresses in Pa (bold: |z| > 2). A pair with a result "
                 "that is not steady is not compared (“—, transient”): a transient's difference is not a model "
                 "difference.");
        rep.table(std::move(sc));
        rep.end_fold();
    }
}

// "key" -> text of every leaf of a JSON object, nested keys joined by '.'.
void flatten(const nlohmann::json& j, const std::string& prefix, std::map<std::string, std::string>& out) {
    if (j.is_object()) {
        for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
        return;
    }
    out[prefix] = j.is_string() ? j.get<std::string>() : j.dump();
}

// Who computed what: one row per run (version, time, seed, hashes), then each solver's settings
// as a key-value table (folded), a value that differs between points given per point.
void provenance_section(Report& rep, const Collection& col) {
    Table prov;
    prov.header = {"solver", "point", "granlub", "written (UTC)", "seed", "case hash", "inputs hash"};
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (!r.usable()) continue;
            const Provenance& pv = r.summary->provenance;
            prov.rows.push_back({{s, ""},
                                 {p->id, ""},
                                 {pv.version, ""},
                                 {pv.utc_time, ""},
                                 {pv.seed ? std::to_string(*pv.seed) : "—", ""},
                                 {pv.case_hash, "code"},
                                 {pv.inputs_hash, "code"}});
        }
    rep.table(std::move(prov));
    rep.text("Each run's full record (inputs, settings, run diagnostics) is its summary.json: "
             "results/<solver>/<point>/summary.json.");
    for (const auto& s : col.solvers) {
        std::vector<std::pair<std::string, std::map<std::string, std::string>>> per_point;
        for (const OperatingPoint* p : col.points)
            if (const Run& r = col.run(s, p->id); r.usable()) {
                std::map<std::string, std::string> kv;
                flatten(r.summary->provenance.settings, "", kv);
                per_point.emplace_back(p->id, std::move(kv));
            }
        if (per_point.empty()) continue;
        std::set<std::string> keys;
        for (const auto& [id, kv] : per_point)
            for (const auto& [k, v] : kv) keys.insert(k);
        Table t;
        t.header = {"setting", "value"};
        for (const auto& k : keys) {
            auto value = [&](const std::map<std::string, std::string>& kv) {
                const auto it = kv.find(k);
                return it == kv.end() ? std::string("—") : it->second;
            };
            const std::string v0 = value(per_point.front().second);
            const bool same = std::all_of(per_point.begin(), per_point.end(),
                                          [&](const auto& pp) { return value(pp.second) == v0; });
            std::string v = v0;
            if (!same) {
                v.clear();
                for (const auto& [id, kv] : per_point) v += (v.empty() ? "" : "; ") + id + ": " + value(kv);
            }
            t.rows.push_back({{k, "code"}, {v, ""}});
        }
        rep.fold(fmt::format("Settings of {} ({} keys)", s, keys.size()));
        rep.table(std::move(t));
        rep.end_fold();
    }
}

}  // namespace

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

// value ± standard error, and for a value checked at half the time step its time-step error
std::string value_cell(const Run& r, const std::string& q, double scale = 1.0, int digits = 4) {
    std::string v = value_pm(scaled(r.scalar(q), scale), scaled(r.scalar_stderr(q), scale), digits);
    if (const auto e = r.scalar_dt_error(q); e && !v.empty()) v += " [Δt " + num(*e * scale, 2) + "]";
    return v;
}

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
                row.push_back({lattice_stresses(s) ? "— (lattice, fixed fill)"
                               : per > 0 ? value_pm(scaled(r.scalar("normal_stress_top"), per),
                                                  scaled(r.scalar_stderr("normal_stress_top"), per), 3)
                                       : "",
                               cls});
            }
            // The automaton's stresses are lattice analogues: marked in every cell, not only in a footnote.
            const char* lattice = lattice_stresses(s) ? " (lattice)" : "";
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

Report build_report(const Case& c, const Collection& col, const std::vector<MetricRow>& metrics,
                    const ReportFigures& figs, const std::vector<std::filesystem::path>& paraview_files,
                    const RingSliceSection* ring, const RegimeSection* regime) {
    Report rep;
    rep.title = fmt::format("Cross-code comparison: {}", c.title.empty() ? c.name : c.title);
    std::vector<std::string> with_results, without;
    for (const auto& s : col.solvers) (col.any_usable(s) ? with_results : without).push_back(s);
    for (const auto& s : col.missing_solvers) without.push_back(s);
    rep.text(fmt::format("Case {} ({}), {} operating point(s). Written {} by granlub {}.", c.name, c.file.string(),
                         col.points.size(), utc_now(), version()));
    rep.text(fmt::format("Solvers compared: {}.", with_results.empty() ? "none" : list_text(with_results)));
    if (!without.empty()) rep.text(fmt::format("Missing solvers (no usable results): {}.", list_text(without)));

    rep.heading("Results found");
    rep.table(status_table(col));
    rep.text("steady: a steady-state result, compared. transient: the run ended before a steady state was "
             "detected; dt-unconverged: halving the time step changed the answer; status unknown: the summary does "
             "not say (written before granlub recorded it). These three are shown greyed and hollow, never fitted, "
             "compared or bold. failed: the solver failed on the point (its message below); no answer: the solver's model "
             "cannot answer the point's question (why below), not a failure; missing: no result; "
             "stale: computed for other inputs (rerun the solver); corrupt: cannot be read or fails the checks.");
    Table problems;
    problems.header = {"solver", "point", "state", "why"};
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (const std::string why = r.state_reason(); !why.empty())
                problems.rows.push_back({{r.solver, ""}, {p->id, ""}, {r.state_name(), r.state_class()}, {why, ""}});
        }
    if (!problems.rows.empty()) rep.table(std::move(problems));
    rep.heading("Key numbers", 3);
    rep.table(key_numbers(c, col));
    if (any_dt_checked(col))
        rep.text(fmt::format("[Δt x]: the value comes from the run at half the time step, checked against a run at the "
                             "full step; x = |value(Δt) − value(Δt/2)| is its time-step error estimate (the methods "
                             "converge at first order). A point whose mean solid fraction moves by more than {} or "
                             "whose wall shear stress moves by more than {} % and {} standard errors is "
                             "dt-unconverged, and says so above.",
                             num(kDtMaxSolidFractionChange), num(100 * kDtMaxRelativeStressChange),
                             num(kDtMaxStressZ)));
    rep.heading("What each solver's numbers mean", 3);
    rep.table(scope_table(c, col));
    if (Table order = order_table(col); !order.rows.empty()) {
        rep.heading("How ordered the particle packings are", 3);
        rep.table(std::move(order));
        rep.text("q6: the mean local bond-orientational order of the grains (Steinhardt, Nelson & Ronchetti 1983; "
                 "neighbours within 1.2 (r_i + r_j), grains with at least 4): 0.575 for FCC, 0.485 for HCP, about 0.35–0.45 "
                 "for a dense disordered packing. Q6: the same over all bonds at once, near 0 without long-range "
                 "order. Layer order Λ: how sharply the grain centres stack in layers parallel to the walls (the peak of "
                 "|⟨exp(2πi y/λ)⟩| over λ = 0.6–1.0 d, grains a diameter clear of the walls): 1 for flat layers, "
                 "small without. Layering of ν(y): the relative spread std(ν)/mean(ν) of the solid-fraction profile "
                 "the report draws, half a diameter from the walls; it smears each grain over its diameter and also "
                 "shows the layering any flat wall imposes. The continuum describes a disordered "
                 "fluid: where the particle packings are ordered, its profiles are not expected to match.");
    }

    rep.heading("How to read this report");
    rep.text("Geometry: y/H = 0 is the moving wall (speed U), y/H = 1 the stationary wall. Profiles are "
             "dimensionless: u/U, ν/ν_max with each model's own ν_max taken from its summary (the automaton "
             "reports lattice occupancy with ν_max = 1), and T/U². Shaded bands and error bars are ±1 standard "
             "error of the statistical solvers (particle solvers, automaton); the continuum solver is deterministic "
             "and has none.");
    rep.text("Wall stresses are shown against U on log–log axes with the power law σ = c Uⁿ fitted per solver over "
             "its steady points (at least three) that differ only in speed: rapid (Bagnold) flow at fixed solid fraction gives n = 2, "
             "quasi-static flow n → 0. A difference between two solvers is significant when it exceeds twice the "
             "combined standard error (|z| > 2, shown bold); between deterministic results every difference is a "
             "model difference.");

    rep.heading("Profiles across the gap");
    for (const OperatingPoint* p : col.points) {
        const auto it = figs.profiles.find(p->id);
        if (it == figs.profiles.end()) continue;
        rep.fold(fmt::format("Point {}", p->id), it == figs.profiles.find(col.points.front()->id));
        rep.figures(it->second);
        rep.end_fold();
    }

    rep.heading("Wall stresses against speed");
    rep.figures(figs.stress);
    Table ex;
    ex.header = {"solver", "speed group"};
    for (const char* q : kStressOutputs) ex.header.push_back(std::string("n, ") + short_label(q));
    for (const auto& group : speed_groups(col.points)) {
        if (group.points.size() < static_cast<std::size_t>(kMinFitPoints)) continue;  // never fittable
        const std::string g = group.label.empty() ? "all" : group.label;
        for (const auto& s : col.solvers) {
            std::vector<Cell> row{{s, ""}, {g, ""}};
            bool any = false;
            for (const char* q : kStressOutputs) {
                const MetricRow* r = find_row(metrics, "exponent", g, q, s, "");
                any = any || r;
                if (!r)
                    row.push_back({});
                else if (!r->a)
                    row.push_back({r->note, "transient"});
                else
                    row.push_back({fmt::format("{} ({} steady speeds)", value_pm(r->a, r->a_stderr, 3), *r->fit_points), ""});
            }
            if (any) ex.rows.push_back(std::move(row));
        }
    }
    if (ex.rows.empty())
        rep.text(fmt::format("No stress–speed exponent: it needs at least {} steady results from the same solver at "
                             "as many speeds, with everything else equal.",
                             kMinFitPoints));
    else
        rep.table(std::move(ex));

    if (regime) add_regime_section(rep, *regime, figs.regime);

    rep.heading("Slip at the walls");  // against roughness or speed: the figure titles say which
    rep.figures(figs.slip);
    rep.heading("Mean solid fraction");
    rep.figures(figs.solid_fraction);

    if (ring && !ring->slice_case.empty()) {
        rep.heading("The whole ring against its slice");
        rep.text(fmt::format(
            "granlub dem ran this case as the whole ring ([cell] geometry = \"annulus\": turning floor and side "
            "walls, the curvature instead of a body force); [report] slice_case = \"{}\" ran the same points as a "
            "periodic slice with the centripetal body force standing in for the curvature. Both are written in the "
            "slice's frame (the ring by an equal-area map: z/W = −1/2 is the outer wall), so they compare quantity by "
            "quantity. A difference is significant when it exceeds twice the combined standard error (|z| > 2, "
            "shown bold). The standard errors are each run's own (block averages over one seed's steady window); runs "
            "with other seeds can scatter by more than that (they do in a dense, layered bed), so a bold z says that "
            "these two runs differ, and whether the geometries do needs more seeds (--seed). The side walls' shear "
            "stresses are the ring's torques on the cylinders over their areas and radii.",
            ring->slice_case));
        for (const auto& n : ring->notes) rep.text(n);
        if (!ring->table.rows.empty()) rep.table(ring->table);
        rep.figures(figs.ring_slice);
    }

    rep.heading("Differences between solvers");
    if (std::count_if(col.points.begin(), col.points.end(), [&](const OperatingPoint* p) { return col.usable(p->id).size() >= 2; }) == 0)
        rep.text("No point has results from two solvers: nothing to compare yet.");
    rep.text("Every number is also in metrics.csv (one row per pair, point and quantity).");
    difference_tables(rep, col, metrics);

    rep.heading("Provenance of every run");
    provenance_section(rep, col);

    rep.heading("Files");
    std::vector<std::pair<std::string, std::string>> files = {
        {"metrics.csv: every metric, one row per pair, point and quantity", "metrics.csv"},
        {"report.md: this report in Markdown", "report.md"},
        {"plots/: every figure as SVG, with its data (.dat) and gnuplot script (.gp)", "plots/"}};
    for (const auto& f : paraview_files)
        files.emplace_back(fmt::format("paraview/{}: profiles of every solver, one block per solver (ParaView)",
                                       f.filename().string()),
                           "paraview/" + f.filename().string());
    rep.links(std::move(files));

    rep.heading("The case");
    rep.pre(describe(c));
    return rep;
}

}  // namespace granlub::postproc
