#include "statistics/metrics.h"

#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "formats/format.h"
#include "statistics/stats.h"

namespace granlub::postproc {
namespace {

// Groups points by a key; the label names only the keys that vary between groups.
template <class Key>
std::vector<PointGroup> group_by(const std::vector<const OperatingPoint*>& points, Key key) {
    std::vector<PointGroup> groups;
    std::vector<decltype(key(*points.front()))> keys;
    for (const OperatingPoint* p : points) {
        const auto k = key(*p);
        std::size_t g = 0;
        while (g < keys.size() && keys[g] != k) ++g;
        if (g == keys.size()) keys.push_back(k), groups.push_back({});
        groups[g].points.push_back(p);
    }
    return groups;
}

std::string varying_label(const std::vector<PointGroup>& groups, std::size_t g, bool include_speed) {
    if (groups.size() < 2) return {};
    const OperatingPoint& p = *groups[g].points.front();
    auto varies = [&](auto get) {
        for (const auto& other : groups)
            if (get(*other.points.front()) != get(p)) return true;
        return false;
    };
    std::vector<std::string> parts;
    if (include_speed && varies([](const OperatingPoint& q) { return q.speed; }))
        parts.push_back(fmt::format("U = {} m/s", num(p.speed)));
    if (varies([](const OperatingPoint& q) { return q.bottom.roughness; }))
        parts.push_back(fmt::format("R = {}", num(p.bottom.roughness)));
    else if (varies([](const OperatingPoint& q) { return q.top.roughness; }))
        parts.push_back(fmt::format("R top = {}", num(p.top.roughness)));
    if (varies([](const OperatingPoint& q) { return q.solid_fraction; }))
        parts.push_back(fmt::format("ν = {}", num(p.solid_fraction)));
    if (varies([](const OperatingPoint& q) { return q.normal_stress; }))
        parts.push_back(fmt::format("P = {} Pa", num(p.normal_stress)));
    if (parts.empty()) return fmt::format("group {}", g + 1);
    std::string s = parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i) s += ", " + parts[i];
    return s;
}

MetricRow row(std::string kind, std::string point, std::string quantity, std::string a, std::string b) {
    MetricRow r;
    r.kind = std::move(kind);
    r.point = std::move(point);
    r.quantity = std::move(quantity);
    r.solver_a = std::move(a);
    r.solver_b = std::move(b);
    return r;
}

auto wall_key(const Wall& w) { return std::tuple(w.restitution, w.friction, w.roughness); }

}  // namespace

std::vector<PointGroup> speed_groups(const std::vector<const OperatingPoint*>& points) {
    if (points.empty()) return {};
    auto g = group_by(points, [](const OperatingPoint& p) {
        return std::tuple(static_cast<int>(p.control), p.solid_fraction, p.normal_stress, wall_key(p.bottom),
                          wall_key(p.top));
    });
    for (std::size_t i = 0; i < g.size(); ++i) g[i].label = varying_label(g, i, false);
    return g;
}

std::vector<PointGroup> roughness_groups(const std::vector<const OperatingPoint*>& points) {
    if (points.empty()) return {};
    auto g = group_by(points, [](const OperatingPoint& p) {
        return std::tuple(p.speed, static_cast<int>(p.control), p.solid_fraction, p.normal_stress,
                          p.bottom.restitution, p.bottom.friction, p.top.restitution, p.top.friction);
    });
    for (std::size_t i = 0; i < g.size(); ++i) g[i].label = varying_label(g, i, true);
    return g;
}

bool controlled_stress(const PointGroup& group, const std::string& q) {
    // The top plate carries the load; the bottom wall carries the load plus the grains' weight:
    // both follow the control, so a power law in U would fit the case, not the model.
    return (q == "normal_stress_top" || q == "normal_stress_bottom") && !group.points.empty() &&
           group.points.front()->control == Control::Load;
}

StressFit stress_fit(const Collection& col, const PointGroup& group, const std::string& solver, const std::string& q) {
    StressFit out;
    std::vector<double> u, s;
    std::vector<std::optional<double>> se;
    for (const OperatingPoint* p : group.points) {
        const Run& r = col.run(solver, p->id);
        if (!r.usable()) continue;
        if (!r.steady()) {
            ++out.other_points;
            continue;
        }
        ++out.steady_points;
        u.push_back(p->speed);
        s.push_back(*r.scalar(q));
        se.push_back(r.scalar_stderr(q));
    }
    if (controlled_stress(group, q))
        out.why_not = "not fitted: the load control sets it (the control variable, not a result)";
    else if (out.steady_points < kMinFitPoints)
        out.why_not = fmt::format("not fitted: {} steady point{} (needs {})", out.steady_points,
                                  out.steady_points == 1 ? "" : "s", kMinFitPoints);
    else if (!(out.fit = power_fit(u, s, se)))
        out.why_not = fmt::format("not fitted: the {} steady points do not span two speeds with positive stress",
                                  out.steady_points);
    return out;
}

