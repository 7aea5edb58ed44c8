// `granlub dem`: the per-point pipeline (command.h); the [dem] section is in section.cpp.
#include "granlub/dem/command.h"

#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "deck.h"
#include "diagnostics.h"
#include "engine.h"
#include "granlub/annulus.h"
#include "granlub/coarse_grain.h"
#include "granlub/error.h"
#include "granlub/particles.h"
#include "granlub/regime.h"
#include "granlub/results.h"
#include "outputs.h"
#include "pvd.h"
#include "ring_deck.h"
#include "ring_meshes.h"
#include "settings.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

// How solve() inserts the grains (the ring: below the plate's start, clear of the facets).
InsertionOptions insertion(const Settings& s) {
    InsertionOptions ins;
    ins.seed = s.seed;
    ins.velocity_noise = s.velocity_noise;
    if (s.ring) ins.height = s.plate_start, ins.wall_sag = s.wall_sag;
    return ins;
}

// The deck's final dump (and plate position) as a particle state file (core particles.h).
void write_final_state(const Case& c, const OperatingPoint& p, const Settings& s, const fs::path& dir,
                       const std::string& prov) {
    ParticleState st;
    double step = 0;
    const std::size_t n = for_each_snapshot(
        dir / kFinalDump, [&](const ParticleSet& g, double k) { st.particles = g, step = k; }, true);
    if (n != 1) throw SolverError(fmt::format("{}: {} snapshots, expected the final one", (dir / kFinalDump).string(), n));
    st.gap = s.load ? read_final_plate(dir / kFinalPlateFile) : s.box.gap;
    st.time = step * s.time_step;
    write_particle_state(dir / kFinalState, st,
                         {fmt::format("final state of granlub dem, case {} point {} ({})", c.name, p.id, prov),
                          "grains after the run (and the contact-persistence steps), with spins; gap = top wall"});
    fs::remove(dir / kFinalDump);
    fs::remove(dir / kFinalPlateFile);
}

// The profile across the width over the steady snapshots (cross_section.h); the ring's also with
// the radius each slice-frame z stands for (granlub/annulus.h).
std::string width_profile_csv(const CrossSection& xs, const DemOutputs& out, double U, const Settings& s,
                              const std::string& what) {
    const std::size_t first =
        out.run.at("snapshots").get<std::size_t>() - out.run.at("snapshots_used").get<std::size_t>();
    Profile t = xs.width_profile(U, first, s.blocks);
    std::string frame = "z across the width, z/W = -1/2 the outer wall (where the centripetal force pushes)";
    if (s.ring) {
        const auto& z = t.column("z_over_W");
        std::vector<double> r(z.size());
        const double R = s.annulus.R, W = s.annulus.W;
        for (std::size_t i = 0; i < z.size(); ++i) r[i] = (std::sqrt(R * R + 0.25 * W * W - 2.0 * R * z[i] * W) - R) / W;
        t.add("r_minus_R_over_W", std::move(r));
        frame = "the whole ring in the slice frame: z/W = -1/2 the outer cylinder, equal-area bands, "
                "r_minus_R_over_W the radius of each band's centre";
    }
    return profile_csv(t, {what, "solid fraction and u/U across the width, over the gap (the mean plate gap under "
                                 "load) and the snapshots of the steady window; " + frame});
}

// One engine run of the point in `dir` with settings s: data file, deck, LIGGGHTS, outputs and
// the flow-regime evidence.
struct OneRun {
    DemOutputs out;
    EngineRun er;
};

