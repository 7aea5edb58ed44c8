// How the grains touching a wall move against it: the wall layer's kinematics, the record every
// particle summary carries (run.wall_layer), shared by both engines through the particle pipeline.
// What a continuum's wall condition needs: a spin-free kinetic condition (Jenkins 1992) sees the
// grains' translational slip, but a grain that rolls carries part of it back at its contact point.
//
// Frame: the engines' own (the pipeline's), x along the flow, y across the gap; the floor at y = 0
// moves at +U along x, the top wall (y = the gap, the plate's position under load) is still. The
// wall's normal into the gap n_w = +y at the floor, -y at the top.
//
// Grains counted: those touching the wall (our tolerance kWallContactTolerance [ASSUMPTION], for
// grains the engine holds slightly apart or pressed in):
//   plane: centre within (1 + tol) a of the wall's plane (a the grain's radius), contact normal n_w;
//   bumps (wall_bumps.h, a rough wall): centre within (1 + tol) (a + d_w/2) of a bump's centre (d_w
//     the bump diameter), contact normal n from the bump's centre to the grain's; a grain that fell
//     between the bumps onto the plane touches it as on a plane wall. Each grain-wall contact is one
//     sample (a grain may touch two bumps and the plane); `grains` counts the grains with one or more.
//     The bumps move with their wall: at the state's time t the floor's are at x0 + U t (mod the
//     length), x0 their layout at t = 0, t counted from the grains' cold start (particles.h
//     ParticleState::time: a run from a state starts its bumps there, wall_bumps.h moved_bumps);
//     the top's lie in the plate's plane. If the grains overlap the bumps so placed by more than
//     kBumpOverlapLimit a, the bumps are not where the engine had them and the wall is not measured.
//
// Per contact, with v, w the grain's velocity and spin, U_w the wall's speed along x, U the floor's:
//   g = v - U_w x + w x (-a n)        the relative velocity of the grain's surface at the contact
//                                     point (floor plane: g_x = v_x - U + a w_z; top: v_x - a w_z)
//   g_t = g - (g . n) n               its part in the contact's tangent plane: the sliding velocity
// and signed with s_w = +1 at the floor, -1 at the top, so that each is positive when the grains
// lag their wall in the sense the shear drives them (as the outputs slip_bottom = U - u and
// slip_top = u, particle_reduction.h):
//   slip         = s_w (U_w - v_x) / U       translational slip (floor: (U - v_x)/U; top: v_x/U)
//   rolling      = -s_w a (w x n)_x / U      the spin's part, positive when it reduces the slip
//                                            (a w_z / U on either plane)
//   contact_slip = -s_w g_t,x / U            the contact point's slip along the flow; on a plane
//                                            exactly slip - rolling
//   rolling_share = 1 - <contact_slip> / <slip>, the share of the translational slip the spin
//                  carries back: 1 rolling without sliding, 0 sliding without spin
//   rolling_fraction: the share of the contacts with |g_t| < kRollingSlip U (both tangential
//                  components), our threshold [ASSUMPTION]: those that roll
// On a bump the translational slip's part along n (the grain meeting or leaving it) is no slip:
// contact_slip = tangential_slip - rolling there, tangential_slip = s_w (-(v - U_w x)_t,x) / U the
// slip's part in the tangent plane, which the record gives beside slip.
//
// Source: the particle engines' snapshots over the steady window carry no spins (LIGGGHTS' dump
// and YADE's samples hold positions and velocities), so the record is taken from one snapshot, the
// run's final state (final_state.csv, after the run and its contact-persistence steps); means
// with standard errors over the contacts, taken as independent [ASSUMPTION: neighbours in a layer
// are correlated, so the errors are lower bounds]. Not measured: the ring (its walls turn about
// the axis; the slice only), the side walls of a trough, a run that left no final state.
#pragma once
#include <cstddef>
#include <optional>

#include <nlohmann/json.hpp>

#include "granlub/case/particle_box.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/particles/particles.h"

namespace granlub {

inline constexpr double kWallContactTolerance = 0.02;  // centre distance / (touching distance) - 1
inline constexpr double kRollingSlip = 0.02;          // |g_t| / U below which a contact rolls
inline constexpr double kBumpOverlapLimit = 0.1;      // grain-bump overlap / a: bumps misplaced beyond it

enum class WallSide { Bottom, Top };

// One wall as the grains meet it.
struct WallLayerWall {
    WallSide side = WallSide::Bottom;
    double plane = 0;                    // y of the wall's plane (through its bumps' centres), m
    double speed = 0;                    // U_w along x, m/s
    const BumpLayer* bumps = nullptr;    // a rough wall's bumps at their layout (t = 0); none: a plane
    double bump_shift = 0;               // how far the bumps moved along x since their layout, m
};

struct WallLayer {
    std::size_t grains = 0, contacts = 0, bump_contacts = 0;
    double slip = 0, slip_stderr = 0;                        // over U
    double tangential_slip = 0, tangential_slip_stderr = 0;  // over U
    double rolling = 0, rolling_stderr = 0;                  // over U
    double contact_slip = 0, contact_slip_stderr = 0;        // over U
    std::optional<double> rolling_share;                     // none when <slip> = 0
    double rolling_fraction = 0;
    double max_bump_overlap = 0;  // over the grain's radius, the deepest grain-bump overlap
};

// The wall layer of one snapshot at wall w, U the floor's speed (> 0); periodic images in x (the
// box's length) and in z when box.periodic_z. Nothing counted: grains = 0 and every mean 0.
WallLayer wall_layer(const ParticleSet& p, const ParticleBox& box, const WallLayerWall& w, double U);

// run.wall_layer of a particle summary from a run's final state (none: not measured, said), for
// the slice box `box` (ring: not measured), U the floor's speed, the walls' bumps (null: a plane).
nlohmann::json wall_layer_record(const std::optional<ParticleState>& state, const ParticleBox& box, double U,
                                 const BumpLayer* bottom, const BumpLayer* top, bool ring);

}  // namespace granlub
