// The core's rheology of a wide plane-shear cell (bulk_rheology.h).
#include "granlub/particles/bulk_rheology.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "granlub/case/wall_bumps.h"
#include "granlub/error.h"
#include "granlub/particles/seed_mean.h"
#include "granlub/results/run_status.h"

namespace granlub {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& y_error) {
    const std::size_t n = x.size();
    if (n < 3 || y.size() != n || y_error.size() != n)
        throw Error(fmt::format("line fit: need at least 3 points with a value and an error each (got {}, {}, {})", n,
                                y.size(), y_error.size()));
    bool weighted = true;  // weights 1/sigma^2, or equal weights when an error is zero
    for (double e : y_error) weighted = weighted && e > 0;
    double S = 0, Sx = 0, Sy = 0, Sxx = 0, Sxy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double w = weighted ? 1.0 / (y_error[i] * y_error[i]) : 1.0;
        S += w, Sx += w * x[i], Sy += w * y[i], Sxx += w * x[i] * x[i], Sxy += w * x[i] * y[i];
    }
    const double D = S * Sxx - Sx * Sx;
    if (!(D > 0)) throw Error("line fit: the points' x do not spread");
    LineFit f;
    f.points = n;
    f.slope = (S * Sxy - Sx * Sy) / D;
    f.intercept = (Sxx * Sy - Sx * Sxy) / D;
    double chi2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double w = weighted ? 1.0 / (y_error[i] * y_error[i]) : 1.0;
        const double r = y[i] - f.intercept - f.slope * x[i];
        chi2 += w * r * r;
    }
    const double reduced = chi2 / static_cast<double>(n - 2);
    // propagated: sqrt(S / D) (weighted); from the scatter: that times sqrt(reduced chi^2)
    f.slope_error = std::sqrt(S / D) * (weighted ? std::max(1.0, std::sqrt(reduced)) : std::sqrt(reduced));
    return f;
}

namespace {

Measured mean_of(const Measured& a, const Measured& b) {
    return {0.5 * (a.value + b.value), 0.5 * std::hypot(a.error, b.error)};
}

// value = a / b, errors relative and in quadrature
Measured ratio(const Measured& a, const Measured& b) {
    const double v = a.value / b.value;
    return {v, std::abs(v) * std::hypot(a.error / a.value, b.error / b.value)};
}

struct CoreStations {
    std::vector<double> y, u, ue, nu, nue, T, Te;
};

CoreStations core_stations(const Profile& p, double from, double to) {
    CoreStations c;
    const auto& y = p.column("y_over_H");
    const std::vector<double> no_error(y.size(), 0.0);  // a continuum's profile: exact values
    const auto error = [&](const char* column) -> const std::vector<double>& {
        return p.has(column) ? p.column(column) : no_error;
    };
    const auto& u = p.column("u_over_U");
    const auto& ue = error("u_over_U_stderr");
    const auto& nu = p.column("solid_fraction");
    const auto& nue = error("solid_fraction_stderr");
    const auto& T = p.column("temperature_over_U2");
    const auto& Te = error("temperature_over_U2_stderr");
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (y[i] < from || y[i] > to) continue;
        c.y.push_back(y[i]), c.u.push_back(u[i]), c.ue.push_back(ue[i]);
        c.nu.push_back(nu[i]), c.nue.push_back(nue[i]), c.T.push_back(T[i]), c.Te.push_back(Te[i]);
    }
    return c;
}

// mean of the values, and of their errors (the fully correlated bound: bulk_rheology.h)
Measured station_mean(const std::vector<double>& v, const std::vector<double>& e) {
    Measured m;
    for (std::size_t i = 0; i < v.size(); ++i) m.value += v[i], m.error += e[i];
    m.value /= static_cast<double>(v.size());
    m.error /= static_cast<double>(v.size());
    return m;
}

// the slope of u/U against y/H over the stations [lo, hi)
double half_slope(const CoreStations& c, std::size_t lo, std::size_t hi) {
    const auto part = [&](const std::vector<double>& v) { return std::vector<double>(v.begin() + lo, v.begin() + hi); };
    return fit_line(part(c.y), part(c.u), part(c.ue)).slope;
}

