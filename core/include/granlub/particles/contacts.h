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

#include "granlub/particles/particles.h"

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

// The contacts per grain of the grains whose centres lie in the band lo <= y <= hi (each contact
// counted once for each of its grains in the band); nothing when no grain lies in it. The core of a
// wide gap, away from the walls' layers (the bulk rheology, cases/bulk_shear).
struct Band {
    double lo = 0, hi = 0;
};
std::optional<double> band_coordination(const ParticleSet& p, const ContactList& pairs, Band band);

// The coordination number of each snapshot from t_start on (earlier ones are not averaged, so
// they are skipped), and over the same snapshots the deepest overlap and the mean overlap of the
// overlapping pairs, collected as the snapshots are read. With a core band, also the band's
// coordination number (band_coordination) of each snapshot.
class ContactSeries {
public:
    ContactSeries(const ParticleBox& box, double t_start, std::optional<Band> core = std::nullopt)
        : box_(box), t_start_(t_start), core_(core) {}
    void add(const ParticleSet& p, double time);
    const std::vector<double>& coordination() const { return z_; }
    const std::vector<double>& core_coordination() const { return z_core_; }  // snapshots with grains in the band
    const std::optional<Band>& core() const { return core_; }
    double seconds() const { return seconds_; }  // time spent finding contacts
    double max_overlap() const { return max_overlap_; }
    double mean_overlap() const { return overlapping_ ? overlap_sum_ / static_cast<double>(overlapping_) : 0.0; }

private:
    ParticleBox box_;
    double t_start_;
    std::optional<Band> core_;
    std::vector<double> z_, z_core_;
    double seconds_ = 0;
    double max_overlap_ = 0, overlap_sum_ = 0;
    std::size_t overlapping_ = 0;
};

}  // namespace granlub
