#include "granlub/yade/settings.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/yade/command.h"
#include "granlub/particles/contact_laws.h"
#include "granlub/particles/particle_section.h"

namespace granlub::yade {

namespace {
// The window servo capped from the contact stiffness, as granlub dem's (servo.h), and refused where
// it would ram: a window shorter than the contacts' response moves the plate again before they
// have answered the last move. A weight plate has no window: nothing to cap.
void resolve_window_servo(const Case& c, const OperatingPoint& p, const Section& s, Settings& r) {
    const Grains& g = c.grains;
    const double P = r.servo.target_stress;
    const bool hertz = r.law->stiffness == Stiffness::Hertz;
    if (hertz) {
        r.plate_overlap = hertz_plate_overlap(g, P);
    } else {  // Stiffness::Linear: ViscElMat at a wall of mass wall_mass (Pournin et al. 2001): k_n = m* (pi^2 + ln^2 e)/t_c^2
        const double m = g.mass(), m_star = m * r.wall_mass / (m + r.wall_mass);
        const double ln_e = std::log(p.top.restitution);
        const double kn = m_star * (std::numbers::pi * std::numbers::pi + ln_e * ln_e) /
                          (r.contact_time * r.contact_time);
        r.plate_overlap = linear_plate_overlap(g, P, kn);
    }
    r.plate_gain = capped_plate_gain(r.servo.servo_gain, r.plate_overlap, g.diameter);
    if (r.servo.weight_plate) return;
    const double response = plate_response_time(g, P, r.plate_overlap, hertz);
    const double window = static_cast<double>(r.servo.servo_every) * r.time_step;
    if (window < response)
        s.fail("servo_every",
               fmt::format("{} steps of {:g} s ({:g} s) with servo_plate = \"window\": shorter than the grain-plate "
                           "contacts' response at the load ({:g} s), so the plate would move again before they "
                           "answered its last move and ram the bed (allowed: servo_every >= {}, or "
                           "servo_plate = \"weight\")",
                           r.servo.servo_every, r.time_step, window, response,
                           static_cast<std::int64_t>(std::ceil(response / r.time_step / static_cast<double>(r.sample_every))) *
                               r.sample_every));
}

// [yade] time_step, or the law's rule (contact_laws.h) with dt = 0; checked against the rule's limit.
double law_time_step(const Case& c, const Section& s, const ContactLaw& law, double contact_time) {
    const double given = s.real("time_step");
    switch (law.step) {
    case StepRule::ContactTime: {
        const double dt = given == 0 ? contact_time / 20.0 : given;
        if (dt > contact_time / 10.0)
            s.fail("time_step", fmt::format("too large for contact_time = {:g} s: a contact needs at least 10 steps "
                                     "(allowed: time_step <= {:g} s, or 0 for contact_time/20)",
                                     contact_time, contact_time / 10.0));
        return dt;
    }
    case StepRule::Rayleigh: {
        const double tr = c.grains.rayleigh_time();
        const double dt = given == 0 ? kHertzStepFraction * tr : given;
        if (dt > kHertzMaxStepFraction * tr)
            s.fail("time_step", fmt::format("too large for Hertz contacts of these grains (Rayleigh time {:g} s) "
                                     "(allowed: time_step <= {:g} s, or 0 for {} Rayleigh times)",
                                     tr, kHertzMaxStepFraction * tr, kHertzStepFraction));
        return dt;
    }
    case StepRule::Travel: break;  // no [yade] law is rigid
    }
    throw Error(fmt::format("internal: [yade] has no time-step rule for the contact law '{}'", law.name));
}
}  // namespace

Settings resolve_settings(const Case& c, const OperatingPoint& p, const RunOptions& o) {
    if (c.cell.ring())
        throw NoAnswer(fmt::format("point {}: granlub yade runs the slice only; [cell] geometry = \"annulus\" (the "
                                   "whole ring) is granlub dem's",
                                   p.id));
    const Section& s = c.section(kSolver.name);
    Settings r;
    yade_keys().read(r, s, {o.full, o.vtk});  // the plain keys (src/section.cpp); time_full with --full
    r.law = &contact_law(s.string("model"));
    r.warm_start = s.string("start") == "warm";
    
    // The initial grains of `granlub dem` too: [particles] is one section for both engines.
    const ParticleStart start = particle_start(c, p, o.seed);
    r.insertion = start.insertion;
    r.periodic_depth = start.periodic_depth;

    r.time_step = law_time_step(c, s, *r.law, r.contact_time);

    const std::string time_key = yade_keys().key_name("time", {o.full, o.vtk});
    const double time = r.time;
    r.until_steady = until_steady_cap(s, o.full, time);
    const double steps = time / r.time_step;
    if (!(steps <= kMaxSteps))
        s.fail(time_key, fmt::format("{:g} s is {:.3g} steps of {:g} s; at most {:g} steps are allowed", time, steps,
                                     r.time_step, kMaxSteps));
    const auto rows = static_cast<std::int64_t>(std::llround(time / (r.time_step * static_cast<double>(r.sample_every))));
    if (rows < 2 * r.blocks)
        s.fail(time_key, fmt::format("gives {} wall-force block(s) of sample_every = {} steps of {:g} s; the "
                                     "standard errors need at least 2 x blocks = {} (allowed: {} >= {:g} s)",
                                     rows, r.sample_every, r.time_step, 2 * r.blocks, time_key,
                                     static_cast<double>(2 * r.blocks * r.sample_every) * r.time_step));
    r.steps = rows * r.sample_every;
    r.servo = resolve_servo(c, p, s, r.sample_every, r.time_step, r.steps);
    const ParticleBox box = particle_box(c, r.periodic_depth);
    r.bumps_bottom = wall_bumps(c, p, p.bottom, "bottom", box);
    r.bumps_top = wall_bumps(c, p, p.top, "top", box);
    r.bumps_side = side_bumps(c, p, box, r.servo.load ? r.servo.gap_max : box.gap);  // up to the highest plate
    if (r.servo.load) resolve_window_servo(c, p, s, r);

    r.persistence_every = persistence_every_steps(p.speed / c.cell.gap, r.time_step, r.steps);

    // snapshots at whole wall-force blocks (under load: whole servo windows)
    const std::int64_t unit = r.servo.load ? r.servo.servo_every : r.sample_every;
    const std::int64_t snapshots = s.integer("snapshots");
    r.snapshot_every = unit * std::max<std::int64_t>(1, r.steps / unit / snapshots);
    if (r.servo.load)  // rounded up: at least the plate updates resolve_servo() checked
        r.steps = (r.steps + r.snapshot_every - 1) / r.snapshot_every * r.snapshot_every;
    else
        r.steps -= r.steps % r.snapshot_every;  // whole snapshot intervals (drops < snapshots rows)
    return r;
}

}  // namespace granlub::yade
