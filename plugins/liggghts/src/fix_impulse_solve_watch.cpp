// fix impulse/solve: overlaps the solver did not remove, named while the run goes on and at its end
// (doc/fix_impulse_solve.txt, "Overlaps that are not removed").
//
// Rigid grains must not overlap: the position sweeps (split impulses, fix_impulse_solve.cpp) take
// every overlap found at a step back to the slop. What they cannot take back shows at the next
// step as an overlap much larger than the slop: the grains were compressed beyond what rigid
// spheres can fill (a packing grown or squeezed past random close packing), moved further in a
// step than the correction can follow, or the position sweeps stopped at their cap. The run's
// numbers are then those of soft grains of unknown stiffness, so the user is told.
//
// The limit (keyword overlap_limit, a fraction of r_i + r_j; r_i for a wall): 0.05 by default (our
// choice). A step of granlub's default size moves a grain by 0.02 d at most, so a single step's
// approach never reaches 0.05 (r_i + r_j) = 0.05 d (equal grains); and 0.05 d is the overlap a
// stiff Hertz contact is usually tuned to stay well below, so a rigid model carrying it has lost
// its geometry.
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_impulse_solve.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

// what the user can do, in every message
const char* const kAdvice =
    "Rigid grains cannot be compressed: keep a grown or squeezed packing below what rigid spheres fill (random "
    "close packing, solid fraction about 0.64) or compact it with a soft model (hertz); keep the travel per step "
    "well below the diameter (smaller timestep); raise 'iterations' if the position sweeps stop at the cap";

}  // namespace

FixImpulseSolve* FixImpulseSolve::active() {
    if (!superseded_) return this;
    for (int k = 0; k < modify->nfix; k++) {
        FixImpulseSolve* f = dynamic_cast<FixImpulseSolve*>(modify->fix[k]);
        if (f && f != this && !f->superseded_) return f;
    }
    return this;
}

// The largest overlap of the step's corrected contacts (found before this step's correction), on
// all ranks; a step beyond the limit is counted and named, the first time and then each time the
// count reaches ten times the last warned one; with `overlaps error` the run stops.
void FixImpulseSolve::watch_overlaps(bool positions_capped) {
    struct {
        double value;
        int rank;
    } mine = {0.0, comm->me}, all;
    int worst = -1;
    const int n = static_cast<int>(contacts_.size());
    for (int k = 0; k < n; k++) {
        const Contact& c = contacts_[k];
        if (!c.separate) continue;
        const double r = c.overlap / (c.ri + c.rj);
        if (r > mine.value) {
            mine.value = r;
            worst = k;
        }
    }
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
    last_overlap_ = all.value;
    if (positions_capped) run_position_capped_++;
    if (all.value > run_max_overlap_) {
        run_max_overlap_ = all.value;
        run_max_overlap_step_ = update->ntimestep;
    }
    if (all.value <= overlap_limit_) return;
    run_bad_steps_++;
    if (!overlap_error_ && run_bad_steps_ < 10 * warned_at_) return;
    warned_at_ = run_bad_steps_;
    // the two atoms (tags), from the rank that has the contact
    double tags[2] = {0.0, 0.0};
    if (comm->me == all.rank && worst >= 0) {
        const Contact& c = contacts_[worst];
        tags[0] = static_cast<double>(atom->tag[c.i]);
        tags[1] = c.j >= 0 ? static_cast<double>(atom->tag[c.j]) : -1.0;
    }
    MPI_Bcast(tags, 2, MPI_DOUBLE, all.rank, world);
    char where[96];
    if (tags[1] >= 0.0)
        std::snprintf(where, sizeof(where), "atoms %.0f and %.0f, of r_i + r_j", tags[0], tags[1]);
    else
        std::snprintf(where, sizeof(where), "atom %.0f and a wall, of r_i", tags[0]);
    char msg[2048];
    std::snprintf(msg, sizeof(msg),
                  "fix impulse/solve: step %lld: an overlap of %.3g (%s) was not removed (overlap_limit %g); %lld "
                  "step(s) so far in this run, %lld with the position sweeps at the cap of %d. %s%s.",
                  static_cast<long long>(update->ntimestep), all.value, where, overlap_limit_,
                  static_cast<long long>(run_bad_steps_), static_cast<long long>(run_position_capped_), iterations_,
                  kAdvice,
                  overlap_error_ ? "" : ". Next warning at ten times as many such steps; fix impulse/solve ... overlaps error stops the run here");
    if (overlap_error_) error->all(FLERR, msg);
    if (comm->me == 0) error->warning(FLERR, msg);
}

// At the end of a run: how many steps carried overlaps beyond the limit, the largest and when.
void FixImpulseSolve::report_overlaps() const {
    if (comm->me != 0 || (run_bad_steps_ == 0 && run_position_capped_ == 0)) return;
    char msg[2048];
    std::snprintf(msg, sizeof(msg),
                  "fix impulse/solve: %lld of %lld steps of this run carried overlaps that were not removed (beyond "
                  "overlap_limit %g of r_i + r_j), %lld with the position sweeps at the cap of %d; the largest, %.3g "
                  "of r_i + r_j, at step %lld: the grains behaved as soft grains of unknown stiffness there. %s.",
                  static_cast<long long>(run_bad_steps_), static_cast<long long>(run_steps_), overlap_limit_,
                  static_cast<long long>(run_position_capped_), iterations_, run_max_overlap_,
                  static_cast<long long>(run_max_overlap_step_), kAdvice);
    error->warning(FLERR, msg);
}
