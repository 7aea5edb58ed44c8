// From the driver's raw outputs to granlub's result files, with the definitions of `granlub dem`
// (plugins/liggghts/src/dem/outputs.cpp) and the shared code (core/include/granlub/coarse_grain.h):
// stresses = wall force / wall area from wall-force means over blocks of sample_every steps;
// steady state = the latest MSER-5 truncation of the four wall-stress series; standard errors by
// block averaging; profiles by exact sphere-slice coarse-graining of the snapshots from the
// steady state on; slip from the slabs next to the walls.
//
// Driver outputs read here (all in the point folder):
//   driver_summary.json  written last by the driver: counts, dt, timings, YADE version
//   wallforce.csv        per sample_every steps: mean force of the grains on each wall (N)
//   samples.bin          per snapshot: y, vx, vy, vz of every grain, float64 little-endian,
//                        grains in the order of the initial file (deleted once coarse-grained)
//   plate.csv            control = load: plate position (m) after each servo window; reduced
//                        to gap.csv and run.load_control as `granlub dem` (granlub/load_control.h)
#pragma once
#include <filesystem>
#include <vector>

#include "granlub/case.h"
#include "granlub/particles.h"
#include "granlub/sweep.h"
#include "granlub/yade/settings.h"

namespace granlub::yade {

struct WallForces {  // one row per sample interval; forces of the grains on the walls, N
    std::vector<double> step, fx_bottom, fy_bottom, fz_bottom, fx_top, fy_top, fz_top, fx_side1, fx_side2;
    std::size_t rows() const { return step.size(); }
};
WallForces read_wall_forces(const std::filesystem::path& file);

// Builds the point's profile and summary (summary starts as `base`, from make_summary()).
// `radius` gives each grain's radius in file order. Throws SolverError on missing or
// inconsistent driver output.
PointResult reduce_point(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleBox& box,
                         const std::vector<double>& radius, const std::filesystem::path& dir, Summary base);

}  // namespace granlub::yade
