// Reading LIGGGHTS' wall-force and snapshot files and forming the point's results (outputs.h).
#include "outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "deck.h"
#include "granlub/error.h"
#include "granlub/regime.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

// Calls row(values, line number) for each data line of a LIGGGHTS text output (fix ave/time
// style: blank lines and # comments skipped); `what` names the file in the "not written" error.
// Numbers are read with strtod, which also takes the "nan" and "inf" LIGGGHTS prints when a run
// blows up (an istream stops there, silently shortening the row).
template <class Row>
void for_each_data_line(const fs::path& file, const char* what, Row row) {
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("{}: LIGGGHTS wrote no {} file", file.string(), what));
    std::string l, token;
    std::vector<double> values;
    std::size_t lineno = 0;
    while (std::getline(in, l)) {
        ++lineno;
        if (l.empty() || l[0] == '#') continue;
        std::istringstream ss(l);
        values.clear();
        while (ss >> token) {
            char* end = nullptr;
            values.push_back(std::strtod(token.c_str(), &end));
            if (end != token.c_str() + token.size())
                throw SolverError(fmt::format("{}:{}: '{}' is not a number", file.string(), lineno, token));
        }
        if (!values.empty()) row(values, lineno);
    }
}

}  // namespace

WallSeries read_wall_series(const fs::path& file) {
    WallSeries w;
    for_each_data_line(file, "wall-force", [&](const std::vector<double>& v, std::size_t lineno) {
        const std::size_t n = v.size() - 1;  // columns after the step
        if (w.columns.empty()) w.columns.resize(n);
        if (n != w.columns.size() || n == 0)
            throw SolverError(fmt::format("{}:{}: expected {} columns after the step", file.string(), lineno,
                                          std::max<std::size_t>(w.columns.size(), 1)));
        for (std::size_t k = 1; k <= n; ++k)
            if (!std::isfinite(v[k]))
                throw SolverError(fmt::format("{}:{}: non-finite wall force (the run blew up; reduce the time step)",
                                              file.string(), lineno));
        w.step.push_back(v[0]);
        for (std::size_t k = 0; k < n; ++k) w.columns[k].push_back(v[k + 1]);
    });
    if (w.step.empty()) throw SolverError(fmt::format("{}: no wall-force samples", file.string()));
    return w;
}

std::size_t for_each_snapshot(const fs::path& file, const std::function<void(const ParticleSet&, double)>& snapshot) {
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("{}: LIGGGHTS wrote no particle snapshots", file.string()));
    std::string l;
    std::size_t count = 0;
    ParticleSet p;
    auto bad = [&](const std::string& why) {
        return SolverError(fmt::format("{}: snapshot {}: {}", file.string(), count + 1, why));
    };
    while (std::getline(in, l)) {
        if (l.rfind("ITEM: TIMESTEP", 0) != 0) continue;
        double step = 0;
        std::size_t n = 0;
        if (!(in >> step)) throw bad("no time step");
        std::getline(in, l);
        std::getline(in, l);  // ITEM: NUMBER OF ATOMS
        if (!(in >> n)) throw bad("no atom count");
        std::getline(in, l);
        for (int k = 0; k < 4; ++k) std::getline(in, l);  // box bounds
        std::getline(in, l);                               // ITEM: ATOMS <columns>
        if (l != std::string("ITEM: ATOMS ") + kSnapshotColumns && l != std::string("ITEM: ATOMS ") + kSnapshotColumns + " ")
            throw bad(fmt::format("unexpected columns: '{}' (expected: {})", l, kSnapshotColumns));
        p.clear();
        p.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            double id, x, y, z, vx, vy, vz, r;
            if (!(in >> id >> x >> y >> z >> vx >> vy >> vz >> r)) throw bad("truncated");
            if (id != static_cast<double>(i + 1)) throw bad(fmt::format("atom {} has id {} (sorted ids expected)", i + 1, id));
            p.push_back(x, y, z, vx, vy, vz, r);
        }
        snapshot(p, step);
        ++count;
    }
    return count;
}

PlateSeries read_plate_series(const fs::path& file) {
    PlateSeries p;
    for_each_data_line(file, "plate-position", [&](const std::vector<double>& v, std::size_t lineno) {
        if (v.size() != 2 || !std::isfinite(v[1]))
            throw SolverError(fmt::format("{}:{}: expected: step gap", file.string(), lineno));
        const double step = v[0], gap = v[1];
        if (step <= 0 || (!p.step.empty() && step <= p.step.back())) return;  // initial position, repeats
        p.step.push_back(step);
        p.gap.push_back(gap);
    });
    if (p.step.size() < 2) throw SolverError(fmt::format("{}: fewer than 2 plate positions", file.string()));
    return p;
}

