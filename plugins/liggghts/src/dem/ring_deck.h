// The LIGGGHTS deck of the whole ring ([cell] geometry = "annulus"; granlub/particles/annulus.h): the
// trough's floor and both cylinders turn at Omega = U / R about the y axis, in place, and the flat
// annular top is still and, under load control, moved along the axis by the slice's servo rule at
// a steady speed over each window. By default ([dem] ring_walls = "primitive") all four are exact
// primitives (fix wall/gran/moving); with "mesh" STL meshes (ring_meshes.h; LIGGGHTS'
// surface_ang_vel and fix move/mesh). Gravity along -y and no centripetal body force: the
// curvature makes it. Readable and rerunnable by hand like the slice's deck (deck.h), with the
// same result files; only the wall file's columns differ.
#pragma once
#include <string>

#include "deck.h"

namespace granlub::dem {

// Columns of the ring's wall file (kWallFile) after the step: force along the axis and torque
// about it of the grains on the floor, top, outer and inner wall (the order of RingWallLoads).
inline constexpr std::size_t kRingWallColumns = 8;

// The data file's box: the ring's square around the axis, a diameter below the floor to two above
// the cylinders.
DataBounds ring_bounds(const Settings& s, double diameter);

// Height of the ring's cylinders: a diameter above the box top (the plate's highest position).
double ring_wall_height(const Settings& s, double diameter);

std::string ring_deck(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleSet& grains,
                      const std::string& provenance);

}  // namespace granlub::dem
