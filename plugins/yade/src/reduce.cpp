#include "granlub/yade/reduce.h"

#include <cmath>
#include <fstream>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "granlub/error.h"
#include "granlub/particles/particle_pipeline.h"
#include "granlub/results/table.h"

namespace granlub::yade {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A driver CSV file with exactly this header, every value finite (the driver never writes nan).
std::vector<std::vector<double>> read_driver_csv(const fs::path& file, const std::string& header,
                                                 const std::string& what) {
    TableFormat f;
    f.expected_header = header;
    f.finite = true;
    return read_solver_output(file, f, fmt::format("missing (the YADE run wrote no {})", what)).columns;
}

}  // namespace

WallForceSeries read_wall_forces(const fs::path& file) {
    auto t = read_driver_csv(file, "step,fx_bottom,fy_bottom,fz_bottom,fx_top,fy_top,fz_top,fx_side1,fx_side2",
                            "wall forces");
    return WallForceSeries{std::move(t[0]), std::move(t[1]), std::move(t[2]), std::move(t[3]), std::move(t[4]),
                      std::move(t[5]), std::move(t[6]), std::move(t[7]), std::move(t[8])};
}

PlateSeries read_plate(const fs::path& file) {
    auto t = read_driver_csv(file, "step,gap", "plate positions");
    if (t[0].size() < 2) throw SolverError(fmt::format("{}: fewer than 2 plate positions", file.string()));
    return PlateSeries{std::move(t[0]), std::move(t[1])};
}

namespace {

json read_json(const fs::path& file, const std::string& what) {
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("{}: missing ({})", file.string(), what));
    try {
        json j;
        in >> j;
        return j;
    } catch (const json::exception& e) {
        throw SolverError(fmt::format("{}: malformed: {}", file.string(), e.what()));
    }
}

// Streams samples.bin, one snapshot at a time (no whole-run buffer), to `each` with its time.
std::size_t read_samples(const fs::path& file, std::size_t n, std::size_t snapshots, double snapshot_dt,
                         const std::vector<double>& radius, const ParticleBox& box, const SnapshotVisitor& each) {
    constexpr std::size_t kCols = 6;  // x, y, z, vx, vy, vz
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SolverError(fmt::format("{}: missing (the YADE run wrote no snapshots)", file.string()));
    const auto bytes = fs::file_size(file);
    if (bytes != snapshots * n * kCols * sizeof(double))
        throw SolverError(fmt::format("{}: {} bytes, expected {} snapshots x {} grains x {} doubles", file.string(),
                                      bytes, snapshots, n, kCols));
    std::vector<double> buf(n * kCols);
    ParticleSet p;
    p.x.resize(n), p.y.resize(n), p.z.resize(n), p.vx.resize(n), p.vy.resize(n), p.vz.resize(n);
    p.radius = radius;
    for (std::size_t s = 0; s < snapshots; ++s) {
        in.read(reinterpret_cast<char*>(buf.data()), static_cast<std::streamsize>(buf.size() * sizeof(double)));
        if (!in) throw SolverError(fmt::format("{}: short read at snapshot {}", file.string(), s));
        for (std::size_t i = 0; i < n; ++i) {
            const double* r = &buf[i * kCols];  // little-endian doubles, as on every supported host
            p.x[i] = r[0], p.y[i] = r[1], p.z[i] = r[2], p.vx[i] = r[3], p.vy[i] = r[4], p.vz[i] = r[5];
            if (box.periodic_z)  // YADE does not wrap positions into the periodic cell
                p.z[i] -= box.width * std::floor((p.z[i] + 0.5 * box.width) / box.width);
        }
        each(p, static_cast<double>(s + 1) * snapshot_dt);
    }
    return snapshots;
}

}  // namespace

