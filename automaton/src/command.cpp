// `granlub automaton`: every selected operating point through the ensemble runner, written as
// profile.csv + summary.json (plus timeseries.csv, and VTK snapshots with --vtk).
#include "granlub/automaton/command.h"

#include <cmath>
#include <mutex>

#include <fmt/format.h>

#include "granlub/automaton/case_mapping.h"
#include "granlub/automaton/ensemble.h"
#include "granlub/automaton/keys.h"
#include "granlub/automaton/variants.h"
#include "granlub/automaton/vtk.h"
#include "granlub/error.h"
#include "granlub/run/progress.h"
#include "granlub/results/run_status.h"
#include "granlub/results/results.h"
#include "granlub/results/run_id.h"

namespace granlub::automaton {

namespace {

// The settings that make the numbers: every [automaton] key but the output-only ones (keys.h),
// and the lattice and walls the case mapped.
nlohmann::json settings_json(const Params& p) {
    nlohmann::json out;
    for (const auto& b : automaton_keys().bindings()) {
        if (b.output_only) continue;
        std::visit([&](const auto& v) { out[b.key] = v; }, b.get(p));
    }
    const auto& r = p.rules;
    out.update({{"rows", p.lattice.rows},
                {"columns", p.lattice.columns},
                {"particles", p.lattice.particles()},
                {"e_p", r.e_p},
                {"e_w_bottom", r.e_w_bottom},
                {"e_w_top", r.e_w_top},
                {"R_bottom", r.R_bottom},
                {"R_top", r.R_top}});
    return out;
}

std::vector<double> means(const std::vector<Stat>& v, double scale = 1) {
    std::vector<double> out;
    for (const Stat& s : v) out.push_back(s.mean * scale);
    return out;
}
std::vector<double> sems(const std::vector<Stat>& v, double scale = 1) {
    std::vector<double> out;
    for (const Stat& s : v) out.push_back(s.stderr_ * scale);
    return out;
}

Profile make_profile(const EnsembleResult& r, double nu_max) {
    Profile p;
    std::vector<double> eta, row;
    for (int y = 0; y < r.rows; ++y) {
        eta.push_back((y + 0.5) / r.rows);  // eta = (y + 0.5)/H, docs/automaton-model.md §2.1
        row.push_back(y);
    }
    const auto& R = r.rows_;
    p.add("y_over_H", eta);
    p.add("u_over_U", means(R.u)).add("u_over_U_stderr", sems(R.u));
    p.add("solid_fraction", means(R.nu)).add("solid_fraction_stderr", sems(R.nu));
    p.add("temperature_over_U2", means(R.temp)).add("temperature_over_U2_stderr", sems(R.temp));
    p.add("solid_fraction_scaled", means(R.nu, nu_max)).add("solid_fraction_scaled_stderr", sems(R.nu, nu_max));
    p.add("up_over_U", means(R.up)).add("up_over_U_stderr", sems(R.up));
    p.add("ux_over_U", means(R.ux)).add("ux_over_U_stderr", sems(R.ux));
    p.add("ukin_over_U", means(R.ukin)).add("ukin_over_U_stderr", sems(R.ukin));
    p.add("row", row);
    return p;
}

std::string timeseries_csv(const std::vector<TimePoint>& ts) {
    std::string out = fmt::format("# ensemble mean over replicas; u_p/U\n# {}\n", run_id_comment()) +
                      "step,mean_up_over_U,u_row0_over_U,u_top_row_over_U\n";
    for (const auto& t : ts)
        out += fmt::format("{},{:.6f},{:.6f},{:.6f}\n", t.step, t.mean_up, t.u_bottom_row, t.u_top_row);
    return out;
}

// VTK snapshots of replica 0, written from its thread; the .pvd at the end (finish()).
class Snapshots {
public:
    Snapshots(std::filesystem::path dir, double d, double U) : dir_(std::move(dir)), d_(d), U_(U) {}

