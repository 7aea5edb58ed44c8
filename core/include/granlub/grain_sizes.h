// The grain sizes of the particle solvers ([grains] size_spread): a size distribution declared once
// and drawn once, into the initial grains both engines start from.
//
// Diameters are uniform in [d (1 - a), d (1 + a)] with a = sqrt(3) s: number mean d, standard
// deviation s d, bounded on both sides (no clipping needed; the lattice insertion and the neighbour
// lists see at most d (1 + a)). Our choice of distribution [ASSUMPTION]: Sawyer & Tichy 2001 give the
// beads' mean diameter only; sieved glass beads span about +-10-20 % of it. Equal hard spheres
// crystallise under shear and load; a size spread above about 0.07 suppresses it (Pusey et al.
// 2009, Phil. Trans. R. Soc. A 367:4993). The continuum and the automaton use the mean d.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace granlub {

// The largest spread a case may ask for: d_max / d_min = 2.1 (a = 0.35); the insertion lattice is
// spaced for the largest grain, so wider spreads insert ever looser packings.
inline constexpr double kMaxSizeSpread = 0.2;

struct GrainSizes {
    double mean = 0;    // d, m (number mean)
    double spread = 0;  // s = standard deviation / mean; 0 = equal grains
    double half_width() const;          // a = sqrt(3) s
    double min() const;                 // d (1 - a)
    double max() const;                 // d (1 + a)
    double mean_volume() const;         // pi <d^3> / 6 = pi d^3 (1 + 3 s^2) / 6
    bool equal() const { return spread == 0; }
};

// n diameters drawn from `seed` (a stream of its own: the positions and velocities of an
// insertion do not depend on the sizes' draws); all equal to the mean when s = 0.
std::vector<double> draw_diameters(const GrainSizes& g, std::size_t n, std::uint64_t seed);

}  // namespace granlub