// the value at x of the straight lines through the points (x_i, v_i), x ascending; held beyond the ends
double line_at(const std::vector<double>& x, const std::vector<double>& v, double at) {
    if (at <= x.front()) return v.front();
    if (at >= x.back()) return v.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
    const double w = (at - x[k - 1]) / (x[k] - x[k - 1]);
    return v[k - 1] + w * (v[k] - v[k - 1]);
}

// the mean over [from, to] of the straight lines through the points (exact: trapezoids between the breakpoints)
double line_mean(const std::vector<double>& x, const std::vector<double>& v, double from, double to) {
    std::vector<double> at = {from};
    for (double xi : x)
        if (xi > from && xi < to) at.push_back(xi);
    at.push_back(to);
    double sum = 0;
    for (std::size_t k = 1; k < at.size(); ++k)
        sum += 0.5 * (line_at(x, v, at[k - 1]) + line_at(x, v, at[k])) * (at[k] - at[k - 1]);
    return sum / (to - from);
}

// mean of the values over [from, to] in y/H, and of their errors (0 without an error column)
Measured band_mean(const Profile& p, const char* column, double from, double to, BandMean how, std::size_t& n) {
    const auto& y = p.column("y_over_H");
    const auto& v = p.column(column);
    const std::string err = std::string(column) + "_stderr";
    const std::vector<double> no_error(y.size(), 0.0);
    const std::vector<double>& e = p.has(err) ? p.column(err) : no_error;
    std::vector<double> vs, es;
    for (std::size_t i = 0; i < y.size(); ++i)
        if (y[i] >= from && y[i] <= to) vs.push_back(v[i]), es.push_back(e[i]);
    n = vs.size();
    if (vs.empty())
        throw Error(fmt::format("near-wall {}: no profile station lies in y/H [{:.4f}, {:.4f}]: raise [dem] stations",
                                column, from, to));
    if (how == BandMean::Interpolated) return {line_mean(y, v, from, to), line_mean(y, e, from, to)};
    return station_mean(vs, es);
}

}  // namespace

NearWallTemperature near_wall_temperature(const Profile& p, double gap, double diameter, double protrusion_bottom,
                                          double protrusion_top, BandMean how) {
    NearWallTemperature t;
    const double band = kNearWallBand * diameter / gap;
    const double floor = protrusion_bottom / gap, top = 1.0 - protrusion_top / gap;
    t.bottom = band_mean(p, "temperature_over_U2", floor, floor + band, how, t.stations_bottom);
    t.top = band_mean(p, "temperature_over_U2", top - band, top, how, t.stations_top);
    return t;
}

namespace {

Measured output(const std::map<std::string, Scalar>& outs, const std::string& name, const std::string& source) {
    const auto it = outs.find(name);
    if (it == outs.end()) throw Error(fmt::format("{}: no output '{}'", source, name));
    return {it->second.value, it->second.stderr_.value_or(0.0)};
}

std::optional<Measured> flow_number(const nlohmann::json& fr, const std::string& name) {
    if (!fr.contains(name) || !fr.at(name).is_number()) return std::nullopt;
    const std::string e = name + "_stderr";
    return Measured{fr.at(name).get<double>(), fr.contains(e) && fr.at(e).is_number() ? fr.at(e).get<double>() : 0.0};
}

}  // namespace

CoreRun core_run(const Profile& profile, double U, const std::map<std::string, Scalar>& outs,
                 const nlohmann::json& flow_regime, double case_gap, double protrusion_bottom, double protrusion_top,
                 const std::string& source) {
    CoreRun r;
    r.protrusion_bottom = protrusion_bottom, r.protrusion_top = protrusion_top;
    r.profile = &profile;
    r.speed = U;
    r.gap = outs.count("gap") ? outs.at("gap").value : case_gap;  // under load the mean plate gap
    r.normal_bottom = output(outs, "normal_stress_bottom", source);
    r.normal_top = output(outs, "normal_stress_top", source);
    r.shear_bottom = output(outs, "shear_stress_bottom", source);
    r.shear_top = output(outs, "shear_stress_top", source);
    r.z_core = flow_number(flow_regime, "coordination_number_core");
    r.z_bulk = flow_number(flow_regime, "coordination_number");
    if (outs.count("slip_bottom") && outs.count("slip_top"))
        r.slip_bottom = output(outs, "slip_bottom", source), r.slip_top = output(outs, "slip_top", source);
    return r;
}

