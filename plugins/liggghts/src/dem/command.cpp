// `granlub dem`: the per-point pipeline (command.h); the [dem] section is in section.cpp.
#include "granlub/dem/command.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "deck.h"
#include "launch.h"
#include "granlub/particles/annulus.h"
#include "granlub/error.h"
#include "granlub/particles/particle_pipeline.h"
#include "granlub/particles/particles.h"
#include "granlub/particles/seeds.h"
#include "granlub/particles/until_steady.h"
#include "granlub/results/failure_record.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "granlub/statistics/flow_regime.h"
#include "outputs.h"
#include "pvd.h"
#include "ring_deck.h"
#include "ring_meshes.h"
#include "settings.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

// How solve_point() inserts the grains: below the plate's start (servo.h); the ring's clear of the facets.
InsertionOptions insertion(const Case& c, const Settings& s) {
    InsertionOptions ins;
    ins.seed = s.seed;
    ins.velocity_noise = s.velocity_noise;
    if (s.ring || s.plate_start != c.cell.gap) ins.height = s.plate_start;
    if (s.ring) ins.wall_sag = s.wall_sag;
    return ins;
}

// The deck's final dump (and plate position): the grains with their spins at the end, `start` s
// after the grains' cold start (the run's starting state's time: ParticleState::time counts on).
ParticleState read_final_state(const Settings& s, const fs::path& dir, double start) {
    ParticleState st;
    double step = 0;
    const std::size_t n = for_each_snapshot(
        dir / kFinalDump, [&](const ParticleSet& g, double k) { st.particles = g, step = k; }, true);
    if (n != 1) throw SolverError(fmt::format("{}: {} snapshots, expected the final one", (dir / kFinalDump).string(), n));
    st.gap = s.load ? read_final_plate(dir / kFinalPlateFile) : s.box.gap;
    st.time = start + step * s.time_step;
    return st;
}

// The final state as a particle state file (core particles.h), in place of the deck's dumps.
void write_final_state(const Case& c, const OperatingPoint& p, const ParticleState& st, const fs::path& dir,
                       const std::string& prov) {
    write_particle_state(dir / kFinalState, st,
                         {fmt::format("final state of granlub dem, case {} point {} ({})", c.name, p.id, prov),
                          "grains after the run (and the contact-persistence steps), with spins; gap = top wall"});
    fs::remove(dir / kFinalDump);
    fs::remove(dir / kFinalPlateFile);
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
    const DataBounds bounds = s.ring ? ring_bounds(s, d_g) : bump_bounds(slice_bounds(s.box, s.box_top()), s);
    write_file_atomic(dir / kData, data_file(init.particles, bounds, c.grains.density,
                                             fmt::format("case {} point {} ({})", c.name, p.id, prov),
                                             bump_atoms(s, p.speed, init.time)));
    if (s.ring && s.ring_mesh) write_ring_meshes(dir, s.annulus, s.plate_start, ring_wall_height(s, d_g), s.ring_facet_count);
    else
        for (const char* mesh : kRingMeshes) fs::remove(dir / mesh);  // an earlier run's, not this deck's
    write_file_atomic(dir / kDeck, s.ring ? ring_deck(c, p, s, init.particles, prov)
                                          : deck(c, p, s, init.particles, prov));
    for (const char* f :
         {kSnapshots, kContactsFile, kPlateFile, kSectionFile, kWidthProfileFile, kFinalDump, kFinalPlateFile})
        fs::remove(dir / f);
    fs::remove(dir / kFinalState);
    if (s.vtk) fs::remove_all(dir / "post");  // the .pvd lists exactly this run's files

    OneRun r;
    // the check's coarse run names itself in the progress line
    const bool check = dir.filename() == kDtCheckDir;
    const std::string who = point_label(p.id, dir);  // with a set of seeds, the member too
    const std::string label = check ? fmt::format("dem {} {}", who, kDtCheckDir) : "dem " + who;
    r.er = run_engine(dir, kDeck, s.np, s.steps, kWallFile, s.sample_every, label);

    // LIGGGHTS' files into the shared series; the rest is the one particle pipeline
    ParticleRecord rec;
    const WallSeries recorded = read_wall_series(dir / kWallFile);
    if (s.ring)
        rec.ring = ring_wall_loads(recorded, dir / kWallFile);
    else
        rec.forces = wall_forces(recorded);
    if (s.load) rec.plate = read_plate_series(dir / kPlateFile);
    auto dump = [&](const char* file) {
        return SnapshotReader{(dir / file).string(), [&, file](const SnapshotVisitor& each) {
                                  return for_each_snapshot(dir / file, [&](const ParticleSet& g, double step) {
                                      each(g, step * s.time_step);
                                  });
                              }};
    };
    rec.snapshots = dump(kSnapshots);
    rec.persistence = dump(kContactsFile);
    rec.final_state = read_final_state(s, dir, init.time);
    ParticlePipeline pl{.c = c,
                        .p = p,
                        .box = s.box,
                        .servo = s,
                        .time_step = s.time_step,
                        .sample_every = s.sample_every,
                        .stations = s.stations,
                        .blocks = s.blocks,
                        .grains = init.particles.size(),
                        .simulated_s = static_cast<double>(s.steps) * s.time_step,
                        .plate_start = s.plate_start,
                        .annulus = s.ring ? &s.annulus : nullptr,
                        .contact_box = s.contact_box,
                        .persistence_every = s.persistence_every,
                        .bumps_bottom = &s.bumps_bottom,
                        .bumps_top = &s.bumps_top,
                        .bumps_side = &s.bumps_side,
                        .what = fmt::format("case {} point {} ({})", c.name, p.id, prov)};
    r.out = run_particle_pipeline(pl, rec, dir);
    r.out.run["flow_regime"]["persistence_extra_steps"] = s.persistence_run_steps();
    for (const char* f : {kSnapshots, kContactsFile}) fs::remove(dir / f);  // large; the deck regenerates them
    if (s.vtk) write_pvd(dir, s.time_step);
    write_final_state(c, p, *rec.final_state, dir, prov);
    return r;
}

