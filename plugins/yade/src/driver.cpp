#include "granlub/yade/driver.h"

#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/results/results.h"
#include "granlub/run/process.h"

#ifndef GRANLUB_YADE_DRIVER_PATH
#error "GRANLUB_YADE_DRIVER_PATH must name plugins/yade/granlub_yade.py"
#endif

namespace granlub::yade {

namespace fs = std::filesystem;
using nlohmann::json;

DriverPaths locate_driver() {
    DriverPaths d;
    const char* env_yade = std::getenv("GRANLUB_YADE");
    const std::string yade = env_yade && *env_yade ? env_yade : "yade";
    const auto exe = find_executable(yade);
    if (!exe)
        throw SolverError(fmt::format(
            "YADE not found: `{}` is {} (install it with `apt-get install -y --no-install-recommends yade`, "
            "or set GRANLUB_YADE to the yade launcher)",
            yade, yade.find('/') != std::string::npos ? "not an executable file" : "not on PATH"));
    d.yade = *exe;
    const char* env_script = std::getenv("GRANLUB_YADE_DRIVER");
    d.script = env_script && *env_script ? fs::path(env_script) : fs::path(GRANLUB_YADE_DRIVER_PATH);
    if (!fs::is_regular_file(d.script))
        throw SolverError(fmt::format("the YADE driver script {} does not exist (set GRANLUB_YADE_DRIVER to "
                                      "plugins/yade/granlub_yade.py of the granlub sources)",
                                      d.script.string()));
    return d;
}

namespace {

json material(const Wall& w) { return {{"restitution", w.restitution}, {"friction", w.friction}}; }

json common_params(const Case& c, const OperatingPoint& p, const Settings& s, const char* task) {
    json j;
    j["format"] = kParamsFormat;
    j["task"] = task;
    j["model"] = s.law->yade;
    j["seed"] = s.insertion.seed;
    j["grains"] = {{"diameter", c.grains.diameter},
                   {"density", c.grains.density},
                   {"youngs_modulus", c.grains.youngs_modulus},
                   {"poisson_ratio", c.grains.poisson_ratio}};
    j["materials"] = {{"grain", {{"restitution", c.grains.restitution}, {"friction", c.grains.friction}}},
                      {"bottom", material(p.bottom)},
                      {"top", material(p.top)},
                      {"side", material(p.bottom)}};
    j["contact"] = {{"dt", s.time_step},
                    {"contact_time", s.contact_time},
                    {"tangential_restitution", s.tangential_restitution},
                    {"wall_mass", s.wall_mass},
                    {"calibrate", s.calibrate_restitution}};
    j["output_dir"] = ".";
    return j;
}

}  // namespace

json couette_params(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleBox& box,
                    const fs::path& initial_file, double overlap, double start_time) {
    json j = common_params(c, p, s, "couette");
    j["cell"] = {{"gap", box.gap}, {"length", box.length}, {"width", box.width}, {"periodic_z", box.periodic_z}};
    j["wall_speed"] = p.speed;
    j["gravity"] = c.gravity;
    j["annulus_radius"] = c.cell.annulus_radius;
    j["run"] = {{"steps", s.steps},
                {"sample_every", s.sample_every},
                {"snapshot_every", s.snapshot_every},
                {"body_force_every", s.body_force_every},
                {"verlet_distance", s.neighbor_skin},  // the driver's verletDist = -value
                {"persistence_every", s.persistence_every},  // after the run (flow_regime.h)
                {"persistence_intervals", s.persistence_intervals}};
    j["initial_file"] = fs::absolute(initial_file).string();
    j["initial_overlap"] = overlap;
    j["start_time"] = start_time;
    // rough walls: the bumps' centres in the wall's plane (granlub y = 0, and the top's start; the
    // side walls' at z = -W/2 and W/2, their heights in "y") at the run's start: the floor's and the
    // sides' moved U start_time from their layout, where the starting state's grains met them
    auto layer = [](const BumpLayer& b, const char* across) {
        return json{{"diameter", b.diameter}, {"x", b.x}, {across, b.across}};
    };
    const double shift = p.speed * start_time;
    if (s.bumps_bottom) j["bumps"]["bottom"] = layer(moved_bumps(*s.bumps_bottom, shift, box.length), "z");
    if (s.bumps_top) j["bumps"]["top"] = layer(*s.bumps_top, "z");
    if (s.bumps_side) j["bumps"]["sides"] = layer(moved_bumps(*s.bumps_side, shift, box.length), "y");
    if (s.servo.load) {  // the plate servo of granlub/particles/servo.h, lengths in m
        const ServoSettings& v = s.servo;
        j["servo"] = {{"target_stress", v.target_stress},
                      {"every", v.servo_every},
                      {"step", s.plate_gain * c.grains.diameter},  // capped from the contact stiffness (settings.cpp)
                      {"max_error", v.servo_max_error},
                      {"gap_min", v.gap_min},
                      {"gap_max", v.gap_max},
                      {"plate", s.servo.weight_plate ? "weight" : "window"},
                      {"plate_mass_ratio", s.servo.plate_mass}};
    }
    return j;
}

json collision_params(const Case& c, const OperatingPoint& p, const Settings& s, double impact_speed) {
    json j = common_params(c, p, s, "collision");
    j["impact_speed"] = impact_speed;
    return j;
}

void run_driver(const DriverPaths& paths, const fs::path& dir, json params, const std::string& point,
                double timeout_s, const std::function<void()>& poll) {
    fs::create_directories(dir);
    write_file_atomic(dir / "params.json", params.dump(1) + "\n");
    const fs::path script = dir / "granlub_yade.py";
    fs::copy_file(paths.script, script, fs::copy_options::overwrite_existing);
    const fs::path log = dir / "yade.log";
    {
        std::ofstream l(log, std::ios::trunc);
        l << fmt::format("# {} -n -j1 -x granlub_yade.py params.json   (in {})\n", paths.yade.string(), dir.string());
    }
    // -n: no GUI; -j1: one thread, bitwise reproducible (docs/yade-notes.md §5); -x: exit at the end
    const ProcessResult r = run_process({paths.yade.string(), "-n", "-j1", "-x", "granlub_yade.py", "params.json"},
                                        dir, log, timeout_s, poll);
    if (r.exit_code == 0 && !r.timed_out && !r.signal) return;
    std::string what = r.describe();
    if (r.exit_code == 2) what += " (the driver rejected its parameters)";
    throw SolverError(fmt::format("point {}: YADE {} (timeout {:.0f} s); log {}, last lines:\n{}", point, what,
                                  timeout_s, log.string(), tail_lines(log, 8)));
}

Restitution measure_restitution(const Case& c, const OperatingPoint& p, const Settings& s, const fs::path& dir,
                                double impact_speed) {
    const DriverPaths paths = locate_driver();
    run_driver(paths, dir, collision_params(c, p, s, impact_speed), p.id, 300.0);
    const fs::path file = dir / "collision.json";
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("point {}: YADE finished but wrote no {}", p.id, file.string()));
    json j;
    try {
        in >> j;
        Restitution r;
        auto values = [&](const json& v) {
            return CollisionValues{v.at("grain").get<double>(), v.at("bottom").get<double>(),
                                   v.at("top").get<double>(), v.at("side").get<double>()};
        };
        r.e = values(j.at("restitution"));
        r.duration = values(j.at("contact_duration"));
        if (j.contains("en")) r.en = j["en"];
        return r;
    } catch (const json::exception& ex) {
        throw SolverError(fmt::format("{}: malformed collision result: {}", file.string(), ex.what()));
    }
}

}  // namespace granlub::yade
