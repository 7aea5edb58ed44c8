// The one particle pipeline: what `granlub dem` (LIGGGHTS) and `granlub yade` do with a run once
// their engine has stopped. Each engine reads its own files into a ParticleRecord; everything
// after that is written here once, for both:
//   wall stresses (particle_reduction.h; the ring's from its wall loads, annulus.h)
//   -> under load, the plate history gap.csv (load_control.h)
//   -> the steady window (steady_state.h) -> the mean gap the profiles span
//   -> coarse-graining across the gap and over the cross-section (coarse_grain.h, cross_section.h),
//      and the contact measures of the steady snapshots (contacts.h)
//   -> the shared reduction (reduce_particles) -> section.csv and width_profile.csv
//   -> the flow-regime record (flow_regime.h) in run.flow_regime
//   -> from the final state, the wall layer's kinematics (wall_layer.h) in run.wall_layer.
// A feature of the particle results (a grain or wall property, a measure) is added here, not in
// the engines.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "granlub/particles/annulus.h"
#include "granlub/case/case.h"
#include "granlub/particles/load_control.h"
#include "granlub/particles/particle_reduction.h"
#include "granlub/particles/particles.h"
#include "granlub/particles/servo.h"
#include "granlub/case/wall_bumps.h"

namespace granlub {

// Snapshots of the grains in the engine's own frame, in time order: read(each) calls each(grains,
// t) with t in s and returns how many it read; `name` (the file) is for messages.
using SnapshotVisitor = std::function<void(const ParticleSet&, double time_s)>;
struct SnapshotReader {
    std::string name;
    std::function<std::size_t(const SnapshotVisitor&)> read;
    explicit operator bool() const { return static_cast<bool>(read); }
};

// What an engine's run left, in the engine-independent series.
struct ParticleRecord {
    WallForceSeries forces = {};         // the slice: the force of the grains on each wall, per block
    std::optional<RingWallLoads> ring = {};  // the whole ring: its walls' loads instead of `forces`
    std::optional<PlateSeries> plate = {};   // control = load
    SnapshotReader snapshots = {};       // over the run
    SnapshotReader persistence = {};     // after the run, persistence_every steps apart; empty: none
    std::optional<ParticleState> final_state = {};  // the grains (with spins) at the end: run.wall_layer
};

struct ParticlePipeline {
    const Case& c;
    const OperatingPoint& p;
    ParticleBox box;                     // the slice-frame box; gap: where the top wall started
    const ServoSettings& servo;
    double time_step = 0;                // s
    std::int64_t sample_every = 0;       // steps per wall-force block
    std::size_t stations = 0;            // slabs across the gap
    std::size_t blocks = 0;              // blocks for standard errors
    std::size_t grains = 0;
    double simulated_s = 0;              // the run's simulated time
    double plate_start = 0;              // m, where the plate started (0: box.gap)
    const Annulus* annulus = nullptr;    // the whole ring: snapshots mapped to the slice frame
    // contacts (coordination, overlaps) are searched in the engine's frame in this box; none: the
    // snapshots do not hold the positions a search needs
    std::optional<ParticleBox> contact_box = {};
    std::int64_t persistence_every = 0;  // steps between the persistence snapshots
    const std::optional<BumpLayer>* bumps_bottom = nullptr;  // rough walls (wall_bumps.h), for run.walls
    const std::optional<BumpLayer>* bumps_top = nullptr;
    const std::optional<BumpLayer>* bumps_side = nullptr;    // each side wall's ([walls] sides)
    std::string what;                    // the first comment of every table: case, point, provenance
};

// Runs the pipeline on the files in `dir`, writes gap.csv (under load), section.csv and
// width_profile.csv there, and returns the point's profile, outputs and run facts (with
// run.flow_regime, run.order, run.walls, run.wall_layer, and for the ring run.geometry and the
// torque balance).
// Throws SolverError.
ParticleReduction run_particle_pipeline(const ParticlePipeline& in, const ParticleRecord& rec,
                                        const std::filesystem::path& dir);

}  // namespace granlub