// [dem] time_max: until steady, with a cap (the policy and the record: granlub/particles/until_steady.h).
// A piece starts from the run's own final state (grains, spins, plate) at the same step: one longer
// run, cut (not a warm start at another step, whose memory of the first step's packing was measured
// to bias a check). The single pass keeps no contact history a piece could lose; `iterate on` loses
// its warm-start impulses for one step.
struct Continued {
    OneRun last;
    Continuation record;
    double loop_s = 0, wall_s = 0;   // all pieces
    double engine_steps = 0;         // all pieces, with their persistence runs
};

// The run s, `times` times as long: whole servo windows, the same snapshots per run.
Settings lengthened(const Settings& s, std::int64_t times) {
    Settings l = s;
    l.steps = s.steps * times;
    l.time = s.time * static_cast<double>(times);
    l.snapshot_every = std::max<std::int64_t>(1, l.steps / std::max<std::int64_t>(1, s.snapshots));
    return l;
}

Continued run_continued(const Case& c, const OperatingPoint& p, const Settings& s, const InitialParticles& init,
                        const fs::path& dir, const std::string& prov) {
    Continued r;
    InitialParticles start = init;
    r.record = continue_until_steady(s.until_steady, s.time, "dem " + point_label(p.id, dir), [&](std::int64_t times, int index) {
        Settings piece = s;
        if (index > 0) {  // from where the last piece ended: its grains, spins and plate
            const ParticleState st = read_particle_state(dir / kFinalState);
            start.particles = st.particles;
            start.file = dir / kFinalState;
            start.reused = true;
            start.time = st.time;
            piece = lengthened(s, times);
            if (s.load) piece.plate_start = st.gap;
        }
        r.last = run_once(c, p, piece, start, dir, prov);
        r.loop_s += r.last.er.loop_time_s > 0 ? r.last.er.loop_time_s : r.last.er.wall_clock_s;
        r.wall_s += r.last.er.wall_clock_s;
        r.engine_steps += static_cast<double>(piece.steps + piece.persistence_run_steps());
        return PieceRun{r.last.out.run.at("steady_state_detected").get<bool>(),
                        static_cast<double>(piece.steps) * piece.time_step};
    });
    if (r.record.time_max_s <= 0) return r;
    record_continuation(r.last.out.run, r.record);
    r.last.out.line += continuation_note(r.record);
    return r;
}

