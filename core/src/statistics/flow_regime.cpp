// Inertial number and flow-regime classification (flow_regime.h).
#include "granlub/statistics/flow_regime.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

std::int64_t persistence_every_steps(double shear_rate, double time_step, std::int64_t steps) {
    const double every = shear_rate > 0 ? std::round(kPersistenceStrain / (shear_rate * time_step)) : 1.0;
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::min(every, 1e12)), 1,
                                    std::max<std::int64_t>(1, steps / kPersistenceRunFraction));
}

std::optional<double> inertial_number(double shear_rate, double diameter, double pressure, double density) {
    if (!(pressure > 0) || !(diameter > 0) || !(density > 0) || !std::isfinite(shear_rate)) return std::nullopt;
    return std::abs(shear_rate) * diameter / std::sqrt(pressure / density);
}

double mid_gap_shear_rate(std::span<const double> y, std::span<const double> u, double gap) {
    if (y.size() != u.size() || y.size() < 2 || !(gap > 0))
        throw Error(fmt::format("mid-gap shear rate: need y and u of the same size >= 2 and a positive gap (got {} "
                                "and {} values, gap {:g})",
                                y.size(), u.size(), gap));
    std::vector<std::size_t> use;
    for (std::size_t k = 0; k < y.size(); ++k)
        if (y[k] >= gap / 3.0 && y[k] <= 2.0 * gap / 3.0) use.push_back(k);
    if (use.size() < 2) {  // too few stations: the two nearest the middle
        std::vector<std::size_t> all(y.size());
        for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
        std::partial_sort(all.begin(), all.begin() + 2, all.end(), [&](std::size_t a, std::size_t b) {
            return std::abs(y[a] - 0.5 * gap) < std::abs(y[b] - 0.5 * gap);
        });
        use.assign(all.begin(), all.begin() + 2);
    }
    double my = 0, mu = 0;
    for (std::size_t k : use) my += y[k], mu += u[k];
    my /= static_cast<double>(use.size());
    mu /= static_cast<double>(use.size());
    double sxy = 0, sxx = 0;
    for (std::size_t k : use) sxy += (y[k] - my) * (u[k] - mu), sxx += (y[k] - my) * (y[k] - my);
    return sxx > 0 ? std::abs(sxy / sxx) : 0.0;
}

void set_inertial_numbers(FlowDiagnostics& d, const Profile& profile, double U, double H, double P, double diameter,
                          double density) {
    d.inertial_nominal = inertial_number(U / H, diameter, P, density);
    std::vector<double> y(profile.column("y_over_H")), u(profile.column("u_over_U"));
    for (double& v : y) v *= H;
    for (double& v : u) v *= U;
    d.inertial_mid_gap = inertial_number(mid_gap_shear_rate(y, u, H), diameter, P, density);
}

std::string to_string(InertialClass c) {
    switch (c) {
        case InertialClass::QuasiStatic: return "quasi-static";
        case InertialClass::DenseInertial: return "dense-inertial";
        case InertialClass::Rapid: return "rapid";
    }
    return "unknown";
}

InertialClass inertial_class(double I) {
    if (I < kQuasiStaticMaxInertialNumber) return InertialClass::QuasiStatic;
    if (I > kRapidMinInertialNumber) return InertialClass::Rapid;
    return InertialClass::DenseInertial;
}

bool enduring_contacts(std::optional<double> z, std::optional<double> persistence) {
    return z && persistence && *z >= kEnduringMinCoordination && *persistence >= kEnduringMinPersistence;
}

std::string to_string(Lubrication l) {
    switch (l) {
        case Lubrication::Contact: return "contact lubrication";
        case Lubrication::Collision: return "collision lubrication";
        case Lubrication::Undetermined: return "undetermined";
    }
    return "undetermined";
}

Verdict lubrication_verdict(std::optional<double> z, std::optional<double> persistence) {
    const std::string zmin = fmt::format("{:g}", kEnduringMinCoordination);
    const std::string pmin = fmt::format("{:.0f} %", 100 * kEnduringMinPersistence);
    if (!z) return {Lubrication::Undetermined, "coordination number Z not measured"};
    if (*z < kEnduringMinCoordination)
        return {Lubrication::Collision,
                fmt::format("Z = {:.3g} < {} (no contact network below the jamming coordination)", *z, zmin)};
    if (!persistence)
        return {Lubrication::Undetermined,
                fmt::format("Z = {:.3g} >= {}, but the contact persistence was not measured", *z, zmin)};
    if (*persistence < kEnduringMinPersistence)
        return {Lubrication::Collision, fmt::format("Z = {:.3g} >= {}, but {:.0f} % of contacts persist < {} over a "
                                                    "strain of {:g}",
                                                    *z, zmin, 100 * *persistence, pmin, kPersistenceStrain)};
    return {Lubrication::Contact, fmt::format("Z = {:.3g} >= {} and {:.0f} % of contacts persist >= {} over a strain "
                                              "of {:g}",
                                              *z, zmin, 100 * *persistence, pmin, kPersistenceStrain)};
}

