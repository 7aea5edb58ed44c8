// The servo keys and their resolution for both particle engines (servo.h).
#include "granlub/particles/servo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/case/wall_bumps.h"

namespace granlub {

void add_servo_keys(SectionSpec& s) {
    s.real("fill_for_load", 0.55, Range::open(0, 0.74), "",
           "control = load: solid fraction inserted when [operating] solid_fraction is not given");
    s.choice("servo_plate", "weight", {"window", "weight"},
             "control = load: weight = a loaded plate free along the gap (mass: plate_mass), pressed by P A, one "
             "rigid body with a rough top's bumps: its mean force on the grains is P A by Newton's law; window = "
             "the plate moved every servo_every steps by servo_gain times the window's stress error (capped at one "
             "grain-plate overlap at the load on soft contacts)");
    s.real("plate_mass", 1.0, Range::positive(), "",
           "servo_plate = \"weight\": the plate's mass as a multiple of the grains' (a numerical choice: a light "
           "plate follows the bed within a millisecond, a dead weight P A / g oscillates for tens of ms)");
    s.integer("servo_every", 0, Range::closed(0, 1e8),
              "control = load: steps between the window servo's plate updates (force averaged over them), and "
              "between the plate positions recorded (plate.txt, gap.csv); 0 = sample_every");
    s.real("servo_gain", 0.05, Range::open_closed(0, 0.1), "",
           "control = load: plate move per update in grain diameters per unit relative stress error "
           "(soft contacts, granlub dem's hertz and granlub yade: at most one grain-plate contact overlap at the "
           "load)");
    s.real("servo_max_gap", 1.5, Range::open_closed(1, 4), "",
           "control = load: highest plate position (the box top) as a multiple of [cell] gap");
}

ServoSettings resolve_servo(const Case& c, const OperatingPoint& p, const Section& s, std::int64_t sample_every,
                            double time_step, std::int64_t& steps) {
    ServoSettings v;
    v.plate_start = c.cell.gap;
    if (p.control != Control::Load) {
        v.insert_fill = p.solid_fraction;
        v.insert_fill_key = "[operating] solid_fraction";
        return v;
    }
    v.load = true;
    v.weight_plate = s.string("servo_plate") == "weight";
    v.plate_mass = s.real("plate_mass");
    v.target_stress = p.normal_stress;
    if (!(v.target_stress > 0))  // core rejects this already; a guard for hand-built points
        throw SolverError(fmt::format("point {}: control = \"load\" needs [operating] normal_stress > 0 (got {:g} Pa)",
                                      p.id, v.target_stress));
    const auto every = s.integer("servo_every");
    v.servo_every = every > 0 ? every : sample_every;
    if (v.servo_every % sample_every != 0)
        s.fail("servo_every", fmt::format("servo_every = {} must be a multiple of sample_every = {} (the plate "
                                          "history is matched to the wall-force blocks), or 0 (= sample_every)",
                                          v.servo_every, sample_every));
    v.servo_gain = s.real("servo_gain");
    v.servo_max_error = kServoMaxError;
    v.gap_max = s.real("servo_max_gap") * c.cell.gap;
    steps = (steps + v.servo_every - 1) / v.servo_every * v.servo_every;  // whole servo windows
    if (steps < kMinServoUpdates * v.servo_every)
        s.fail("servo_every", fmt::format("{} steps of {:g} s give only {} plate updates of {} steps; at least {} "
                                          "are needed (shorten servo_every or run longer)",
                                          steps, time_step, steps / v.servo_every, v.servo_every, kMinServoUpdates));
    v.insert_fill = p.solid_fraction > 0 ? p.solid_fraction : s.real("fill_for_load");
    v.insert_fill_key = p.solid_fraction > 0 ? "[operating] solid_fraction"
                                             : fmt::format("[{}] fill_for_load{}", s.name(),
                                                           s.is_default("fill_for_load") ? " (default)" : "");
    // the plate cannot go below the closest packing of the inserted grains (between the bumps' halves)
    const double bumps = bump_protrusion(c, p.bottom) + bump_protrusion(c, p.top);
    v.gap_min = v.insert_fill * c.cell.gap / kClosestPacking + bumps;
    if (c.cell.ring() || !c.grains.sizes().equal() || bumps > 0) v.plate_start = v.gap_max;
    return v;
}

double hertz_plate_overlap(const Grains& g, double load) {
    const double e_star = g.youngs_modulus / (2.0 * (1.0 - g.poisson_ratio * g.poisson_ratio));
    const double force = load * g.diameter * g.diameter;
    return std::pow(3.0 * force / (4.0 * e_star * std::sqrt(0.5 * g.diameter)), 2.0 / 3.0);
}

double linear_plate_overlap(const Grains& g, double load, double kn) { return load * g.diameter * g.diameter / kn; }

double capped_plate_gain(double servo_gain, double overlap, double diameter) {
    return std::min(servo_gain, overlap / diameter);
}

double plate_response_time(const Grains& g, double load, double overlap, bool hertz) {
    const double force = load * g.diameter * g.diameter;
    const double k = (hertz ? 1.5 : 1.0) * force / overlap;
    return std::numbers::pi * std::sqrt(g.mass() / k);
}

nlohmann::json ServoSettings::to_json() const {
    return {{"control", load ? "load" : "fill"},
            {"target_normal_stress_Pa", target_stress},
            {"servo_plate", weight_plate ? "weight" : "window"},
            {"plate_mass", plate_mass},
            {"servo_every", servo_every},
            {"servo_gain", servo_gain},
            {"servo_max_error", servo_max_error},
            {"gap_min_m", gap_min},
            {"gap_max_m", gap_max},
            {"plate_start_m", plate_start},
            {"insert_fill", insert_fill}};
}

}  // namespace granlub
