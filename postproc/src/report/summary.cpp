#include "report/summary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "granlub/particles/contact_laws.h"
#include "granlub/statistics/point_verdict.h"

#include "formats/format.h"
#include "granlub/statistics/flow_regime.h"
#include "results/verdict_engines.h"
#include "results/scope.h"
#include "statistics/stats.h"

namespace granlub::postproc {
namespace {

// A quantity the summary asks about.
struct Asked {
    const char* key;
    const char* label;
    const char* unit;  // of the difference in the largest-disagreement sentence
    bool stress;    // lattice analogues for the automaton
    bool absolute;  // a difference's size as it is (slips, already / U), else relative to the reference
};
constexpr Asked kAsked[] = {
    {"nu_bar_over_numax", "ν̄/ν_max", "", false, false},
    {"gap", "gap", " m", false, false},
    {"shear_stress_bottom", "τ moving wall", " Pa", true, false},
    {"shear_stress_top", "τ stationary wall", " Pa", true, false},
    {"slip_bottom_over_U", "slip moving wall", "", false, true},
    {"slip_top_over_U", "slip stationary wall", "", false, true}};

struct Answer {
    const Run* run;
    double v, se, dt;  // value, standard error and time-step error (0 when none)
};

bool particle(const Run& r) { return r.summary->run.is_object() && r.summary->run.contains("simulated_time_s"); }

// The run's contact law is the impulse operator (its row in granlub/particles/contact_laws.h).
bool impulse_operator(const Run& r) {
    const ContactLaw* law = find_contact_law(run_text(r, "model"));
    return law && law->impulse_options;
}

bool agree(const Answer& a, const Answer& b) {
    const double se = std::hypot(a.se, b.se), d = std::abs(a.v - b.v);
    return se > 0 ? d <= 2 * se : d <= 1e-12 * std::max(std::abs(a.v), std::abs(b.v));
}

// The largest set of answers that agree pairwise (the earlier solvers on a tie).
std::vector<std::size_t> agreeing(const std::vector<Answer>& a) {
    std::vector<std::size_t> best;
    for (unsigned mask = 1; mask < (1u << a.size()); ++mask) {
        std::vector<std::size_t> set;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (mask & (1u << i)) set.push_back(i);
        bool ok = set.size() > best.size();
        for (std::size_t i = 0; ok && i < set.size(); ++i)
            for (std::size_t j = i + 1; ok && j < set.size(); ++j) ok = agree(a[set[i]], a[set[j]]);
        if (ok) best = set;
    }
    return best;
}

// The continuum against a particle run on equal grains: outside its scope (kinetic theory describes a
// disordered fluid; equal grains order into layers in the particle runs), not a model difference.
// The particle run's layer order (its summary's layer_order) is quoted when it has one.
std::string equal_grains_scope(const Run& particles) {
    const auto order = particles.scalar("layer_order");
    return fmt::format("outside the continuum's scope (not a model difference): its kinetic theory does not describe "
                       "the layered crystal that equal grains ([grains] size_spread = 0) form in the particle runs{} "
                       "(How ordered the particle packings are)",
                       order ? fmt::format(", layer order {} in {} here", num(*order, 2), particles.solver) : "");
}

// Whether one of a, b is the continuum and the other a particle run; the particle run in `particles`.
bool continuum_and_particles(const Run& a, const Run& b, const Run** particles) {
    const auto ka = a.kind(), kb = b.kind();
    *particles = ka == SolverKind::Particles ? &a : &b;
    return (ka == SolverKind::Continuum && kb == SolverKind::Particles) ||
           (kb == SolverKind::Continuum && ka == SolverKind::Particles);
}

// What the report knows about a difference b − a beyond the combined standard errors.
std::string known_cause(const Asked& q, const Answer& a, const Answer& b, bool equal_grains) {
    const double d = std::abs(b.v - a.v), rel = a.v != 0 ? d / std::abs(a.v) : 0;
    if ((a.dt > 0 || b.dt > 0) && d <= 2 * std::sqrt(a.se * a.se + b.se * b.se + a.dt * a.dt + b.dt * b.dt))
        return "within the time-step error ([Δt] in the key numbers)";
    const bool impulse_a = impulse_operator(*a.run), impulse_b = impulse_operator(*b.run);
    if (q.stress && particle(*a.run) && particle(*b.run) && impulse_a != impulse_b)
        return rel <= 0.15 ? "the size of the impulse operator's time-step error (about 10 % at the default step; "
                             "What each solver's numbers mean)"
                           : "larger than the impulse operator's time-step error (about 10 %): no known cause";
    if (const Run* grains = nullptr; equal_grains && continuum_and_particles(*a.run, *b.run, &grains))
        return equal_grains_scope(*grains);
    if (!particle(*a.run) || !particle(*b.run))
        return "a model difference";  // what each model leaves out: the scope table
    return "no known cause";
}

struct Disagreement {
    double size = 0;
    std::string text;
};

std::string size_text(const Asked& q, const Answer& ref, const Answer& b) {
    const double d = b.v - ref.v;
    const double se = std::hypot(ref.se, b.se);
    const std::string z = se > 0 ? " (" + z_text(d / se) + ")" : "";
    if (q.absolute || ref.v == 0) return fmt::format("{:+.2g}{}", d, z);
    return fmt::format("{:+.2g}\u00a0%{}", 100 * d / std::abs(ref.v), z);  // no break before the %
}

// One cell: who agrees, and each other solver's difference from the first of them.
// "Largest disagreement: τ moving wall at U2.0: dem − continuum = −327 ± 64 Pa (−20 %, z = −5.1): cause."
std::string largest_text(const Asked& q, const Answer& ref, const Answer& b, const std::string& point,
                         bool equal_grains) {
    const double d = b.v - ref.v, se = std::hypot(ref.se, b.se);
    std::string size = num(d, 3) + (se > 0 ? " ± " + num(se, 2) : "") + q.unit;
    std::vector<std::string> extra;
    if (!q.absolute && ref.v != 0) extra.push_back(fmt::format("{:+.2g}\u00a0%", 100 * d / std::abs(ref.v)));
    if (se > 0) extra.push_back(z_text(d / se));
    if (!extra.empty()) size += " (" + list_text(extra) + ")";
    return fmt::format("Largest disagreement: {} at {}: {} − {} = {}: {}.", q.label, point, b.run->solver, ref.run->solver,
                       size, known_cause(q, ref, b, equal_grains));
}

// `largest`: the largest relative disagreement so far; `largest_slip` the largest in units of U.
Cell quantity_cell(const Asked& q, const std::vector<Answer>& a, const std::string& point, Disagreement& largest,
                   Disagreement& largest_slip, bool equal_grains) {
    if (a.empty()) return {"—", ""};
    if (a.size() == 1) return {"only " + a[0].run->solver, ""};
    const auto group = agreeing(a);
    std::string names;
    for (std::size_t i : group) names += (names.empty() ? "" : " = ") + a[i].run->solver;
    if (group.size() == a.size()) return {names, "ok"};
    const Answer& ref = a[group.front()];
    std::string text = group.size() > 1 ? names : "";
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::find(group.begin(), group.end(), i) != group.end()) continue;
        text += fmt::format("{}{} {}", text.empty() ? "" : "; ", a[i].run->solver, size_text(q, ref, a[i]));
        const double size = q.absolute ? std::abs(a[i].v - ref.v) : std::abs(a[i].v - ref.v) / std::abs(ref.v);
        if (Disagreement& l = q.absolute ? largest_slip : largest; size > l.size)
            l = {size, largest_text(q, ref, a[i], point, equal_grains)};
    }
    if (group.size() == 1) text += " vs " + ref.run->solver;
    return {text, ""};
}