OneRun run_once(const Case& c, const OperatingPoint& p, const Settings& s, const InitialParticles& init,
                const fs::path& dir, const std::string& prov) {
    const double d_g = c.grains.diameter;
    // load control: room above H for the plate to rise
    const DataBounds bounds = s.ring ? ring_bounds(s, d_g) : slice_bounds(s.box, s.box_top());
    write_file_atomic(dir / kData, data_file(init.particles, bounds, c.grains.density,
                                             fmt::format("case {} point {} ({})", c.name, p.id, prov)));
    if (s.ring) write_ring_meshes(dir, s.annulus, s.plate_start, ring_wall_height(s, d_g), s.ring_facets);
    write_file_atomic(dir / kDeck, s.ring ? ring_deck(c, p, s, init.particles.size(), prov)
                                          : deck(c, p, s, init.particles.size(), prov));
    for (const char* f :
         {kSnapshots, kContactsFile, kPlateFile, kSectionFile, kWidthProfileFile, kFinalDump, kFinalPlateFile})
        fs::remove(dir / f);
    fs::remove(dir / kFinalState);
    if (s.vtk) fs::remove_all(dir / "post");  // the .pvd lists exactly this run's files

    OneRun r;
    r.er = run_engine(dir, kDeck, s.np, s.steps, kWallFile, s.sample_every, "dem " + p.id);

    const WallSeries recorded = read_wall_series(dir / kWallFile);
    std::optional<RingWallLoads> ring_loads;
    if (s.ring) ring_loads = ring_wall_loads(recorded, dir / kWallFile);
    const WallForceSeries walls = s.ring ? ring_wall_forces(*ring_loads, s.annulus) : wall_forces(recorded);
    const WallStresses stresses = wall_stresses(walls, s.box);
    std::optional<PlateSeries> plate;
    if (s.load) {
        plate = read_plate_series(dir / kPlateFile);
        const std::string what = fmt::format("case {} point {} ({})", c.name, p.id, prov);
        write_file_atomic(dir / kGapFile, gap_csv(s, s.time_step, walls.step, stresses.normal_top, *plate, what));
    }
    const SteadyWindow window = wall_steady_window(stresses, walls, s.sample_every, s.time_step,
                                                   plate ? &*plate : nullptr, s.servo_every);
    // profile slabs span the gap: the case's H, or the mean plate position under load control
    const double gap = plate ? mean_gap(*plate, window, s.blocks).mean : c.cell.gap;
    SliceCoarseGrainer cg({0.0, gap, s.stations}, s.box.length * s.box.width);
    CoordinationSeries z(s.contact_box, window.t_start);
    CrossSection xs = CrossSection::for_grains(d_g, gap, s.box.width, s.box.length);
    ParticleSet mapped;  // the ring's grains in the slice frame (granlub/annulus.h)
    const std::size_t snapshots = for_each_snapshot(dir / kSnapshots, [&](const ParticleSet& g, double step) {
        const double t = step * s.time_step;
        if (s.ring) to_slice(g, s.annulus, mapped);
        const ParticleSet& sg = s.ring ? mapped : g;
        cg.add_snapshot(sg, t);
        xs.add_snapshot(sg, t);
        z.add(g, t);  // contacts in the engine's own frame
    });
    if (snapshots < 2)
        throw SolverError(fmt::format("{}: fewer than 2 particle snapshots", (dir / kSnapshots).string()));
    fs::remove(dir / kSnapshots);  // large; the deck regenerates it

    if (s.vtk) write_pvd(dir, s.time_step);

    r.out = reduce_particles({.c = c,
                              .speed = p.speed,
                              .box = s.box,
                              .forces = walls,
                              .stresses = stresses,
                              .cg = cg,
                              .window = window,
                              .plate = plate ? &*plate : nullptr,
                              .servo = s,
                              .blocks = s.blocks,
                              .grains = init.particles.size(),
                              .simulated_s = static_cast<double>(s.steps) * s.time_step,
                              .section = &xs,
                              .plate_start = s.plate_start});
    write_file_atomic(dir / kSectionFile,
                      profile_csv(r.out.section,
                                  {fmt::format("case {} point {} ({})", c.name, p.id, prov),
                                   "solid fraction and u/U over the cross-section: y across the gap (0 = moving floor), "
                                   "z across the width (z/W = -1/2: the outer wall, where the centripetal force pushes), "
                                   "averaged along the flow and over the snapshots of the steady window"}));
    write_file_atomic(dir / kWidthProfileFile, width_profile_csv(xs, r.out, p.speed, s,
                                                                 fmt::format("case {} point {} ({})", c.name, p.id, prov)));
    if (s.ring) {  // the torques about the axis: nothing else turns the grains
        const BlockEstimate e = ring_torque_balance(*ring_loads, window.wall_start, s.blocks);
        r.out.outputs["torque_balance"] = Scalar{e.mean, e.stderr_, ""};
        r.out.run["geometry"] = "annulus";
    }
    r.out.run["flow_regime"] = flow_regime_record(c, p, s, r.out, cg, z, dir / kContactsFile);
    fs::remove(dir / kContactsFile);
    write_final_state(c, p, s, dir, prov);
    return r;
}

// run.dt_refinement: the point rerun at half the time step in <dir>/dt_half (its profile.csv and
// engine files stay there), compared with the main run.
nlohmann::json refine_dt(const Case& c, const OperatingPoint& p, const Settings& s, const InitialParticles& init,
                         const fs::path& dir, const std::string& prov, const DemOutputs& main) {
    const Settings h = half_step(s);
    const fs::path sub = dir / kRefineDir;
    fs::create_directories(sub);
    const OneRun r = run_once(c, p, h, init, sub, prov);
    write_file_atomic(sub / "profile.csv",
                      profile_csv(r.out.profile, {fmt::format("case {} point {}: the rerun at half the time step ({:g} "
                                                              "s); the point's result is ../profile.csv",
                                                              c.name, p.id, h.time_step),
                                                  prov}));
    nlohmann::json rec = dt_refinement_record(h.time_step, main.outputs, r.out.outputs);
    nlohmann::json outputs;
    for (const auto& [name, v] : r.out.outputs)
        outputs[name] = v.stderr_ ? nlohmann::json{{"value", v.value}, {"stderr", *v.stderr_}}
                                  : nlohmann::json{{"value", v.value}};
    rec["refined_run"] = {{"folder", kRefineDir},
                          {"steps", h.steps},
                          {"status", r.out.run.at("status")},
                          {"status_reason", r.out.run.at("status_reason")},
                          {"steady_state_start_s", r.out.run.at("steady_state_start_s")},
                          {"wall_clock_s", r.er.wall_clock_s},
                          {"flow_regime", r.out.run.at("flow_regime")},
                          {"outputs", outputs}};
    return rec;
}