PointResult reduce_point(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleBox& box,
                         const std::vector<double>& radius, const fs::path& dir, Summary base,
                         std::optional<ParticleState> final_state) {
    const json ds = read_json(dir / "driver_summary.json", "the YADE run did not finish");
    const auto n = ds.at("grains").get<std::size_t>();
    const auto snapshots = ds.at("snapshots").get<std::size_t>();
    const double dt = ds.at("dt").get<double>();
    if (n != radius.size())
        throw SolverError(fmt::format("{}: {} grains, the initial file has {}", (dir / "driver_summary.json").string(),
                                      n, radius.size()));
    WallForceSeries w = read_wall_forces(dir / "wallforce.csv");
    const auto expected_rows = static_cast<std::size_t>(s.steps / s.sample_every);
    if (w.rows() != expected_rows)
        throw SolverError(fmt::format("{}: {} rows, expected {}", (dir / "wallforce.csv").string(), w.rows(),
                                      expected_rows));
    if (box.periodic_z) w.fx_side1.clear(), w.fx_side2.clear();  // no side walls

    // the driver's files into the shared series; the rest is the one particle pipeline
    ParticleRecord rec;
    rec.forces = std::move(w);
    if (s.servo.load) {
        rec.plate = read_plate(dir / "plate.csv");
        const auto expected_updates = static_cast<std::size_t>(s.steps / s.servo.servo_every);
        if (rec.plate->step.size() != expected_updates)
            throw SolverError(fmt::format("{}: {} plate positions, expected {}", (dir / "plate.csv").string(),
                                          rec.plate->step.size(), expected_updates));
    }
    const double snapshot_dt = dt * static_cast<double>(s.snapshot_every);
    rec.snapshots = {(dir / "samples.bin").string(), [&](const SnapshotVisitor& each) {
                         return read_samples(dir / "samples.bin", n, snapshots, snapshot_dt, radius, box, each);
                     }};
    rec.final_state = std::move(final_state);  // the grains with their spins at the end: run.wall_layer
    // contact persistence after the run (flow_regime.h), as granlub dem measures it
    const auto persistence_snapshots = ds.value("persistence_snapshots", std::size_t{0});
    const double persistence_dt = dt * static_cast<double>(s.persistence_every);
    if (persistence_snapshots > 0)
        rec.persistence = {(dir / "contacts.bin").string(), [&](const SnapshotVisitor& each) {
                               return read_samples(dir / "contacts.bin", n, persistence_snapshots, persistence_dt,
                                                   radius, box, each);
                           }};
    const ParticlePipeline pl{.c = c,
                              .p = p,
                              .box = box,
                              .servo = s.servo,
                              .time_step = dt,
                              .sample_every = s.sample_every,
                              .stations = static_cast<std::size_t>(s.stations),
                              .blocks = static_cast<std::size_t>(s.blocks),
                              .grains = n,
                              .simulated_s = ds.at("simulated_time").get<double>(),
                              .contact_box = box,  // coordination, order and persistence
                              .persistence_every = s.persistence_every,
                              .bumps_bottom = &s.bumps_bottom,
                              .bumps_top = &s.bumps_top,
                              .bumps_side = &s.bumps_side,
                              .what = fmt::format("case {} point {} (granlub yade)", c.name, p.id)};
    ParticleReduction red = run_particle_pipeline(pl, rec, dir);
    Summary sum = std::move(base);
    for (auto& [name, v] : red.outputs) sum.outputs[name] = std::move(v);
    sum.run.update(red.run);

    const auto steps = ds.at("steps").get<double>();
    const double yade_run_s = ds.at("wall_clock_run_s").get<double>();
    sum.run["engine"] = "YADE " + ds.value("yade_version", std::string("?"));
    sum.run["model"] = s.law->name;
    sum.run["grains"] = n;
    sum.run["steps"] = ds.at("steps");
    sum.run["time_step_s"] = dt;
    sum.run["simulated_time_s"] = ds.at("simulated_time");
    sum.run["max_overlap_over_d"] = ds.at("max_overlap_over_d");
    sum.run["yade_wall_clock_s"] = ds.at("wall_clock_s");
    sum.run["loop_time_s"] = yade_run_s;
    sum.run["atom_steps_per_s"] = yade_run_s > 0 ? static_cast<double>(n) * steps / yade_run_s : 0.0;
    if (ds.contains("en")) sum.run["calibrated_en"] = ds["en"];
    sum.run["command"] = "yade -n -j1 -x granlub_yade.py params.json";
    PointResult r;
    r.profile = std::move(red.profile);
    r.summary = std::move(sum);
    r.line = fmt::format("{}  [{} grains, {} steps, {:.3g} atom-steps/s]", red.line, n,
                         ds.at("steps").get<long long>(), r.summary.run["atom_steps_per_s"].get<double>());
    return r;
}

}  // namespace granlub::yade
