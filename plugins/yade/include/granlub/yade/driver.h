// The YADE side of a run: where the launcher and the driver script are, the JSON parameter file
// the driver reads (plugins/yade/granlub_yade.py, format "granlub-yade/1"), and one checked run.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/case/case.h"
#include "granlub/particles/particles.h"
#include "granlub/yade/settings.h"

namespace granlub::yade {

inline constexpr const char* kParamsFormat = "granlub-yade/1";

struct DriverPaths {
    std::filesystem::path yade;    // launcher: $GRANLUB_YADE, else `yade` on PATH
    std::filesystem::path script;  // $GRANLUB_YADE_DRIVER, else plugins/yade/granlub_yade.py
};
// Throws SolverError saying what is missing and how to get it.
DriverPaths locate_driver();

// Parameter files. Under load control couette_params() has a "servo" object (target_stress Pa,
// every steps, step m per unit relative error, max_error, gap_min and gap_max m). Materials: "grain" (grain-grain), "bottom", "top" (the point's walls) and
// "side" (the side walls, which slide with the bottom wall and take its restitution and friction,
// as in `granlub dem`).
// `overlap`: how far (a fraction of its radius) a starting grain may reach into a wall: 0.01 for
// a start from the shared grains or granlub dem's rigid grains; a continued run starts from YADE's
// own soft contacts, pressed by the load (until_steady.h), and passes kContinuedOverlap.
inline constexpr double kStartOverlap = 0.01;
inline constexpr double kContinuedOverlap = 0.1;
// `start_time`: the starting state's time (ParticleState::time; 0 from the initial grains): the
// floor's and side walls' bumps go in moved U start_time from their layout (wall_bumps.h
// moved_bumps), and the driver's final state counts on from it ("start_time").
nlohmann::json couette_params(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleBox& box,
                              const std::filesystem::path& initial_file, double overlap = kStartOverlap,
                              double start_time = 0);
nlohmann::json collision_params(const Case& c, const OperatingPoint& p, const Settings& s, double impact_speed);

// Writes `params` to dir/params.json, copies the driver into dir (the folder can be rerun by
// hand: cd dir && yade -n -j1 -x granlub_yade.py params.json), runs it with the log in
// dir/yade.log and checks the exit code. Throws SolverError naming the point, what happened,
// the log file and its last lines.
void run_driver(const DriverPaths& paths, const std::filesystem::path& dir, nlohmann::json params,
                const std::string& point, double timeout_s, const std::function<void()>& poll = {});

// Binary collisions in YADE with the contact law of the run: measured normal restitution and
// contact duration for grain-grain and grain-wall (each wall material), head-on impacts at
// impact_speed (relative normal velocity), no gravity. Files go to `dir`.
struct CollisionValues {
    double grain = 0, bottom = 0, top = 0, side = 0;
};
struct Restitution {
    CollisionValues e;         // -v_n' / v_n
    CollisionValues duration;  // s, steps with overlap x dt
    nlohmann::json en;         // viscel: the calibrated e_n per material (null otherwise)
};
Restitution measure_restitution(const Case& c, const OperatingPoint& p, const Settings& s,
                                const std::filesystem::path& dir, double impact_speed = 1.0);

}  // namespace granlub::yade
