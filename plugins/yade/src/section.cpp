// The [yade] case section: one line per key (type, default, range, unit, doc) and, for a plain key,
// the Settings field it fills (granlub/case/bound_keys.h; resolve_settings() reads them in one loop).
#include "granlub/yade/command.h"
#include "granlub/yade/settings.h"

#include "granlub/particles/contact_laws.h"
#include "granlub/particles/engine_keys.h"
#include "granlub/particles/particle_section.h"
#include "granlub/particles/servo.h"

namespace granlub::yade {

namespace {

// The same shape as plugins/liggghts/src/dem/section.cpp's declare(), not shared: each engine's own keys, Settings and default law.
BoundKeys<Settings> declare() {
    BoundKeys<Settings> k(SectionSpec(kSolver.name, "YADE cross-check of the particle simulation (plugins/yade)"));
    SectionSpec& s = k.spec;  // keys read by hand: their values convert or combine (settings.cpp)
    add_contact_law_key(s, ParticleEngine::Yade, "viscel");
    k.real("contact_time", &Settings::contact_time, 1e-5, Range::positive(), "s", "viscel: binary contact duration t_c");
    k.real("tangential_restitution", &Settings::tangential_restitution, 0.01, Range::open_closed(0, 1), "",
           "viscel: tangential restitution e_t (small: sliding stops when slip vanishes)");
    k.real("wall_mass", &Settings::wall_mass, 1e3, Range::positive(), "kg",
           "viscel: mass given to the walls (ViscElMat needs one for the right reduced mass)");
    k.boolean("calibrate_restitution", &Settings::calibrate_restitution, true,
              "viscel: search e_n so that a binary collision in YADE gives the case's restitution");
    s.real("time_step", 0.0, Range::non_negative(), "s",
           "time step; 0 = contact_time/20 (viscel) or 0.15 Rayleigh times (hertz, as granlub dem; at most 0.3)")
        .old_names({"dt"});
    k.real("time", &Settings::time, 1.5e-3, Range::positive(), "s",
           "simulated time of a quick run (3000 steps, ~45 s of YADE per sawyer2001 point with viscel)")
        .full("time_full", 0.2, "simulated time with --full");
    add_until_steady_keys(s);  // time_max, time_max_full (granlub/particles/particle_section.h)
    k.integer("body_force_every", &Settings::body_force_every, 50, Range::closed(1, 1e8),
              "steps between refreshes of the centripetal force m v_x^2 / (annulus_radius - z)");
    k.real("neighbor_skin", &Settings::neighbor_skin, 0.2, Range::open_closed(0, 5), "",
           "neighbour skin as in [dem]: pairs closer than contact plus this gap are tracked, in diameters of the "
           "smallest grain. YADE enlarges each grain's bound by half of it (InsertionSortCollider.verletDist = "
           "-value smallest radii) and reruns the collider when a grain has moved that far; exact at any value, "
           "the cost is not (YADE's own 0.5 costs 25 % more on sawyer2001)")
        .old_names({"verlet_distance"});
    k.real("timeout", &Settings::timeout, 0.0, Range::non_negative(), "s",
           "wall-clock limit of one YADE run; 0 = 600 s + 100 us per grain-step (a guard against hangs, generous for shared machines)");
    s.choice("start", "cold", {"cold", "warm"},
             "initial grains: cold = the shared initial file ([particles]); warm = granlub dem's final "
             "state of the same point (results/dem/<point>/final_state.csv: positions, velocities, spins, "
             "plate), so the run starts in the DEM's steady state");
    add_engine_keys(k);  // sampling and servo keys, [particles] (granlub/particles/engine_keys.h)
    return k;
}

}  // namespace

const BoundKeys<Settings>& yade_keys() { return keys_once<Settings, declare>(); }

SectionSpec section() { return yade_keys().spec; }

}  // namespace granlub::yade
