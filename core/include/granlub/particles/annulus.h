// The whole ring ([cell] geometry = "annulus"): the annular trough as built, instead of a periodic
// slice with a centripetal stand-in for the curvature.
//
// Ring frame (what the engine runs): y is the ring's axis (gravity along -y), the floor at y = 0,
// the side walls the cylinders r = R - W/2 (inner) and r = R + W/2 (outer), r = sqrt(x^2 + z^2).
// The floor and both cylinders turn at Omega = U / R about +y; the angle theta = atan2(-z, x)
// grows along their motion.
//
// Slice frame (what every result is written in, so that ring and slice compare column by
// column): the equal-area map
//   x_s = R theta,   y_s = y,   z_s = (R^2 + W^2/4 - r^2) / (2 R),
// which takes the trough onto the slice's box [0, 2 pi R) x [0, H] x [-W/2, W/2] with the outer
// wall at z_s = -W/2, where the slice's centripetal force pushes. Its Jacobian is 1: a volume in
// the ring is the same volume in the slice, so solid fractions coarse-grained in the slice frame
// are the ring's. Velocities are the map's time derivatives: u_s = R d(theta)/dt = v_theta R / r,
// so the mean of u_s / U is omega / Omega (the ring's angular velocity over the walls'), and a
// bed turning rigidly with the floor has no spurious fluctuation across the width. Our choice (no
// paper runs this cell whole): fluctuations along theta are scaled by R / r, within +-W / (2R)
// of the true ones (12 % at the walls of the Sawyer & Tichy cell, 0.5 % in the mean square).
#pragma once
#include <cstddef>

#include "granlub/statistics/block_average.h"
#include "granlub/particles/particle_reduction.h"
#include "granlub/particles/particles.h"

namespace granlub {

struct Case;

struct Annulus {
    double R = 0;  // mean radius, m
    double W = 0;  // trough width, m
    double inner() const { return R - 0.5 * W; }
    double outer() const { return R + 0.5 * W; }
    double area() const;          // of the floor (and the top): pi (r_o^2 - r_i^2) = 2 pi R W
    double polar_moment() const;  // integral of r over the floor's area: 2 pi (r_o^3 - r_i^3) / 3
};

// The case's ring ([cell] annulus_radius and width).
Annulus annulus(const Case& c);

// The slice-frame box of the ring: 2 pi R x H x W with side walls; its area L W is the floor's.
ParticleBox ring_slice_box(const Case& c);

// Ring-frame grains in the slice frame (the map above); radii unchanged, spins dropped.
void to_slice(const ParticleSet& ring, const Annulus& a, ParticleSet& slice);

// A box in which core's contact search (contacts.h, periodic along x) sees the ring-frame grains
// as they are: a period longer than twice the ring's diameter, so no grain meets an image.
ParticleBox ring_contact_box(const Annulus& a, double gap, double diameter);

// Ring walls' loads as the engine records them: force along the axis and torque about it (N,
// N m) of the grains on each wall, per block.
struct RingWallLoads {
    std::vector<double> step;
    std::vector<double> fy_floor, t_floor, fy_top, t_top, fy_outer, t_outer, fy_inner, t_inner;
};

// The same loads as the slice's wall forces (particle_reduction.h), so that the shared reduction
// gives the ring's stresses: the shear force of the floor and the top is the torque over
// polar_moment() times the area (the tangential force whose uniform stress T / J has the torque
// T), a side wall's is T L / (2 pi r^2) (stress T / (2 pi r^2 H) on its height H), side 1 the
// outer wall and side 2 the inner as in the slice (z_s = -W/2 is the outer); the forces along the
// axis are the normal forces.
WallForceSeries ring_wall_forces(const RingWallLoads& loads, const Annulus& a);

// The torques' balance over the blocks from `first` on: the mean of the four walls' summed torques
// over the mean of the top's (0 in a steady state: nothing else turns the grains about the axis),
// with the block standard error of the sum over the top's mean. Ratio of means, not a mean of
// per-block ratios: a light load's top torque is noisy block by block.
BlockEstimate ring_torque_balance(const RingWallLoads& loads, std::size_t first, std::size_t blocks);

// The fewest inner-wall radii a ring may have: kMinRingInnerRadiusDiameters (case.h).

// Overlap-free placement of n grains of diameter d in the ring trough below height h: layers a
// apart along the axis, in each layer circles a apart across the width, on each circle sites at
// least a apart (chords); the largest spacing a >= d that gives n sites; a random subset of the
// sites, each displaced at random by at most (a - d)/2; velocities a rigid rotation decreasing
// linearly from Omega at the floor to 0 at h, plus Gaussian noise (opt.velocity_noise U). `sag`
// (m) is kept clear of the side walls in addition: how far a meshed wall's facets lie inside its
// circle. Same inputs, same grains, bit for bit. Throws CaseError when n grains do not fit; the
// message gives the most that do.
ParticleSet insert_ring_grains(const Annulus& a, double h, double d, std::size_t n, const InsertionOptions& opt,
                               double sag = 0);

// The most grains insert_ring_grains can place (spacing a = d).
std::size_t ring_capacity(const Annulus& a, double h, double d, double sag = 0);

}  // namespace granlub
