/* ----------------------------------------------------------------------
    granlub: the single pass's pairs across a periodic or processor
    boundary (one grain a ghost), seen by both owners with one geometry.

    With newton off both owners of such a pair resolve it, each from its
    own copy: grain i owned and the image of j on one side, j owned and the
    image of i on the other. The impulses are equal and opposite only if
    both copies see the same pair. The velocities are the start of the
    step's on both sides (model impulse, boundary_pair). The positions were
    not: `separate` (and impact_time's replay) moves an owned grain during
    the pair pass, as soon as each of its overlaps is resolved, while its
    image on the other side stays where the step's communication put it.
    So each side saw the pair with its own grain already pushed by some of
    its other contacts and the other grain where it started: two normals,
    two overlaps, and at the margin a contact on one side and none on the
    other -- an impulse without its reaction. A sheared box periodic in x,
    y and z gained 2e-3 of its summed |m v| in 1000 steps (measured
    2026-12-06, tests/liggghts/test_periodic_momentum.cpp; 0 with separate
    off); in cases/bulk_shear, periodic across the width too, the two
    walls' shear stresses, equal in steady state, differed by 10 % (its
    README).

    The rule (ours; model impulse's boundary_start on, off by default so
    that earlier results stay as they were): a boundary pair's geometry (normal, distance, whether
    it touches) is taken from both grains' positions at the start of the
    pair pass, which the ghost still has; the owned grain's is recorded
    when the pass begins. Both sides then compute the same pair from the
    same numbers, so the impulses are equal and opposite to rounding, on
    one rank (periodic images) and across ranks alike. The other pairs keep
    the sequential pass unchanged.

    A pair that touched at the start but whose owned grain has since been
    pushed away is no longer an overlap for LIGGGHTS' own check; it reaches
    the models' surfacesClose only within the contact distance factor, so
    the single pass with moving positions registers kBoundaryDistance. A
    grain pushed further than that margin within one pass could lose such a
    pair on one side; the pass counts those grains (BoundaryStart::beyond)
    and model impulse warns.

    Contributing author: granlub (plugins/liggghts), GPL-2.0-or-later like
    LIGGGHTS. Drops unchanged into a LIGGGHTS 3.8 source tree.
------------------------------------------------------------------------- */

#ifndef GRANLUB_IMPULSE_BOUNDARY_H_
#define GRANLUB_IMPULSE_BOUNDARY_H_

#include <cmath>
#include <vector>

#include "contact_interface.h"

namespace LIGGGHTS {
namespace ContactModels {

// The contact distance factor of the single pass when positions move in the pass: pairs closer
// than 1.1 (r_i + r_j) reach the models. [ASSUMPTION] the margin, ours: `separate` moves a grain by
// at most its overlaps, made within one step; 0.1 d in a step is an approach of 14 m/s at
// cases/sawyer2001's step (as kSpeculativeDistance, impulse_speculative.h), several times the
// shear speed. A larger move is counted (BoundaryStart::beyond), not silently lost.
static const double kBoundaryDistance = 1.1;

class BoundaryStart {
public:
  // at the start of the pair pass: the owned grains' positions
  void record(double ** x, int nlocal)
  {
    x0_.resize(3 * static_cast<std::size_t>(nlocal));
    for (int k = 0; k < nlocal; k++)
      for (int d = 0; d < 3; d++) x0_[3 * k + d] = x[k][d];
  }

  // A boundary pair (grain i owned, j a ghost): its geometry from i's recorded position and the
  // ghost's (sidata delta, rsq, radsum, r, rinv, en, vn, deltan); false if the surfaces were
  // farther apart than `reach` times r_i + r_j then.
  bool geometry(SurfacesIntersectData & sidata, double ** x, double reach) const
  {
    const int i = sidata.i, j = sidata.j;
    const double * const xi = &x0_[3 * i];
    const double delta[3] = {xi[0] - x[j][0], xi[1] - x[j][1], xi[2] - x[j][2]};
    const double rsq = delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2];
    const double radsum = sidata.radi + sidata.radj;
    if (!(rsq < reach * reach * radsum * radsum)) return false;
    const double r = std::sqrt(rsq);
    sidata.rsq = rsq;
    sidata.radsum = radsum;
    sidata.r = r;
    sidata.rinv = 1.0 / r;
    double vn = 0.0;
    for (int d = 0; d < 3; d++) {
      sidata.delta[d] = delta[d];
      sidata.en[d] = delta[d] / r;
      vn += (sidata.v_i[d] - sidata.v_j[d]) * sidata.en[d];
    }
    sidata.vn = vn;
    sidata.deltan = radsum - r;
    return true;
  }

  // after the pass: owned grains moved by more than (kBoundaryDistance - 1) r_i since it began
  // (a boundary pair of theirs that touched at the start could have been missed on one side)
  int beyond(double ** x, const double * radius, int nlocal) const
  {
    int n = 0;
    const int m = static_cast<int>(x0_.size() / 3) < nlocal ? static_cast<int>(x0_.size() / 3) : nlocal;
    for (int k = 0; k < m; k++) {
      const double a = x[k][0] - x0_[3 * k], b = x[k][1] - x0_[3 * k + 1], c = x[k][2] - x0_[3 * k + 2];
      const double lim = (kBoundaryDistance - 1.0) * radius[k];
      if (a * a + b * b + c * c > lim * lim) n++;
    }
    return n;
  }

private:
  std::vector<double> x0_;
};

}
}

#endif // GRANLUB_IMPULSE_BOUNDARY_H_