SteadyWindow steady_window(const Settings& s, const WallSeries& w, const PlateSeries* plate) {
    SteadyWindow win;
    for (std::size_t col : {1u, 4u, 0u, 3u}) {  // normal and shear force, bottom and top (MSER is scale-free)
        const SteadyState ss = detect_steady_state(w.columns.at(col));
        win.wall_start = std::max(win.wall_start, ss.start);
        win.steady = win.steady && ss.steady;
    }
    auto wall_begin = [&](std::size_t i) { return w.step[i] - static_cast<double>(s.sample_every); };
    if (plate) {
        const SteadyState ss = detect_steady_state(plate->gap);
        win.steady = win.steady && ss.steady;
        const std::size_t last = plate->step.size() - 1;
        const double begin = plate->step[std::min(ss.start, last)] - static_cast<double>(s.servo_every);
        while (win.wall_start + 1 < w.step.size() && wall_begin(win.wall_start) < begin - 0.5) ++win.wall_start;
        while (win.plate_start + 1 < plate->step.size() &&
               plate->step[win.plate_start] - static_cast<double>(s.servo_every) < wall_begin(win.wall_start) - 0.5)
            ++win.plate_start;
    }
    win.t_start = win.wall_start < w.step.size() ? wall_begin(win.wall_start) * s.time_step : 0.0;
    return win;
}

BlockEstimate mean_gap(const Settings& s, const PlateSeries& plate, const SteadyWindow& w) {
    return block_average(std::span<const double>(plate.gap).subspan(w.plate_start), s.blocks);
}

std::vector<double> window_stresses(const Settings& s, const WallSeries& w, const PlateSeries& plate) {
    const double A = s.box.length * s.box.width;
    std::vector<double> out;
    std::size_t i = 0;
    for (std::size_t j = 0; j < plate.step.size(); ++j) {
        double sum = 0;
        std::size_t n = 0;
        while (i < w.step.size() && w.step[i] <= plate.step[j] + 0.5) {
            if (w.step[i] > plate.step[j] - static_cast<double>(s.servo_every) + 0.5) {
                sum += -w.columns[4][i] / A;
                ++n;
            }
            ++i;
        }
        out.push_back(n > 0 ? sum / static_cast<double>(n) : -1.0);
    }
    return out;
}

std::string gap_csv(const Settings& s, const WallSeries& w, const PlateSeries& plate, const std::string& comment) {
    const std::vector<double> p_w = window_stresses(s, w, plate);
    std::string out = fmt::format("# {}\n# plate (top wall) position after each servo window of {} steps; stress = "
                                  "top-wall normal stress averaged over the window; target {} Pa\n"
                                  "time_s,gap_m,normal_stress_top_Pa\n",
                                  comment, s.servo_every, s.target_stress);
    for (std::size_t j = 0; j < plate.step.size(); ++j)
        out += fmt::format("{},{},{}\n", plate.step[j] * s.time_step, plate.gap[j],
                           p_w[j] >= 0 ? fmt::format("{}", p_w[j]) : std::string(""));
    return out;
}

