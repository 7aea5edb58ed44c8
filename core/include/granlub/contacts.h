// Contacts between grains in one particle snapshot, and how long they last: the coordination
// number Z and the contact persistence that tell enduring contacts from brief collisions
// (flow_regime.h classifies them). Shared by the particle solvers.
//
// Two grains touch when the gap between their surfaces is at most kContactGapTolerance times the
// sum of their radii (an overlap, of any depth, also counts). The impulse model finds contacts only
// by overlap and leaves grains a hair apart after an impact, so an exact-contact test would miss
// resting contacts; 1 % of a diameter is far below the mean free path of a collisional flow.
// Periodic images: x always (length box.length), z when box.periodic_z (width box.width), by the
// minimum image. Walls are not grains: Z counts grain-grain contacts only.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "granlub/particles.h"

namespace granlub {

inline constexpr double kContactGapTolerance = 0.01;  // surface gap / (r_i + r_j)

// Touching pairs (i, j), i < j, as indices into the snapshot, sorted. O(n) with a cell list.
using ContactList = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
ContactList touching_pairs(const ParticleSet& p, const ParticleBox& box, double tolerance = kContactGapTolerance);

// Overlaps of the listed pairs, (r_i + r_j - distance) / (r_i + r_j), counting only pairs that
// overlap: how far rigid grains interpenetrate (0 when none does).
struct OverlapStats {
    std::size_t overlapping = 0;
    double max = 0;
    double mean = 0;  // over the overlapping pairs
};
OverlapStats overlaps(const ParticleSet& p, const ParticleBox& box, const ContactList& pairs);

// Mean contacts per grain, 2 |pairs| / grains (0 for no grains).
double coordination_number(const ContactList& pairs, std::size_t grains);

// Fraction of the pairs touching in `before` that still touch in `after` (the same grains, same
// indices, a short time later); nothing when `before` has no contact.
std::optional<double> contact_persistence(const ContactList& before, const ContactList& after);

}  // namespace granlub