// Why a state's numbers are not answers, in a few words (Results found gives each run's reason).
const char* why_not(const std::string& state) {
    static const std::map<std::string, const char*> why = {
        {"transient", "it ended before a steady state"},
        {"dt-unconverged", "halving the time step changed the answer"},
        {"status unknown", "the summary does not say whether the run is steady"},
        {"failed", "the solver failed"},
        {"no answer", "the solver's model cannot answer the point"},
        {"stale", "computed for other inputs: rerun the solver"},
        {"corrupt", "the result cannot be read"}};
    const auto it = why.find(state);
    return it == why.end() ? "" : it->second;
}

// Which numbers are not answers and why: runs that are not steady results, and the automaton's
// lattice stresses (and its fixed fill under load control).
std::string not_answers(const Collection& col) {
    std::vector<std::pair<std::string, std::vector<std::string>>> by;  // "solver: state" -> points
    for (const auto& s : col.solvers)
        for (const OperatingPoint* p : col.points) {
            const Run& r = col.run(s, p->id);
            if (r.steady() || (r.status.state == ResultState::Missing && !r.failure)) continue;
            const std::string key = fmt::format("{}: {}", s, r.state_name());
            auto it = std::find_if(by.begin(), by.end(), [&](const auto& b) { return b.first == key; });
            if (it == by.end()) it = by.insert(by.end(), {key, {}});
            it->second.push_back(p->id);
        }
    std::string out;
    for (const auto& [key, points] : by) {
        const std::string state = key.substr(key.find(": ") + 2);
        const std::string where = points.size() == col.points.size() ? "every point" : list_text(points);
        out += fmt::format("{}{} at {} ({}: {})", out.empty() ? "" : "; ", key.substr(0, key.find(": ")), where, state,
                           why_not(state));
    }
    for (const auto& s : col.solvers) {
        if (!lattice_stresses(col, s) || !col.any_usable(s)) continue;
        const bool load = std::any_of(col.points.begin(), col.points.end(),
                                      [](const OperatingPoint* p) { return p->control == Control::Load; });
        out += fmt::format("{}{}'s wall stresses (lattice analogues){}", out.empty() ? "" : "; ", s,
                           load ? " and its ν̄ (the lattice's fixed fill under load control)" : "");
    }
    return out.empty() ? "" : "Not answers: " + out + ".";
}

}  // namespace

