// From a particle engine's wall forces and coarse-grained snapshots to a point's results, the same
// for `granlub dem` (LIGGGHTS) and `granlub yade`: each engine only reads its own files into the
// series below. Stresses = wall force / wall area from wall-force means over blocks of
// sample_every steps; steady state from the four wall-stress series (and, under load, the plate)
// as granlub/statistics/steady_state.h decides it; standard errors by block averaging; the
// profile from the snapshots from the steady state on; slip from the slabs next to the walls.
#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granlub/case/case.h"
#include "granlub/particles/coarse_grain.h"
#include "granlub/particles/cross_section.h"
#include "granlub/particles/load_control.h"
#include "granlub/particles/particles.h"
#include "granlub/results/results.h"
#include "granlub/particles/servo.h"

namespace granlub {

// The force of the grains on each wall (N; Newton's third law of what the walls exert), one row
// per block of sample_every steps, `step` at the end of each block. fx_side* are empty when the
// box is periodic across z (no side walls); fy_side* also when the engine does not record them;
// fz_* (unused by the reduction) when the engine does not record them (the ring, annulus.h).
struct WallForceSeries {
    std::vector<double> step, fx_bottom, fy_bottom, fz_bottom, fx_top, fy_top, fz_top, fx_side1, fx_side2;
    std::vector<double> fy_side1 = {}, fy_side2 = {};
    std::size_t rows() const { return step.size(); }
};

// Wall stresses per block (Pa), positive for a sheared, compressed layer: the grains push the
// bottom wall to -y and the top wall to +y, drag the bottom (and side) walls to -x and the top
// wall to +x. Normal = f_y / (L W), shear = f_x / (L W), side = mean of both side walls / (L H).
// side_support: the upward force of both side walls on the grains over the floor area, (L W): the
// vertical balance of the layer is P_bot - P_top = weight / (L W) - side_support.
// shear_outer, shear_inner: each side wall alone, side 1 (z = -W/2) the outer wall of the annulus.
struct WallStresses {
    std::vector<double> normal_bottom, normal_top, shear_bottom, shear_top, shear_side;  // side: may be empty
    std::vector<double> side_support = {};                                               // may be empty
    std::vector<double> shear_outer = {}, shear_inner = {};                              // may be empty
};
WallStresses wall_stresses(const WallForceSeries& f, const ParticleBox& box);

// The steady window of the four wall-stress series and, under load, the plate.
SteadyWindow wall_steady_window(const WallStresses& st, const WallForceSeries& f, std::int64_t sample_every,
                                double time_step, const PlateSeries* plate, std::int64_t servo_every);

struct ParticleReductionInputs {
    const Case& c;
    double speed;                      // U, m/s
    const ParticleBox& box;            // gap = the case's H (the plate's start under load)
    const WallForceSeries& forces;
    const WallStresses& stresses;
    const SliceCoarseGrainer& cg;      // every snapshot of the run, time-stamped in s
    const SteadyWindow& window;
    const PlateSeries* plate;          // control = load, else null
    const ServoSettings& servo;
    std::size_t blocks;                // requested: the wall stresses use fewer when their
                                       // decorrelation time asks for longer blocks (decorrelation.h)
    std::size_t grains;
    double solids_volume;              // m^3, the grains' volume (particles.h, solids_volume)
    double simulated_s;                // the run's simulated time (for the transient message)
    double time_step = 0;              // s: the decorrelation time in seconds (run.wall_stress_blocks)
    const CrossSection* cross_section = nullptr;  // the same snapshots over y x z, when recorded
    double plate_start = 0;            // m, where the plate started (0: box.gap)
    // slip is taken at the first station whose centre is at least this far from the wall's plane
    // (a rough wall: its bumps' tops, wall_bumps.h; 0: the station next to the plane)
    double slip_bottom_from = 0, slip_top_from = 0;  // m
};

struct ParticleReduction {
    Profile profile;
    Profile cross_section;  // y x z over the same snapshots (cross_section.h); empty when not recorded
    std::map<std::string, Scalar> outputs;
    nlohmann::json run;  // steady-state facts, status, and under load run.load_control
    std::string line;    // the one-line console report
};

// outputs: normal_stress_{bottom,top}, shear_stress_{bottom,top}[, shear_stress_{side,outer,inner},
// side_wall_support] (Pa, mean
// and block standard error over the steady window), slip_{bottom,top} (m/s: U - u and u at the
// stations slip_*_from from the walls), mean_solid_fraction,
// max_solid_fraction (the case's nu_max); under load also gap (load_summary).
ParticleReduction reduce_particles(const ParticleReductionInputs& in);

}  // namespace granlub
