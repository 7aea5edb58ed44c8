// One verdict per operating point (see point_verdict.h).
#include "granlub/statistics/point_verdict.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "granlub/results/run_status.h"
#include "granlub/statistics/flow_regime.h"

namespace granlub {

std::string to_string(PointRegime r) {
    switch (r) {
        case PointRegime::Contact: return "contact lubrication";
        case PointRegime::Collision: return "collision lubrication";
        case PointRegime::Transition: return "at the transition";
        case PointRegime::Undetermined: return "undetermined";
    }
    return "undetermined";
}

namespace {

std::optional<double> number(const nlohmann::json& j, const char* key) {
    if (!j.is_object()) return std::nullopt;
    const auto it = j.find(key);
    return it != j.end() && it->is_number() ? std::optional<double>(it->get<double>()) : std::nullopt;
}

// "contact", "collision", "undetermined": a verdict's first word
std::string short_name(Lubrication l) {
    const std::string name = to_string(l);
    return name.substr(0, name.find(' '));
}

// "Z = 4.12, contact" for the time-step check's coarser run; empty without one
std::string coarser_numbers(const EngineRegime& r) {
    if (!r.coarser.is_object()) return "";
    const auto z = number(r.coarser, "coordination_number");
    return (z ? fmt::format("Z = {:.3g}", *z) : std::string("Z not measured")) + ", " +
           short_name(read_flow_verdict(r.coarser).lubrication);
}

// "dem: Z = 4.17 ± 0.03, 87 % persist (contact lubrication; at twice the step Z = 4.31, contact)"
std::string numbers(const EngineRegime& r, const FlowVerdict& v) {
    const auto z = number(r.flow_regime, "coordination_number");
    const auto se = number(r.flow_regime, "coordination_number_stderr");
    const auto p = number(r.flow_regime, "contact_persistence");
    std::string s = r.engine + ": Z = " + (z ? fmt::format("{:.3g}", *z) : std::string("not measured"));
    if (z && se) s += fmt::format(" ± {:.2g}", *se);
    s += p ? fmt::format(", {:.0f} % persist", 100 * *p) : std::string(", persistence not measured");
    const std::string coarse = coarser_numbers(r);
    return s + " (" + to_string(v.lubrication) + (coarse.empty() ? "" : "; at twice the step " + coarse) + ")";
}

// The time step's own say (point_verdict.h): the run at twice the step on the other side of the
// threshold, or Z nearer to it than the check moved Z.
bool step_moves_across(const EngineRegime& r, const FlowVerdict& v) {
    if (!r.coarser.is_object() || v.lubrication == Lubrication::Undetermined) return false;
    const Lubrication coarse = read_flow_verdict(r.coarser).lubrication;
    if (coarse != Lubrication::Undetermined && coarse != v.lubrication) return true;
    const auto z = number(r.flow_regime, "coordination_number");
    const auto zc = number(r.coarser, "coordination_number");
    return z && zc && std::abs(*z - kEnduringMinCoordination) < std::abs(*zc - *z);
}

bool straddles(const nlohmann::json& fr) {
    const auto z = number(fr, "coordination_number");
    const auto se = number(fr, "coordination_number_stderr");
    return z && se && std::abs(*z - kEnduringMinCoordination) < kTransitionSigmas * *se;
}

// "dem Z = 4.35 (contact)"; "dem Z = 3.93 (collision; 4.12 at twice the step)" where the step is what
// puts it at the transition (the summary's short form: the check's Z only where it decides)
std::string brief(const EngineRegime& r, const FlowVerdict& v, bool step) {
    const auto z = number(r.flow_regime, "coordination_number");
    const auto zc = number(r.coarser, "coordination_number");
    return r.engine + " Z = " + (z ? fmt::format("{:.3g}", *z) : std::string("not measured")) + " (" +
           short_name(v.lubrication) + (step && zc ? fmt::format("; {:.3g} at twice the step", *zc) : std::string()) +
           ")";
}

}  // namespace

EngineRegime engine_regime(const std::string& engine, const nlohmann::json& run) {
    if (!run.is_object()) return {engine, nullptr, nullptr};
    EngineRegime r{engine, run.value("flow_regime", nlohmann::json()), nullptr};
    const auto rec = run.find("dt_refinement");
    if (rec == run.end()) return r;
    const nlohmann::json* check = dt_check_run(*rec).run;
    if (check && check->contains("flow_regime") && check->at("flow_regime").is_object())
        r.coarser = check->at("flow_regime");
    return r;
}

PointVerdict point_verdict(const std::vector<EngineRegime>& runs) {
    std::string each, briefs;
    std::optional<Lubrication> agreed;
    bool disagree = false, near = false, step = false, seeds_error = false;
    for (const EngineRegime& r : runs) {
        const FlowVerdict v = read_flow_verdict(r.flow_regime);
        const bool moved = step_moves_across(r, v);
        each += (each.empty() ? "" : "; ") + numbers(r, v);
        briefs += (briefs.empty() ? "" : ", ") + brief(r, v, moved);
        if (v.lubrication == Lubrication::Undetermined) continue;
        if (agreed && *agreed != v.lubrication) disagree = true;
        agreed = v.lubrication;
        if (straddles(r.flow_regime)) {
            near = true;
            // pooled over seeds (seed_pool.h): its error is the seeds' standard error
            seeds_error = seeds_error || r.flow_regime.contains("coordination_number_block_stderr");
        }
        step = step || moved;
    }
    const std::string thresholds =
        fmt::format("thresholds Z = {:g}, {:.0f} % persisting", kEnduringMinCoordination, 100 * kEnduringMinPersistence);
    if (!agreed) return {PointRegime::Undetermined, each.empty() ? "no flow-regime record" : each, briefs};
    if (disagree)
        return {PointRegime::Transition, fmt::format("the engines fall on either side: {} ({})", each, thresholds),
                briefs, true};
    if (step)
        return {PointRegime::Transition,
                fmt::format("Z within its time-step error of {0:g}: halving the step moves it across {0:g}, or by more "
                            "than Z lies from {0:g}, so its Δt → 0 value may lie on either side: {1} ({2})",
                            kEnduringMinCoordination, each, thresholds),
                briefs, false, true};
    if (near)
        return {PointRegime::Transition,
                fmt::format("Z within {:g} {} of {:g}: {} ({})", kTransitionSigmas,
                            seeds_error ? "standard errors (the seeds')" : "block errors", kEnduringMinCoordination,
                            each, thresholds),
                briefs};
    return {*agreed == Lubrication::Contact ? PointRegime::Contact : PointRegime::Collision, each, briefs};
}

}  // namespace granlub