DemOutputs make_outputs(const Case& c, const OperatingPoint& pt, const Settings& s, const WallSeries& w,
                        const SliceCoarseGrainer& cg, const SteadyWindow& win, const PlateSeries* plate,
                        std::size_t grains) {
    DemOutputs o;
    const double A = s.box.length * s.box.width;
    const double U = pt.speed;
    // the four stresses as time series (Pa)
    auto series = [&](std::size_t col, double sign) {
        std::vector<double> v(w.columns.at(col));
        for (double& x : v) x *= sign / A;
        return v;
    };
    const std::vector<double> sig_b = series(1, 1.0), sig_t = series(4, -1.0);
    const std::vector<double> tau_b = series(0, 1.0), tau_t = series(3, -1.0);

    const std::size_t start = win.wall_start;
    const bool steady = win.steady;
    const double t_start = win.t_start;
    auto est = [&](const std::vector<double>& v) {
        return block_average(std::span<const double>(v).subspan(start), s.blocks);
    };
    auto put = [&](const std::string& name, const BlockEstimate& e) {
        o.outputs[name] = Scalar{e.mean, e.stderr_, "Pa"};
    };
    put("normal_stress_bottom", est(sig_b));
    put("normal_stress_top", est(sig_t));
    put("shear_stress_bottom", est(tau_b));
    put("shear_stress_top", est(tau_t));
    if (w.columns.size() >= 8) {  // side walls: shear stress on each (area L H), mean of both
        std::vector<double> side(w.columns[6].size());
        const double As = s.box.length * s.box.gap;
        for (std::size_t i = 0; i < side.size(); ++i) side[i] = 0.5 * (w.columns[6][i] + w.columns[7][i]) / As;
        const auto e = est(side);
        o.outputs["shear_stress_side"] = Scalar{e.mean, e.stderr_, "Pa"};
    }

    // snapshots from the steady state on
    const auto& times = cg.times();
    std::size_t first = 0;
    while (first < times.size() && times[first] < t_start - 1e-12) ++first;
    if (times.size() - first < 2) first = times.size() >= 2 ? times.size() - 2 : 0;
    o.profile = cg.profile(U, first, s.blocks);

    const auto& u = o.profile.column("u_over_U");
    const auto& ue = o.profile.column("u_over_U_stderr");
    const std::size_t n = u.size();
    // slip: wall speed minus the mean velocity of the slab next to the wall (the wall layer)
    o.outputs["slip_bottom"] = Scalar{U * (1.0 - u[0]), U * ue[0], "m/s"};
    o.outputs["slip_top"] = Scalar{U * u[n - 1], U * ue[n - 1], "m/s"};
    o.outputs["mean_solid_fraction"] = Scalar{cg.mean_solid_fraction(first, cg.snapshots()), std::nullopt, ""};
    std::string load_line;
    if (plate) {
        // the grains' volume over the mean gap: exact for the grain count (the slabs end at the mean
        // gap, so the coarse-grained value would miss grains while the plate is above it)
        const BlockEstimate g = mean_gap(s, *plate, win);
        const double vg = std::numbers::pi / 6.0 * std::pow(c.grains.diameter, 3);
        const double nu = static_cast<double>(grains) * vg / (A * g.mean);
        o.outputs["gap"] = Scalar{g.mean, g.stderr_, "m"};
        o.outputs["mean_solid_fraction"] = Scalar{nu, nu * g.stderr_ / g.mean, ""};
        const Scalar& top = o.outputs["normal_stress_top"];
        auto at_a_limit = [&](double h) { return h <= s.gap_min * (1 + 1e-9) || h >= s.gap_max * (1 - 1e-9); };
        const auto at_limit = static_cast<std::size_t>(std::count_if(plate->gap.begin(), plate->gap.end(), at_a_limit));
        const bool limit_now = at_a_limit(plate->gap.back());
        // windows whose stress error hit the upper clamp (their plate move was capped)
        std::size_t clamped = 0;
        for (double pw : window_stresses(s, w, *plate))
            if (pw > (1.0 + s.servo_max_error) * s.target_stress) ++clamped;
        o.run["load_control"] = {
            {"target_normal_stress_Pa", s.target_stress},
            {"normal_stress_top_over_target", top.value / s.target_stress},
            {"deviation_in_stderr",  // 0 when there is no error bar (never inf/NaN in a result)
             top.stderr_.value_or(0) > 0 ? (top.value - s.target_stress) / *top.stderr_ : 0.0},
            {"gap_initial_m", s.box.gap},
            {"gap_mean_m", g.mean},
            {"gap_stderr_m", g.stderr_},
            {"gap_final_m", plate->gap.back()},
            {"servo_updates", plate->gap.size()},
            {"servo_updates_used", plate->gap.size() - win.plate_start},
            {"updates_at_plate_limit", at_limit},
            {"updates_error_clamped", clamped},
            {"plate_at_limit_at_end", limit_now},
            {"gap_file", kGapFile}};
        load_line = fmt::format(" gap={:.4g} mm (P_top/P={:.3f}{})", 1e3 * g.mean, top.value / s.target_stress,
                                limit_now ? ", PLATE AT ITS LIMIT: target not reachable" : "");
    }
    o.outputs["max_solid_fraction"] = Scalar{c.cell.max_solid_fraction, std::nullopt, ""};

    o.run.update(nlohmann::json{{"steady_state_detected", steady},
             {"steady_state_start_s", t_start},
             {"wall_samples", w.step.size()},
             {"wall_samples_used", w.step.size() - start},
             {"snapshots", cg.snapshots()},
             {"snapshots_used", cg.snapshots() - first}});
    const double simulated = static_cast<double>(s.steps) * s.time_step;
    set_regime(o.run, steady ? RegimeStatus::Steady : RegimeStatus::Transient,
               steady ? "" : fmt::format("no steady state detected in {:.3g} s of simulated time: run longer (--full)",
                                         simulated));
    o.line = fmt::format("nu={:.3f} P_bot={:.4g} P_top={:.4g} tau_bot={:.4g} tau_top={:.4g} Pa slip={:.3f}/{:.3f} U{}",
                         o.outputs["mean_solid_fraction"].value, o.outputs["normal_stress_bottom"].value,
                         o.outputs["normal_stress_top"].value, o.outputs["shear_stress_bottom"].value,
                         o.outputs["shear_stress_top"].value, o.outputs["slip_bottom"].value / U,
                         o.outputs["slip_top"].value / U,
                         steady ? fmt::format(" (steady from {:.3g} s)", t_start) : " (NO steady state detected: run longer)");
    o.line += load_line;
    return o;
}

}  // namespace granlub::dem
