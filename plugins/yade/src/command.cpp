// `granlub yade CASE [--point ID]`: per point, the shared initial configuration, the driver run
// (checked), the shared coarse-graining, the result files (through run_sweep).
#include "granlub/yade/command.h"

#include <fstream>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/progress.h"
#include "granlub/yade/driver.h"
#include "granlub/yade/reduce.h"
#include "granlub/yade/settings.h"

namespace granlub::yade {

namespace fs = std::filesystem;

namespace {

nlohmann::json settings_json(const Settings& s) {
    nlohmann::json j = s.servo.to_json();
    j.update(nlohmann::json{{"model", to_string(s.model)},
                            {"contact_time", s.contact_time},
                            {"tangential_restitution", s.tangential_restitution},
                            {"wall_mass", s.wall_mass},
                            {"calibrate_restitution", s.calibrate_restitution},
                            {"dt", s.dt},
                            {"steps", s.steps},
                            {"sample_every", s.sample_every},
                            {"snapshot_every", s.snapshot_every},
                            {"body_force_every", s.body_force_every},
                            {"stations", s.stations},
                            {"blocks", s.blocks},
                            {"seed", s.insertion.seed},
                            {"velocity_noise", s.insertion.velocity_noise},
                            {"periodic_depth", s.periodic_depth}});
    return j;
}

PointResult solve_point(const Case& c, const RunOptions& o, const OperatingPoint& p0, const fs::path& dir) {
    // Everything that can be wrong with the inputs is checked before YADE starts.
    const Settings s = resolve_settings(c, p0, o);
    OperatingPoint p = p0;
    p.solid_fraction = s.servo.insert_fill;  // under load: the point's, or fill_for_load
    const InitialParticles init =
        initial_particles(c, p, results_root(c, o), s.insertion, s.periodic_depth, s.servo.insert_fill_key);
    const DriverPaths paths = locate_driver();

    const auto steps = static_cast<double>(s.steps);
    // a guard against hangs (docs/yade-notes.md §5), not a performance limit: a 2-core machine shared
    // by several jobs ran YADE 6x slower than a quiet one
    const double timeout = s.timeout > 0 ? s.timeout : 600.0 + 1e-4 * static_cast<double>(init.particles.size()) * steps;
    Progress progress(fmt::format("yade {}", p.id), static_cast<std::uint64_t>(steps));
    const fs::path progress_file = dir / "progress";
    auto poll = [&] {
        std::ifstream in(progress_file);
        std::uint64_t done = 0, total = 0;
        if (in >> done >> total) progress.update(done, fmt::format("{} grains", init.particles.size()));
    };
    fs::remove(dir / "driver_summary.json");  // a stale marker must not pass for this run's
    run_driver(paths, dir, couette_params(c, p, s, init.box, init.file), p.id, timeout, poll);

    Summary base = make_summary(c, p0, "yade", s.insertion.seed);
    base.provenance.settings = settings_json(s);
    base.provenance.settings["initial_file"] = init.file.string();
    base.provenance.settings["initial_file_reused"] = init.reused;
    PointResult r = reduce_point(c, p, s, init.box, init.particles.radius, dir, std::move(base));
    fs::remove(dir / "samples.bin");  // raw snapshots: large, and reproducible from params.json
    fs::remove(dir / "progress");
    return r;
}

}  // namespace

void check(const Case& c, const RunOptions& o) {
    for_each_run(c, o, [&](const OperatingPoint& p0, const RunOptions& v) {
        const Settings s = resolve_settings(c, p0, v);
        OperatingPoint p = p0;
        p.solid_fraction = s.servo.insert_fill;  // as solve_point() inserts it
        check_initial_particles(c, p, s.periodic_depth, s.servo.insert_fill_key);
    });
}

int run(const Case& c, const RunOptions& o) {
    // each point is one single-threaded YADE process (-j1): as many side by side as cores allow
    const int at_once = points_at_once(o, static_cast<int>(c.select(o.point).size()));
    return run_sweep(c, "yade", o, [&](const OperatingPoint& p, const fs::path& dir) {
        try {
            return solve_point(c, o, p, dir);
        } catch (const SolverError&) {
            throw;
        } catch (const Error& e) {  // bad input found for this point: same message, as a point failure
            throw SolverError(e.what());
        } catch (const std::exception& e) {
            throw SolverError(fmt::format("point {}: {}", p.id, e.what()));
        }
    }, at_once);
}

}  // namespace granlub::yade
