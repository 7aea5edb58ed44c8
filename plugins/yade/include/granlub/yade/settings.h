// The [yade] settings of one run, resolved from the case, the point and the command line, and
// checked before YADE starts. Run length, sampling and averaging follow `granlub dem`'s
// definitions (wall forces summed every step and averaged over blocks of sample_every steps,
// `snapshots` particle snapshots over the run, granlub/statistics/steady_state.h's window, block standard errors).
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "granlub/case/bound_keys.h"
#include "granlub/case/case.h"
#include "granlub/particles/contact_laws.h"
#include "granlub/particles/particles.h"
#include "granlub/particles/servo.h"
#include "granlub/particles/until_steady.h"
#include "granlub/run/sweep.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/statistics/flow_regime.h"

namespace granlub::yade {

// Every field that a [yade] key sets is set by resolve_settings() from that key: the key's
// default, range and doc are the schema's (src/section.cpp), so none is restated here. A plain
// key is this field and its line in src/section.cpp, which names the field (yade_keys()).
struct Settings {
    const ContactLaw* law = nullptr;       // [yade] model, a row of granlub/particles/contact_laws.h
    double contact_time = 0;               // viscel: t_c, s
    double tangential_restitution = 0;     // viscel: e_t
    double wall_mass = 0;                  // viscel: kg
    bool calibrate_restitution = false;    // viscel: e_n such that a binary collision gives e
    double time_step = 0;                  // s, resolved (never 0; [yade] time_step)
    double time = 0;                       // s, the run length the case asks for (time or time_full)
    std::int64_t steps = 0;                // multiple of sample_every and of snapshot_every
    std::int64_t sample_every = 0;         // steps per wall-force mean
    std::int64_t snapshot_every = 0;       // steps between particle snapshots
    std::int64_t body_force_every = 0;     // steps between centripetal-force refreshes
    double neighbor_skin = 0;              // smallest diameters; the collider's verletDist in smallest radii
    std::int64_t stations = 0;
    std::int64_t blocks = 0;
    double timeout = 0;                    // s; 0 = from the run size
    UntilSteadyCap until_steady;           // time_max: continued until steady up to this in all; 0 = off
    // The initial configuration, shared with `granlub dem`: [particles] seed, velocity_noise and
    // periodic_depth (granlub/particles/particle_section.h); --seed overrides.
    InsertionOptions insertion;
    double periodic_depth = 0;
    // [yade] start = "warm": start from granlub dem's final state of the point (final_state_path())
    bool warm_start = false;
    // control = "load": the top wall is a plate the driver moves every servo_every steps, the
    // servo of `granlub dem` (granlub/particles/servo.h) with the same keys in [yade]; or, with
    // servo_plate = "weight", a plate of plate_mass x the grains' mass pressed by P A
    ServoSettings servo;
    // the window servo's gain capped from the contact stiffness (servo.h capped_plate_gain), as
    // granlub dem caps it: a unit error moves the plate by one grain-plate overlap at the load
    double plate_overlap = 0;              // m
    double plate_gain = 0;                 // diameters per unit relative error, the driver's
    // contact persistence after the run, as granlub dem measures it (flow_regime.h)
    std::int64_t persistence_every = 1;
    std::int64_t persistence_intervals = kPersistenceIntervals;
    // rough walls ([walls] surface = "bumps", core wall_bumps.h): fixed spheres in the driver, the
    // floor's moving with it, the top's with the plate (window servo or weight plate)
    std::optional<BumpLayer> bumps_bottom, bumps_top, bumps_side;  // bumps_side: each side wall's
};


// Reads [yade] for point p; --full selects time_full, --seed overrides the seed. Under load,
// steps are whole servo windows and whole snapshot intervals (rounded up).
// Throws CaseError (file, key, value, what is allowed) for settings that cannot work.
Settings resolve_settings(const Case& c, const OperatingPoint& p, const RunOptions& o);

// The [yade] section with each plain key's field (src/section.cpp); section() is its spec.
const BoundKeys<Settings>& yade_keys();

}  // namespace granlub::yade
