// `granlub yade CASE [--point ID]`: per point, the shared initial configuration, the driver run
// (checked), the shared coarse-graining, the result files (through run_sweep).
#include "granlub/yade/command.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/particles/seeds.h"
#include "granlub/run/progress.h"
#include "granlub/results/run_id.h"
#include "granlub/yade/driver.h"
#include "granlub/yade/reduce.h"
#include "granlub/yade/settings.h"

namespace granlub::yade {

namespace fs = std::filesystem;

namespace {

// How the grains are inserted, as granlub dem inserts them: below the plate's start (servo.h).
InsertionOptions insertion(const Case& c, const Settings& s) {
    InsertionOptions ins = s.insertion;
    if (s.servo.plate_start != c.cell.gap) ins.height = s.servo.plate_start;
    return ins;
}

nlohmann::json settings_json(const Settings& s) {
    nlohmann::json j = s.servo.to_json();
    j.update(nlohmann::json{{"model", s.law->name},
                            {"contact_time", s.contact_time},
                            {"tangential_restitution", s.tangential_restitution},
                            {"wall_mass", s.wall_mass},
                            {"calibrate_restitution", s.calibrate_restitution},
                            {"dt", s.time_step},
                            {"steps", s.steps},
                            {"sample_every", s.sample_every},
                            {"snapshot_every", s.snapshot_every},
                            {"body_force_every", s.body_force_every},
                            {"verlet_distance", s.neighbor_skin},
                            {"stations", s.stations},
                            {"blocks", s.blocks},
                            {"seed", s.insertion.seed},
                            {"velocity_noise", s.insertion.velocity_noise},
                            {"periodic_depth", s.periodic_depth},
                            {"start", s.warm_start ? "warm" : "cold"},
                            {"persistence_every", s.persistence_every},
                            {"persistence_intervals", s.persistence_intervals}});
    if (s.servo.load) j.update(nlohmann::json{{"servo_gain_used", s.plate_gain}, {"plate_overlap_m", s.plate_overlap}});
    return j;
}

// [yade] start = "warm": granlub dem's final state of the point, checked against the case (grains,
// box, plate limits) and copied into the point folder, so the folder reruns by hand.
InitialParticles warm_start(const Case& c, const RunOptions& o, const OperatingPoint& p, const Settings& s,
                            const fs::path& dir, nlohmann::json& record) {
    // DEM's realisation of the same seed (seeds.h); with one seed its point folder, as always
    const fs::path from = point_result_dir(c, o, kSolver.warm_from, p.id) / kFinalStateFile;
    if (!fs::exists(from))
        throw SolverError(fmt::format("point {}: [yade] start = \"warm\" starts from granlub dem's final state {}, "
                                      "which does not exist: run `granlub dem` on this case first, or set "
                                      "[yade] start = \"cold\"",
                                      p.id, from.string()));
    InitialParticles init;
    init.box = particle_box(c, s.periodic_depth);
    const GrainSizes g = c.grains.sizes();
    const std::size_t n = grains_for_fill(init.box, g, p.solid_fraction);
    ParticleState st = read_particle_state(from);
    const double tol = 1e-9 * g.mean;
    const bool grains_match = st.particles.size() == n &&
        std::all_of(st.particles.radius.begin(), st.particles.radius.end(), [&](double r) {
            return 0.5 * g.min() - tol <= r && r <= 0.5 * g.max() + tol;
        });
    if (!grains_match)
        throw SolverError(fmt::format("point {}: the warm-start state {} holds {} grains, the case {} of diameter {:g} m{}: "
                                      "it is from another case; rerun `granlub dem`",
                                      p.id, from.string(), st.particles.size(), n, g.mean,
                                      g.equal() ? "" : fmt::format(" (spread {:g})", g.spread)));
    if (s.servo.load ? !(s.servo.gap_min < st.gap && st.gap <= s.servo.gap_max)
                     : std::abs(st.gap - init.box.gap) > 1e-9 * init.box.gap)
        throw SolverError(fmt::format("point {}: the warm-start state {} has its top wall at {:g} m, outside what this "
                                      "case allows; rerun `granlub dem`",
                                      p.id, from.string(), st.gap));
    init.box.gap = st.gap;
    init.file = dir / "warm_start.csv";
    fs::create_directories(dir);
    fs::copy_file(from, init.file, fs::copy_options::overwrite_existing);
    record = {{"from", from.string()}, {"time_s", st.time}, {"gap_m", st.gap}, {"grains", st.particles.size()},
              {"dem_run_id", read_table_run_id(from).value_or("")}};  // which dem run it started from
    init.particles = std::move(st.particles);
    init.time = st.time;  // the floor's bumps start where dem's grains met them (particles.h)
    return init;
}

// The run s, `times` times as long: the same sampling, the same number of snapshots.
Settings lengthened(const Settings& s, std::int64_t times) {
    Settings l = s;
    l.steps = s.steps * times;
    l.snapshot_every = s.snapshot_every * times;
    return l;
}

// One YADE process: the run `s` from the grains in `from`, in the cell `start`, with its progress line.
void run_piece(const DriverPaths& paths, const Case& c, const OperatingPoint& p, const Settings& s,
               const ParticleBox& start, const fs::path& from, double start_time, const fs::path& dir,
               std::size_t grains, double overlap) {
    const auto steps = static_cast<double>(s.steps);
    // a guard against hangs (docs/yade-notes.md §5), not a performance limit: a 2-core machine shared
    // by several jobs ran YADE 6x slower than a quiet one
    const double timeout = s.timeout > 0 ? s.timeout : 600.0 + 1e-4 * static_cast<double>(grains) * steps;
    Progress progress(fmt::format("yade {}", point_label(p.id, dir)), static_cast<std::uint64_t>(steps));
    const fs::path progress_file = dir / "progress";
    auto poll = [&] {
        if (!progress.due()) return;  // the driver's file is read only when a line will be written
        std::ifstream in(progress_file);
        std::uint64_t done = 0, total = 0;
        if (in >> done >> total) progress.update(done, fmt::format("{} grains", grains));
    };
    fs::remove(dir / "driver_summary.json");  // a stale marker must not pass for this run's
    run_driver(paths, dir, couette_params(c, p, s, start, from, overlap, start_time), p.id, timeout, poll);
}

PointResult solve_point(const Case& c, const OperatingPoint& p0, const RunOptions& o, const fs::path& dir) {
    // Everything that can be wrong with the inputs is checked before YADE starts.
    const Settings s = resolve_settings(c, p0, o);
    OperatingPoint p = p0;
    p.solid_fraction = s.servo.insert_fill;  // under load: the point's, or fill_for_load
    nlohmann::json warm;
    fs::remove(dir / "warm_start.csv");
    const InitialParticles init =
        s.warm_start ? warm_start(c, o, p, s, dir, warm)
                     : initial_particles(c, p, results_root(c, o), insertion(c, s), s.periodic_depth,
                                         s.servo.insert_fill_key, initial_subfolder(c, o));
    ParticleBox start = init.box;  // the driver's cell: the top wall starts where granlub dem's does
    if (!s.warm_start) start.gap = s.servo.plate_start;
    const DriverPaths paths = locate_driver();

    Summary base = make_summary(c, p0, kSolver, s.insertion.seed);
    base.provenance.settings = settings_json(s);
    base.provenance.settings["initial_file"] = init.file.string();
    base.provenance.settings["initial_file_reused"] = init.reused;
    if (s.warm_start) base.provenance.settings["warm_start"] = warm;

    // until steady, with a cap ([yade] time_max; granlub/particles/until_steady.h): a piece starts
    // from the last one's final state. YADE's contacts start afresh there (their tangential
    // springs and a weight plate's velocity are not carried over), a small kick in the piece's
    // own transient, which the steady-state search cuts off.
    fs::path from = init.file;
    double wall_s = 0, end_gap = start.gap;  // the last piece's plate at its end
    double start_time = init.time, end_time = init.time;  // the piece's state's, ParticleState::time
    PointResult r;
    const Continuation k = continue_until_steady(s.until_steady, s.time, "yade " + point_label(p.id, dir), [&](std::int64_t times,
                                                                                              int index) {
        const Settings piece = index > 0 ? lengthened(s, times) : s;
        if (index > 0) {  // from where the last piece ended
            from = dir / "continued_from.csv";
            fs::copy_file(dir / kFinalStateFile, from, fs::copy_options::overwrite_existing);
            start.gap = end_gap;
            start_time = end_time;
        }
        run_piece(paths, c, p, piece, start, from, start_time, dir, init.particles.size(),
                  index > 0 ? kContinuedOverlap : kStartOverlap);
        // the driver's final state, read once: run.wall_layer, and the next piece's start
        std::optional<ParticleState> end;
        if (fs::exists(dir / kFinalRawFile)) end = read_particle_state(dir / kFinalRawFile);
        r = reduce_point(c, p, piece, init.box, init.particles.radius, dir, base, end);
        if (!end) end = read_particle_state(dir / kFinalRawFile);  // throws, naming the missing file
        end_gap = end->gap, end_time = end->time;
        write_particle_state(dir / kFinalStateFile, *end,
                             {fmt::format("final state of granlub yade, case {} point {}", c.name, p.id),
                              "grains after the run, with spins; gap = top wall"});
        fs::remove(dir / kFinalRawFile);
        wall_s += r.summary.run.value("yade_wall_clock_s", 0.0);
        return PieceRun{r.summary.run.value("steady_state_detected", false),
                        static_cast<double>(piece.steps) * piece.time_step};
    });
    if (k.time_max_s > 0) {
        record_continuation(r.summary.run, k);
        r.summary.run["simulated_time_s"] = k.earlier_s + k.last_s;
        r.summary.run["yade_wall_clock_s"] = wall_s;  // every piece's
        r.line += continuation_note(k);
    }
    fs::remove(dir / "continued_from.csv");
    // how the result was obtained, in words the report shows
    r.summary.run["start"] =
        s.warm_start ? fmt::format("warm, from granlub dem's final state of the point (t = {:g} s)",
                                   warm.at("time_s").get<double>())
                     : std::string("cold, from the shared initial grains ([particles])");
    if (s.servo.load)
        r.summary.run["plate"] = s.servo.weight_plate ? fmt::format("a loaded plate of {:g} x the grains' mass", s.servo.plate_mass)
                                                : std::string("the window servo of granlub dem");
    fs::remove(dir / "samples.bin");  // raw snapshots: large, and reproducible from params.json
    fs::remove(dir / "contacts.bin");  // the persistence snapshots, likewise
    fs::remove(dir / "progress");
    return r;
}

}  // namespace

void check(const Case& c, const RunOptions& o) {
    seed_set(c, o);  // --seeds, --seed and [particles] seeds: bad input stops before any point runs
    for_each_run(c, o, [&](const OperatingPoint& p0, const RunOptions& v) {
        const Settings s = resolve_settings(c, p0, v);
        OperatingPoint p = p0;
        p.solid_fraction = s.servo.insert_fill;  // as solve_point() inserts it
        check_initial_particles(c, p, s.periodic_depth, s.servo.insert_fill_key, insertion(c, s));
    });
}

int run(const Case& c, const RunOptions& o) {
    // each point (each seed's realisation of it) is one single-threaded YADE process (-j1)
    // a warm start reads dem's final states: dem's results stay locked (shared) while yade runs, so
    // that no dem run replaces them half-way through the sweep (granlub/run/run_lock.h)
    const bool warm = c.section(kSolver.name).string("start") == "warm";
    return run_particle_sweep(c, kSolver.name, o, [&](const OperatingPoint& p, const RunOptions& ro, const fs::path& dir) {
        try {
            return solve_point(c, p, ro, dir);
        } catch (const SolverError&) {
            throw;
        } catch (const Error& e) {  // bad input found for this point: same message, as a point failure
            throw SolverError(e.what());
        } catch (const std::exception& e) {
            throw SolverError(fmt::format("point {}: {}", p.id, e.what()));
        }
    }, warm ? std::vector<std::string>{kSolver.warm_from} : std::vector<std::string>{});
}

}  // namespace granlub::yade
