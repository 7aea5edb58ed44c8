// fix check/timestep/gran for model impulse (fix_check_timestep_impulse.h). A rigid contact has no
// elastic time scale: LIGGGHTS' check compares dt with the Rayleigh and Hertz times of Young's
// modulus, which the impulse model does not use. What limits the step for rigid contacts found by
// overlap is how far grains move relative to each other in one step: against the diameter (the
// overlap a single step's approach leaves, and tunnelling), and against the neighbor skin (as
// LIGGGHTS' check). Same arguments as LIGGGHTS' fix (nevery, two fractions, warn, error, vmax); the
// two fractions do not apply and are ignored, with a note.
#include "fix_check_timestep_impulse.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixCheckTimestepImpulse::FixCheckTimestepImpulse(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg), warn_(true), error_(false), vmax_user_(0.0), travel_(0.0), skin_fraction_(0.0),
      warned_travel_(0.0), noted_(false) {
    // LIGGGHTS' syntax: [check_every_time] nevery fraction_rayleigh fraction_hertz [warn y/n] [error y/n] [vmax v]
    int iarg = (narg > 3 && std::strcmp(arg[3], "check_every_time") == 0) ? 4 : 3;
    if (narg < iarg + 3) error->all(FLERR, "Illegal fix check/timestep/gran command, not enough arguments");
    nevery = std::atoi(arg[iarg]);
    if (nevery < 1) error->all(FLERR, "fix check/timestep/gran: nevery must be a whole number >= 1");
    for (iarg += 3; iarg < narg; iarg += 2) {
        if (iarg + 1 >= narg) error->all(FLERR, "fix check/timestep/gran: a keyword without its value");
        const std::string key = arg[iarg], val = arg[iarg + 1];
        if ((key == "warn" || key == "error") && val != "yes" && val != "no")
            error->all(FLERR, ("fix check/timestep/gran: expecting 'yes' or 'no' after '" + key + "'").c_str());
        if (key == "warn")
            warn_ = val == "yes";
        else if (key == "error")
            error_ = val == "yes";
        else if (key == "vmax")
            vmax_user_ = force->numeric(FLERR, arg[iarg + 1]);
        else
            error->all(FLERR, ("fix check/timestep/gran: unknown keyword '" + key + "' (warn, error, vmax)").c_str());
    }
    vector_flag = 1;
    size_vector = 3;
    global_freq = nevery;
    extvector = 0;
}

int FixCheckTimestepImpulse::setmask() { return END_OF_STEP; }

void FixCheckTimestepImpulse::init() {
    if (!atom->radius_flag) error->all(FLERR, "fix check/timestep/gran needs spheres (atom_style granular)");
    if (comm->me == 0 && !noted_) {
        noted_ = true;  // once per fix, not at every run
        char msg[512];
        std::snprintf(msg, sizeof(msg),
                      "fix check/timestep/gran %s: model impulse has no stiffness, so the Rayleigh and Hertz time "
                      "fractions do not apply; checking the travel per step against the smallest diameter (warns above "
                      "%g) and against the neighbor skin instead (f_%s[1] travel / d_min, [2] 0, [3] travel / skin)\n",
                      id, kTravelLimit, id);
        if (screen) std::fputs(msg, screen);
        if (logfile) std::fputs(msg, logfile);
    }
}

void FixCheckTimestepImpulse::end_of_step() {
    double local[2] = {0.0, 0.0};  // largest speed squared, -smallest radius
    local[1] = -1e300;
    for (int i = 0; i < atom->nlocal; i++) {
        if (!(atom->mask[i] & groupbit)) continue;
        const double* v = atom->v[i];
        const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (v2 > local[0]) local[0] = v2;
        if (-atom->radius[i] > local[1]) local[1] = -atom->radius[i];
    }
    double global[2];
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, world);
    if (global[1] <= -1e300) return;  // no grains yet
    const double vmax = std::max(std::sqrt(global[0]), vmax_user_);
    const double travel = 2.0 * vmax * update->dt;  // two grains approaching, each at the largest speed
    travel_ = travel / (-2.0 * global[1]);
    skin_fraction_ = neighbor->skin > 0.0 ? travel / neighbor->skin : 0.0;
    char msg[512];
    if (travel_ > kTravelLimit && travel_ > warned_travel_) {
        warned_travel_ = 2.0 * travel_;  // again only when it doubles
        std::snprintf(msg, sizeof(msg),
                      "fix check/timestep/gran: grains may move %.3g of the smallest diameter relative to each other in "
                      "a step (limit %g for rigid contacts: overlaps beyond fix impulse/solve's overlap_limit); use a "
                      "smaller timestep",
                      travel_, kTravelLimit);
        if (error_) error->all(FLERR, msg);
        if (warn_ && comm->me == 0) error->warning(FLERR, msg);
    }
    if (skin_fraction_ > 1.0) {
        std::snprintf(msg, sizeof(msg),
                      "fix check/timestep/gran: grains may move %g m relative to each other in a step, but the skin is "
                      "%g m: contacts may be missed; use a smaller timestep or a larger skin",
                      travel, neighbor->skin);
        if (error_) error->all(FLERR, msg);
        if (warn_ && comm->me == 0) error->warning(FLERR, msg);
    }
}

double FixCheckTimestepImpulse::compute_vector(int n) {
    if (n == 0) return travel_;
    if (n == 2) return skin_fraction_;
    return 0.0;
}