// The run of the point at half the time step is its answer, checked against the full step
// ([dem] refine_dt): the full-step run goes into <dir>/dt_full (cold, from the initial grains, the
// whole `time`, continued until steady under time_max); the half-step run into <dir> itself,
// warm-started from dt_full's final state for refine_time (or, with refine_time = 0, cold from the
// initial grains for the whole `time`). With refine_halvings = 2 a pair that fails the rule (both
// runs steady) is repeated one halving finer: the half-step run moves to <dir>/dt_half and the run
// at a quarter of the step (cold, the whole `time`) becomes the answer in <dir>. Every file of the
// point folder is the answer's, and each output carries dt_error = |value(2 dt') - value(dt')|
// (dt' the answer's step), the error estimate of a first-order method at dt'.
struct Refined {
    std::vector<Continued> runs;     // at the case's step, then each halving: the last is the answer
    std::vector<Settings> settings;  // their settings
    bool warm = false;
    nlohmann::json first_check;      // after a second halving: the failed first pair, with its verdict
    bool twice() const { return runs.size() == 3; }
    const Continued& answer() const { return runs.back(); }
    const Continued& checked_against() const { return runs[runs.size() - 2]; }
};

// A check run's profile beside its other files (the answer's profile.csv is the sweep's).
void write_check_profile(const fs::path& folder, const Continued& run, const std::string& what,
                         const std::string& prov) {
    write_file_atomic(folder / "profile.csv", profile_csv(run.last.out.profile, {what, prov}));
}

// Moves the run in `dir` (every entry but the check folders and the point's records) into `to`.
void move_run(const fs::path& dir, const fs::path& to) {
    fs::create_directories(to);
    std::vector<fs::path> entries;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name == kDtCheckDir || name == kDtHalfDir || name == "summary.json" || name == kFailureFile) continue;
        if (name.starts_with("seed-")) continue;  // the point's realisations of a set of seeds (seeds.h)
        entries.push_back(e.path());
    }
    for (const auto& e : entries) fs::rename(e, to / e.filename());
}

Refined refine_dt(const Case& c, const OperatingPoint& p, const Settings& s, const InitialParticles& init,
                  const fs::path& dir, const std::string& prov) {
    Refined r;
    const fs::path full = dir / kDtCheckDir;
    fs::create_directories(full);
    r.settings.push_back(s);
    r.settings.push_back(refine_settings(s));
    r.warm = s.refine_time > 0;
    // One after the other: run side by side, the point's two cold runs cost more CPU than they save in
    // wall time on 2 cores (docs/measurements/build-and-run.md, 2026-12-06).
    r.runs.push_back(run_continued(c, p, s, init, full, prov));
    write_check_profile(full, r.runs.front(),
                        fmt::format("case {} point {}: the run at the full time step ({:g} s), the coarsest run of "
                                    "the time-step check of the point's result ../profile.csv (run.dt_refinement)",
                                    c.name, p.id, s.time_step),
                        prov);
    InitialParticles start = init;
    if (r.warm) {  // from where the full-step run ended: its grains, spins and plate
        const ParticleState st = read_particle_state(full / kFinalState);
        start.particles = st.particles;
        start.file = full / kFinalState;
        start.reused = true;
        start.time = st.time;
        if (s.load) r.settings.back().plate_start = st.gap;
    }
    if (r.runs.size() < 2) r.runs.push_back(run_continued(c, p, r.settings.back(), start, dir, prov));
    if (s.refine_halvings < 2) return r;
    nlohmann::json first =
        dt_refinement_record(r.settings[1].time_step, r.runs[0].last.out.outputs, r.runs[1].last.out.outputs);
    const auto why = dt_check_failure(r.runs[0].last.out.run, r.runs[1].last.out.run, first);
    if (!why || why->empty()) return r;  // the answer a transient (run it longer), or converged
    first["verdict"] = *why;
    r.first_check = std::move(first);
    fmt::print(stderr, "dem {}: the run at half the step is not checked by the full step ({}); halving it once more "
               "([dem] refine_halvings = {})\n",
               point_label(p.id, dir), *why, s.refine_halvings);
    move_run(dir, dir / kDtHalfDir);
    write_check_profile(dir / kDtHalfDir, r.runs[1],
                        fmt::format("case {} point {}: the run at half the time step ({:g} s), which failed its check "
                                    "against ../dt_full; the check of the point's result ../profile.csv (at a quarter)",
                                    c.name, p.id, r.settings[1].time_step),
                        prov);
    r.settings.push_back(half_step(r.settings[1]));  // cold: refine_halvings = 2 refuses refine_time > 0
    r.runs.push_back(run_continued(c, p, r.settings.back(), init, dir, prov));
    return r;
}