PointResult solve(const Case& c, const OperatingPoint& p0, const RunOptions& o, const fs::path& dir) {
    OperatingPoint p = p0;
    const Settings s = resolve(c, p, o);
    p.solid_fraction = s.insert_fill;

    const InsertionOptions ins = insertion(s);
    const InitialParticles init = initial_particles(c, p, results_root(c, o), ins, s.box.width, s.insert_fill_key);

    const std::string prov = fmt::format("granlub {}, case hash {}, seed {}, {}", version(), c.file_hash, s.seed,
                                         utc_now());
    const OneRun main = run_once(c, p, s, init, dir, prov);
    const DemOutputs& out = main.out;
    const EngineRun& er = main.er;
    fs::remove_all(dir / kRefineDir);  // a rerun of an older result is not this one's
    nlohmann::json dt_record;
    if (s.refine_dt) dt_record = refine_dt(c, p, s, init, dir, prov, out);

    PointResult r;
    r.profile = out.profile;
    r.summary = make_summary(c, p0, "dem", s.seed);
    r.summary.outputs = out.outputs;
    r.summary.provenance.settings["resolved"] = s.to_json();
    const double atoms = static_cast<double>(init.particles.size());
    const double loop = er.loop_time_s > 0 ? er.loop_time_s : er.wall_clock_s;
    const auto engine_steps = s.steps + s.persistence_run_steps();  // the loop time covers both runs
    r.summary.run = out.run;
    r.summary.run["model"] = s.model == Model::Impulse ? "impulse" : "hertz";
    if (s.model == Model::Impulse) r.summary.run["contact_solve"] = s.iterated ? "iterated" : "single_pass";
    r.summary.run["atoms"] = init.particles.size();
    r.summary.run["steps"] = s.steps;
    r.summary.run["time_step_s"] = s.time_step;
    r.summary.run["simulated_time_s"] = static_cast<double>(s.steps) * s.time_step;
    r.summary.run["wall_clock_s"] = er.wall_clock_s;
    r.summary.run["loop_time_s"] = er.loop_time_s;
    r.summary.run["atom_steps_per_s"] = atoms * static_cast<double>(engine_steps) / loop;
    r.summary.run["ranks"] = er.ranks;
    r.summary.run["initial_configuration"] = init.file.string();
    r.summary.run["initial_configuration_reused"] = init.reused;
    const auto& fr = out.run.at("flow_regime");
    r.line = fmt::format("{}  [{} grains, {} steps, {:.3g} atom-steps/s] regime: {}{}", out.line, init.particles.size(),
                         s.steps, r.summary.run["atom_steps_per_s"].get<double>(),
                         fr.at("regime").is_string() ? fr.at("regime").get<std::string>() : std::string("unknown"),
                         fr.at("enduring_contacts").get<bool>() ? ", enduring contacts" : "");
    if (s.refine_dt) {
        r.summary.run["dt_refinement"] = dt_record;
        const std::string why = dt_unconverged_reason(dt_record);
        const RegimeStatus status = read_regime(r.summary.run).status;
        if (!why.empty() && status == RegimeStatus::DtUnconverged)
            set_regime(r.summary.run, RegimeStatus::DtUnconverged, why);
        if (status == RegimeStatus::Transient)
            r.line += " dt/2: no verdict (the run is not steady)";  // its stresses are not an answer to compare
        else
            r.line += why.empty() ? " dt/2: converged" : " dt/2: NOT CONVERGED (" + why + ")";
    }
    return r;
}

}  // namespace

void check(const Case& c, const RunOptions& o) {
    for_each_run(c, o, [&](const OperatingPoint& p0, const RunOptions& v) {
        OperatingPoint p = p0;
        const Settings s = resolve(c, p, v);
        p.solid_fraction = s.insert_fill;  // as solve() inserts it
        check_initial_particles(c, p, s.box.width, s.insert_fill_key, insertion(s));  // as solve() inserts
    });
}

int run(const Case& c, const RunOptions& o) {
    // each point is its own LIGGGHTS process of --np ranks: as many side by side as cores allow
    const int at_once = points_at_once(o, static_cast<int>(c.select(o.point).size()));
    return run_sweep(
        c, "dem", o, [&](const OperatingPoint& p, const fs::path& dir) { return solve(c, p, o, dir); }, at_once);
}

}  // namespace granlub::dem
