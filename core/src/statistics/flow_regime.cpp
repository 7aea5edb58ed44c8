// Inertial number and flow-regime classification (flow_regime.h).
#include "granlub/statistics/flow_regime.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

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

std::string to_string(FlowRegime r) {
    switch (r) {
        case FlowRegime::QuasiStatic: return "quasi-static";
        case FlowRegime::DenseInertial: return "dense-inertial";
        case FlowRegime::Collisional: return "collisional";
    }
    return "unknown";
}

FlowRegime flow_regime(double I) {
    if (I < kQuasiStaticMaxInertialNumber) return FlowRegime::QuasiStatic;
    if (I > kCollisionalMinInertialNumber) return FlowRegime::Collisional;
    return FlowRegime::DenseInertial;
}

bool enduring_contacts(std::optional<double> z, std::optional<double> persistence) {
    return z && persistence && *z >= kEnduringMinCoordination && *persistence >= kEnduringMinPersistence;
}

nlohmann::json flow_regime_json(const FlowDiagnostics& d) {
    auto value = [](std::optional<double> v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
    const std::optional<double> I = d.inertial_mid_gap ? d.inertial_mid_gap : d.inertial_nominal;
    const bool enduring = enduring_contacts(d.coordination, d.persistence);
    nlohmann::json j = {{"inertial_number", value(I)},
                        {"inertial_number_nominal", value(d.inertial_nominal)},
                        {"inertial_number_mid_gap", value(d.inertial_mid_gap)},
                        {"coordination_number", value(d.coordination)},
                        {"contact_persistence", value(d.persistence)},
                        {"enduring_contacts", enduring},
                        {"thresholds",
                         {{"quasi_static_max_inertial_number", kQuasiStaticMaxInertialNumber},
                          {"collisional_min_inertial_number", kCollisionalMinInertialNumber},
                          {"enduring_min_coordination", kEnduringMinCoordination},
                          {"enduring_min_persistence", kEnduringMinPersistence},
                          {"persistence_strain", kPersistenceStrain}}}};
    if (!I) {
        j["regime"] = nullptr;
        j["reason"] = "no inertial number (no positive mean wall normal stress)";
        return j;
    }
    const FlowRegime r = flow_regime(*I);
    j["regime"] = to_string(r);
    std::string why = fmt::format("I = {:.3g} ({}; quasi-static below {:g}, collisional above {:g})", *I,
                                  d.inertial_mid_gap ? "mid-gap shear rate" : "U/H", kQuasiStaticMaxInertialNumber,
                                  kCollisionalMinInertialNumber);
    if (d.coordination && d.persistence)
        why += fmt::format("; Z = {:.2f}, {:.0f} % of contacts persist: {}", *d.coordination, 100 * *d.persistence,
                           enduring ? "enduring contacts"
                                    : fmt::format("no enduring contacts (needs Z >= {:g} and >= {:.0f} %)",
                                                  kEnduringMinCoordination, 100 * kEnduringMinPersistence));
    j["reason"] = why;
    return j;
}

}  // namespace granlub
