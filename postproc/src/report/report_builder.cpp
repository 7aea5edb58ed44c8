#include "report/report_builder.h"

#include <algorithm>

#include <fmt/format.h>

#include "figures/registry.h"
#include "formats/format.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "report/regimes.h"
#include "report/summary.h"
#include "results/scope.h"
#include "report/ring_slice.h"
#include "report/shared_captions.h"
#include "report/twin_part.h"
#include "tables/differences.h"
#include "tables/exponents.h"
#include "tables/provenance.h"
#include "tables/run_tables.h"
#include "tables/wall_layer_table.h"
#include "tables/wall_table.h"

namespace granlub::postproc {
namespace {

// Title, case, solvers compared and missing.
void opening(Report& rep, const Case& c, const Collection& col) {
    rep.title = fmt::format("Cross-code comparison: {}", c.title.empty() ? c.name : c.title);
    std::vector<std::string> with_results, without;
    for (const auto& s : col.solvers) (col.any_usable(s) ? with_results : without).push_back(s);
    for (const auto& s : col.missing_solvers) without.push_back(s);
    const std::size_t n = col.points.size();
    rep.note(fmt::format("Case {}, {} operating point{}; solvers compared: {}{}.", c.name, n, n == 1 ? "" : "s",
                         with_results.empty() ? "none" : list_text(with_results),
                         without.empty() ? "" : fmt::format("; missing (no usable results): {}", list_text(without))));
}

// The answer first (summary.h): who agrees on what, the largest disagreement, what is not an answer.
void summary_part(Report& rep, const Case& c, const Collection& col) {
    rep.heading("Summary");
    const CaseSummary s = case_summary(col, c.grains.size_spread == 0);
    std::vector<std::string> with;
    for (const auto& solver : col.solvers)
        if (col.any_usable(solver)) with.push_back(solver);
    if (s.all_agree) {
        rep.text(fmt::format("All {} solvers ({}) agree within their combined errors on every quantity at every point.",
                             with.size(), list_text(with)));
        return;
    }
    rep.table(s.table);  // how to read its cells: the legend's "Tables" paragraph
    for (const auto& t : s.sentences) rep.note(t);
}

// Which standard error the statistics use (z, "a = b", bold): a result pooled over seeds has the
// seeds' standard error; one run has its own block error, and how far that one can be trusted is
// the measured factor by which other seeds scatter more (the sources named in the text).
std::string error_used(const Collection& col) {
    std::size_t pooled = 0, single = 0;
    for (const auto& [key, r] : col.runs)
        if (r.usable() && r.kind() == SolverKind::Particles) ++(r.seeds_pooled() > 1 ? pooled : single);
    const std::string pooled_text =
        "Where a particle result pools several seeds ([particles] seeds or --seeds; its summary's run.seeds), its ± "
        "and every z and a = b with it use the seeds' standard error, the scatter of the seeds' own results over √n "
        "(the runs' block errors combined are kept beside it, block_stderr in summary.json); a point is steady only "
        "if each of its seeds is, and incomplete while one is missing. ";
    const std::string single_text =
        std::string(pooled > 0 ? "The other statistical results' standard errors are" : "The standard errors are") +
        " each run's own (block averages over one seed's steady window). Runs with other seeds scatter by more, "
        "because each seed packs its own way: measured, in ν̄ 3.5 times one run's block error in LIGGGHTS and 5.1 "
        "times in YADE on the loose rough cell (three seeds; cases/sawyer2001_rough_hertz/README.md, “The error "
        "bars against the seeds”), in the wall shear stresses a median 2.1 and up to 6.5 times on the dense, "
        "layered default cell (three or four seeds at three speeds and four steps; docs/measurements/dt-error.md, "
        "“The main job's slice at its three speeds”; six seeds at 2.0 m/s there: 4–5 times in ν̄ and τ, 9 in the "
        "slips, docs/measurements/engines.md, “Six seeds pooled”). So such a z can be 2–9 times too large: a bold "
        "z says that these two runs differ; whether the solvers do needs several seeds ([particles] seeds or "
        "--seeds), pooled. ";
    if (pooled == 0) return single_text;
    return single == 0 ? pooled_text : pooled_text + single_text;
}

// The one legend: what every figure's markers, lines and bands mean, the statuses and the table
// cells; the captions say only what is particular to their figure.
void how_to_read(Report& rep, const Collection& col) {
    rep.heading("How to read this report");
    rep.text("Figures: one colour, dash and marker per solver, the same in every figure (Okabe–Ito colours, "
             "distinguishable in greyscale). y/H = 0 is the moving wall (speed U), y/H = 1 the stationary wall; "
             "profiles are dimensionless: u/U, ν/ν_max with each model's own ν_max from its summary (the automaton's "
             "lattice occupancy has ν_max = 1), T/U². Shaded bands and error bars are ±1 standard error of the "
             "statistical solvers (particle solvers, automaton); the continuum is deterministic and has none. "
             "Hollow faded markers and dotted lines are results that are NOT steady (the legend entry says which: "
             "“dem: transient”, “dem: dt-unconverged”); they are shown for information only and left out of every fit "
             "and comparison. Under each figure: its SVG, PDF, data and gnuplot source.");
    rep.text("Statuses: steady: a steady-state result, compared. transient: the run ended before a steady state "
             "was detected. dt-unconverged: halving the time step changed the answer. incomplete: a point pooled over seeds that some of "
             "its seeds are still missing from. status unknown: the summary "
             "does not say (written before granlub recorded it). These are greyed and italic in tables and "
             "hollow in figures, never fitted, compared or bold. failed: the solver failed on the point. no answer: "
             "the solver's model cannot answer the point's question (not a failure). missing: no result. stale: "
             "computed for other inputs (rerun the solver). corrupt: cannot be read or fails the checks.");
    rep.text("Tables: in the summary, a = b: steady results agreeing within their combined standard errors "
             "(|z| ≤ 2); the others: their difference from the first. Bold = a significant difference, more than "
             "twice the combined standard error (|z| > 2). " + error_used(col) +
             "Between deterministic results every difference is a model difference and has no z. [Δt x]: the "
             "value's time-step error estimate. “(lattice)”, “lattice analogue”: " + std::string(kLatticeStressNote) +
             ". Wall stresses are fitted against U as σ = c Uⁿ over a solver's steady points (at "
             "least three) that differ only in speed: rapid (Bagnold) flow at fixed solid fraction gives n = 2, "
             "quasi-static flow n → 0.");
}

// The Delta-t note's sentence on dense points ([dem] dense_inertial_number, quarter_step_inertial_number):
// their Delta-t is itself half or a quarter of the case's step. halvings: the most any run had (0: none).
std::string dense_step_note(int halvings) {
    if (halvings == 0) return "";
    std::string s = " For a dense point ([dem] dense_inertial_number) Δt is itself half the case's step: its value "
                    "comes from a run at a quarter of the case's step, checked against half of it";
    if (halvings >= 2)
        s += "; below [dem] quarter_step_inertial_number Δt is a quarter of the case's step, the value comes from an "
             "eighth, checked against a quarter";
    return s + " (named in the same table).";
}

// What was found: the states, their reasons, the key numbers, what each solver's numbers mean and
// how ordered the particle packings are.
void results_found(Report& rep, const Case& c, const Collection& col) {
    rep.heading("Results found");
    rep.table(status_table(col));
    if (Table reasons = state_reasons(col); !reasons.rows.empty()) rep.table(std::move(reasons));
    rep.heading("Key numbers", 3);
    rep.table(key_numbers(c, col));
    if (any_dt_checked(col))
        rep.text(fmt::format("[Δt x]: the value comes from the run at half the time step, checked against a run at the "
                             "full step; x = |value(Δt) − value(Δt/2)| is its time-step error estimate (the methods "
                             "converge at first order). Where that check failed and the case allows a second halving "
                             "([dem] refine_halvings = 2), the value comes from a run at a quarter of the step, "
                             "checked against the half step, and x = |value(Δt/2) − value(Δt/4)|; the solvers' "
                             "table below names those points. A point whose mean solid fraction moves by more than {} "
                             "or whose wall shear stress moves by more than {} % and {} standard errors on its last "
                             "halving is dt-unconverged, and says so above.{}",
                             num(kDtMaxSolidFractionChange), num(100 * kDtMaxRelativeStressChange),
                             num(kDtMaxStressZ),
                             dense_step_note(dense_step_halvings(col))));
    rep.fold("What each solver's numbers mean: body forces, wall stresses, contacts, run length");
    rep.table(scope_table(c, col));
    rep.end_fold();
    if (Table order = order_table(col); !order.rows.empty()) {
        rep.fold("How ordered the particle packings are: q6, Q6, layer order, coordination, regime");
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
        rep.end_fold();
    }
}


// The figures the registry puts under `heading` (figures/registry.h): per point in folds (the
// profiles of the first point unfolded), or once for the case.
void figure_part(Report& rep, const Collection& col, const ReportFigures& figs, const std::string& heading) {
    // A heading without a figure (no row drew one: no particle run with a cross-section) is left out.
    if (std::none_of(figs.groups.begin(), figs.groups.end(), [&](const FigureGroup& g) { return g.heading == heading; }))
        return;
    rep.heading(heading);
    for (const OperatingPoint* p : col.points) {
        const auto refs = figs.of(heading, p->id);
        if (refs.empty()) continue;
        rep.fold(fmt::format("Point {}", p->id), p == col.points.front() && heading == kProfilesHeading);
        rep.figures(refs);
        rep.end_fold();
    }
    auto refs = figs.of(heading);
    // Under load control the normal stresses follow the load (the control variable, never fitted):
    // their figures fold, the shear stresses stay open.
    const bool load = std::any_of(col.points.begin(), col.points.end(),
                                  [](const OperatingPoint* p) { return p->control == Control::Load; });
    std::vector<FigureRef> normal;
    if (heading == kStressHeading && load)
        for (auto it = refs.begin(); it != refs.end();) {
            if (it->name.starts_with("stress_normal_stress")) {
                normal.push_back(std::move(*it));
                it = refs.erase(it);
            } else {
                ++it;
            }
        }
    if (!refs.empty()) rep.figures(std::move(refs));
    if (!normal.empty()) {
        rep.fold("Normal stresses: under load control they follow the load, not fitted");
        rep.figures(std::move(normal));
        rep.end_fold();
    }
}

// A table under its own heading with its note; nothing when it has no rows.
void titled_table(Report& rep, const char* heading, Table t, const char* note) {
    if (t.rows.empty()) return;
    rep.heading(heading, 3);
    rep.table(std::move(t));
    rep.note(note);
}

// Every wall's shear stress where some solver had side walls (tables/wall_table.h).
void wall_part(Report& rep, const Case& c, const Collection& col) {
    titled_table(rep, "Every wall's shear stress", wall_stress_table(c, col),
                 "The floor and both side walls move at U, the top is still. The side walls' drag over the top's: the "
                 "continuum's own (its walls' forces); a particle run's 2 τ_side H / (τ_top W), over the box's side and "
                 "top areas ([cell] gap, width); in a steady bed the forces balance and both equal 1 − τ_floor/τ_top. "
                 "Inner and outer side walls differ by the centripetal force where a solver has it (the body forces in "
                 "“What each solver's numbers mean”). “—”: the solver has no such wall, and why.");
}

// Under the slip figures: the grains beside each wall, from the particle runs' final states (run.wall_layer).
void wall_layer_part(Report& rep, const Collection& col) {
    titled_table(rep, "The grains beside each wall: slip, and the part their spin carries back", wall_layer_table(col),
                 "From each particle run's final state (one snapshot; the steady snapshots hold no spins), over the "
                 "grains touching the wall: their slip against it (U − v_x at the floor, v_x at the top, over U), the "
                 "part of it their spin carries back (a ω_z), and what is left at their contact points. Rolling share = "
                 "1 − contact-point slip / slip: 1 for grains rolling without sliding, 0 for grains sliding without "
                 "spin; contacts rolling: the share sliding slower than 0.02 U. A wall condition that sees the grains' "
                 "slip alone grips too hard where they roll (the continuum's flat walls take the spin in: [continuum] "
                 "flat_wall_spin). Errors over the contacts, taken as independent: lower bounds.");
}

void exponents(Report& rep, const Collection& col, const std::vector<MetricRow>& metrics) {
    Table ex = exponent_table(col, metrics);
    if (ex.rows.empty())
        rep.text(fmt::format("No stress–speed exponent: it needs at least {} steady results from the same solver at "
                             "as many speeds, with everything else equal.",
                             kMinFitPoints));
    else
        rep.table(std::move(ex));
}

void ring_part(Report& rep, const RingSlicePart& ring_s, const ReportFigures& figs) {
    const RingSlicePart* ring = &ring_s;
    if (!ring->slice_case.empty()) {
        rep.heading("The whole ring against its slice");
        rep.text(fmt::format(
            "granlub {} ran this case as the whole ring ([cell] geometry = \"annulus\": turning floor and side "
            "walls, the curvature instead of a body force); [report] slice_case = \"{}\" ran the same points as a "
            "periodic slice with the centripetal body force standing in for the curvature. Both are written in the "
            "slice's frame (the ring by an equal-area map: z/W = −1/2 is the outer wall), so they compare quantity by "
            "quantity. Bold and z as in every table (“How to read this report”): a bold z says that these "
            "two runs differ; whether the geometries do needs more seeds (--seed). The side walls' shear "
            "stresses are the ring's torques on the cylinders over their areas and radii.",
            ring->solver, ring->slice_case));
        for (const auto& n : ring->notes) rep.text(n);
        if (!ring->table.rows.empty()) rep.table(ring->table);
        rep.figures(figs.ring_slice);
    }
}

void differences(Report& rep, const Collection& col, const std::vector<MetricRow>& metrics) {
    rep.heading("Differences between solvers");
    if (std::count_if(col.points.begin(), col.points.end(), [&](const OperatingPoint* p) { return col.usable(p->id).size() >= 2; }) == 0)
        rep.text("No point has results from two solvers: nothing to compare yet.");
    rep.text("Every number is also in metrics.csv (one row per pair, point and quantity).");
    difference_tables(rep, col, metrics);
}

void files(Report& rep, const std::vector<std::filesystem::path>& paraview_files, bool pdf) {
    rep.heading("Files");
    std::vector<std::pair<std::string, std::string>> files = {
        {"metrics.csv: every metric, one row per pair, point and quantity", "metrics.csv"},
        {"report.md: this report in Markdown", "report.md"},
        {pdf ? "plots/: every figure as SVG and PDF, with its data (.dat; the cross-sections .csv) and gnuplot script (.gp)"
             : "plots/: every figure as SVG, with its data (.dat; the cross-sections .csv) and gnuplot script (.gp); no "
               "PDF: rsvg-convert (librsvg2-bin) was not found",
         "plots/"}};
    for (const auto& f : paraview_files)
        files.emplace_back(fmt::format("paraview/{}: profiles of every solver, one block per solver (ParaView)",
                                       f.filename().string()),
                           "paraview/" + f.filename().string());
    rep.links(std::move(files));
}

}  // namespace

std::vector<FigureRef> ReportFigures::of(const std::string& heading, const std::string& point) const {
    std::vector<FigureRef> refs;
    for (const auto& g : groups)
        if (g.heading == heading && g.point == point) refs.insert(refs.end(), g.refs.begin(), g.refs.end());
    return refs;
}

Report build_report(const Case& c, const Collection& col, const std::vector<MetricRow>& metrics,
                    const ReportFigures& figs, const std::vector<std::filesystem::path>& paraview_files,
                    const RingSlicePart* ring, const RegimePart* regime) {
    Report rep;
    opening(rep, c, col);
    summary_part(rep, c, col);
    how_to_read(rep, col);
    results_found(rep, c, col);
    // The registry's headings in its order; the stress exponents after the stress figures, the
    // regimes after them, the ring after the figures.
    for (const auto& heading : figure_headings()) {
        figure_part(rep, col, figs, heading);
        if (heading == kSlipHeading) wall_layer_part(rep, col);
        if (heading == kStressHeading) {
            exponents(rep, col, metrics);
            wall_part(rep, c, col);
            if (regime) add_regime_part(rep, *regime, figs.regime);
        }
    }
    if (ring) ring_part(rep, *ring, figs);
    add_twin_part(rep, c, col);  // a periodic-width case with continuum and DEM results only
    differences(rep, col, metrics);
    rep.heading("Provenance of every run");
    rep.text(fmt::format("This report: written {} by granlub {}.", utc_now(), version()));
    rep.fold("Versions, seeds and hashes of every run; each solver's settings");
    provenance_part(rep, col);
    rep.end_fold();
    files(rep, paraview_files, figs.pdf);
    rep.heading("The case");
    rep.fold("The case as granlub check resolves it (defaults marked)");
    rep.pre(describe(c));
    rep.end_fold();
    say_shared_captions_once(rep);
    return rep;
}

}  // namespace granlub::postproc