// A check run's line in run.dt_refinement: its folder, step, status and outputs.
nlohmann::json check_run_record(const Continued& run, const Settings& s, const char* folder) {
    const DemOutputs& out = run.last.out;
    nlohmann::json outputs;
    for (const auto& [name, v] : out.outputs)
        outputs[name] = v.stderr_ ? nlohmann::json{{"value", v.value}, {"stderr", *v.stderr_}}
                                  : nlohmann::json{{"value", v.value}};
    nlohmann::json rec = {{"folder", folder},
                          {"time_step_s", s.time_step},
                          {"steps", s.steps},
                          {"status", out.run.at("status")},
                          {"status_reason", out.run.at("status_reason")},
                          {"steady_state_start_s", out.run.at("steady_state_start_s")},
                          {"wall_clock_s", run.wall_s},
                          {"flow_regime", out.run.at("flow_regime")},
                          {"outputs", outputs}};
    if (out.run.contains("continuation")) rec["continuation"] = out.run.at("continuation");
    return rec;
}

// run.dt_refinement: the answer against the run at twice its step; dt_error on every output both
// have. After a second halving the failed first pair is kept as first_check.
nlohmann::json refinement_record(const Refined& r, std::map<std::string, Scalar>& outputs) {
    const DemOutputs& coarse = r.checked_against().last.out;
    nlohmann::json rec =
        dt_refinement_record(r.settings.back().time_step, coarse.outputs, r.answer().last.out.outputs);
    for (auto& [name, v] : outputs)
        if (const auto it = coarse.outputs.find(name); it != coarse.outputs.end())
            v.dt_error = std::abs(it->second.value - v.value);
    const bool twice = r.twice();
    rec["halvings"] = static_cast<int>(r.runs.size()) - 1;
    rec["checked_against"] = twice ? kDtHalfDir : kDtCheckDir;
    rec["reported"] = twice ? "the run at a quarter of the time step (this folder), after the check at half the step "
                              "failed (first_check); dt_error = |value(dt/2) - value(dt/4)|"
                            : "the run at half the time step (this folder); dt_error = |value(dt) - value(dt/2)|";
    rec["start"] = r.warm
                       ? fmt::format("warm: from the full-step run's final state, {:g} s at dt/2", r.settings[1].time)
                       : std::string("cold: from the initial grains, the whole run at dt/2");  // and at dt/4
    rec["full_step_run"] = check_run_record(r.runs[0], r.settings[0], kDtCheckDir);
    if (twice) {
        rec["half_step_run"] = check_run_record(r.runs[1], r.settings[1], kDtHalfDir);
        rec["first_check"] = r.first_check;
    }
    return rec;
}

