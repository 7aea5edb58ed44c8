// The force of each listed granular wall on the grains of a group, summed over the grains this step:
// the same numbers, to the bit, as one `compute reduce sum f_force_<wall>[k]` per component (each
// sum starts at 0 and adds the owned grains in index order, then one MPI sum across ranks), but
// one pass over the grains and one MPI_Allreduce for every wall, instead of a pass and an
// Allreduce per component through compute reduce's per-value dispatch. Impulse forces last one
// step, so wall stresses must be summed every step (granlub's decks do): this is that sum.
#include "compute_wall_gran_force.h"

#include <mpi.h>

#include <cstring>

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "fix_property_atom.h"
#include "fix_wall_gran.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeWallGranForce::ComputeWallGranForce(LAMMPS* lmp, int& iarg, int narg, char** arg)
    : Compute(lmp, iarg, narg, arg) {
    if (iarg >= narg)
        error->all(FLERR, "Illegal compute wall/gran/force command: expected "
                          "compute ID group wall/gran/force wallID1 [wallID2 ...]");
    for (; iarg < narg; iarg++) walls_.push_back(arg[iarg]);
    for (const std::string& id : walls_) fixes_.push_back(find_wall(id));  // say so at the command
    local_.assign(3 * walls_.size(), 0.0);
    vector_flag = 1;
    size_vector = 3 * static_cast<int>(walls_.size());
    extvector = 1;  // a sum over grains: extensive
    vector = new double[size_vector];
}

ComputeWallGranForce::~ComputeWallGranForce() { delete[] vector; }

// The wall/gran fix with this ID that stores its forces; stops the run naming the wall otherwise.
FixWallGran* ComputeWallGranForce::find_wall(const std::string& id) {
    const int ifix = modify->find_fix(id.c_str());
    if (ifix < 0) {
        const std::string msg = "Compute wall/gran/force: no fix with ID " + id;
        error->all(FLERR, msg.c_str());
    }
    FixWallGran* wall = dynamic_cast<FixWallGran*>(modify->fix[ifix]);
    if (!wall) {
        const std::string msg = "Compute wall/gran/force: fix " + id + " is not a wall/gran fix";
        error->all(FLERR, msg.c_str());
    }
    if (!wall->store_force() || !wall->fix_wallforce()) {
        const std::string msg = "Compute wall/gran/force: wall " + id + " does not store its forces (add store_force yes)";
        error->all(FLERR, msg.c_str());
    }
    return wall;
}

void ComputeWallGranForce::init() {
    // every run: a wall fix may have been unfixed and made again (granlub's servo does), which
    // replaces its stored-force array
    for (std::size_t w = 0; w < walls_.size(); w++) fixes_[w] = find_wall(walls_[w]);
}

void ComputeWallGranForce::compute_vector() {
    invoked_vector = update->ntimestep;
    const int* mask = atom->mask;
    const int nlocal = atom->nlocal;
    for (std::size_t w = 0; w < walls_.size(); w++) {
        // the wall's store_force array (f_force_<wall>), read here: it moves when the atom arrays grow
        double** f = fixes_[w]->fix_wallforce()->array_atom;
        double sx = 0.0, sy = 0.0, sz = 0.0;
        for (int i = 0; i < nlocal; i++)
            if (mask[i] & groupbit) {
                sx += f[i][0];
                sy += f[i][1];
                sz += f[i][2];
            }
        local_[3 * w] = sx;
        local_[3 * w + 1] = sy;
        local_[3 * w + 2] = sz;
    }
    MPI_Allreduce(local_.data(), vector, size_vector, MPI_DOUBLE, MPI_SUM, world);
}
