// Reading LIGGGHTS' output files into the engine-independent series that granlub/particles/particle_reduction.h
// turns into the point's results.
#pragma once
#include <filesystem>
#include <functional>
#include <vector>

#include "granlub/particles/annulus.h"
#include "granlub/case/case.h"
#include "granlub/particles/coarse_grain.h"
#include "granlub/particles/load_control.h"
#include "granlub/particles/particle_reduction.h"
#include "granlub/results/results.h"
#include "settings.h"

namespace granlub::dem {

// fix ave/time output: one row per block of sample_every steps.
struct WallSeries {
    std::vector<double> step;
    std::vector<std::vector<double>> columns;  // fx fy fz bottom, fx fy fz top[, fx side1, fx side2]
};
WallSeries read_wall_series(const std::filesystem::path& file);

// Calls snapshot(grains, step) for every snapshot of a LIGGGHTS `dump custom ... <kSnapshotColumns>`
// file, or `<kFinalColumns>` with `spins` (sorted by id: index i is grain id i + 1). Returns the
// number of snapshots read.
std::size_t for_each_snapshot(const std::filesystem::path& file,
                              const std::function<void(const ParticleSet&, double step)>& snapshot,
                              bool spins = false);

// control = load: the plate position (gap, m) at the end of each servo window, from LIGGGHTS' fix
// ave/time file (the initial position at step 0 is dropped).
PlateSeries read_plate_series(const std::filesystem::path& file);

// control = load: the plate position the deck printed after the run (kFinalPlateFile), m.
double read_final_plate(const std::filesystem::path& file);

// The common series (granlub/particles/particle_reduction.h): LIGGGHTS records the force of each wall on the
// grains, the reduction takes the force of the grains on the walls, so every column changes sign.
WallForceSeries wall_forces(const WallSeries& walls);

// The ring's wall file (ring_deck.h, kRingWallColumns after the step): the loads of the grains on
// the meshes, as recorded (no sign change: a mesh records the force on itself).
RingWallLoads ring_wall_loads(const WallSeries& walls, const std::filesystem::path& file);

// The point's results: the shared particle reduction (granlub/particles/particle_reduction.h).
using DemOutputs = ParticleReduction;

}  // namespace granlub::dem
