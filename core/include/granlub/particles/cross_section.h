// The trough's cross-section as Sawyer & Tichy drew it (J. Tribol. 123 (2001), Figs. 7-8: density
// and flow velocity over the cross-section, flow out of the page): solid fraction and streamwise
// velocity of the particle solvers over y (across the gap) x z (across the width), averaged over
// the flow direction x and over the snapshots of the steady window. It shows where body forces
// pack the grains (gravity toward the floor, the centripetal force toward the outer wall).
//
// how: a grain's volume is split between the cells as (its exact sphere-slice fraction in the
// y band) x (its exact fraction in the z band), sphere_slice_volume of coarse_grain.h along each
// axis. The product of the two marginals is our choice (the papers leave it open): it keeps each
// grain's volume and both one-dimensional profiles exact, while a cell at a grain's corner gets
// a share slightly different from the exact sphere-box intersection (cells of about one diameter).
// what: nu = <sum V_ic> / V_cell, u = sum V_ic v_x,i / sum V_ic over the snapshots used.
#pragma once
#include <cstddef>
#include <vector>

#include "granlub/particles/particles.h"
#include "granlub/results/results.h"

namespace granlub {

// Written to kSectionFile and kWidthProfileFile (results.h).

class CrossSection {
public:
    // ny x nz cells over y in [0, gap], z in [-width/2, width/2]; `length` is the depth along x.
    CrossSection(std::size_t ny, std::size_t nz, double gap, double width, double length);

    // Cells of about one grain diameter d (at least 2 each way).
    static CrossSection for_grains(double d, double gap, double width, double length);
    // How many such cells span `extent` (the rule of for_grains; the continuum maps its section onto the same cells).
    static std::size_t cells_for_grains(double d, double extent);

    void add_snapshot(const ParticleSet& p, double time);
    std::size_t snapshots() const { return times_.size(); }

    // Columns y_over_H, z_over_W (cell centres; z/W from -1/2 to 1/2), solid_fraction, u_over_U
    // (0 where no grain ever was), over snapshots [first, snapshots()); one row per cell, z fastest.
    // In granlub dem the centripetal force points to -z: z/W = -1/2 is the outer wall.
    Profile table(double U, std::size_t first) const;

    // The profile across the width: the cells of each z band summed over the gap, per snapshot,
    // then averaged over snapshots [first, snapshots()): columns z_over_W, solid_fraction,
    // u_over_U (0 where no grain ever was) and their standard errors from `blocks` blocks of
    // snapshots (block_average.h; the mean u is the volume-weighted one, its error that of the
    // snapshots' own u). Over the whole gap: the radial profile of the annulus.
    Profile width_profile(double U, std::size_t first, std::size_t blocks) const;

private:
    std::size_t ny_, nz_;
    double gap_, width_, length_;
    std::vector<double> times_;
    std::vector<double> volume_, momentum_;  // per snapshot x cell: sum V, sum V v_x
};

}  // namespace granlub
