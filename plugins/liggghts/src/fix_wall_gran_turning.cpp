// A primitive wall/gran whose surface turns about an axis (fix_wall_gran_turning.h). LIGGGHTS 3.8
// turns only meshes (fix mesh/surface surface_ang_vel): a cylinder or disc made of facets, whose
// neighbour lists and edge contacts cost most of an annular cell's loop, and whose chords are not
// the cylinder. Its primitive walls do not turn: `shear` slides a plane, and on a cylinder it gives
// the wall velocity at the grain's centre, not at the contact. This wall is the primitive (the same
// contact geometry, models and stored forces as fix wall/gran) with the surface velocity
//     v_wall = omega x (p - origin),   p = x_i + delta  the contact point on the wall's surface,
// which is what a turning mesh gives at the contact (its nodes' velocities, interpolated linearly
// over a facet, are exactly omega x p there). Nothing moves: a surface of revolution turning about
// its own axis stays in place.
#include "fix_wall_gran_turning.h"

#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "contact_interface.h"
#include "error.h"
#include "fix_contact_property_atom_wall.h"
#include "fix_property_atom.h"
#include "force.h"
#include "neighbor.h"
#include "granular_wall.h"
#include "primitive_wall.h"
#include "vector_liggghts.h"

using namespace LAMMPS_NS;
using namespace LIGGGHTS::ContactModels;

namespace {

const char* const kUsage =
    "fix wall/gran/turning: expected the fix wall/gran arguments of a primitive wall followed by "
    "'surface_ang_vel origin ox oy oz axis ax ay az omega w' (the syntax of fix mesh/surface)";
const int kTurnArgs = 11;  // surface_ang_vel origin x y z axis x y z omega w

// Moves the 11 words of the surface_ang_vel keyword to the end of arg, so that fix wall/gran
// parses the rest as its own; returns the count it is to read. Runs before the base class exists.
int set_turn_aside(LAMMPS* lmp, int narg, char** arg) {
    int k = 3;
    while (k < narg && std::strcmp(arg[k], "surface_ang_vel") != 0) k++;
    if (k >= narg || narg - k < kTurnArgs) lmp->error->all(FLERR, kUsage);
    char* words[kTurnArgs];
    for (int w = 0; w < kTurnArgs; w++) words[w] = arg[k + w];
    for (int m = k + kTurnArgs; m < narg; m++) arg[m - kTurnArgs] = arg[m];
    for (int w = 0; w < kTurnArgs; w++) arg[narg - kTurnArgs + w] = words[w];
    return narg - kTurnArgs;
}

}  // namespace

FixWallGranTurning::FixWallGranTurning(LAMMPS* lmp, int narg, char** arg)
    : FixWallGran(lmp, set_turn_aside(lmp, narg, arg), arg) {
    char** t = arg + narg - kTurnArgs;  // surface_ang_vel origin x y z axis x y z omega w
    if (std::strcmp(t[1], "origin") || std::strcmp(t[5], "axis") || std::strcmp(t[9], "omega"))
        error->all(FLERR, kUsage);
    if (!primitiveWall_)
        error->all(FLERR, "fix wall/gran/turning: a primitive wall only (a mesh turns with fix mesh/surface "
                          "surface_ang_vel)");
    if (shear_) error->all(FLERR, "fix wall/gran/turning: 'shear' and 'surface_ang_vel' exclude each other");
    double axis[3];
    for (int c = 0; c < 3; c++) {
        origin_[c] = force->numeric(FLERR, t[2 + c]);
        axis[c] = force->numeric(FLERR, t[6 + c]);
    }
    const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (!(norm > 0)) error->all(FLERR, "fix wall/gran/turning: the axis must not be the zero vector");
    const double w = force->numeric(FLERR, t[10]);
    for (int c = 0; c < 3; c++) omega_[c] = w * axis[c] / norm;
}

// fix wall/gran's loop over the wall's neighbours for spheres (FixWallGran::post_force_primitive,
// LIGGGHTS 3.8.0, without its superquadric branch, which Debian's build does not compile), with
// the wall velocity taken at each contact point.
void FixWallGranTurning::post_force_primitive(int) {
    const int* mask = atom->mask;
    const double* radius = atom->radius;
    const double contactDistanceMultiplier = neighbor->contactDistanceFactor - 1.0;
    double** c_history = dnum() > 0 ? fix_history_primitive_->array_atom : NULL;
    SurfacesIntersectData sidata;
    sidata.is_wall = true;

    int* neighborList;
    const int nNeigh = primitiveWall_->getNeighbors(neighborList);
    for (int iCont = 0; iCont < nNeigh; iCont++, neighborList++) {
        const int iPart = *neighborList;
        if (!(mask[iPart] & groupbit)) continue;

        sidata.radi = radius_ ? radius_[iPart] : r0_;
        if (fix_store_multicontact_data_) {
            double* deltaData = NULL;
            if (fix_store_multicontact_data_->haveContact(iPart, 1, deltaData)) sidata.radi += deltaData[3];
        }
        double delta[3] = {0.0, 0.0, 0.0};  // from the grain's centre to the wall's surface
        const double deltan = primitiveWall_->resolveContact(x_[iPart], sidata.radi, delta);
        if (deltan > cutneighmax_) continue;

        if (deltan <= 0 || deltan < contactDistanceMultiplier * radius[iPart]) {
            const bool intersectflag = (deltan <= 0);
            // the surface's velocity at the contact point p = x + delta: omega x (p - origin)
            const double p0 = x_[iPart][0] + delta[0] - origin_[0];
            const double p1 = x_[iPart][1] + delta[1] - origin_[1];
            const double p2 = x_[iPart][2] + delta[2] - origin_[2];
            double v_wall[3] = {omega_[1] * p2 - omega_[2] * p1, omega_[2] * p0 - omega_[0] * p2,
                                omega_[0] * p1 - omega_[1] * p0};
            sidata.i = iPart;
            sidata.contact_history = c_history ? c_history[iPart] : NULL;
            if (atom->shapetype_flag && !impl->checkSurfaceIntersect(sidata)) {
                if (c_history) vectorZeroizeN(c_history[iPart], dnum_);
                break;  // as fix wall/gran
            }
            sidata.deltan = -deltan;
            sidata.delta[0] = -delta[0];
            sidata.delta[1] = -delta[1];
            sidata.delta[2] = -delta[2];
            impl->compute_force(this, sidata, intersectflag, v_wall);
        } else if (c_history) {
            vectorZeroizeN(c_history[iPart], dnum_);
        }
    }
}
