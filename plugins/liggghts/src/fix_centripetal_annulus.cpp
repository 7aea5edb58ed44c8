// The centripetal body force of a grain moving along the flow at v_x in an annular cell of mean
// radius R, unrolled into a plane: F_z = -m v_x^2 / (R - z), toward the outer wall (-z), z the
// position across the width (Sawyer & Tichy 2001, J. Tribol. 123, particle simulation: the
// annulus' centripetal acceleration u^2/r at the local radius r = R - z). The same force as
//   variable fcent atom -mass*vx*vx/(R-z)
//   fix cent all addforce 0.0 0.0 v_fcent
// with the same arithmetic (so the same bits), but without parsing and evaluating an atom-style
// variable every step. Per atom, local atoms only: MPI needs nothing more.
#include "fix_centripetal_annulus.h"

#include <cstdio>
#include <cstring>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixCentripetalAnnulus::FixCentripetalAnnulus(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
    if (narg != 4)
        error->all(FLERR, "Illegal fix centripetal/annulus command: expected fix ID group centripetal/annulus R");
    radius_ = force->numeric(FLERR, arg[3]);
    if (!(radius_ > 0))
        error->all(FLERR, "Illegal fix centripetal/annulus command: R must be > 0 (the annulus mean radius)");
}

int FixCentripetalAnnulus::setmask() { return POST_FORCE | MIN_POST_FORCE; }

void FixCentripetalAnnulus::init() {
    if (!atom->rmass_flag) error->all(FLERR, "Fix centripetal/annulus needs per-atom masses (atom_style granular)");
    if (strstr(update->integrate_style, "respa"))
        error->all(FLERR, "Fix centripetal/annulus does not support run_style respa");
}

void FixCentripetalAnnulus::setup(int vflag) { post_force(vflag); }

void FixCentripetalAnnulus::min_setup(int vflag) { post_force(vflag); }

void FixCentripetalAnnulus::min_post_force(int vflag) { post_force(vflag); }

void FixCentripetalAnnulus::post_force(int) {
    double** x = atom->x;
    double** v = atom->v;
    double** f = atom->f;
    const double* rmass = atom->rmass;
    const int* mask = atom->mask;
    const int nlocal = atom->nlocal;
    bool outside = false;
    for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit)) continue;
        const double r = radius_ - x[i][2];
        outside |= !(r > 0);
        // evaluated as the variable form does: ((-m) v_x) v_x / (R - z)
        f[i][2] += -rmass[i] * v[i][0] * v[i][0] / r;
    }
    if (outside) {
        const char* msg = "Fix centripetal/annulus: a grain at z >= R (on or beyond the annulus axis)";
        // error->one aborts with the screen text still buffered when stdout is a pipe: say it on stderr too
        std::fprintf(stderr, "ERROR on proc %d: %s\n", comm->me, msg);
        error->one(FLERR, msg);
    }
}
