// The engine-independent reduction of a particle run (see particle_reduction.h).
#include "granlub/particles/particle_reduction.h"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "granlub/results/run_status.h"
#include "granlub/statistics/decorrelation.h"

namespace granlub {

namespace {

std::vector<double> times(const std::vector<double>& v, double k) {
    std::vector<double> o(v);
    for (double& x : o) x *= k;
    return o;
}

}  // namespace

WallStresses wall_stresses(const WallForceSeries& f, const ParticleBox& box) {
    const double A = box.length * box.width;
    WallStresses s{times(f.fy_bottom, -1.0 / A), times(f.fy_top, 1.0 / A), times(f.fx_bottom, -1.0 / A),
                   times(f.fx_top, 1.0 / A), {}};
    if (!f.fx_side1.empty()) {
        const double As = box.length * box.gap;
        s.shear_side.resize(f.rows());
        s.shear_outer.resize(f.rows());
        s.shear_inner.resize(f.rows());
        for (std::size_t i = 0; i < s.shear_side.size(); ++i) {
            s.shear_side[i] = -0.5 * (f.fx_side1[i] + f.fx_side2[i]) / As;
            s.shear_outer[i] = -f.fx_side1[i] / As;
            s.shear_inner[i] = -f.fx_side2[i] / As;
        }
    }
    if (!f.fy_side1.empty()) {
        s.side_support.resize(f.rows());
        for (std::size_t i = 0; i < s.side_support.size(); ++i) s.side_support[i] = -(f.fy_side1[i] + f.fy_side2[i]) / A;
    }
    return s;
}

SteadyWindow wall_steady_window(const WallStresses& st, const WallForceSeries& f, std::int64_t sample_every,
                                double time_step, const PlateSeries* plate, std::int64_t servo_every) {
    return steady_window({{"normal_stress_bottom", st.normal_bottom, kStressDrift},
                          {"normal_stress_top", st.normal_top, kStressDrift},
                          {"shear_stress_bottom", st.shear_bottom, kStressDrift},
                          {"shear_stress_top", st.shear_top, kStressDrift}},
                         f.step, sample_every,
                         time_step, plate, servo_every);
}

ParticleReduction reduce_particles(const ParticleReductionInputs& in) {
    ParticleReduction o;
    const WallStresses& st = in.stresses;
    const SteadyWindow& win = in.window;
    const std::size_t start = win.wall_start;
    const double U = in.speed;
    auto steady = [&](const std::vector<double>& v) { return std::span<const double>(v).subspan(std::min(start, v.size())); };
    // Blocks no shorter than kBlockDecorrelationTimes decorrelation times of the wall stresses
    // (decorrelation.h): the slowest of the four main series sets one block length for all.
    double tau = 1.0;
    for (const auto* v : {&st.normal_bottom, &st.normal_top, &st.shear_bottom, &st.shear_top})
        tau = std::max(tau, integrated_autocorrelation_time(steady(*v)));
    const std::size_t used = st.normal_top.size() - std::min(start, st.normal_top.size());
    const BlockChoice blocks = decorrelated_blocks(used, tau, in.blocks);
    const double block_s = in.forces.step.size() >= 2 ? in.forces.step[1] - in.forces.step[0] : 0.0;  // steps
    o.run["wall_stress_blocks"] = {
        {"requested", in.blocks},
        {"used", blocks.blocks},
        {"decorrelation_time_samples", tau},
        {"decorrelation_time_s", tau * block_s * in.time_step},
        {"block_length_s", blocks.blocks > 0 ? static_cast<double>(used / blocks.blocks) * block_s * in.time_step : 0.0},
        {"min_decorrelation_times_per_block", kBlockDecorrelationTimes},
        {"decorrelated", blocks.decorrelated}};
    auto put = [&](const std::string& name, const std::vector<double>& v) {
        const BlockEstimate e = block_average(steady(v), blocks.blocks);
        o.outputs[name] = Scalar{e.mean, e.stderr_, "Pa"};
        return e.mean;
    };
    const double P_b = put("normal_stress_bottom", st.normal_bottom);
    const double P_t = put("normal_stress_top", st.normal_top);
    const double T_b = put("shear_stress_bottom", st.shear_bottom);
    const double T_t = put("shear_stress_top", st.shear_top);
    if (!st.shear_side.empty()) put("shear_stress_side", st.shear_side);
    if (!st.shear_outer.empty()) put("shear_stress_outer", st.shear_outer);
    if (!st.shear_inner.empty()) put("shear_stress_inner", st.shear_inner);
    if (!st.side_support.empty()) put("side_wall_support", st.side_support);

    // snapshots from the steady state on (at least the last two)
    const auto& ts = in.cg.times();
    std::size_t first = 0;
    while (first < ts.size() && ts[first] < win.t_start - 1e-12) ++first;
    if (ts.size() - first < 2) first = ts.size() >= 2 ? ts.size() - 2 : 0;
    o.profile = in.cg.profile(U, first, in.blocks);
    if (in.cross_section) o.cross_section = in.cross_section->table(U, first);

    const auto& u = o.profile.column("u_over_U");
    const auto& ue = o.profile.column("u_over_U_stderr");
    // slip: wall speed minus the mean velocity of the slab next to the wall (the wall layer), on a
    // rough wall of the first slab clear of its bumps
    const Stations& st_y = in.cg.stations();
    std::size_t kb = 0, kt = u.size() - 1;
    while (kb + 1 < u.size() && st_y.centre(kb) < in.slip_bottom_from) ++kb;
    while (kt > kb && st_y.hi - st_y.centre(kt) < in.slip_top_from) --kt;
    o.outputs["slip_bottom"] = Scalar{U * (1.0 - u[kb]), U * ue[kb], "m/s"};
    o.outputs["slip_top"] = Scalar{U * u[kt], U * ue[kt], "m/s"};
    o.outputs["mean_solid_fraction"] = Scalar{in.cg.mean_solid_fraction(first, in.cg.snapshots()), std::nullopt, ""};
    o.outputs["max_solid_fraction"] = Scalar{in.c.cell.max_solid_fraction, std::nullopt, ""};
    std::string load_line;
    if (in.plate)  // gap, mean_solid_fraction over the mean gap, run.load_control
        o.run["load_control"] = load_summary({.servo = in.servo,
                                              .initial_gap = in.plate_start > 0 ? in.plate_start : in.box.gap,
                                              .wall_step = in.forces.step,
                                              .top_stress = st.normal_top,
                                              .plate = *in.plate,
                                              .window = win,
                                              .blocks = in.blocks,
                                              .grains = in.grains,
                                              .solids_volume = in.solids_volume,
                                              .area = in.box.length * in.box.width},
                                             o.outputs, load_line);

    const std::size_t rows = in.forces.rows();
    o.run["steady_state"] = win.to_json();
    o.run.update(nlohmann::json{{"steady_state_detected", win.steady},
                                {"steady_state_start_s", win.t_start},
                                {"wall_samples", rows},
                                {"wall_samples_used", rows - std::min(start, rows)},
                                {"snapshots", in.cg.snapshots()},
                                {"snapshots_used", in.cg.snapshots() - first}});
    set_regime(o.run, win.steady ? RegimeStatus::Steady : RegimeStatus::Transient,
               win.steady ? ""
                          : fmt::format("no steady state detected in {:.3g} s of simulated time: run longer (--full, "
                                        "or a longer `time`)",
                                        in.simulated_s));
    o.line = fmt::format("nu={:.3f} P_bot={:.4g} P_top={:.4g} tau_bot={:.4g} tau_top={:.4g} Pa "
                         "slip={:.3f}/{:.3f} U{}{}",
                         o.outputs.at("mean_solid_fraction").value, P_b, P_t, T_b, T_t, 1.0 - u[kb], u[kt],
                         win.steady ? fmt::format(" (steady from {:.3g} s)", win.t_start)
                                    : " (NO steady state detected: run longer)",
                         load_line);
    return o;
}

}  // namespace granlub
