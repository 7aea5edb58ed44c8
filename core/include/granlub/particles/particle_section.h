// What the two particle engines (`granlub dem`, `granlub yade`) share, declared once:
//  - the [particles] section: the initial grains both engines start from (seed, velocity noise)
//    and the periodic depth of a cell without side walls. One section, not a key per engine, so
//    that the engines cannot start from different grains by a forgotten key;
//  - the sampling keys (sample_every, snapshots, stations, blocks) and the until-steady keys
//    (time_max, time_max_full), added to each engine's own section because their steps and run
//    lengths differ (as add_servo_keys does for the servo);
//  - the Hertz time-step rule both engines apply to the same grains.
#pragma once
#include <cstdint>
#include <optional>

#include "granlub/case/case.h"
#include "granlub/particles/particles.h"
#include "granlub/case/schema.h"

namespace granlub {

// Hertz contacts: default step and stability limit, in Rayleigh times of the case's grains.
inline constexpr double kHertzStepFraction = 0.15;
inline constexpr double kHertzMaxStepFraction = 0.3;

// The [particles] section itself (kParticlesSection, particles_section()) is declared in case.h.

// sample_every, snapshots, stations, blocks, in an engine's own section.
void add_sampling_keys(SectionSpec& s);

// time_max and time_max_full (with --full) in an engine's own section: both particle engines
// continue a run that is not steady by one rule (until_steady.h).
void add_until_steady_keys(SectionSpec& s);

struct ParticleStart {
    InsertionOptions insertion;  // seed (--seed overrides), velocity noise, wall speed = the point's U
    double periodic_depth = 0;   // m, 0 = kPeriodicDepthDiameters grain diameters
};

// The [particles] keys of point p; `seed` is the command line's --seed.
ParticleStart particle_start(const Case& c, const OperatingPoint& p, std::optional<std::uint64_t> seed);

}  // namespace granlub
