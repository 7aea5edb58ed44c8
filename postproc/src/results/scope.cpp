#include "results/scope.h"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "formats/format.h"
#include "granlub/particles/contact_laws.h"

namespace granlub::postproc {
namespace {

std::optional<double> run_number(const Run& r, const char* key) {
    const auto& run = r.summary->run;
    if (run.is_object() && run.contains(key) && run[key].is_number()) return run[key].get<double>();
    return std::nullopt;
}


// How the run decided its steady window (run.steady_state of granlub/statistics/steady_state.h), or "".
std::string steady_rule(const Run& r) {
    const auto& run = r.summary->run;
    if (!run.is_object() || !run.contains("steady_state") || !run["steady_state"].is_object()) return "";
    const auto& s = run["steady_state"];
    const auto allowed = s.value("allowed_relative_drift", nlohmann::json::object());
    auto pct = [&](const char* k) {
        return allowed.contains(k) && allowed[k].is_number() ? num(100.0 * allowed[k].get<double>(), 2) + " %" : std::string("?");
    };
    std::string rule = fmt::format("it starts where MSER-5 ends the initial transient and moves on until the two halves "
                                   "of the window agree within {} combined standard errors or within {} (wall "
                                   "stresses) and {} (gap)",
                                   num(s.value("sigmas", 3.0), 2), pct("wall_stress"), pct("gap"));
    if (s.contains("resolution") && s["resolution"].is_number())
        rule += fmt::format("; a window too noisy to see a {} drift is not called steady",
                            num(100.0 * s["resolution"].get<double>(), 2) + " %");
    return rule;
}

// "0.1 s" or "0.0015–0.1 s" over the usable runs; counts (digits 0) as whole numbers.
std::string range_text(const std::vector<double>& v, const char* unit, int digits = 3) {
    if (v.empty()) return "";
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    auto f = [&](double x) { return digits == 0 ? fmt::format("{:.0f}", x) : num(x, digits); };
    return f(*lo) == f(*hi) ? fmt::format("{} {}", f(*lo), unit) : fmt::format("{}–{} {}", f(*lo), f(*hi), unit);
}

// One wall as the solver had it: a particle solver's plane or bumps (run.walls), else R.
std::string wall_text(const Run& r, bool bottom, bool particles) {
    const char* side = bottom ? "bottom" : "top";
    const Wall& w = bottom ? r.point->bottom : r.point->top;
    const auto& run = r.summary->run;
    if (!particles || !run.is_object() || !run.contains("walls") || !run["walls"].contains(side))
        return fmt::format("{}: R = {}", side, num(w.roughness));
    const auto& j = run["walls"][side];
    if (j.value("surface", std::string()) != "bumps")
        return fmt::format("{}: a frictional plane (μ_w = {}; R does not apply)", side, num(w.friction));
    return fmt::format("{}: bumps of {} mm, {} mm apart (R = {} built, θ = {}°)", side,
                       num(1e3 * j.value("bump_diameter_m", 0.0), 3), num(1e3 * j.value("bump_spacing_m", 0.0), 3),
                       num(j.value("roughness_built", 0.0), 3), num(j.value("bump_angle_deg", 0.0), 3));
}

// The grains' sizes and both walls; the continuum and the automaton use the mean diameter.
std::string grains_and_walls(const Case& c, const Run& first, bool particles) {
    const GrainSizes g = c.grains.sizes();
    std::string grains = !particles ? fmt::format("d = {} mm (the mean diameter)", num(1e3 * g.mean, 3))
                         : g.equal() ? fmt::format("equal grains, d = {} mm", num(1e3 * g.mean, 3))
                                     : fmt::format("d = {} mm ± {} % (uniform, {}–{} mm)", num(1e3 * g.mean, 3),
                                                   num(100 * g.spread, 3), num(1e3 * g.min(), 3), num(1e3 * g.max(), 3));
    return grains + "; " + wall_text(first, true, particles) + "; " + wall_text(first, false, particles);
}

// Which contact law made a particle solver's numbers (run.model, run.contact_solve), or "". Under
// enduring contacts the rigid impulse operator, single pass (Sawyer & Tichy 2001) or solved to
// convergence (Moreau 1988, Jean 1999), carries a first-order time-step error. Measured on the
// default case's loaded slice, three seeds at four steps (docs/measurements/liggghts.md, "The main
// job's slice at its three speeds" and "The gap to Hertz on the slice"): the full step 2-8 % high in
// the wall shear stresses, the half step within 0.2-3.5 % of the Delta-t -> 0 limit, and that limit
// 3-10 % above Hertz at 1 GPa; at 1.4, 2 and 2.8 m/s Hertz at 4 and 16 GPa extrapolates to it within 1 %,
// so a difference of that size to soft grains is their compliance, not the step.
std::string contact_text(const Run& r) {
    const std::string model = run_text(r, "model");
    const ContactLaw* law = find_contact_law(model);
    if (!law) return "";
    if (law->contacts) return law->contacts;  // the table's line (granlub/particles/contact_laws.h)
    if (!law->impulse_options) return "";  // the impulse operator's words follow
    const std::string dt_error =
        " (under enduring contacts its wall stresses carry a first-order time-step error, which the Δt check "
        "measures; on the default case's loaded slice the full step is 2–8 % high and the half step within "
        "0.2–3.5 % of the Δt → 0 limit. That limit lies 3–10 % above Hertz–Mindlin at 1 GPa, and at 1.4, 2 and 2.8 "
        "m/s, where stiffer Hertz was run, it is Hertz's stiff limit within 1 %: a DEM − soft-sphere difference of that "
        "size is the soft grains' compliance, not this error)";
    if (run_text(r, "contact_solve") == "iterated")
        return "contacts: rigid grains, the impulse operator's contacts of each step solved together to convergence "
               "(contact dynamics)" + dt_error;
    return "contacts: rigid grains, Sawyer & Tichy's impulse operator, one pass over the contacts per step, which in "
           "a sheared cell gives the wall stresses of the contacts solved to convergence at about a ninth of the cost" +
           dt_error;
}

// The lengths of a solver's runs, gathered over its usable points.
struct RunLengths {
    std::vector<double> simulated, steady_from, steps, iterations;
    std::vector<double> check_simulated, check_steady_from;  // the runs a Delta-t check compared the answers with
    std::string check_start;                                  // how the first checked run's half-step run began
    std::vector<std::string> quarter;                         // points answered at a quarter step (second halving)
    std::vector<std::string> first_failed;                    // their first checks' verdicts
    std::vector<std::string> dense;                           // points at half the case's step ([dem] dense_inertial_number)
    std::vector<std::string> dense_quarter;                   // points at a quarter of it ([dem] quarter_step_inertial_number)
    double dense_below = 0;                                   // those keys' values
    double quarter_below = 0;
    double cap = 0;                                           // [dem] time_max: runs continued until steady
    int continued = 0;
};

RunLengths run_lengths(const std::vector<const Run*>& runs) {
    RunLengths l;
    for (const Run* r : runs) {
        if (auto v = run_number(*r, "simulated_time_s")) l.simulated.push_back(*v);
        if (auto v = run_number(*r, "steady_state_start_s")) l.steady_from.push_back(*v);
        if (auto v = run_number(*r, "steps")) l.steps.push_back(*v);
        if (auto v = run_number(*r, "iterations")) l.iterations.push_back(*v);
        if (const nlohmann::json* d = run_object(*r, "dense_step")) {
            const bool quarter = dense_step_halvings(*r) == 2;
            (quarter ? l.dense_quarter : l.dense)
                .push_back(fmt::format("{} (nominal I {})", r->point ? r->point->id : r->dir.filename().string(),
                                       num(d->value("inertial_number_nominal", 0.0), 2)));
            l.dense_below = d->value("dense_inertial_number", 0.0);
            if (quarter) l.quarter_below = d->value("quarter_step_inertial_number", 0.0);
        }
        if (const nlohmann::json* c = run_object(*r, "continuation")) {
            l.cap = c->value("time_max_s", 0.0);
            if (c->value("pieces", 1) > 1) ++l.continued;
        }
        const nlohmann::json* refinement = run_object(*r, "dt_refinement");
        if (refinement && refinement->contains("full_step_run")) {
            const auto& rec = *refinement;
            const DtCheckRun check = dt_check_run(rec);  // the run the answer was compared with
            const bool twice = check.second_halving && check.run;
            const auto& f = twice ? *check.run : rec["full_step_run"];
            if (twice) {
                l.quarter.push_back(r->point ? r->point->id : r->dir.filename().string());
                const auto& first = rec.value("first_check", nlohmann::json::object());
                l.first_failed.push_back(first.is_object() ? first.value("verdict", std::string()) : std::string());
            }
            if (l.check_start.empty()) l.check_start = rec.value("start", std::string("not recorded"));
            if (f.contains("continuation"))  // continued until steady ([dem] time_max): all its pieces
                l.check_simulated.push_back(f["continuation"].value("simulated_s", 0.0));
            else if (f.contains("steps") && f.contains("time_step_s"))
                l.check_simulated.push_back(f["steps"].get<double>() * f["time_step_s"].get<double>());
            if (f.contains("steady_state_start_s") && f["steady_state_start_s"].is_number())
                l.check_steady_from.push_back(f["steady_state_start_s"].get<double>());
        }
    }
    return l;
}

// The solvers that leave out body forces say so in their run block; the particle engines apply
// the case's gravity.
std::string body_forces(const Case& c, const std::vector<const Run*>& runs, bool particles) {
    const Run& first = *runs.front();
    if (std::string note = run_text(first, "body_forces"); !note.empty()) return "gravity " + note;
    if (std::string note = run_text(first, "ignored"); !note.empty()) return "ignores " + note;
    if (!particles) return "not stated in its summary";
    if (c.gravity <= 0) return "no gravity ([body_forces] gravity = 0)";
    const double nu = first.summary->value("mean_solid_fraction");
    std::vector<double> difference, side;  // the measured P_bot − P_top of each run; side-wall support
    for (const Run* r : runs) {
        if (auto b = r->scalar("normal_stress_bottom"), t = r->scalar("normal_stress_top"); b && t)
            difference.push_back(*b - *t);
        if (auto v = r->scalar("side_wall_support")) side.push_back(*v);
    }
    std::string s = fmt::format("gravity g = {} m/s² acts on the grains: P_bot − P_top includes their weight, "
                                "ρ ν̄ g H ≈ {} Pa",
                                num(c.gravity, 3), num(c.grains.density * nu * c.gravity * c.cell.gap, 2));
    if (!difference.empty()) {
        s += " (measured P_bot − P_top: " + range_text(difference, "Pa");
        // the vertical balance: P_bot − P_top = weight − what the side walls hold up
        if (!side.empty()) s += "; upward force of the side walls per floor area: " + range_text(side, "Pa");
        s += ")";
    }
    return s;
}

std::string stresses(const Run& first, bool particles, bool iterated) {
    if (lattice_stresses(first))
        return "lattice analogues in Pa (wall momentum per lattice step × ρ_p ν_max U², ∝ U² by construction): "
               "not measured stresses, not comparable with the others";
    if (particles) {
        std::string s = "time-averaged wall force / wall area (Pa) over the steady window";
        if (std::string rule = steady_rule(first); !rule.empty()) s += "; " + rule;
        if (std::string law = contact_text(first); !law.empty()) s += "; " + law;
        return s;
    }
    return iterated ? "kinetic-theory wall stresses (Pa) of the steady solution" : "as its summary gives them";
}

std::string particle_run_length(const Run& first, const RunLengths& l, std::size_t runs) {
    std::string s = range_text(l.simulated, "s") + " simulated" + (l.check_simulated.empty() ? "" : " at half the time step");
    if (!l.steady_from.empty()) s += ", averaged from " + range_text(l.steady_from, "s");
    if (!l.steps.empty()) s += " (" + range_text(l.steps, "steps", 0) + ")";
    if (l.cap > 0)
        s += fmt::format("; runs not steady at their length continued from where they ended, doubling, "
                         "up to {} s in all, the last piece averaged ({} of {} points continued)",
                         num(l.cap, 3), l.continued, runs);
    if (!l.check_simulated.empty()) {  // what the numbers are: the half-step run, checked (refine_dt)
        s += "; checked against a run of " + range_text(l.check_simulated, "s") + " at twice the step";
        if (!l.check_steady_from.empty()) s += " (steady from " + range_text(l.check_steady_from, "s") + ")";
        s += "; the half-step run's start: " + l.check_start;
        for (std::size_t k = 0; k < l.quarter.size(); ++k)  // refine_halvings = 2: say which, and why
            s += fmt::format("; {}: at a quarter of the step (cold, the whole run), checked against the half "
                             "step, because the half step failed its check against the full step ({})",
                             l.quarter[k], l.first_failed[k].empty() ? "reason not recorded" : l.first_failed[k]);
    }
    if (!l.dense.empty())  // [dem] dense_inertial_number: the step of every run of these points, checks too
        s += fmt::format("; dense points, whose nominal inertial number U d/(H √(P/ρ)) is below {} ([dem] "
                         "dense_inertial_number), run at half the case's step, and so do their checks: {}",
                         num(l.dense_below, 3), fmt::join(l.dense, ", "));
    if (!l.dense_quarter.empty())  // [dem] quarter_step_inertial_number: the same, one halving more
        s += fmt::format("; dense points whose nominal inertial number is below {} ([dem] "
                         "quarter_step_inertial_number) run at a quarter of the case's step, and so do their "
                         "checks: {}",
                         num(l.quarter_below, 3), fmt::join(l.dense_quarter, ", "));
    if (const std::string start = run_text(first, "start"); !start.empty()) s += "; start: " + start;
    if (const std::string plate = run_text(first, "plate"); !plate.empty()) s += "; load: " + plate;
    return s;
}

std::string run_length(const Run& first, const RunLengths& l, std::size_t runs) {
    if (!l.simulated.empty()) return particle_run_length(first, l, runs);
    if (!l.iterations.empty()) return "steady solution, " + range_text(l.iterations, "iterations", 0);
    if (l.steps.empty()) return "";
    std::string s = range_text(l.steps, "lattice steps", 0);
    if (auto reps = run_number(first, "replicas")) s += fmt::format(" × {} replicas", num(*reps, 3));
    return s;
}

}  // namespace

std::string run_text(const Run& r, const char* key) {
    const auto& run = r.summary->run;
    return run.is_object() && run.contains(key) && run[key].is_string() ? run[key].get<std::string>() : "";
}

const nlohmann::json* run_object(const Run& r, const char* key) {
    const auto& run = r.summary->run;
    return run.is_object() && run.contains(key) && run[key].is_object() ? &run[key] : nullptr;
}

int dense_step_halvings(const Run& r) {
    const nlohmann::json* d = run_object(r, "dense_step");
    return d ? d->value("halvings", 1) : 0;
}

bool lattice_stresses(const Run& r) { return r.kind() == SolverKind::Lattice; }
bool lattice_stresses(const Collection& col, const std::string& solver) { return col.kind(solver) == SolverKind::Lattice; }

SolverScope solver_scope(const Case& c, const Collection& col, const std::string& solver) {
    std::vector<const Run*> runs;
    for (const OperatingPoint* p : col.points)
        if (const Run& r = col.run(solver, p->id); r.usable()) runs.push_back(&r);
    SolverScope s;
    if (runs.empty()) return s;
    const Run& first = *runs.front();
    const RunLengths l = run_lengths(runs);
    const bool particles = !l.simulated.empty();
    s.body_forces = body_forces(c, runs, particles);
    s.stresses = stresses(first, particles, !l.iterations.empty());
    s.grains_walls = grains_and_walls(c, first, particles);
    s.run_length = run_length(first, l, runs.size());
    return s;
}

}  // namespace granlub::postproc
