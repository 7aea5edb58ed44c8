// From LIGGGHTS' output files to granlub results: wall stresses (steady state, block errors)
// and the coarse-grained profile.
#pragma once
#include <filesystem>
#include <functional>
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

// Calls snapshot(grains, step) for every snapshot of a LIGGGHTS `dump custom ... <kSnapshotColumns>`
// file (sorted by id: index i is grain id i + 1). Returns the number of snapshots read.
std::size_t for_each_snapshot(const std::filesystem::path& file,
                              const std::function<void(const ParticleSet&, double step)>& snapshot);

// control = load: the plate position (gap, m) at the end of each servo window (LIGGGHTS' fix
// ave/time file; the initial position at step 0 is dropped).
struct PlateSeries {
    std::vector<double> step;
    std::vector<double> gap;
};
PlateSeries read_plate_series(const std::filesystem::path& file);

// Where the steady state starts: MSER-5 on the four wall-stress series and (load control) on the
// plate position; the latest start wins. Indices into the wall and plate series.
struct SteadyWindow {
    std::size_t wall_start = 0;
    std::size_t plate_start = 0;
    double t_start = 0;  // s
    bool steady = true;
};
SteadyWindow steady_window(const Settings& s, const WallSeries& walls, const PlateSeries* plate);

// Mean gap (m) and its block standard error over the steady part of the plate history.
BlockEstimate mean_gap(const Settings& s, const PlateSeries& plate, const SteadyWindow& w);

// The top-wall normal stress (Pa) averaged over each servo window of the plate history (the
// wall-force blocks inside it; -1 for a window without blocks).
std::vector<double> window_stresses(const Settings& s, const WallSeries& walls, const PlateSeries& plate);

// gap.csv: time_s, gap_m, normal_stress_top_Pa (the top-wall stress averaged over each servo window).
std::string gap_csv(const Settings& s, const WallSeries& walls, const PlateSeries& plate, const std::string& comment);

struct DemOutputs {
    Profile profile;
    std::map<std::string, Scalar> outputs;
    nlohmann::json run;  // steady-state facts
    std::string line;
};

// Stresses (Pa, positive magnitudes, as docs/architecture.md): normal bottom = f_y(bottom)/A, top =
// -f_y(top)/A; shear bottom = f_x(bottom)/A, top = -f_x(top)/A, with f the force of the wall
// on the grains and A = L W. Steady state: MSER-5 on each of the four series, the latest start.
// Load control: also `gap` (m, the mean plate position), mean_solid_fraction = N V_grain / (A gap),
// and the servo facts in `run`. `grains` = N.
DemOutputs make_outputs(const Case& c, const OperatingPoint& p, const Settings& s, const WallSeries& walls,
                        const SliceCoarseGrainer& cg, const SteadyWindow& window, const PlateSeries* plate,
                        std::size_t grains);

}  // namespace granlub::dem
