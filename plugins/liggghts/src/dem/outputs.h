// From LIGGGHTS' output files to granlub results: wall stresses (steady state, block errors)
// and the coarse-grained profile.
#pragma once
#include <filesystem>
#include <functional>
#include <vector>

#include "granlub/case.h"
#include "granlub/coarse_grain.h"
#include "granlub/load_control.h"
#include "granlub/results.h"
#include "settings.h"

namespace granlub::dem {

// fix ave/time output: one row per block of sample_every steps.
struct WallSeries {
    std::vector<double> step;
    std::vector<std::vector<double>> columns;  // fx fy fz bottom, fx fy fz top[, fx side1, fx side2]
};
WallSeries read_wall_series(const std::filesystem::path& file);

// Calls snapshot(grains, step) for every snapshot of a LIGGGHTS `dump custom ... <kSnapshotColumns>`
// file (sorted by id: index i is grain id i + 1). Returns the number of snapshots read.
std::size_t for_each_snapshot(const std::filesystem::path& file,
                              const std::function<void(const ParticleSet&, double step)>& snapshot);

// control = load: the plate position (gap, m) at the end of each servo window, from LIGGGHTS' fix
// ave/time file (the initial position at step 0 is dropped).
PlateSeries read_plate_series(const std::filesystem::path& file);

// The steady window (granlub/load_control.h) of the four wall-force series and, under load, the plate.
SteadyWindow steady_window(const Settings& s, const WallSeries& walls, const PlateSeries* plate);

// The top-wall normal stress (Pa) per wall-force block: -f_y(top) / (L W).
std::vector<double> top_normal_stress(const Settings& s, const WallSeries& walls);

struct DemOutputs {
    Profile profile;
    std::map<std::string, Scalar> outputs;
    nlohmann::json run;  // steady-state facts
    std::string line;
};

// Stresses (Pa, positive magnitudes, as architecture.md): normal bottom = f_y(bottom)/A, top =
// -f_y(top)/A; shear bottom = f_x(bottom)/A, top = -f_x(top)/A, with f the force of the wall
// on the grains and A = L W. Steady state: MSER-5 on each of the four series, the latest start.
// Load control: also `gap` (m, the mean plate position), mean_solid_fraction = N V_grain / (A gap),
// and the servo facts in `run`. `grains` = N.
DemOutputs make_outputs(const Case& c, const OperatingPoint& p, const Settings& s, const WallSeries& walls,
                        const SliceCoarseGrainer& cg, const SteadyWindow& window, const PlateSeries* plate,
                        std::size_t grains);

}  // namespace granlub::dem
