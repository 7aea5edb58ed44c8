// Load control (control = "load") of the particle engines, `granlub dem` and `granlub yade`: the
// top wall is a plate moved every `every` steps by gain d clamp((P_top - P)/P, -1, max_error),
// P_top the top-wall normal stress averaged over those steps, and kept in [gap_min, gap_max]. An
// integral controller: at steady state the plate's mean drift is zero, so the window-averaged
// P_top equals P while the clamps are inactive. Its keys (fill_for_load, servo_every, servo_gain,
// servo_max_gap) are declared here once and added to each engine's own section.
#pragma once
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/case/case.h"
#include "granlub/case/schema.h"

namespace granlub {

// Upper clamp of the relative stress error in a servo update: spikes of an impulsive top-wall
// force raise the plate by at most this many gains (a stress below target lowers it by at most 1).
inline constexpr double kServoMaxError = 3.0;

// Solid fraction of the closest packing of equal spheres (FCC): the plate's lowest position.
inline constexpr double kClosestPacking = 0.7405;

// Fewest plate updates of a load-controlled run.
inline constexpr std::int64_t kMinServoUpdates = 20;

struct ServoSettings {
    bool load = false;                // control = "load"; all below but insert_fill* unused otherwise
    // servo_plate = "weight": the top is a rigid plate of plate_mass x the grains' mass, free along
    // the gap and pressed by P A (the experiment's weighted upper disc): its own Newton's law, no
    // window, no gain. "window": the plate moved every servo_every steps by the rule below.
    bool weight_plate = false;
    double plate_mass = 0;            // multiples of the grains' mass (weight_plate)
    double target_stress = 0;         // Pa, the point's normal_stress
    std::int64_t servo_every = 0;     // steps between plate updates (a multiple of sample_every)
    double servo_gain = 0;            // plate move per update, diameters per unit relative error
    double servo_max_error = 0;       // relative stress error is clamped to [-1, servo_max_error]
    double gap_min = 0;               // plate limits, m: closest packing of the grains ...
    double gap_max = 0;               // ... and the box top (servo_max_gap x H)
    // where the top wall starts and below which the grains are inserted: H, or under load gap_max
    // for grains that need more room than H (the whole ring, whose insertion lattice holds fewer
    // grains per volume, annulus.h; grains of several sizes, on a lattice spaced for the largest;
    // rough walls, whose bumps take room, wall_bumps.h)
    double plate_start = 0;
    double insert_fill = 0;           // solid fraction inserted (point's, or fill_for_load)
    std::string insert_fill_key;      // which key it came from, for messages

    nlohmann::json to_json() const;   // control, target, servo_*, gap limits (summary provenance)
};

// The window servo's cap for soft contacts, shared by both engines. The plate is moved once per
// window; a move into loaded contacts compresses each of them by the move, and moves of servo_gain
// d (0.05 d, ~100 contact overlaps at the load) hammered the bed (plugins/liggghts/README.md and
// plugins/yade/README.md, "Load control"). So the gain is capped at plate_overlap / d: a unit error
// moves the plate by one grain-plate overlap at the load. The load's share of one grain is P d^2
// [ASSUMPTION] ours, an estimate of the plate's contact force.
//   Hertz (Hertz 1882; Johnson 1985, Contact Mechanics, eq. 4.23): F = 4/3 E* sqrt(R) delta^(3/2),
//   1/E* = 2 (1 - nu^2)/E (a wall of the grains' material), R = d/2 (LIGGGHTS' wall: infinite radius).
double hertz_plate_overlap(const Grains& g, double load);
//   Linear spring k_n (N/m; YADE's ViscElMat, Pournin et al. 2001: k_n = m* (pi^2 + ln^2 e)/t_c^2):
//   delta = P d^2 / k_n.
double linear_plate_overlap(const Grains& g, double load, double kn);
// The gain the window servo uses: min(servo_gain, overlap / d).
double capped_plate_gain(double servo_gain, double overlap, double diameter);
// The time a grain-plate contact takes to respond to a move, pi sqrt(m / k) with k = dF/d(delta)
// at the load (half a period of the grain on the loaded contact): Hertz k = 3/2 F / delta,
// linear k = k_n. A servo window shorter than this moves the plate again before the contacts have
// answered the last move: the moves pile up (the window servo "rams").
double plate_response_time(const Grains& g, double load, double overlap, bool hertz);

// Adds fill_for_load, servo_plate, plate_mass, servo_every, servo_gain and servo_max_gap to an
// engine's section.
void add_servo_keys(SectionSpec& s);

// The servo of point p from the servo keys of section `s` (the engine's own, which add_servo_keys
// declared). Under load, `steps` is rounded up to whole servo windows and checked to give at least
// kMinServoUpdates updates; servo_every = 0 means sample_every. Throws CaseError naming the key.
ServoSettings resolve_servo(const Case& c, const OperatingPoint& p, const Section& s, std::int64_t sample_every,
                            double time_step, std::int64_t& steps);

}  // namespace granlub
