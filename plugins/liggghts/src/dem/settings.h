// The resolved settings of one DEM run: [dem] keys, the point and the run options, with the
// time step derived from the case and checked.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/particles/annulus.h"
#include "granlub/particles/contact_laws.h"
#include "granlub/case/bound_keys.h"
#include "granlub/case/case.h"
#include "granlub/particles/particles.h"
#include "granlub/particles/servo.h"
#include "granlub/particles/until_steady.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/run/sweep.h"
#include "granlub/statistics/flow_regime.h"

namespace granlub::dem {

// The servo part (control = "load": the top wall is a plate moved by the deck every servo_every
// steps, see deck.h and README "Load control") is shared with granlub yade (granlub/particles/servo.h).
struct Settings : ServoSettings {
    const ContactLaw* law = nullptr;  // [dem] model, a row of contact_laws.h (set by resolve_settings)
    double beta0 = 0;             // Walton's tangential restitution (impulse); 0 = stick limit
    bool separate = false;        // impulse: remove overlaps (position correction)
    double bounce_speed = 0;      // impulse: restitution only above this approach speed (m/s)
    bool iterated = false;        // impulse: contacts solved to convergence (fix impulse/solve), not one pass
    bool impact_time = false;     // impulse, single pass: each impact applied at its time within the step
    bool speculative = false;     // impulse, single pass: contacts activated on their predicted gap
    bool boundary_start = false;  // impulse, single pass: boundary pairs from the pass's start positions
    double solve_tolerance = 0;   // iterated: largest impulse change / largest normal impulse, to stop
    std::int64_t solve_iterations = 0;  // iterated: cap on the sweeps per step
    double time_step = 0;         // s
    double time = 0;              // simulated time, s
    std::int64_t steps = 0;       // ceil(time / time_step)
    UntilSteadyCap until_steady;  // time_max: continued until steady up to this in all; 0 = off
    std::int64_t sample_every = 0;    // wall-force block length, steps (forces summed every step)
    std::int64_t snapshot_every = 0;  // particle snapshots for coarse-graining, steps
    std::size_t stations = 0;     // coarse-graining slabs across the gap
    std::size_t blocks = 0;       // blocks for standard errors
    double skin_m = 0;            // neighbour skin, m ([dem] neighbor_skin is in grain diameters)
    std::uint64_t seed = 0;       // [particles] seed (--seed overrides); every key-set field is set by resolve_settings
    double velocity_noise = 0;
    bool vtk = false;
    bool refine_dt = false;       // the point's answer at time_step / 2, checked against time_step (run.dt_refinement)
    double refine_time = 0;       // s, the half-step run warm-started from the full-step run's end; 0: cold, `time`
    double refine_strain = 0;     // [dem] refine_strain: refine_time resolved from it (settings.cpp); 0 = off
    std::int64_t refine_halvings = 1;  // refine_dt: 2 = a failed check at dt/2 is repeated at dt/4 (cold)
    // [dem] dense_inertial_number: a point whose nominal inertial number is below it runs at half the
    // step the case derives (apply_dense_step); 0 = off. [dem] quarter_step_inertial_number (below
    // dense_inertial_number): below it, a quarter of that step; 0 = off
    double dense_inertial_number = 0;
    double quarter_step_inertial_number = 0;
    double inertial_nominal = 0;  // U d / (H sqrt(P / rho)) of the point, when that rule is on
    // how often the rule halved this point's step (0, 1 or 2): the case's step is 2^n time_step
    int dense_halvings() const {
        if (!(dense_inertial_number > 0 && inertial_nominal < dense_inertial_number)) return 0;
        return quarter_step_inertial_number > 0 && inertial_nominal < quarter_step_inertial_number ? 2 : 1;
    }
    bool dense_halved() const { return dense_halvings() > 0; }
    // the threshold of the tier the point is in, and its key (dense_halved() points only)
    double dense_threshold() const {
        return dense_halvings() == 2 ? quarter_step_inertial_number : dense_inertial_number;
    }
    const char* dense_key() const {
        return dense_halvings() == 2 ? "quarter_step_inertial_number" : "dense_inertial_number";
    }
    std::int64_t snapshots = 0;   // particle snapshots per run ([dem] snapshots)
    // contact persistence: after the run, persistence_intervals + 1 snapshots persistence_every
    // steps apart (a shear strain U/H t of kPersistenceStrain each; flow_regime.h)
    std::int64_t persistence_every = 1;
    std::int64_t persistence_intervals = kPersistenceIntervals;
    // steps of the persistence run after the main run: up to the next multiple of
    // persistence_every (the first snapshot), then the intervals
    std::int64_t persistence_run_steps() const {
        return (persistence_every - steps % persistence_every) % persistence_every +
               persistence_intervals * persistence_every;
    }
    int np = 1;
    ParticleBox box;              // the cell (box.gap = the case's gap H)
    // Load control with soft (Hertz) contacts: the deck moves the plate in jumps, one per servo
    // window, and a jump into loaded contacts compresses each of them by the jump at once: jumps
    // of servo_gain d (0.05 d, ~100 Hertz overlaps at 1 GPa) hammered the bed, dilated it and
    // injected momentum the walls did not record (plugin README, "Load control with Hertz
    // contacts"). So the gain is at most plate_overlap / d: a unit error moves the plate by one
    // contact overlap at the target load. Impulse contacts have no overlap scale: no cap.
    // [cell] geometry = "annulus": the whole ring (ring_deck.h). box is then its slice-frame box
    // (granlub/particles/annulus.h): 2 pi R x H x W, the frame the results are written in.
    bool ring = false;
    Annulus annulus;
    bool ring_mesh = false;       // the ring's walls as STL meshes (else primitives, ring_deck.h)
    std::size_t ring_facet_count = 0;  // facets per circle of the ring's meshes (ring_mesh only; [dem] ring_facet is their length)
    double wall_sag = 0;          // m: how far the outer wall's facets lie inside its circle at most
    ParticleBox contact_box;      // what core's contact search (contacts.h) is given for the grains
    double plate_overlap = 0;     // m, Hertz grain-plate overlap under the load's share of one grain
    double plate_gain = 0;        // the servo gain the deck uses, diameters per unit relative error