std::vector<MetricRow> compute_metrics(const Collection& col) {
    std::vector<MetricRow> rows;
    for (const OperatingPoint* p : col.points) {
        const auto runs = col.usable(p->id);
        for (std::size_t i = 0; i < runs.size(); ++i) {
            for (std::size_t j = i + 1; j < runs.size(); ++j) {
                const Run& a = *runs[i];
                const Run& b = *runs[j];
                // A result that is not steady is not compared: its values are listed, no difference.
                std::string not_compared;
                for (const Run* r : {&a, &b})
                    if (!r->steady())
                        not_compared += fmt::format("{}{} is {}", not_compared.empty() ? "not compared: " : ", ",
                                                    r->solver, r->state_name());
                auto pair_row = [&](const char* kind, const char* q) {
                    MetricRow r = row(kind, p->id, q, a.solver, b.solver);
                    r.status_a = a.state_name();
                    r.status_b = b.state_name();
                    r.note = not_compared;
                    return r;
                };
                for (const auto& q : kProfileQuantities) {
                    const auto d = profile_difference(a.y(), a.column(q.key), a.column_stderr(q.key), b.y(),
                                                      b.column(q.key), b.column_stderr(q.key));
                    if (!(d.hi > d.lo)) continue;  // the station ranges do not overlap: nothing to compare
                    MetricRow r = pair_row("profile", q.key);
                    if (not_compared.empty()) {
                        r.rms = d.rms;
                        r.max = d.max;
                        r.y_at_max = d.y_at_max;
                        r.noise_rms = d.noise_rms;
                    }
                    rows.push_back(std::move(r));
                }
                for (const auto& q : kScalarQuantities) {
                    MetricRow r = pair_row("scalar", q.key);
                    r.a = a.scalar(q.key);
                    r.b = b.scalar(q.key);
                    if (!r.a || !r.b) continue;
                    r.a_stderr = a.scalar_stderr(q.key);
                    r.b_stderr = b.scalar_stderr(q.key);
                    if (not_compared.empty()) {
                        r.difference = *r.a - *r.b;
                        r.combined_stderr = combined_stderr(r.a_stderr, r.b_stderr);
                        if (r.combined_stderr && *r.combined_stderr > 0) r.z = *r.difference / *r.combined_stderr;
                    }
                    rows.push_back(std::move(r));
                }
            }
        }
    }
    for (const auto& group : speed_groups(col.points)) {
        for (const auto& solver : col.solvers) {
            for (const char* q : kStressOutputs) {
                const StressFit f = stress_fit(col, group, solver, q);
                if (f.steady_points + f.other_points == 0) continue;
                MetricRow r = row("exponent", group.label.empty() ? "all" : group.label, q, solver, "");
                if (f.fit) {
                    r.a = f.fit->exponent;
                    r.a_stderr = f.fit->exponent_stderr;
                    r.fit_points = f.fit->points;
                    r.status_a = "steady";
                }
                r.note = f.why_not;
                if (f.other_points > 0)
                    r.note += fmt::format("{}{} point{} not steady, left out", r.note.empty() ? "" : "; ", f.other_points,
                                          f.other_points == 1 ? "" : "s");
                rows.push_back(std::move(r));
            }
        }
    }
    return rows;
}

std::string metrics_csv(const std::vector<MetricRow>& rows) {
    std::string out = "# granlub compare: cross-code metrics. Differences are solver_a - solver_b on normalised\n"
                      "# profiles (y/H grid of 101 points over the overlap of both solvers' stations) and scalars;\n"
                      "# combined_stderr = sqrt(se_a^2 + se_b^2), z = difference / combined_stderr, significant = |z| > 2.\n"
                      "# a_stderr, b_stderr: a particle result pooled over seeds (run.seeds in its summary): the seeds'\n"
                      "# standard error; one run: its own block error (other seeds scatter 2-9x more: the report's legend).\n"
                      "# exponent rows: n in stress = c U^n fitted per solver (a = n, a_stderr its standard error)\n"
                      "# over steady points only, at least 3. status_a/status_b: each run's regime (steady, transient,\n"
                      "# dt-unconverged, status unknown); a pair with a run that is not steady has no difference, z or\n"
                      "# rms (note says why).\n";
    out += kMetricsHeader;
    out += '\n';
    const auto n = [](const std::optional<double>& v) { return num(v, 8); };
    for (const auto& r : rows) {
        out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.kind, csv_field(r.point),
                           r.quantity, csv_field(r.solver_a), csv_field(r.solver_b), n(r.a), n(r.a_stderr), n(r.b),
                           n(r.b_stderr), n(r.difference), n(r.combined_stderr), n(r.z),
                           r.z ? (r.significant() ? "yes" : "no") : "", n(r.rms), n(r.max), n(r.y_at_max),
                           n(r.noise_rms), r.fit_points ? std::to_string(*r.fit_points) : "", csv_field(r.status_a),
                           csv_field(r.status_b), csv_field(r.note));
    }
    return out;
}

}  // namespace granlub::postproc
