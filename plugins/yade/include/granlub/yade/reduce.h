// From the driver's raw outputs to granlub's result files: this file reads the driver's outputs;
// stresses, steady state, standard errors, profile, slips and the console line are the shared
// particle reduction of `granlub dem` as well (granlub/particles/particle_reduction.h).
//
// Driver outputs read here (all in the point folder):
//   driver_summary.json  written last by the driver: counts, dt, timings, YADE version
//   wallforce.csv        per sample_every steps: mean force of the grains on each wall (N)
//   samples.bin          per snapshot: x, y, z, vx, vy, vz of every grain, float64 little-endian,
//                        grains in the order of the initial file (deleted once coarse-grained)
//   plate.csv            control = load: plate position (m) after each servo window; reduced
//                        to gap.csv and run.load_control as `granlub dem` (granlub/particles/load_control.h)
//   final_raw.csv        the grains with their spins at the end (core particles.h's state format),
//                        read once by the command: passed here for run.wall_layer
//                        (granlub/particles/wall_layer.h), then the point's final_state.csv
#pragma once
#include <filesystem>
#include <optional>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/particles/particle_reduction.h"
#include "granlub/particles/particles.h"
#include "granlub/run/sweep.h"
#include "granlub/yade/settings.h"

namespace granlub::yade {

inline constexpr const char* kFinalRawFile = "final_raw.csv";

// wallforce.csv: the forces of the grains on the walls, as the shared reduction takes them (the
// side-wall columns are always there; reduce_point drops them for a box periodic across z).
WallForceSeries read_wall_forces(const std::filesystem::path& file);

// Builds the point's profile and summary (summary starts as `base`, from make_summary()).
// `radius` gives each grain's radius in file order. Throws SolverError on missing or
// inconsistent driver output. `final_state`: the driver's final_raw.csv, read by the caller (none: the wall
// layer is recorded as not measured).
PointResult reduce_point(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleBox& box,
                         const std::vector<double>& radius, const std::filesystem::path& dir, Summary base,
                         std::optional<ParticleState> final_state = {});

}  // namespace granlub::yade
