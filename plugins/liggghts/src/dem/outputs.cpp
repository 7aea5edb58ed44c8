// Reading LIGGGHTS' wall-force and snapshot files and forming the point's results (outputs.h).
#include "outputs.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub::dem {

namespace fs = std::filesystem;

WallSeries read_wall_series(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("{}: LIGGGHTS wrote no wall-force file", file.string()));
    WallSeries w;
    std::string l;
    std::size_t lineno = 0;
    while (std::getline(in, l)) {
        ++lineno;
        if (l.empty() || l[0] == '#') continue;
        std::istringstream ss(l);
        double step;
        ss >> step;
        std::vector<double> row;
        double v;
        while (ss >> v) row.push_back(v);
        if (w.columns.empty()) w.columns.resize(row.size());
        if (row.size() != w.columns.size() || row.empty())
            throw SolverError(fmt::format("{}:{}: expected {} columns after the step", file.string(), lineno,
                                          w.columns.size()));
        for (double x : row)
            if (!std::isfinite(x))
                throw SolverError(fmt::format("{}:{}: non-finite wall force (the run blew up; reduce the time step)",
                                              file.string(), lineno));
        w.step.push_back(step);
        for (std::size_t k = 0; k < row.size(); ++k) w.columns[k].push_back(row[k]);
    }
    if (w.step.empty()) throw SolverError(fmt::format("{}: no wall-force samples", file.string()));
    return w;
}

std::size_t read_snapshots(const fs::path& file, double dt, SliceCoarseGrainer& cg) {
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
        std::getline(in, l);                               // ITEM: ATOMS id y vx vy vz radius
        if (l.find("id y vx vy vz radius") == std::string::npos) throw bad("unexpected columns: " + l);
        p.clear();
        p.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            double id, y, vx, vy, vz, r;
            if (!(in >> id >> y >> vx >> vy >> vz >> r)) throw bad("truncated");
            p.push_back(0.0, y, 0.0, vx, vy, vz, r);
        }
        cg.add_snapshot(p, step * dt);
        ++count;
    }
    return count;
}

DemOutputs make_outputs(const Case& c, const OperatingPoint& pt, const Settings& s, const WallSeries& w,
                        const SliceCoarseGrainer& cg) {
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

    std::size_t start = 0;
    bool steady = true;
    for (const auto* v : {&sig_b, &sig_t, &tau_b, &tau_t}) {
        const SteadyState ss = detect_steady_state(*v);
        start = std::max(start, ss.start);
        steady = steady && ss.steady;
    }
    const double t_start = start < w.step.size() ? (w.step[start] - static_cast<double>(s.sample_every)) * s.time_step
                                                 : 0.0;
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
    o.outputs["max_solid_fraction"] = Scalar{c.cell.max_solid_fraction, std::nullopt, ""};

    o.run = {{"steady_state_detected", steady},
             {"steady_state_start_s", t_start},
             {"wall_samples", w.step.size()},
             {"wall_samples_used", w.step.size() - start},
             {"snapshots", cg.snapshots()},
             {"snapshots_used", cg.snapshots() - first}};
    o.line = fmt::format("nu={:.3f} P_bot={:.4g} P_top={:.4g} tau_bot={:.4g} tau_top={:.4g} Pa slip={:.3f}/{:.3f} U{}",
                         o.outputs["mean_solid_fraction"].value, o.outputs["normal_stress_bottom"].value,
                         o.outputs["normal_stress_top"].value, o.outputs["shear_stress_bottom"].value,
                         o.outputs["shear_stress_top"].value, o.outputs["slip_bottom"].value / U,
                         o.outputs["slip_top"].value / U,
                         steady ? fmt::format(" (steady from {:.3g} s)", t_start) : " (NO steady state detected: run longer)");
    return o;
}

}  // namespace granlub::dem
