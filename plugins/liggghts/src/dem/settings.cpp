// [dem] keys and the derived run settings (see settings.h and command.h).
#include "settings.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "granlub/dem/command.h"
#include "granlub/error.h"
#include "granlub/statistics/flow_regime.h"
#include "granlub/particles/contact_laws.h"
#include "granlub/particles/particle_section.h"

namespace granlub::dem {

double impulse_reference_speed(const Case& c, const OperatingPoint& p) {
    const double v_fall = std::sqrt(2.0 * c.gravity * c.cell.gap);
    const double v_load = p.control == Control::Load
                              ? std::sqrt(12.0 * p.normal_stress / (std::numbers::pi * c.grains.density))
                              : 0.0;
    // the ring's outer wall moves faster than U (at the mean radius) by r_o / R
    const double v_wall = c.cell.ring() ? p.speed * (1.0 + 0.5 * c.cell.width / c.cell.annulus_radius) : p.speed;
    return std::max({v_wall, v_fall, v_load});
}

namespace {

// The contact law and the checks of its options (beta0 ... solve_iterations, read by dem_keys()):
// the impulse options are refused with a law that has none (contact_laws.h, impulse_options).
void read_contact(const Section& s, Settings& st) {
    st.law = &contact_law(s.string("model"));
    const bool impulse = st.law->impulse_options;
    st.iterated = s.string("contact_solve") == "iterated";
    if (st.iterated && !impulse)
        s.fail("contact_solve", fmt::format("'iterated' solves the impulse model's contacts; model = '{}' has none (its "
                                            "forces come from springs): use contact_solve = 'single_pass' or model = "
                                            "'impulse'",
                                            st.law->name));
    if (st.impact_time && (!impulse || st.iterated))
        s.fail("impact_time", "true is an option of the impulse model's single pass: it needs model = 'impulse' and "
                              "contact_solve = 'single_pass' (allowed: false with any model, true with those two)");
    if (st.speculative && (!impulse || st.impact_time))
        s.fail("speculative", "true is an option of the impulse model (single pass or iterated): it needs model = "
                              "'impulse' and impact_time = false (allowed: false with any model, true with those "
                              "two)");
    st.boundary_start = s.string("boundary_pairs") == "pass_start";
    if (st.boundary_start && (!impulse || st.iterated || !(st.separate || st.impact_time)))
        s.fail("boundary_pairs", "'pass_start' is an option of the impulse model's single pass where grains move in "
                                 "the pass: it needs model = 'impulse', contact_solve = 'single_pass' (the iterated "
                                 "solve conserves momentum already) and separate_overlaps or impact_time = true "
                                 "(else nothing moves and the geometries agree) (allowed: 'sequential' always, "
                                 "'pass_start' with those)");
}

// The time step by the law's rule (contact_laws.h): derived from the case, or given and checked.
double law_time_step(const Case& c, const OperatingPoint& p, const Section& s, const ContactLaw& law) {
    const double given = s.real("time_step");
    switch (law.step) {
    case StepRule::Travel: {
        // a grain at the reference speed travels step_fraction of the smallest grain's diameter per step
        const double v_ref = impulse_reference_speed(c, p);
        const double d_min = c.grains.sizes().min();
        const double dt = given > 0 ? given : s.real("step_fraction") * d_min / v_ref;
        const double frac = dt * v_ref / d_min;
        if (frac > kMaxStepFraction)
            s.fail(given > 0 ? "time_step" : "step_fraction",
                   fmt::format("a grain at {:g} m/s moves {:.3g} diameters of the smallest grain ({:g} m) per step of "
                               "{:g} s; the impulse model finds contacts only by overlap, so at most {:g} diameters "
                               "per step are allowed",
                               v_ref, frac, d_min, dt, kMaxStepFraction));
        return dt;
    }
    case StepRule::Rayleigh: {
        const double tr = c.grains.rayleigh_time();
        const double dt = given > 0 ? given : s.real("hertz_step_fraction") * tr;
        if (dt > kHertzMaxStepFraction * tr)
            s.fail(given > 0 ? "time_step" : "hertz_step_fraction",
                   fmt::format("time step {:g} s is {:.2f} Rayleigh times ({:g} s) of the Hertz contacts; at most {:g} "
                               "is stable",
                               dt, dt / tr, tr, kHertzMaxStepFraction));
        return dt;
    }
    case StepRule::ContactTime: break;  // no [dem] law has a contact time
    }
    throw Error(fmt::format("internal: [dem] has no time-step rule for the contact law '{}'", law.name));
}

// time, steps, sample_every, the servo, snapshots: the run's length and its sampling.
void resolve_run_length(const Case& c, const OperatingPoint& p, const RunOptions& o, const Section& s, Settings& st) {
    const std::string time_key = dem_keys().key_name("time", {o.full, o.vtk});
    const double time = st.time;  // time, or time_full with --full (bound, section.cpp)
    if (const double strain = s.real("strain"); strain > 0 && p.speed > 0)  // [dem] strain: a run length in U t / H
        st.time = std::max(st.time, std::min(strain * c.cell.gap / p.speed, s.real("strain_time_max")));
    st.until_steady = until_steady_cap(s, o.full, time);
    const double steps = std::ceil(st.time / st.time_step - 1e-9);
    if (!(steps <= kMaxSteps))
        s.fail(time_key, fmt::format("{:g} s is {:.3g} steps of {:g} s; at most {:g} steps are allowed", st.time,
                                     steps, st.time_step, kMaxSteps));
    st.steps = static_cast<std::int64_t>(steps);
    static_cast<ServoSettings&>(st) = resolve_servo(c, p, s, st.sample_every, st.time_step, st.steps);
    st.plate_gain = st.servo_gain;
    if (st.load && st.law->stiffness == Stiffness::Hertz) {
        st.plate_overlap = hertz_plate_overlap(c.grains, st.target_stress);
        st.plate_gain = capped_plate_gain(st.servo_gain, st.plate_overlap, c.grains.diameter);
    }
    if (st.steps < 20 * st.sample_every)
        s.fail(time_key,
               fmt::format("{:g} s is {} steps of {:g} s: fewer than 20 wall-stress samples of {} steps "
                           "(sample_every); run longer",
                           st.time, st.steps, st.time_step, st.sample_every));
    st.snapshot_every = std::max<std::int64_t>(1, st.steps / st.snapshots);
}

// [cell] geometry = "annulus": the ring, its walls' meshes and the contact search's box.
void resolve_ring(const Case& c, const Section& s, Settings& st) {
    st.annulus = annulus(c);
    st.ring_mesh = s.string("ring_walls") == "mesh";
    if (st.ring_mesh && st.load && st.weight_plate)  // move/mesh moves a mesh at a given speed, not by its load
        s.fail("servo_plate", "'weight' needs ring_walls = 'primitive' (the meshes' top moves only at a given "
                              "speed); allowed with ring_walls = 'mesh': 'window'");
    if (st.ring_mesh) {  // the meshes' facets, and how far inside the outer circle their chords lie
        const double chord = s.real("ring_facet") * c.grains.diameter, ro = st.annulus.outer();
        st.ring_facet_count =
            static_cast<std::size_t>(std::max(64.0, std::ceil(2.0 * std::numbers::pi * ro / chord)));
        st.wall_sag = ro * (1.0 - std::cos(std::numbers::pi / static_cast<double>(st.ring_facet_count)));
    }
    st.contact_box = ring_contact_box(st.annulus, st.box_top(), c.grains.diameter);
}

// [dem] dense_inertial_number: a dense point runs at half the case's step, and so does its check
// (the plugin README's step rule for dense loaded flows, made a rule of the case). The nominal
// inertial number is the GDR MiDi (2004) I at the shear rate U/H of the case's gap; it is known
// before the run, which the measured density (Z, I mid-gap) is not. The threshold is the case's
// choice: measured on sawyer2001's slice (single pass, step_fraction 0.02, 3-4 seeds), the full step
// is +8.3 % from its limit in tau_bot at I = 0.19, +3.7 % at 0.27 and +1.8 % at 0.38.
// [dem] quarter_step_inertial_number: below it, a quarter of the case's step (the check at an
// eighth). Measured on sawyer2001_regimes at 0.4 m/s (cold, 1 s, two or three seeds): at 2250 Pa (I
// 0.084) half to a quarter of the step moves tau by 8 %, a quarter to an eighth by 2-4 %; at 5550 Pa
// (I 0.053) a quarter to an eighth still by 10 %. At a fixed step the error grows about as 1/I^2
// (docs/measurements/liggghts.md, "The slowest loaded points"). Also the case's choice.
void apply_dense_step(const Case& c, const OperatingPoint& p, const Section& s, Settings& st) {
    const char* key = "dense_inertial_number";
    if (st.law->step != StepRule::Travel)
        s.fail(key, fmt::format("halves the impulse model's step (step_fraction); model = '{}' sets its own step "
                                "(allowed: 0 with model = '{}', > 0 with model = 'impulse')",
                                st.law->name, st.law->name));
    if (s.real("time_step") > 0)
        s.fail(key, fmt::format("halves the step derived from step_fraction, but time_step = {:g} s is given and "
                                "used as it is (allowed: dense_inertial_number = 0 with time_step > 0, or time_step "
                                "= 0)",
                                s.real("time_step")));
    if (p.control != Control::Load)
        s.fail(key, fmt::format("needs the point's pressure, and point {} holds a fill, not a load (allowed: 0 "
                                "unless every point has control = \"load\")",
                                p.id));
    const auto I = inertial_number(p.speed / c.cell.gap, c.grains.diameter, p.normal_stress, c.grains.density);
    if (!I) throw Error(fmt::format("internal: point {} has no nominal inertial number", p.id));
    st.inertial_nominal = *I;
    const int halvings = st.dense_halvings();
    const bool refine = st.refine_dt;
    for (int k = 0; k < halvings; ++k) st = half_step(st);  // the same windows, blocks and snapshots in seconds
    st.refine_dt = refine;
    if (!(static_cast<double>(st.steps) <= kMaxSteps))
        s.fail(st.dense_key(),
               fmt::format("point {} is dense (nominal inertial number {:.3g} < {:g}): at {} its run is {} steps; "
                           "at most {:g} are allowed (shorten time, or raise step_fraction)",
                           p.id, *I, st.dense_threshold(), dense_step_name(halvings), st.steps, kMaxSteps));
}

// [dem] refine_strain: the warm half-step run's length as a shear strain, as `strain` is the run's, so
// that a sweep over U checks each point over as many strains (a fixed refine_time is a few strains at
// a slow point and many at a fast one).
void resolve_refine_strain(const Case& c, const OperatingPoint& p, const Section& s, Settings& st) {
    const double strain = s.real("refine_strain");
    if (strain <= 0) return;
    if (!st.refine_dt)
        s.fail("refine_strain", fmt::format("{:g} sets the length of the time-step check's half-step run, and "
                                            "refine_dt is false (allowed: 0 without refine_dt, >= 0 with it)",
                                            strain));
    if (!(p.speed > 0))
        s.fail("refine_strain", fmt::format("{:g} strains need a moving wall, and point {} has U = {:g} m/s "
                                            "(allowed: 0, or > 0 when every point's speed is > 0)",
                                            strain, p.id, p.speed));
    st.refine_strain = strain;
    st.refine_time = std::max(st.refine_time, std::min(strain * c.cell.gap / p.speed, s.real("strain_time_max")));
}

}  // namespace

Settings resolve_settings(const Case& c, const OperatingPoint& p, const RunOptions& o) {
    const Section& s = c.section(kSolver.name);
    Settings st;
    dem_keys().read(st, s, {o.full, o.vtk});  // the plain keys (section.cpp); time_full with --full
    read_contact(s, st);
    const ParticleStart start = particle_start(c, p, o.seed);
    st.ring = c.cell.ring();
    st.box = st.ring ? ring_slice_box(c) : particle_box(c, start.periodic_depth);
    st.contact_box = st.box;
    st.np = std::max(1, o.np);
    st.vtk = o.vtk;
    st.seed = start.insertion.seed;
    st.velocity_noise = start.insertion.velocity_noise;
    if (c.cell.annulus_radius > 0 && c.cell.annulus_radius <= 0.5 * st.box.width)
        s.fail("annulus_radius", fmt::format("the annulus radius {:g} m must exceed half the cell width {:g} m "
                                             "(the centripetal term divides by the local radius R - z)",
                                             c.cell.annulus_radius, 0.5 * st.box.width));
    st.time_step = law_time_step(c, p, s, *st.law);
    resolve_run_length(c, p, o, s, st);
    st.skin_m = s.real("neighbor_skin") * c.grains.diameter;
    resolve_refine_strain(c, p, s, st);
    if (st.refine_dt) try {  // a refine_time too short fails now, not after the full-step run
            (void)refine_settings(st);
        } catch (const CaseError& e) {
            s.fail(st.refine_strain > 0 ? "refine_strain" : "refine_time", e.what());
        }
    if (st.refine_halvings > 1 && !st.refine_dt)
        s.fail("refine_halvings", fmt::format("{} halvings need the time-step check: set refine_dt = true, or "
                                              "refine_halvings = 1 (allowed: 1 without the check, 1 or 2 with it)",
                                              st.refine_halvings));
    if (st.refine_halvings > 1 && st.refine_time > 0)
        s.fail("refine_halvings", fmt::format("{} halvings repeat a cold check only: a warm-started half-step run "
                                              "(refine_time = {:g} s) keeps the coarser step's packing, so a second "
                                              "halving would check that memory, not the step (allowed: 1 with "
                                              "refine_time > 0, 2 with refine_time = 0)",
                                              st.refine_halvings, st.refine_time));
    if (st.ring) resolve_ring(c, s, st);
    st.bumps_bottom = wall_bumps(c, p, p.bottom, "bottom", st.box);
    st.bumps_top = wall_bumps(c, p, p.top, "top", st.box);
    st.bumps_side = side_bumps(c, p, st.box, st.box_top());
    // rough walls with the iterated solve: the bumps are moved by fix move or by no fix, and fix
    // impulse/solve treats such atoms as kinematic (infinite mass), as the walls they are
    // a shear strain of kPersistenceStrain at U/H, at most a hundredth of the run
    st.persistence_every = persistence_every_steps(p.speed / c.cell.gap, st.time_step, st.steps);
    if (st.quarter_step_inertial_number > 0 && !(st.quarter_step_inertial_number < st.dense_inertial_number))
        s.fail("quarter_step_inertial_number",
               st.dense_inertial_number > 0
                   ? fmt::format("{:g} must lie below dense_inertial_number = {:g}: the step is quartered at "
                                 "inertial numbers below those where it is halved (allowed: 0 = off, or 0 < value "
                                 "< dense_inertial_number)",
                                 st.quarter_step_inertial_number, st.dense_inertial_number)
                   : fmt::format("{:g} quarters the step below the threshold where dense_inertial_number halves it, "
                                 "and dense_inertial_number is off (allowed: 0 = off, or 0 < value < "
                                 "dense_inertial_number with dense_inertial_number > 0)",
                                 st.quarter_step_inertial_number));
    // The quarter tier's points are the slowest sheared ones, where a warm check measures the change of
    // step's own transient (about 20 strains at 0.4 m/s on sawyer2001_regimes: it failed a point cold runs
    // pass and passed one they fail; docs/measurements/liggghts.md, "The slowest loaded points"), as
    // refine_halvings = 2 refuses a warm check for the packing's memory.
    if (st.quarter_step_inertial_number > 0 && st.refine_dt && st.refine_time > 0)
        s.fail("quarter_step_inertial_number",
               fmt::format("{:g} runs the slowest points at a quarter of the step, and there a warm-started check "
                           "(refine_time = {:g} s) measures the step change's own transient, not the step "
                           "(allowed: quarter_step_inertial_number > 0 with refine_time = 0, a cold check, or "
                           "without refine_dt; quarter_step_inertial_number = 0 with a warm check)",
                           st.quarter_step_inertial_number, st.refine_time));
    if (st.dense_inertial_number > 0) apply_dense_step(c, p, s, st);
    return st;
}

Settings refine_settings(const Settings& s) {
    Settings h = half_step(s);
    if (s.refine_time <= 0) return h;
    h.time = s.refine_time;
    const std::int64_t window = h.load ? h.servo_every : h.sample_every;
    h.steps = static_cast<std::int64_t>(std::ceil(h.time / h.time_step - 1e-9));
    h.steps = (h.steps + window - 1) / window * window;
    const auto fail = [&](const std::string& why) {
        throw CaseError(fmt::format("{} steps of {:g} s {}; run the half-step check longer", h.steps, h.time_step,
                                    why));
    };
    if (h.steps < 20 * h.sample_every) fail(fmt::format("give fewer than 20 wall-stress samples of {} steps", h.sample_every));
    if (h.load && h.steps < kMinServoUpdates * h.servo_every)
        fail(fmt::format("give fewer than {} plate updates of {} steps", kMinServoUpdates, h.servo_every));
    h.snapshot_every = std::max<std::int64_t>(1, h.steps / s.snapshots);
    return h;
}

Settings half_step(const Settings& s) {
    Settings h = s;
    h.time_step = 0.5 * s.time_step;
    for (std::int64_t* n : {&h.steps, &h.sample_every, &h.snapshot_every, &h.servo_every, &h.persistence_every})
        *n *= 2;
    h.refine_dt = false;
    return h;
}

nlohmann::json Settings::to_json() const {
    nlohmann::json j = ServoSettings::to_json();
    j.update(nlohmann::json{{"model", law->name},
                            {"beta0", beta0},
                            {"separate_overlaps", separate},
                            {"bounce_speed", bounce_speed},
                            {"contact_solve", iterated ? "iterated" : "single_pass"},
                            {"time_step_s", time_step},
                            {"time_s", time},
                            {"time_max_s", until_steady.time_max},
                            {"steps", steps},
                            {"sample_every", sample_every},
                            {"snapshot_every", snapshot_every},
                            {"stations", stations},
                            {"blocks", blocks},
                            {"skin_m", skin_m},
                            {"seed", seed},
                            {"velocity_noise", velocity_noise},
                            {"ranks", np},
                            {"box_m", {box.length, box.gap, box.width}},
                            {"periodic_z", box.periodic_z},
                            {"refine_dt", refine_dt},
                            {"refine_time_s", refine_time},
                            {"geometry", ring ? "annulus" : "slice"},
                            {"persistence_every", persistence_every},
                            {"persistence_intervals", persistence_intervals}});
    if (refine_strain > 0) j.update(nlohmann::json{{"refine_strain", refine_strain}});  // absent: off, as earlier
    if (refine_halvings != 1)  // absent: 1, as every earlier result
        j.update(nlohmann::json{{"refine_halvings", refine_halvings}});
    if (dense_inertial_number > 0)  // absent: off, as every earlier result
        j.update(nlohmann::json{{"dense_inertial_number", dense_inertial_number},
                                {"inertial_number_nominal", inertial_nominal},
                                {"dense_step_halved", dense_halved()}});
    if (quarter_step_inertial_number > 0)  // absent: off, as every earlier result
        j.update(nlohmann::json{{"quarter_step_inertial_number", quarter_step_inertial_number},
                                {"dense_step_halvings", dense_halvings()}});
    if (impact_time) j.update(nlohmann::json{{"impact_time", true}});  // absent: off, as every earlier result
    if (speculative) j.update(nlohmann::json{{"speculative", true}});  // absent: off, as every earlier result
    if (boundary_start) j.update(nlohmann::json{{"boundary_pairs", "pass_start"}});  // absent: sequential, as earlier
    if (iterated)
        j.update(nlohmann::json{{"solve_tolerance", solve_tolerance}, {"solve_iterations", solve_iterations}});
    if (load) j.update(nlohmann::json{{"servo_gain_used", plate_gain}, {"plate_overlap_m", plate_overlap}});
    if (ring)
        j.update(ring_mesh ? nlohmann::json{{"annulus_radius_m", annulus.R},
                                            {"ring_walls", "mesh"},
                                            {"ring_facets_per_circle", ring_facet_count},
                                            {"ring_wall_sag_m", wall_sag}}
                           : nlohmann::json{{"annulus_radius_m", annulus.R}, {"ring_walls", "primitive"}});
    return j;
}

}  // namespace granlub::dem