CoreRheology run_core(const Case& c, const OperatingPoint& p, const Profile& profile,
                      const std::map<std::string, Scalar>& outputs, const nlohmann::json& record,
                      const std::string& source) {
    const nlohmann::json none = nlohmann::json::object();
    const nlohmann::json& fr = record.contains("flow_regime") ? record.at("flow_regime") : none;
    return core_rheology(core_run(profile, p.speed, outputs, fr, c.cell.gap, bump_protrusion(c, p.bottom),
                                  bump_protrusion(c, p.top), source),
                         c.grains.diameter, c.grains.density);
}

CoreRheology core_rheology(const CoreRun& run, double diameter, double density) {
    if (!run.profile) throw Error("core rheology: no profile");
    CoreRheology r;
    const CoreStations c = core_stations(*run.profile, r.core_from, r.core_to);
    r.stations = c.y.size();
    if (r.stations < 6)
        throw Error(fmt::format("core rheology: {} profile stations lie in the core (y/H in [{:.3f}, {:.3f}]); at least "
                                "6 are needed for the fit and its two halves: raise [dem] stations",
                                r.stations, r.core_from, r.core_to));
    // u/U = a + b y/H: gamma_dot = b U / H. Its sign: the floor moves at +U, the top is held, so u
    // falls across the gap and the shear rate is -b U / H.
    const LineFit f = fit_line(c.y, c.u, c.ue);
    const double scale = -run.speed / run.gap;
    r.shear_rate = {f.slope * scale, std::abs(f.slope_error * scale)};
    if (!(r.shear_rate.value > 0))
        throw Error(fmt::format("core rheology: the core's shear rate is {:.4g} 1/s: the core does not flow",
                                r.shear_rate.value));
    const std::size_t half = r.stations / 2;
    r.shear_rate_halves = (half_slope(c, half, r.stations) - half_slope(c, 0, half)) / f.slope;

    r.pressure = mean_of(run.normal_bottom, run.normal_top);
    if (!(r.pressure.value > 0)) throw Error(fmt::format("core rheology: the walls' normal stress is {:.4g} Pa", r.pressure.value));
    r.shear_stress = mean_of(run.shear_bottom, run.shear_top);
    r.wall_shear_imbalance = (run.shear_top.value - run.shear_bottom.value) / r.shear_stress.value;
    r.wall_normal_imbalance = (run.normal_top.value - run.normal_bottom.value) / r.pressure.value;
    r.friction = ratio(r.shear_stress, r.pressure);
    // I = gamma_dot d / sqrt(P / rho): relative error of gamma_dot and half that of P
    const double I = r.shear_rate.value * diameter / std::sqrt(r.pressure.value / density);
    r.inertial_number = {I, I * std::hypot(r.shear_rate.error / r.shear_rate.value,
                                           0.5 * r.pressure.error / r.pressure.value)};
    r.solid_fraction = station_mean(c.nu, c.nue);
    // T/(d gamma_dot)^2 = (T/U^2) U^2 / (d gamma_dot)^2: relative error of T and twice that of gamma_dot
    const Measured T = station_mean(c.T, c.Te);
    const double k = run.speed / (diameter * r.shear_rate.value);
    const double Ts = T.value * k * k;
    r.temperature_scaled = {Ts, Ts * std::hypot(T.error / T.value, 2.0 * r.shear_rate.error / r.shear_rate.value)};
    r.coordination_core = run.z_core.has_value();
    r.coordination = run.z_core ? run.z_core : run.z_bulk;
    if (run.slip_bottom && run.slip_top) {
        const NearWallTemperature nw =
            near_wall_temperature(*run.profile, run.gap, diameter, run.protrusion_bottom, run.protrusion_top);
        const auto over_U = [&](const Measured& m) { return Measured{m.value / run.speed, m.error / run.speed}; };
        r.walls = WallLayers{over_U(*run.slip_bottom), over_U(*run.slip_top), nw.bottom, nw.top};
    }
    return r;
}

