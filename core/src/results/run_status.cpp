// A result's regime status in summary.json's run block (run_status.h).
#include "granlub/results/run_status.h"

#include <cmath>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

namespace {
constexpr std::pair<RegimeStatus, const char*> kNames[] = {{RegimeStatus::Steady, "steady"},
                                                           {RegimeStatus::Transient, "transient"},
                                                           {RegimeStatus::DtUnconverged, "dt-unconverged"},
                                                           {RegimeStatus::Ordered, "ordered"},
                                                           {RegimeStatus::Incomplete, "incomplete"}};

double number(const nlohmann::json& j, const char* key, const std::string& where) {
    if (!j.is_object() || !j.contains(key) || !j.at(key).is_number())
        throw Error(fmt::format("run.dt_refinement{}: '{}' is missing or not a number", where, key));
    const double v = j.at(key).get<double>();
    if (!std::isfinite(v)) throw Error(fmt::format("run.dt_refinement{}.{} = {} (allowed: finite)", where, key, v));
    return v;
}
}  // namespace

std::string to_string(RegimeStatus s) {
    for (const auto& [status, name] : kNames)
        if (status == s) return name;
    return "unknown";
}

std::optional<RegimeStatus> regime_status_from_string(std::string_view s) {
    for (const auto& [status, name] : kNames)
        if (s == name) return status;
    return std::nullopt;
}

void set_regime(nlohmann::json& run, RegimeStatus status, const std::string& reason) {
    if (status == RegimeStatus::Unknown) throw Error("internal: a solver cannot write the regime status 'unknown'");
    run["status"] = to_string(status);
    run["status_reason"] = reason;
}

std::string dt_unconverged_reason(const nlohmann::json& r) {
    if (!r.is_object()) throw Error("run.dt_refinement is not an object");
    const double dnu = number(r.value("mean_solid_fraction", nlohmann::json()), "change", ".mean_solid_fraction");
    std::string why;
    if (std::abs(dnu) > kDtMaxSolidFractionChange)
        why = fmt::format("halving the time step changes the mean solid fraction by {:+.4f} (allowed: ±{})", dnu,
                          kDtMaxSolidFractionChange);
    for (const char* wall : {"shear_stress_bottom", "shear_stress_top"}) {
        const std::string where = std::string(".") + wall;
        const auto& e = r.value(wall, nlohmann::json());
        const double rel = number(e, "relative_change", where), z = number(e, "z", where);
        if (std::abs(rel) > kDtMaxRelativeStressChange && std::abs(z) > kDtMaxStressZ)
            why += fmt::format("{}halving the time step moves {} by {:+.1f} % ({:.1f} standard errors; allowed: "
                               "{:.0f} % or {} standard errors)",
                               why.empty() ? "" : "; ", wall, 100 * rel, z, 100 * kDtMaxRelativeStressChange,
                               kDtMaxStressZ);
    }
    return why;
}

std::optional<std::string> dt_check_failure(const nlohmann::json& coarse_run, const nlohmann::json& fine_run,
                                            const nlohmann::json& record) {
    if (!read_regime(fine_run).steady()) return std::nullopt;
    if (const Regime coarse = read_regime(coarse_run); !coarse.steady())
        return "the run at twice the step did not reach a steady state" +
               (coarse.reason.empty() ? std::string() : " (" + coarse.reason + ")");
    return dt_unconverged_reason(record);
}

DtCheckRun dt_check_run(const nlohmann::json& r) {
    if (!r.is_object()) return {};
    const bool twice = r.contains("half_step_run");
    const auto it = r.find(twice ? "half_step_run" : "full_step_run");
    return {it != r.end() && it->is_object() ? &*it : nullptr, twice};
}

nlohmann::json dt_refinement_record(double refined_time_step, const std::map<std::string, Scalar>& original,
                                    const std::map<std::string, Scalar>& refined) {
    auto both = [&](const std::string& name) -> std::pair<const Scalar*, const Scalar*> {
        const auto o = original.find(name), r = refined.find(name);
        if (o == original.end() || r == refined.end()) return {nullptr, nullptr};
        return {&o->second, &r->second};
    };
    nlohmann::json j = {{"time_step_s", refined_time_step}};
    const auto [nu_o, nu_r] = both("mean_solid_fraction");
    if (!nu_o) throw Error("internal: dt refinement without mean_solid_fraction in both runs");
    j["mean_solid_fraction"] = {
        {"change", nu_r->value - nu_o->value}, {"original", nu_o->value}, {"refined", nu_r->value}};
    for (const char* name : {"shear_stress_bottom", "shear_stress_top", "normal_stress_bottom", "normal_stress_top",
                             "slip_bottom", "slip_top"}) {
        const auto [o, r] = both(name);
        if (!o) {
            if (std::string_view(name).starts_with("shear"))
                throw Error(fmt::format("internal: dt refinement without {} in both runs", name));
            continue;
        }
        const double change = r->value - o->value;
        const double so = o->stderr_.value_or(0), sr = r->stderr_.value_or(0);
        const double se = std::sqrt(so * so + sr * sr);
        auto ratio = [&](double den) { return den != 0 ? change / den : (change == 0 ? 0.0 : std::copysign(1e300, change)); };
        const double z = ratio(se);
        j[name] = {{"relative_change", ratio(o->value)},
                   {"z", z},
                   {"original", o->value},
                   {"refined", r->value},
                   {"original_stderr", so},
                   {"refined_stderr", sr}};
    }
    return j;
}

Regime read_regime(const nlohmann::json& run) {
    if (!run.is_object() || !run.contains("status"))
        return {RegimeStatus::Unknown, "the summary does not say whether the run reached a steady state (no run.status)"};
    const auto& s = run.at("status");
    const auto status = s.is_string() ? regime_status_from_string(s.get<std::string>()) : std::nullopt;
    if (!status)
        return {RegimeStatus::Unknown,
                fmt::format("run.status = {} (allowed: \"steady\", \"transient\", \"dt-unconverged\", \"ordered\", \"incomplete\")", s.dump())};
    Regime r{*status, run.contains("status_reason") && run.at("status_reason").is_string()
                          ? run.at("status_reason").get<std::string>()
                          : std::string()};
    if (r.status == RegimeStatus::Steady && run.contains("dt_refinement")) {
        // a check against a run that never reached a steady state is no check: the point is a
        // transient (summaries written before the solver said so itself read the same way)
        // (after a second halving the answer is checked against the half-step run)
        const DtCheckRun against = dt_check_run(run.at("dt_refinement"));
        const bool twice = against.second_halving;
        if (against.run) {
            const auto& check = *against.run;
            if (check.contains("status") && check.at("status") != "steady") {
                // its own reason, when it gives one, says how to run it longer (e.g. the cap that stopped it)
                const auto own = check.value("status_reason", std::string());
                return {RegimeStatus::Transient,
                        std::string(twice ? "the half-step run the quarter-step run checks against"
                                          : "the full-step run the half-step run checks against") +
                            " did not reach a steady state: " +
                            (own.empty() ? std::string("run longer (--full, or a longer `time`)") : own)};
            }
        }
        try {
            if (auto why = dt_unconverged_reason(run.at("dt_refinement")); !why.empty())
                r = {RegimeStatus::DtUnconverged, why};
        } catch (const Error& e) {
            return {RegimeStatus::Unknown, e.what()};
        }
    }
    return r;
}

}  // namespace granlub