// The point's one verdict is core's (point_verdict.h), as in the regime table: the engines' verdicts
// combined, "at the transition" where they straddle the threshold or a Z lies within its block errors
// or its time-step error of it.
std::optional<RegimeReading> regime_reading(const Collection& col, const std::string& point) {
    const std::vector<EngineRegime> engines = verdict_engines(col, point);
    if (engines.empty()) return std::nullopt;
    const PointVerdict v = point_verdict(engines);
    std::string names;
    for (const auto& x : engines) names += (names.empty() ? "" : ", ") + x.engine;
    switch (v.regime) {
        case PointRegime::Contact:
        case PointRegime::Collision: return RegimeReading{fmt::format("{} ({})", to_string(v.regime), names), false};
        case PointRegime::Transition:  // short: the regime table has the numbers and the thresholds
            return RegimeReading{fmt::format("at the transition ({}): {}",
                                             v.engines_disagree ? "engines disagree"
                                             : v.step_moves     ? fmt::format("Z within its time-step error of {:g}",
                                                                              kEnduringMinCoordination)
                                                                : fmt::format("Z near {:g}", kEnduringMinCoordination),
                                             v.brief),
                                 true};
        case PointRegime::Undetermined: break;
    }
    return RegimeReading{fmt::format("undetermined: {}", v.criterion), true};
}

CaseSummary case_summary(const Collection& col, bool equal_grains) {
    CaseSummary s;
    s.table.header = {"quantity"};
    for (const OperatingPoint* p : col.points) s.table.header.push_back(p->id);
    Disagreement largest, largest_slip;  // a slip's size (in units of U) is not a relative one
    bool all = true;
    for (const Asked& q : kAsked) {
        std::vector<Cell> row{{q.label, ""}};
        bool any = false;
        for (const OperatingPoint* p : col.points) {
            std::vector<Answer> a;
            for (const Run* r : col.usable(p->id)) {
                const auto v = r->scalar(q.key);
                const bool fixed_fill = lattice_stresses(*r) && p->control == Control::Load;
                if (!v || !r->steady() || (q.stress && lattice_stresses(*r)) ||
                    (fixed_fill && std::string(q.key) == "nu_bar_over_numax"))
                    continue;
                a.push_back({r, *v, r->scalar_stderr(q.key).value_or(0), r->scalar_dt_error(q.key).value_or(0)});
            }
            any = any || !a.empty();
            row.push_back(quantity_cell(q, a, p->id, largest, largest_slip, equal_grains));
            all = all && (a.size() < 2 || row.back().cls == "ok");
        }
        if (any) s.table.rows.push_back(std::move(row));
    }
    std::vector<Cell> regime{{"regime", ""}};
    bool any_regime = false;
    for (const OperatingPoint* p : col.points) {
        const auto r = regime_reading(col, p->id);
        any_regime = any_regime || r;
        regime.push_back(r ? Cell{r->text, r->uncertain ? "uncertain" : ""} : Cell{"—", ""});
        all = all && !(r && r->uncertain);
    }
    if (any_regime) s.table.rows.push_back(std::move(regime));
    if (!largest.text.empty()) s.sentences.push_back(largest.text);
    else if (!largest_slip.text.empty()) s.sentences.push_back(largest_slip.text);
    s.sentences.push_back(not_answers(col));
    s.all_agree = all && s.sentences.back().empty();
    if (s.sentences.back().empty()) s.sentences.pop_back();
    return s;
}

}  // namespace granlub::postproc