std::vector<std::string> core_dt_unconverged(const CoreRheology& a, const CoreRheology& b) {
    std::vector<std::string> out;
    const auto moved = [](const Measured& x, const Measured& y) {
        const double change = x.value - y.value, err = std::hypot(x.error, y.error);
        return std::abs(change) > kDtMaxRelativeStressChange * std::abs(y.value) &&
               !(err > 0 && std::abs(change) <= kDtMaxStressZ * err);
    };
    if (moved(a.inertial_number, b.inertial_number)) out.emplace_back("I");
    if (moved(a.friction, b.friction)) out.emplace_back("mu");
    if (std::abs(a.solid_fraction.value - b.solid_fraction.value) > kDtMaxSolidFractionChange) out.emplace_back("nu");
    return out;
}

CoreRheology pool_core_rheology(const std::vector<CoreRheology>& m) {
    if (m.empty()) throw Error("pooled core rheology: no member");
    for (const CoreRheology& x : m)
        if (x.stations != m.front().stations)
            throw Error(fmt::format("pooled core rheology: the members' cores hold {} and {} stations", m.front().stations,
                                    x.stations));
    const auto measured = [&](auto field) {
        std::vector<double> v;
        std::vector<std::optional<double>> se;
        for (const CoreRheology& x : m) {
            const Measured f = field(x);
            v.push_back(f.value), se.push_back(f.error);
        }
        const SeedMean p = seed_mean(v, se);
        return Measured{p.mean, std::max(p.seed_stderr, p.block_stderr.value_or(0))};
    };
    const auto mean = [&](auto field) {
        double s = 0;
        for (const CoreRheology& x : m) s += field(x);
        return s / static_cast<double>(m.size());
    };
    CoreRheology r = m.front();
    r.shear_rate = measured([](const CoreRheology& x) { return x.shear_rate; });
    r.pressure = measured([](const CoreRheology& x) { return x.pressure; });
    r.shear_stress = measured([](const CoreRheology& x) { return x.shear_stress; });
    r.inertial_number = measured([](const CoreRheology& x) { return x.inertial_number; });
    r.friction = measured([](const CoreRheology& x) { return x.friction; });
    r.solid_fraction = measured([](const CoreRheology& x) { return x.solid_fraction; });
    r.temperature_scaled = measured([](const CoreRheology& x) { return x.temperature_scaled; });
    r.shear_rate_halves = mean([](const CoreRheology& x) { return x.shear_rate_halves; });
    r.wall_shear_imbalance = mean([](const CoreRheology& x) { return x.wall_shear_imbalance; });
    r.wall_normal_imbalance = mean([](const CoreRheology& x) { return x.wall_normal_imbalance; });
    const bool all_z = std::all_of(m.begin(), m.end(), [&](const CoreRheology& x) {
        return x.coordination && x.coordination_core == m.front().coordination_core;
    });
    r.coordination = std::nullopt;
    if (all_z) r.coordination = measured([](const CoreRheology& x) { return *x.coordination; });
    r.walls = std::nullopt;
    if (std::all_of(m.begin(), m.end(), [](const CoreRheology& x) { return x.walls.has_value(); }))
        r.walls = WallLayers{measured([](const CoreRheology& x) { return x.walls->slip_bottom; }),
                             measured([](const CoreRheology& x) { return x.walls->slip_top; }),
                             measured([](const CoreRheology& x) { return x.walls->T_bottom; }),
                             measured([](const CoreRheology& x) { return x.walls->T_top; })};
    return r;
}

}  // namespace granlub