PointResult solve_point(const Case& c, const OperatingPoint& p0, const RunOptions& o, const fs::path& dir) {
    OperatingPoint p = p0;
    const Settings s = resolve_settings(c, p, o);
    p.solid_fraction = s.insert_fill;

    const InsertionOptions ins = insertion(c, s);
    const InitialParticles init =
        initial_particles(c, p, results_root(c, o), ins, s.box.width, s.insert_fill_key, initial_subfolder(c, o));

    const std::string prov = fmt::format("granlub {}, case hash {}, seed {}, {}", version(), c.file_hash, s.seed,
                                         utc_now());
    fs::remove_all(dir / kDtCheckDir);  // a check of an older result is not this one's
    fs::remove_all(dir / kDtHalfDir);
    std::optional<Refined> refined;
    Continued single;
    if (s.refine_dt)
        refined = refine_dt(c, p, s, init, dir, prov);
    else
        single = run_continued(c, p, s, init, dir, prov);
    const Continued& reported = refined ? refined->answer() : single;
    const Settings& rs = refined ? refined->settings.back() : s;
    const DemOutputs& out = reported.last.out;

    PointResult r;
    r.profile = out.profile;
    r.summary = make_summary(c, p0, kSolver, s.seed);
    r.summary.outputs = out.outputs;
    r.summary.provenance.settings["resolved"] = s.to_json();
    const double atoms = static_cast<double>(init.particles.size());
    // the loop time covers the run and its persistence snapshots, of both runs when checked, and
    // of every piece of a continued run
    double loop = reported.loop_s, wall = reported.wall_s, engine_steps = reported.engine_steps;
    if (refined)
        for (std::size_t k = 0; k + 1 < refined->runs.size(); ++k) {
            const Continued& check = refined->runs[k];
            loop += check.loop_s, wall += check.wall_s, engine_steps += check.engine_steps;
        }
    r.summary.run = out.run;
    r.summary.run["model"] = s.law->name;
    if (s.law->impulse_options) r.summary.run["contact_solve"] = s.iterated ? "iterated" : "single_pass";
    r.summary.run["atoms"] = init.particles.size();
    r.summary.run["steps"] = static_cast<std::int64_t>(std::llround(reported.record.last_s / rs.time_step));
    r.summary.run["time_step_s"] = rs.time_step;
    r.summary.run["simulated_time_s"] = reported.record.last_s + reported.record.earlier_s;
    r.summary.run["wall_clock_s"] = wall;
    r.summary.run["loop_time_s"] = loop;
    r.summary.run["atom_steps_per_s"] = atoms * engine_steps / loop;
    r.summary.run["ranks"] = reported.last.er.ranks;
    r.summary.run["initial_configuration"] = init.file.string();
    r.summary.run["initial_configuration_reused"] = init.reused;
    const auto& fr = out.run.at("flow_regime");
    const FlowVerdict verdict = read_flow_verdict(fr);
    r.line = fmt::format("{}  [{} grains, {} steps, {:.3g} atom-steps/s] regime: {} ({})", out.line,
                         init.particles.size(), r.summary.run["steps"].get<std::int64_t>(), r.summary.run["atom_steps_per_s"].get<double>(),
                         verdict.label(), verdict.criterion);
    if (const int n = s.dense_halvings()) {  // [dem] dense_inertial_number: every run of the point at 1/2^n the case's step
        r.summary.run["dense_step"] = {{"inertial_number_nominal", s.inertial_nominal},
                                       {"dense_inertial_number", s.dense_inertial_number},
                                       {"halvings", n},
                                       {"case_time_step_s", std::ldexp(s.time_step, n)}};
        if (n == 2) r.summary.run["dense_step"]["quarter_step_inertial_number"] = s.quarter_step_inertial_number;
        r.line += fmt::format(" [dense: nominal I {:.3g} < {:g}, dt {}]", s.inertial_nominal, s.dense_threshold(),
                              dense_step_name(n));
    }
    if (refined) {
        r.summary.run["dt_refinement"] = refinement_record(*refined, r.summary.outputs);
        // the point's status is read as the report reads it (read_regime): its own run's, then the
        // check's verdict on it; written out so that summary.json says it too
        const Regime point = read_regime(r.summary.run);
        if (point.status == RegimeStatus::Unknown) throw Error("internal: " + point.reason);
        set_regime(r.summary.run, point.status, point.reason);
        const bool twice = refined->twice();
        const std::string at = twice ? " [dt/4, after dt/2 failed its check]" : " [dt/2]";
        const std::string against = twice ? "dt/2" : "dt";
        if (!read_regime(out.run).steady())
            r.line += at + " no verdict on " + against + " (this run is not steady)";  // no answer to compare
        else if (point.status == RegimeStatus::Transient)
            r.line += at + " TRANSIENT: " + point.reason + " (no verdict on " + against + ")";
        else
            r.line += point.steady() ? at + " converged in " + against
                                     : at + " NOT CONVERGED in " + against + " (" + point.reason + ")";
    }
    return r;
}

}  // namespace

void check(const Case& c, const RunOptions& o) {
    seed_set(c, o);  // --seeds, --seed and [particles] seeds: bad input stops before any point runs
    for_each_run(c, o, [&](const OperatingPoint& p0, const RunOptions& v) {
        OperatingPoint p = p0;
        const Settings s = resolve_settings(c, p, v);
        p.solid_fraction = s.insert_fill;  // as solve_point() inserts it
        check_initial_particles(c, p, s.box.width, s.insert_fill_key, insertion(c, s));  // as solve_point() inserts
    });
}

int run(const Case& c, const RunOptions& o) {
    // each point (each seed's realisation of it) is its own LIGGGHTS process of --np ranks
    return run_particle_sweep(c, kSolver.name, o, [&](const OperatingPoint& p, const RunOptions& ro, const fs::path& dir) {
        return solve_point(c, p, ro, dir);
    });
}

}  // namespace granlub::dem
