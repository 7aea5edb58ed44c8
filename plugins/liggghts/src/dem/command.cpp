// `granlub dem`: the per-point pipeline (command.h); the [dem] section is in section.cpp.
#include "granlub/dem/command.h"

#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "deck.h"
#include "engine.h"
#include "granlub/coarse_grain.h"
#include "granlub/error.h"
#include "granlub/particles.h"
#include "granlub/results.h"
#include "outputs.h"
#include "pvd.h"
#include "settings.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

PointResult solve(const Case& c, const OperatingPoint& p0, const RunOptions& o, const fs::path& dir) {
    OperatingPoint p = p0;
    const Settings s = resolve(c, p, o);
    p.solid_fraction = s.insert_fill;

    InsertionOptions ins;
    ins.seed = s.seed;
    ins.velocity_noise = s.velocity_noise;
    const InitialParticles init = initial_particles(c, p, results_root(c, o), ins, s.box.width);

    const std::string prov = fmt::format("granlub {}, case hash {}, seed {}, {}", version(), c.file_hash, s.seed,
                                         utc_now());
    ParticleBox data_box = s.box;
    data_box.gap = s.box_top();  // load control: room above H for the plate to rise
    write_file_atomic(dir / kData, data_file(init.particles, data_box, c.grains.density,
                                             fmt::format("case {} point {} ({})", c.name, p.id, prov)));
    write_file_atomic(dir / kDeck, deck(c, p, s, init.particles.size(), prov));
    fs::remove(dir / kSnapshots);
    fs::remove(dir / kPlateFile);
    if (s.vtk) fs::remove_all(dir / "post");  // the .pvd lists exactly this run's files

    const EngineRun er = run_engine(dir, kDeck, s.np, s.steps, kWallFile, s.sample_every, "dem " + p.id);

    const WallSeries walls = read_wall_series(dir / kWallFile);
    std::optional<PlateSeries> plate;
    if (s.load) {
        plate = read_plate_series(dir / kPlateFile);
        const std::string what = fmt::format("case {} point {} ({})", c.name, p.id, prov);
        write_file_atomic(dir / kGapFile, gap_csv(s, walls, *plate, what));
    }
    const SteadyWindow window = steady_window(s, walls, plate ? &*plate : nullptr);
    // profile slabs span the gap: the case's H, or the mean plate position under load control
    const double gap = plate ? mean_gap(s, *plate, window).mean : c.cell.gap;
    SliceCoarseGrainer cg({0.0, gap, s.stations}, s.box.length * s.box.width);
    if (read_snapshots(dir / kSnapshots, s.time_step, cg) < 2)
        throw SolverError(fmt::format("{}: fewer than 2 particle snapshots", (dir / kSnapshots).string()));
    fs::remove(dir / kSnapshots);  // large; the deck regenerates it

    if (s.vtk) write_pvd(dir, s.time_step);

    DemOutputs out = make_outputs(c, p, s, walls, cg, window, plate ? &*plate : nullptr, init.particles.size());
    PointResult r;
    r.profile = std::move(out.profile);
    r.summary = make_summary(c, p0, "dem", s.seed);
    r.summary.outputs = std::move(out.outputs);
    r.summary.provenance.settings["resolved"] = s.to_json();
    const double atoms = static_cast<double>(init.particles.size());
    const double loop = er.loop_time_s > 0 ? er.loop_time_s : er.wall_clock_s;
    r.summary.run = out.run;
    r.summary.run["model"] = s.model == Model::Impulse ? "impulse" : "hertz";
    r.summary.run["atoms"] = init.particles.size();
    r.summary.run["steps"] = s.steps;
    r.summary.run["time_step_s"] = s.time_step;
    r.summary.run["simulated_time_s"] = static_cast<double>(s.steps) * s.time_step;
    r.summary.run["wall_clock_s"] = er.wall_clock_s;
    r.summary.run["loop_time_s"] = er.loop_time_s;
    r.summary.run["atom_steps_per_s"] = atoms * static_cast<double>(s.steps) / loop;
    r.summary.run["ranks"] = er.ranks;
    r.summary.run["initial_configuration"] = init.file.string();
    r.summary.run["initial_configuration_reused"] = init.reused;
    r.line = fmt::format("{}  [{} grains, {} steps, {:.3g} atom-steps/s]", out.line, init.particles.size(), s.steps,
                         r.summary.run["atom_steps_per_s"].get<double>());
    return r;
}

}  // namespace

void check(const Case& c, const RunOptions& o) {
    for_each_run(c, o, [&](const OperatingPoint& p0, const RunOptions& v) {
        OperatingPoint p = p0;
        const Settings s = resolve(c, p, v);
        p.solid_fraction = s.insert_fill;  // as solve() inserts it
        check_initial_particles(c, p, s.box.width);  // the depth solve() passes
    });
}

int run(const Case& c, const RunOptions& o) {
    return run_sweep(c, "dem", o, [&](const OperatingPoint& p, const fs::path& dir) { return solve(c, p, o, dir); });
}

}  // namespace granlub::dem
