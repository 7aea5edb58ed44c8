// The [dem] case section: one line per key (type, default, range, unit, doc) and, for a plain key,
// the Settings field it fills (granlub/case/bound_keys.h; resolve_settings() reads them in one
// loop). Apart from the engine pipeline so that it compiles with core alone (the case-parser fuzzer
// builds it).
#include "granlub/dem/command.h"
#include "granlub/particles/contact_laws.h"
#include "granlub/particles/engine_keys.h"
#include "granlub/particles/particle_section.h"
#include "granlub/particles/servo.h"
#include "settings.h"

namespace granlub::dem {

namespace {

// The same shape as plugins/yade/src/section.cpp's declare(), not shared: each engine's own keys, Settings and default law.
BoundKeys<Settings> declare() {
    BoundKeys<Settings> k(SectionSpec(kSolver.name, "particle simulation in LIGGGHTS (granlub-liggghts)"));
    SectionSpec& s = k.spec;  // keys read by hand: their values convert or combine (settings.cpp)
    add_contact_law_key(s, ParticleEngine::Liggghts, "impulse");
    k.real("beta0", &Settings::beta0, 0.0, Range::closed(-1, 1), "",
           "Walton's tangential restitution of sticking impacts (impulse model); 0 = the stick limit");
    k.boolean("separate_overlaps", &Settings::separate, true,
              "impulse model: also remove overlaps by moving grains apart (our assumption, not S&T's; "
              "without it enduring contacts sink into each other)");
    k.real("bounce_speed", &Settings::bounce_speed, 0.0, Range::closed(0, 1e3), "m/s",
           "impulse model: restitution only for approach speeds above this (below, e = 0); 0 = at every speed "
           "(our assumption, not S&T's)");
    s.choice("contact_solve", "single_pass", {"single_pass", "iterated"},
             "impulse model: 'single_pass' = Sawyer & Tichy's operator (each contact resolved once per step, in "
             "sequence); 'iterated' = all contacts of a step solved together to convergence (fix impulse/solve: "
             "projected Gauss-Seidel, warm start, overlaps corrected by pseudo-velocities; our addition)");
    k.boolean("impact_time", &Settings::impact_time, false,
              "contact_solve = 'single_pass': apply each impact at its time within the step (grains moved by the "
              "distance their new velocity covers since the surfaces met), not at the step's end as Sawyer & Tichy "
              "do; removes the single pass's first-order flight-timing error (plugin doc gran_model_impulse)").neutral_default();
    k.boolean("speculative", &Settings::speculative, false,
              "impulse model: also act on grains and walls close but not yet touching, so that surfaces meeting "
              "within the step stop at contact (restitution on a real impact) and no overlap is made at the contact "
              "(speculative contacts; plugin doc gran_model_impulse); with contact_solve = 'iterated' the close "
              "contacts join the solve with their gap. Neither removes the loaded cells' time-step error "
              "(docs/measurements/liggghts.md); cost: about 1.6x the single pass, and far more iterated").neutral_default();
    s.choice("boundary_pairs", "sequential", {"sequential", "pass_start"},
             "contact_solve = 'single_pass': a pair across a periodic or processor boundary (resolved by both of its "
             "owners) takes its geometry from 'sequential' = the positions as the pass has moved them so far (every "
             "earlier result; separate_overlaps moves the owned grain but not its image, so the two sides can differ "
             "and momentum is made at those boundaries) or 'pass_start' = the positions as the pair pass began "
             "(model impulse boundary_start on: momentum conserved at periodic and processor boundaries, about +27 % "
             "per step; plugin README, Missing / deviations); 'pass_start' is refused with another model, with "
             "contact_solve = 'iterated' (which conserves it already) and without separate_overlaps or impact_time "
             "(nothing moves in the pass)").neutral_default();
    k.real("solve_tolerance", &Settings::solve_tolerance, 1e-4, Range::closed(1e-12, 0.5), "",
           "contact_solve = 'iterated': stop when the largest impulse change of a sweep is at most this times the "
           "largest normal impulse of the step");
    k.integer("solve_iterations", &Settings::solve_iterations, 200, Range::closed(1, 100000),
              "contact_solve = 'iterated': at most this many sweeps per step (velocities, and positions, each)");
    k.boolean("refine_dt", &Settings::refine_dt, false,
              "check every point's time step: a run at the full step (folder dt_full/), then the point's answer at "
              "half the step; run.dt_refinement compares them, each output carries dt_error = |value(dt) - "
              "value(dt/2)|, and a point that moves more than the rule allows is dt-unconverged");
    k.real("refine_time", &Settings::refine_time, 0.0, Range::non_negative(), "s",
           "refine_dt: 0 = the half-step run is cold, the whole `time` from the initial grains; > 0 = this long, "
           "warm-started from the full-step run's final state (cheaper, but a layered packing keeps the full "
           "step's state: on sawyer2001 it missed the cold run's answer by 3-6 standard errors at 1.4 and 2 m/s)");
    k.integer("refine_halvings", &Settings::refine_halvings, 1, Range::closed(1, 2),
              "refine_dt: the most halvings of the step. 1 = the answer at half the step, checked against the full "
              "step; 2 = where that check fails the rule, or the full-step run never got steady while the half-step run "
              "did, the step is halved once more (cold, the "
              "whole `time`; the half-step run moves to folder dt_half/) and the answer is the run at a quarter of "
              "the step, checked against the half step").neutral_default();
    k.real("dense_inertial_number", &Settings::dense_inertial_number, 0.0, Range::closed(0, 10), "",
           "impulse model under load control: a point whose nominal inertial number U d / (H sqrt(P / rho)) is "
           "below this is dense and runs at half the step step_fraction gives, its time-step check too (in dense "
           "flows with enduring contacts the single pass's full step is several per cent from its limit: plugin "
           "README, the step rule); 0 = off").neutral_default();
    k.real("quarter_step_inertial_number", &Settings::quarter_step_inertial_number, 0.0, Range::closed(0, 10), "",
           "with dense_inertial_number: a point whose nominal inertial number is below this (a smaller value) runs "
           "at a quarter of the step step_fraction gives, its time-step check at an eighth (at the slowest loaded "
           "points half the step is still several per cent from its limit: plugin README, the step rule); needs a "
           "cold check (refine_time = 0) or none; 0 = off").neutral_default();
    k.real("time", &Settings::time, 0.1, Range::positive(), "s", "simulated time of a quick run (the README's main job)")
        .full("time_full", 1.0, "simulated time with --full");
    add_until_steady_keys(s);  // time_max, time_max_full (granlub/particles/particle_section.h)
    s.real("strain", 0.0, Range::closed(0, 1e6), "",
           "run length in shear strain U t / H (H the case's gap) instead of a time: each point runs max(time, "
           "min(strain H / U, strain_time_max)) (time_full with --full), so slow points run as many strains as fast "
           "ones; 0 = off");
    s.real("strain_time_max", 2.0, Range::positive(), "s",
           "the cap on a strain-derived run length (a point at a small U would otherwise run for ever)");
    s.real("refine_strain", 0.0, Range::closed(0, 1e6), "",
           "refine_dt with a warm check: the half-step run's length in shear strain U t / H, so that every point's "
           "check covers as many strains; the check runs max(refine_time, min(refine_strain H / U, "
           "strain_time_max)); 0 = off (refine_time alone)").neutral_default();
    s.real("time_step", 0.0, Range::non_negative(), "s", "time step; 0 = derived from the case (step_fraction)");
    s.real("step_fraction", 0.02, Range::open_closed(0, kMaxStepFraction), "",
           "impulse model: diameters of the smallest grain travelled per step at the larger of U, sqrt(2 g H) and, under load "
           "control, sqrt(12 P / (pi rho)) (the load's push on one grain over one diameter)");
    s.real("hertz_step_fraction", kHertzStepFraction, Range::open_closed(0, kHertzMaxStepFraction), "",
           "hertz model: time step as a fraction of the Rayleigh time");
    s.real("neighbor_skin", 0.25, Range::positive(), "",
           "neighbour skin: pairs closer than contact plus this gap are listed (LIGGGHTS' neighbor skin), in grain "
           "diameters (the case's d); the list is rebuilt when a grain has moved half of it")
        .old_names({"skin"});
    s.choice("ring_walls", "primitive", {"primitive", "mesh"},
             "[cell] geometry = annulus: 'primitive' = all four walls exact (fix wall/gran/moving: the floor and "
             "both cylinders turning in place, the top a plane the servo moves); 'mesh' = STL meshes (ring_facet), "
             "the cylinders polygons. Either way the servo moves the top at a steady speed over each window");
    s.real("ring_facet", 0.7, Range::closed(0.05, 5), "",
           "[cell] geometry = annulus: longest facet edge along the ring's circles, in grain diameters (the "
           "meshes' facets per circle follow from the outer wall's circumference; ring_walls = 'mesh' only)");
    add_engine_keys(k);  // sampling and servo keys, [particles] (granlub/particles/engine_keys.h)
    k.bind("snapshots", &Settings::snapshots);
    return k;
}

}  // namespace

const BoundKeys<Settings>& dem_keys() { return keys_once<Settings, declare>(); }

SectionSpec section() { return dem_keys().spec; }

}  // namespace granlub::dem
