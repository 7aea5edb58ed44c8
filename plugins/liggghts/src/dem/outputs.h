// From LIGGGHTS' output files to granlub results: wall stresses (steady state, block errors)
// and the coarse-grained profile.
#pragma once
#include <filesystem>
#include <vector>

#include "granlub/case.h"
#include "granlub/coarse_grain.h"
#include "granlub/results.h"
#include "settings.h"

namespace granlub::dem {

// fix ave/time output: one row per block of sample_every steps.
struct WallSeries {
    std::vector<double> step;
    std::vector<std::vector<double>> columns;  // fx fy fz bottom, fx fy fz top[, fx side1, fx side2]
};
WallSeries read_wall_series(const std::filesystem::path& file);

// Feeds every snapshot of a LIGGGHTS `dump custom ... id y vx vy vz radius` file to `cg`
// (time = step * dt). Returns the number of snapshots read.
std::size_t read_snapshots(const std::filesystem::path& file, double dt, SliceCoarseGrainer& cg);

struct DemOutputs {
    Profile profile;
    std::map<std::string, Scalar> outputs;
    nlohmann::json run;  // steady-state facts
    std::string line;
};

// Stresses (Pa, positive magnitudes, as architecture.md): normal bottom = f_y(bottom)/A, top =
// -f_y(top)/A; shear bottom = f_x(bottom)/A, top = -f_x(top)/A, with f the force of the wall
// on the grains and A = L W. Steady state: MSER-5 on each of the four series, the latest start.
DemOutputs make_outputs(const Case& c, const OperatingPoint& p, const Settings& s, const WallSeries& walls,
                        const SliceCoarseGrainer& cg);

}  // namespace granlub::dem
