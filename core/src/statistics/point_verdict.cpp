// One verdict per operating point (see point_verdict.h).
#include "granlub/statistics/point_verdict.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

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

// "dem: Z = 4.17 ± 0.03, 87 % persist (contact lubrication)"
std::string numbers(const EngineRegime& r, const FlowVerdict& v) {
    const auto z = number(r.flow_regime, "coordination_number");
    const auto se = number(r.flow_regime, "coordination_number_stderr");
    const auto p = number(r.flow_regime, "contact_persistence");
    std::string s = r.engine + ": Z = " + (z ? fmt::format("{:.3g}", *z) : std::string("not measured"));
    if (z && se) s += fmt::format(" ± {:.2g}", *se);
    s += p ? fmt::format(", {:.0f} % persist", 100 * *p) : std::string(", persistence not measured");
    return s + " (" + to_string(v.lubrication) + ")";
}

// "dem Z = 4.35 (contact)"
std::string brief(const EngineRegime& r, const FlowVerdict& v) {
    const auto z = number(r.flow_regime, "coordination_number");
    const std::string name = to_string(v.lubrication);
    return r.engine + " Z = " + (z ? fmt::format("{:.3g}", *z) : std::string("not measured")) + " (" +
           name.substr(0, name.find(' ')) + ")";
}

bool straddles(const nlohmann::json& fr) {
    const auto z = number(fr, "coordination_number");
    const auto se = number(fr, "coordination_number_stderr");
    return z && se && std::abs(*z - kEnduringMinCoordination) < kTransitionSigmas * *se;
}

}  // namespace

PointVerdict point_verdict(const std::vector<EngineRegime>& runs) {
    std::string each, briefs;
    std::optional<Lubrication> agreed;
    bool disagree = false, near = false;
    for (const EngineRegime& r : runs) {
        const FlowVerdict v = read_flow_verdict(r.flow_regime);
        each += (each.empty() ? "" : "; ") + numbers(r, v);
        briefs += (briefs.empty() ? "" : ", ") + brief(r, v);
        if (v.lubrication == Lubrication::Undetermined) continue;
        if (agreed && *agreed != v.lubrication) disagree = true;
        agreed = v.lubrication;
        near = near || straddles(r.flow_regime);
    }
    const std::string thresholds =
        fmt::format("thresholds Z = {:g}, {:.0f} % persisting", kEnduringMinCoordination, 100 * kEnduringMinPersistence);
    if (!agreed) return {PointRegime::Undetermined, each.empty() ? "no flow-regime record" : each, briefs};
    if (disagree)
        return {PointRegime::Transition, fmt::format("the engines fall on either side: {} ({})", each, thresholds),
                briefs, true};
    if (near)
        return {PointRegime::Transition,
                fmt::format("Z within {:g} block errors of {:g}: {} ({})", kTransitionSigmas, kEnduringMinCoordination,
                            each, thresholds),
                briefs};
    return {*agreed == Lubrication::Contact ? PointRegime::Contact : PointRegime::Collision, each, briefs};
}

}  // namespace granlub