    double box_top() const { return load ? gap_max : box.gap; }
    // rough walls ([walls] surface = "bumps", core wall_bumps.h): atoms of the wall's type that the
    // deck does not integrate; the floor's and the side walls' move with the floor, the top's with
    // the plate. bumps_side: the layer of each side wall ([walls] sides = "as_bottom")
    std::optional<BumpLayer> bumps_bottom, bumps_top, bumps_side;
    bool bumps() const { return bumps_bottom || bumps_top || bumps_side; }
    // the group of the integrated grains: "all" without bumps (the deck as it always was)
    std::string grains_group() const { return bumps() ? "grains" : "all"; }

    nlohmann::json to_json() const;
};

// Reads [dem], derives and checks the time step (throws CaseError naming the key).
Settings resolve_settings(const Case& c, const OperatingPoint& p, const RunOptions& o);

// The [dem] section with each plain key's field (section.cpp); section() is its spec. A plain key
// is its field here and its line there.
const BoundKeys<Settings>& dem_keys();

// The same run at half the time step: the same simulated time, blocks, snapshots, servo windows
// and persistence interval in seconds, twice the steps.
Settings half_step(const Settings& s);

// The step the dense rule gives a point, in words: "half the case's step" (1 halving) or "a quarter of
// the case's step" (2)
inline const char* dense_step_name(int halvings) {
    return halvings >= 2 ? "a quarter of the case's step" : "half the case's step";
}

// The half-step run of refine_dt: half_step(s), and with refine_time > 0 that simulated time (whole
// servo windows, the same number of snapshots). Throws CaseError (why, without the key: resolve_settings()
// names it) when it is too short for the blocks or the servo.
Settings refine_settings(const Settings& s);

// Reference speed of the impulse model's time step: the largest of
//  - the wall speed U;
//  - sqrt(2 g H), a grain falling across the gap under gravity;
//  - under load control, sqrt(2 a d) = sqrt(12 P / (pi rho)): a grain pushed by the load's share
//    of one grain, a = P d^2 / m, over one diameter (2.87 m/s for glass at 5.5 kPa).
// The last term is our choice (Sawyer & Tichy 2001 set dt from the flow speed only): under a
// sustained load the enduring contacts, not the shear, set the step. Measured on sawyer2001 at
// 5.5 kPa: nu and the wall stresses converge at first order in dt, and a step of 0.02 d at
// about 2.8 m/s is needed at every U for |d nu| <= 0.005 between dt and dt/2 (plugin README).
double impulse_reference_speed(const Case& c, const OperatingPoint& p);


// Largest safe displacement per step for the impulse model, in diameters (contacts are found
// only by overlap; more than this risks tunnelling and deep overlaps).
inline constexpr double kMaxStepFraction = 0.05;

}  // namespace granlub::dem
