// The force of each listed granular wall on the grains of a group, summed over the grains this step:
// the same numbers, to the bit, as one `compute reduce sum f_force_<wall>[k]` per component (each
// sum starts at 0 and adds the owned grains in index order, then one MPI sum across ranks), but
// one pass over the grains and one MPI_Allreduce for every wall, instead of a pass and an
// Allreduce per component through compute reduce's per-value dispatch. Impulse forces last one
// step, so wall stresses must be summed every step (granlub's decks do): this is that sum.
// With `torque`, each wall's torque on the grains about an axis, summed at the contact points: a
// primitive wall's contact point is where its own contact geometry puts it (x_i + delta, on the
// wall's surface; a fix wall/gran/moving plane's where the plane is now), as fix
// mesh/surface/stress takes it for a mesh.
#include "compute_wall_gran_force.h"

#include <mpi.h>

#include <cmath>
#include <cstring>

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "fix_property_atom.h"
#include "fix_wall_gran.h"
#include "fix_wall_gran_moving.h"
#include "force.h"
#include "modify.h"
#include "primitive_wall.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeWallGranForce::ComputeWallGranForce(LAMMPS* lmp, int& iarg, int narg, char** arg)
    : Compute(lmp, iarg, narg, arg) {
    const char* usage = "Illegal compute wall/gran/force command: expected compute ID group wall/gran/force "
                        "wallID1 [wallID2 ...] [torque ox oy oz ax ay az]";
    for (; iarg < narg && std::strcmp(arg[iarg], "torque") != 0; iarg++) walls_.push_back(arg[iarg]);
    if (walls_.empty()) error->all(FLERR, usage);
    if (iarg < narg) {  // torque ox oy oz ax ay az
        if (narg - iarg != 7) error->all(FLERR, usage);
        for (int c = 0; c < 3; c++) {
            origin_[c] = force->numeric(FLERR, arg[iarg + 1 + c]);
            axis_[c] = force->numeric(FLERR, arg[iarg + 4 + c]);
        }
        const double norm = std::sqrt(axis_[0] * axis_[0] + axis_[1] * axis_[1] + axis_[2] * axis_[2]);
        if (!(norm > 0)) error->all(FLERR, "Compute wall/gran/force: the torque axis must not be the zero vector");
        for (int c = 0; c < 3; c++) axis_[c] /= norm;
        per_wall_ = 4;
    }
    for (const std::string& id : walls_) fixes_.push_back(find_wall(id));  // say so at the command
    local_.assign(per_wall_ * walls_.size(), 0.0);
    vector_flag = 1;
    size_vector = per_wall_ * static_cast<int>(walls_.size());
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
    if (per_wall_ == 4 && !wall->primitiveWall()) {
        const std::string msg = "Compute wall/gran/force: wall " + id + " is a mesh; torque needs primitive walls "
                                "(fix mesh/surface/stress gives a mesh's torque)";
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
    double** x = atom->x;
    const double* radius = atom->radius;
    const int* mask = atom->mask;
    const int nlocal = atom->nlocal;
    for (std::size_t w = 0; w < walls_.size(); w++) {
        // the wall's store_force array (f_force_<wall>), read here: it moves when the atom arrays grow
        double** f = fixes_[w]->fix_wallforce()->array_atom;
        // a moving wall knows where it is now; another primitive is where it was made
        const FixWallGranMoving* moving = dynamic_cast<const FixWallGranMoving*>(fixes_[w]);
        PrimitiveWall* prim = per_wall_ == 4 ? fixes_[w]->primitiveWall() : NULL;
        // One pass: most grains do not touch the wall this step, and skipping their exact zeros
        // leaves every sum as compute reduce's, to the bit (x + 0.0 == x). Only the grains the wall
        // evaluated can hold a nonzero force, so where the wall lists them in index order (a moving
        // wall's last force pass, a primitive wall's neighbour list) only those are visited.
        const int* list = NULL;
        const int n = candidates(fixes_[w], moving, list, nlocal);
        double sx = 0.0, sy = 0.0, sz = 0.0, tq = 0.0;
        for (int k = 0; k < n; k++) {
            const int i = list ? list[k] : k;
            const double* fi = f[i];
            if (!(mask[i] & groupbit) || (fi[0] == 0.0 && fi[1] == 0.0 && fi[2] == 0.0)) continue;
            sx += fi[0];
            sy += fi[1];
            sz += fi[2];
            if (per_wall_ == 4) tq += torque(moving, prim, x[i], radius[i], fi);
        }
        double* out = &local_[per_wall_ * w];
        out[0] = sx;
        out[1] = sy;
        out[2] = sz;
        if (per_wall_ == 4) out[3] = tq;
    }
    MPI_Allreduce(local_.data(), vector, size_vector, MPI_DOUBLE, MPI_SUM, world);
}

// The owned grains a wall's stored force can be nonzero for, in index order: a fix wall/gran/moving's
// evaluated grains, a fixed primitive wall's neighbour list (rebuilt with the pair neighbour lists,
// within half the skin of the wall: every grain that can touch it until the next rebuild), and for
// a mesh wall all n owned grains (list = NULL: the indices 0 .. n-1).
int ComputeWallGranForce::candidates(FixWallGran* wall, const FixWallGranMoving* moving, const int*& list, int n) {
    list = NULL;
    if (moving) {
        list = moving->evaluated().data();
        return static_cast<int>(moving->evaluated().size());
    }
    PrimitiveWall* prim = wall->primitiveWall();
    if (!prim) return n;
    int* neigh = NULL;
    const int size = prim->getNeighbors(neigh);
    list = neigh;
    return size;
}

// a . (p - o) x F for a grain at x that the wall pushes with F, p = x + delta its contact point
// on the wall's surface
double ComputeWallGranForce::torque(const FixWallGranMoving* moving, PrimitiveWall* prim, double* x,
                                    double r, const double* F) const {
    double delta[3] = {0.0, 0.0, 0.0};
    if (moving)
        moving->resolve(x, r, delta);
    else
        prim->resolveContact(x, r, delta);
    const double r0 = x[0] + delta[0] - origin_[0];
    const double r1 = x[1] + delta[1] - origin_[1];
    const double r2 = x[2] + delta[2] - origin_[2];
    return axis_[0] * (r1 * F[2] - r2 * F[1]) + axis_[1] * (r2 * F[0] - r0 * F[2]) +
           axis_[2] * (r0 * F[1] - r1 * F[0]);
}
