// Reading LIGGGHTS' wall-force and snapshot files and forming the point's results (outputs.h).
#include "outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
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
    // normal and shear force, bottom and top
    std::vector<std::span<const double>> series;
    for (std::size_t col : {1u, 4u, 0u, 3u}) series.emplace_back(w.columns.at(col));
    return granlub::steady_window(series, w.step, s.sample_every, s.time_step, plate, s.servo_every);
}

std::vector<double> top_normal_stress(const Settings& s, const WallSeries& w) {
    std::vector<double> v(w.columns.at(4));
    for (double& x : v) x *= -1.0 / (s.box.length * s.box.width);
    return v;
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
    const std::vector<double> sig_b = series(1, 1.0), sig_t = top_normal_stress(s, w);
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
        o.run["load_control"] = load_summary({.servo = s,
                                              .initial_gap = s.box.gap,
                                              .wall_step = w.step,
                                              .top_stress = sig_t,
                                              .plate = *plate,
                                              .window = win,
                                              .blocks = s.blocks,
                                              .grains = grains,
                                              .grain_diameter = c.grains.diameter,
                                              .area = A},
                                             o.outputs, load_line);
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
