// Steady-state detection of particle runs (see steady_state.h).
#include "granlub/statistics/steady_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "granlub/statistics/block_average.h"

namespace granlub {

SteadyState detect_steady_state(std::span<const double> x, std::size_t batch, double max_cut) {
    SteadyState s;
    if (batch == 0) batch = 1;
    const std::size_t m = x.size() / batch;
    if (m < 4) return s;  // too short to say
    std::vector<double> z(m, 0.0);
    for (std::size_t j = 0; j < m; ++j) {
        for (std::size_t i = 0; i < batch; ++i) z[j] += x[j * batch + i];
        z[j] /= static_cast<double>(batch);
    }
    // suffix sums give the mean and variance of z[d..m) in O(1) per d
    std::vector<double> s1(m + 1, 0.0), s2(m + 1, 0.0);
    for (std::size_t j = m; j-- > 0;) {
        s1[j] = s1[j + 1] + z[j];
        s2[j] = s2[j + 1] + z[j] * z[j];
    }
    const auto cut = static_cast<std::size_t>(max_cut * static_cast<double>(m));
    const std::size_t dmax = std::min(cut, m - 2);  // keep at least two batches
    double best = std::numeric_limits<double>::infinity();
    std::size_t dbest = 0;
    for (std::size_t d = 0; d <= dmax; ++d) {
        const double k = static_cast<double>(m - d);
        const double ss = std::max(0.0, s2[d] - s1[d] * s1[d] / k);  // sum of squared deviations
        const double stat = ss / (k * k);
        if (stat < best) {
            best = stat;
            dbest = d;
        }
    }
    s.start = dbest * batch;
    s.steady = dbest <= m / 2;
    return s;
}

DriftCheck drift_check(const std::string& name, std::span<const double> w, double allowed) {
    DriftCheck c{.name = name, .allowed = allowed};
    const std::size_t half = w.size() / 2;
    if (half < 2) return c;  // too short to test: no evidence of drift
    const std::size_t blocks = std::min(kDriftBlocks, half);
    const BlockEstimate a = block_average(w.first(half), blocks);
    const BlockEstimate b = block_average(w.last(half), blocks);
    double mean = 0;
    for (double v : w) mean += v;
    mean /= static_cast<double>(w.size());
    c.change = b.mean - a.mean;
    const double se = std::hypot(a.stderr_, b.stderr_);
    constexpr double inf = std::numeric_limits<double>::infinity();
    c.relative = mean != 0 ? c.change / std::abs(mean) : (c.change == 0 ? 0.0 : inf);
    c.z = se > 0 ? c.change / se : (c.change == 0 ? 0.0 : inf);
    c.resolvable = kDriftSigmas * se <= kDriftResolution * std::abs(mean);
    c.pass = std::abs(c.relative) <= allowed || (c.resolvable && std::abs(c.z) <= kDriftSigmas);
    return c;
}

nlohmann::json SteadyWindow::to_json() const {
    nlohmann::json j = {{"method", "MSER-5 start within the first half of the run, then no half-to-half drift "
                                   "beyond the allowance or 3 combined standard errors"},
                        {"allowed_relative_drift", {{"wall_stress", kStressDrift}, {"gap", kGapDrift}}},
                        {"sigmas", kDriftSigmas},
                        {"resolution", kDriftResolution},
                        {"checks", nlohmann::json::array()}};
    for (const auto& c : checks) {
        auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
        j["checks"].push_back({{"series", c.name},
                               {"relative_change", num(c.relative)},
                               {"z", num(c.z)},
                               {"resolvable", c.resolvable},
                               {"pass", c.pass}});
    }
    return j;
}

SteadyWindow steady_window(const std::vector<NamedSeries>& wall_series, std::span<const double> wall_step,
                           std::int64_t sample_every, double time_step, const PlateSeries* plate,
                           std::int64_t servo_every) {
    SteadyWindow win;
    const std::size_t n = wall_step.size();
    constexpr std::size_t kBatch = 5;  // MSER-5's batch: the start moves in these steps
    // 1. the initial transient: MSER-5, cut searched in the first half only
    std::size_t start = 0;
    for (const auto& s : wall_series) {
        const SteadyState ss = detect_steady_state(s.values, kBatch, 0.5);
        start = std::max(start, ss.start);
        win.steady = win.steady && ss.steady;  // false: too short to say
    }
    auto wall_begin = [&](std::size_t i) { return wall_step[i] - static_cast<double>(sample_every); };
    auto plate_begin = [&](std::size_t j) { return plate->step[j] - static_cast<double>(servo_every); };
    // aligns a wall index to the next plate window: both windows start at the same step
    auto align = [&](std::size_t i, std::size_t& j) {
        j = 0;
        if (!plate) return i;
        while (j + 1 < plate->step.size() && plate_begin(j) < wall_begin(std::min(i, n - 1)) - 0.5) ++j;
        while (i + 1 < n && wall_begin(i) < plate_begin(j) - 0.5) ++i;
        return i;
    };
    if (plate) {
        const SteadyState ss = detect_steady_state(plate->gap, kBatch, 0.5);
        win.steady = win.steady && ss.steady;
        const double begin = plate_begin(std::min(ss.start, plate->step.size() - 1));
        while (start + 1 < n && wall_begin(start) < begin - 0.5) ++start;
    }
    if (n == 0) return win;
    // 2. no drift left: move the start on by MSER batches until every series passes
    auto checks_from = [&](std::size_t i, std::size_t j) {
        std::vector<DriftCheck> cs;
        for (const auto& s : wall_series)
            cs.push_back(drift_check(s.name, s.values.subspan(std::min(i, s.values.size())), s.allowed_drift));
        if (plate) cs.push_back(drift_check("gap", std::span<const double>(plate->gap).subspan(j), kGapDrift));
        return cs;
    };
    auto all_pass = [](const std::vector<DriftCheck>& cs) {
        return std::all_of(cs.begin(), cs.end(), [](const DriftCheck& c) { return c.pass; });
    };
    std::size_t j0 = 0;
    const std::size_t first = align(start, j0);
    bool found = false;
    for (std::size_t i = first; win.steady && i <= n / 2; i += kBatch) {
        std::size_t j = 0;
        const std::size_t a = align(i, j);
        if (a > n / 2) break;
        auto cs = checks_from(a, j);
        if (all_pass(cs)) {
            win.wall_start = a, win.plate_start = j, win.checks = std::move(cs), found = true;
            break;
        }
        i = a;
    }
    if (!found) {  // a transient: the values from the MSER start on, labelled as such by the caller
        win.steady = false;
        win.wall_start = first, win.plate_start = j0, win.checks = checks_from(first, j0);
    }
    win.t_start = win.wall_start < n ? wall_begin(win.wall_start) * time_step : 0.0;
    return win;
}

}  // namespace granlub
