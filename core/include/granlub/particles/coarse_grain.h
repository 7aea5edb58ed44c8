// Coarse-graining particle snapshots into profiles across the gap, shared by the particle solvers.
// It is described by the three aspects MercuryDPM's CG separates (Weinhart et al. 2012, Granular
// Matter 14:289, "From discrete particles to continuum fields near a boundary"), but here each aspect
// has exactly one implementation, fixed in SliceCoarseGrainer; none is a template parameter or a
// run-time option:
//   where: Stations, equal slabs across the gap y in [0, H] (averaged over x and z);
//   how:   each grain's volume is split between the slabs by exact sphere-slice volumes
//          V_k = pi * integral over the slab of (r^2 - (y - y_c)^2) dy;
//   what:  solid fraction  nu_k = <sum_i V_ik> / V_slab
//          velocity         u_k  = sum_i V_ik v_i / sum_i V_ik            (volume = mass weighting
//                                                                          for equal densities)
//          temperature      T_k  = (1/3) sum_c [ sum_i V_ik v_ic^2 / sum_i V_ik - u_kc^2 ]
//          i.e. T from the velocity fluctuations about the local mean velocity of the same
//          averaging window (docs/architecture.md: T = <C^2>/3), sums running over all snapshots used.
// Standard errors come from block averaging (granlub/statistics/block_average.h; Flyvbjerg & Petersen 1989,
// J. Chem. Phys. 91:461): the snapshots are cut into contiguous blocks, each block gives its own
// profile, and the standard error is that of the block values.
// The steady window the profiles are taken over comes from granlub/statistics/steady_state.h.
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "granlub/statistics/block_average.h"
#include "granlub/particles/particles.h"
#include "granlub/results/results.h"

namespace granlub {

// where: n equal slabs between lo and hi (y across the gap).
struct Stations {
    double lo = 0;
    double hi = 0;
    std::size_t n = 0;
    double width() const { return (hi - lo) / static_cast<double>(n); }
    double centre(std::size_t k) const { return lo + (static_cast<double>(k) + 0.5) * width(); }
};

// how: volume of the sphere (centre yc, radius r) between the planes y = a and y = b (a <= b).
double sphere_slice_volume(double yc, double r, double a, double b);

// what: accumulates per-snapshot slab sums; profiles and standard errors are formed at the end,
// so the steady-state start can be chosen after the run.
class SliceCoarseGrainer {
public:
    // cross_area: the slabs' area in x-z (length x width of the cell).
    SliceCoarseGrainer(Stations s, double cross_area);

    void add_snapshot(const ParticleSet& p, double time = 0);  // adds one snapshot
    std::size_t snapshots() const { return times_.size(); }
    const std::vector<double>& times() const { return times_; }
    const Stations& stations() const { return st_; }

    struct Fields {  // per station
        std::vector<double> nu, ux, uy, uz, T;
    };
    // Fields over snapshots [first, last).
    Fields fields(std::size_t first, std::size_t last) const;

    // Profile over snapshots [first, snapshots()) with `blocks` blocks for the standard errors:
    // columns y_over_H, u_over_U, solid_fraction, temperature_over_U2, their *_stderr, and
    // v_over_U, w_over_U (mean cross-gap and cross-width velocities). U > 0; H = stations().hi.
    Profile profile(double U, std::size_t first = 0, std::size_t blocks = 10) const;

    // Volume-averaged solid fraction over the stations, from snapshots [first, last).
    double mean_solid_fraction(std::size_t first, std::size_t last) const;

private:
    // per snapshot, per station: V, V vx, V vy, V vz, V vx^2, V vy^2, V vz^2
    static constexpr std::size_t kSums = 7;
    Stations st_;
    double area_;
    std::vector<double> sums_;  // snapshot-major: [snapshot][station][kSums]
    std::vector<double> times_;
};

}  // namespace granlub