    void attach(Observer& obs) {
        std::filesystem::create_directories(dir_ / "vtk");
        obs.snapshot = [this](std::int64_t step, const Lattice& e) {
            const std::string name = fmt::format("vtk/lattice_{:08d}.vti", step);
            write_file_atomic(dir_ / name, lattice_vti(e, d_));
            std::lock_guard<std::mutex> lock(mutex_);
            snaps_.emplace_back(static_cast<double>(step) * d_ / U_, name);  // one step = d/U seconds
        };
    }
    void finish() const {
        if (!snaps_.empty()) write_file_atomic(dir_ / "lattice.pvd", snapshot_pvd(snaps_));
    }

private:
    std::filesystem::path dir_;
    double d_, U_;
    std::vector<std::pair<double, std::string>> snaps_;
    std::mutex mutex_;
};

// Slips, wall stresses and the mean speed with their standard errors. The wall stresses are the
// CA's momentum exchange, converted with a lattice cell of mass rho nu_max d^3 (a full lattice =
// nu_max), area d x d per column and a step of d/U: stress = rho nu_max U^2 x (momentum per step
// per column in units of cell mass x U).
void put_wall_values(Summary& s, const EnsembleResult& r, double U, double stress) {
    auto put = [&](const std::string& name, const Stat& st, double f, const std::string& unit) {
        s.set(name, st.mean * f, unit, st.stderr_ * std::abs(f));
    };
    put("slip_bottom", r.slip_bottom, U, "m/s");
    put("slip_top", r.slip_top, U, "m/s");
    put("slip_bottom_over_U", r.slip_bottom, 1, "");
    put("slip_top_over_U", r.slip_top, 1, "");
    if (r.has_fit) {
        put("slip_bottom_fit_over_U", r.slip_bottom_fit, 1, "");
        put("slip_top_fit_over_U", r.slip_top_fit, 1, "");
    }
    put("shear_stress_bottom", r.tangential_bottom, stress, "Pa");
    put("shear_stress_top", r.tangential_top, -stress, "Pa");
    put("normal_stress_bottom", r.normal_bottom, stress, "Pa");
    put("normal_stress_top", r.normal_top, stress, "Pa");
    const std::string momentum = "grain mass x U per step per column";
    put("wall_momentum_bottom", r.tangential_bottom, 1, momentum);
    put("wall_momentum_top", r.tangential_top, -1, momentum);
    put("wall_normal_momentum_bottom", r.normal_bottom, 1, momentum);
    put("wall_normal_momentum_top", r.normal_top, 1, momentum);
    put("mean_speed_over_U", r.mean_up, 1, "");
}

// How the steady state was judged: the block test, or JH06's runs with their differences.
nlohmann::json steady_json(const EnsembleResult& r, const RunSpec& run) {
    const RunsProtocol& rp = r.runs;
    nlohmann::json steady = {{"protocol", variant_name(run.steady_protocol)},
                             {"reached", r.steady.reached}, {"from_step", r.steady.step},
                             {"note", r.steady.note}};
    if (rp.used) {
        steady["window"] = "second half of the last run [ASSUMPTION]";
        steady["run_lengths"] = rp.lengths;
        steady["max_du_over_U"] = rp.du;  // run k vs run k-1, k >= 2
        steady["max_dnu"] = rp.dnu;
        steady["final_max_du_over_U"] = rp.du.back();
        steady["final_max_dnu"] = rp.dnu.back();
        steady["final_rows"] = {{"du", rp.du_row}, {"dnu", rp.dnu_row}};
        steady["tol_u"] = run.runs_tol_u;
        steady["tol_nu"] = run.runs_tol_nu;
    } else {
        steady["drift_U_per_block"] = r.steady.drift;
        steady["tol_u"] = run.steady_tol_u;
        steady["tol_nu"] = run.steady_tol_nu;
    }
    return steady;
}

// The summary's run{}: lengths, the lattice and where its fill came from, the steady state, the
// collision counts per replica and what the model ignores.
nlohmann::json run_json(const EnsembleResult& r, const Mapping& m, std::int64_t steps_run) {
    const auto& T = r.totals;
    const double reps = r.replicas;
    return {{"steps", steps_run},
            {"replicas", r.replicas},
            {"threads", r.threads},
            {"window_blocks", r.window_blocks},
            {"lattice", {{"rows", r.rows}, {"columns", r.columns}, {"particles", r.particles},
                         {"fill", m.params.lattice.fill}, {"fill_source", m.fill_source},
                         {"mapping", "rows = round(gap/d), columns = round(length/d); one grain per cell; "
                                     "solid_fraction = lattice occupancy (max 1); solid_fraction_scaled = "
                                     "occupancy x max_solid_fraction"}}},
            {"steady_state", steady_json(r, m.params.run)},
            {"per_replica", {{"particle_updates", static_cast<double>(T.visits) / reps},
                             {"moves", static_cast<double>(T.moves) / reps},
                             {"grain_collisions", static_cast<double>(T.pp) / reps},
                             {"bottom_wall_collisions", static_cast<double>(T.wall_bottom) / reps},
                             {"top_wall_collisions", static_cast<double>(T.wall_top) / reps},
                             {"exhausted", static_cast<double>(T.exhausted) / reps}}},
            {"particle_updates_per_second", r.updates_per_second},
            {"ignored", "gravity, the centripetal force and the side walls: the JH06 lattice has no body force "
                        "and is 2-D"}};
}

// The point's line on the terminal.
std::string point_line(const EnsembleResult& r, const Summary& s, std::int64_t steps_run) {
    const RunsProtocol& rp = r.runs;
    return fmt::format("{}x{} N={} slip {:.3f}/{:.3f} U (+-{:.4f}) tau {:.3g}/{:.3g} Pa{}", r.rows, r.columns,
                       r.particles, r.slip_bottom.mean, r.slip_top.mean, r.slip_bottom.stderr_,
                       s.value("shear_stress_bottom"), s.value("shear_stress_top"),
                       r.steady.reached ? "" : "  NOT STEADY: " + r.steady.note) +
           (rp.used ? fmt::format("  [runs to {} steps, du {:.4f} U, dnu {:.4f}]", steps_run, rp.du.back(),
                                  rp.dnu.back())
                    : std::string());
}

PointResult solve_point(const Case& c, const OperatingPoint& pt, const RunOptions& o, const std::filesystem::path& dir) {
    const Mapping m = resolve_settings(c, pt, o);
    const Params& prm = m.params;
    const double U = pt.speed, d = c.grains.diameter, nu_max = c.cell.max_solid_fraction;

    Observer obs;
    Snapshots snapshots(dir, d, U);
    if (prm.run.snapshot_every > 0) snapshots.attach(obs);
    const bool by_runs = prm.run.steady_protocol == SteadyProtocol::Runs;
    const std::int64_t max_steps = by_runs ? prm.run.runs_max_steps : prm.run.steps;
    Progress progress(fmt::format("automaton {}", pt.id), static_cast<std::uint64_t>(max_steps) * prm.run.replicas);
    obs.progress = [&](std::uint64_t done, std::uint64_t) { progress.update(done); };

    const EnsembleResult r = run_ensemble(prm, obs);
    require_converged(pt.id, prm, r.runs);
    snapshots.finish();
    if (prm.run.timeseries_every > 0) write_file_atomic(dir / "timeseries.csv", timeseries_csv(r.timeseries));

    PointResult out;
    out.profile = make_profile(r, nu_max);
    Summary& s = out.summary;
    s = make_summary(c, pt, kSolver, prm.run.seed);
    s.provenance.settings = settings_json(prm);
    put_wall_values(s, r, U, c.grains.density * nu_max * U * U);
    const double occupancy = static_cast<double>(r.particles) / (static_cast<double>(r.rows) * r.columns);
    s.set("mean_solid_fraction", occupancy, "");
    s.set("max_solid_fraction", 1.0, "");
    s.set("mean_solid_fraction_scaled", occupancy * nu_max, "");

    const std::int64_t steps_run = r.runs.used ? r.runs.lengths.back() : prm.run.steps;
    s.run = run_json(r, m, steps_run);
    set_regime(s.run, r.steady.reached ? RegimeStatus::Steady : RegimeStatus::Transient,
               r.steady.reached ? "" : "no steady state: " + r.steady.note);
    out.line = point_line(r, s, steps_run);
    return out;
}

}  // namespace

void check(const Case& c, const RunOptions& o) {
    for_each_run(c, o, [&](const OperatingPoint& p, const RunOptions& v) { resolve_settings(c, p, v); });
}

int run(const Case& c, const RunOptions& o) {
    return run_sweep(c, kSolver.name, o,
                     [&](const OperatingPoint& p, const std::filesystem::path& dir) { return solve_point(c, p, o, dir); });
}

}  // namespace granlub::automaton