nlohmann::json flow_regime_json(const FlowDiagnostics& d) {
    auto value = [](std::optional<double> v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
    const std::optional<double> I = d.inertial_mid_gap ? d.inertial_mid_gap : d.inertial_nominal;
    const Verdict v = lubrication_verdict(d.coordination, d.persistence);
    nlohmann::json j = {{"verdict_version", 2},
                        {"regime", to_string(v.lubrication)},
                        {"criterion", v.criterion},
                        {"inertial_class", I ? nlohmann::json(to_string(inertial_class(*I))) : nlohmann::json()},
                        {"inertial_number", value(I)},
                        {"inertial_number_nominal", value(d.inertial_nominal)},
                        {"inertial_number_mid_gap", value(d.inertial_mid_gap)},
                        {"coordination_number", value(d.coordination)},
                        {"coordination_number_stderr", value(d.coordination_stderr)},
                        {"contact_persistence", value(d.persistence)},
                        {"enduring_contacts", enduring_contacts(d.coordination, d.persistence)},
                        {"thresholds",
                         {{"quasi_static_max_inertial_number", kQuasiStaticMaxInertialNumber},
                          {"rapid_min_inertial_number", kRapidMinInertialNumber},
                          {"enduring_min_coordination", kEnduringMinCoordination},
                          {"enduring_min_persistence", kEnduringMinPersistence},
                          {"persistence_strain", kPersistenceStrain}}}};
    std::string why = fmt::format("{}: {}", to_string(v.lubrication), v.criterion);
    if (I)
        why += fmt::format("; beside it, I = {:.3g} ({}) is {} (quasi-static below {:g}, rapid above {:g})", *I,
                           d.inertial_mid_gap ? "mid-gap shear rate" : "U/H", to_string(inertial_class(*I)),
                           kQuasiStaticMaxInertialNumber, kRapidMinInertialNumber);
    else
        why += "; no inertial number (no positive mean wall normal stress)";
    j["reason"] = why;
    return j;
}

std::string FlowVerdict::label() const {
    return inertial_class.empty() ? to_string(lubrication)
                                  : fmt::format("{} (I {})", to_string(lubrication), inertial_class);
}

FlowDiagnostics read_flow_diagnostics(const nlohmann::json& fr) {
    auto number = [&](const char* k) -> std::optional<double> {
        const auto it = fr.find(k);
        return it != fr.end() && it->is_number() ? std::optional<double>(it->get<double>()) : std::nullopt;
    };
    FlowDiagnostics d;
    d.inertial_nominal = number("inertial_number_nominal");
    d.inertial_mid_gap = number("inertial_number_mid_gap");
    d.coordination = number("coordination_number");
    d.coordination_stderr = number("coordination_number_stderr");
    d.persistence = number("contact_persistence");
    return d;
}

FlowVerdict read_flow_verdict(const nlohmann::json& fr) {
    FlowVerdict out;
    if (!fr.is_object()) {
        out.criterion = "no flow-regime record";
        return out;
    }
    const FlowDiagnostics d = read_flow_diagnostics(fr);
    out.inertial_nominal = d.inertial_nominal;
    out.inertial_mid_gap = d.inertial_mid_gap;
    const Verdict v = lubrication_verdict(d.coordination, d.persistence);
    const auto version = fr.find("verdict_version");
    if (version != fr.end() && version->is_number_integer() && version->get<int>() >= 2) {
        const std::string r = fr.value("regime", nlohmann::json()).is_string() ? fr["regime"].get<std::string>() : "";
        for (Lubrication l : {Lubrication::Contact, Lubrication::Collision, Lubrication::Undetermined})
            if (r == to_string(l)) out.lubrication = l;
        out.criterion = fr.value("criterion", nlohmann::json()).is_string() ? fr["criterion"].get<std::string>() : "";
        if (fr.value("inertial_class", nlohmann::json()).is_string())
            out.inertial_class = fr["inertial_class"].get<std::string>();
        return out;
    }
    // before verdict_version 2: "regime" was the inertial class, "collisional" above I = 0.1
    out.lubrication = v.lubrication;
    out.criterion = v.criterion + " (recomputed from an older record)";
    if (const auto it = fr.find("regime"); it != fr.end() && it->is_string()) {
        const std::string r = it->get<std::string>();
        out.inertial_class = r == "collisional" ? "rapid" : r;
    }
    return out;
}

}  // namespace granlub
