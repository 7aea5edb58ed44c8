// A primitive wall/gran whose surface moves (fix_wall_gran_moving.h).
//
// Turning (surface_ang_vel): LIGGGHTS 3.8 turns only meshes (fix mesh/surface surface_ang_vel): a
// cylinder or disc made of facets, whose neighbour lists and edge contacts cost most of an annular
// cell's loop, and whose chords are not the cylinder. Its primitive walls do not turn: `shear`
// slides a plane, and on a cylinder it gives the wall velocity at the grain's centre, not at the
// contact. Here the surface velocity is
//     v_wall = omega x (p - origin),   p = x_i + delta  the contact point on the wall's surface,
// which is what a turning mesh gives at the contact (its nodes' velocities, interpolated linearly
// over a facet, are exactly omega x p there). A surface of revolution turning about its own axis
// stays in place.
//
// Moving along its normal (normal_velocity, planes): LIGGGHTS moves only meshes (fix move/mesh);
// a primitive plane can only be unfixed and made again elsewhere, and a servo's plate that jumps
// so leaves momentum out of the walls' recorded forces (plugin README, "The whole ring"). Here the
// plane advances by v dt every step, v the variable's value that step, as fix move/mesh moves a
// mesh at the start of the step, and v is its surface velocity along the normal. Contacts are
// found over all owned grains (one subtraction each): the primitive's neighbour list is built
// for where the plane was.
//
// Under a load (normal_load F M lo hi, planes): a weighted plate, the experiment's loaded upper
// disc (Sawyer & Tichy 2001). The plate is a rigid body of mass M moving along the normal only:
//     M dv/dt = F + F_grains,
// F_grains the grains' force on it (minus the wall's force on them, store_force, summed over all
// ranks at the end of each step, after every contact pass and fix impulse/solve). Semi-implicit
// Euler: the velocity takes the step's force at its end, the plane moves by the new velocity in the
// next step's contact pass (advance()). Within a step the plate is a wall of infinite mass for the contacts (the
// impulse models' walls are): the plate takes the momentum the grains took from it one step later,
// so momentum is conserved and the time-averaged F_grains equals -F in a steady state, with no
// controller in between (a servo window's clamps biased that average: docs/measurements/liggghts.md).
// With `carry G` the atoms of group G (a rough top's bumps, moved at the plate's velocity by fix
// move variable ... v_vplate, vplate = f_ID[2]) are part of the plate: the forces on them count.
// [ASSUMPTION] ours: this explicit coupling; it needs M well above a grain's mass, which the deck's
// M (a multiple of all the grains') is by far. At lo or hi the plate stops.
#include "fix_wall_gran_moving.h"

#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "contact_interface.h"
#include "error.h"
#include "fix_contact_property_atom_wall.h"
#include "fix_property_atom.h"
#include "force.h"
#include "group.h"
#include "granular_wall.h"
#include "input.h"
#include "mpi.h"
#include "neighbor.h"
#include "primitive_wall.h"
#include "update.h"
#include "variable.h"
#include "vector_liggghts.h"

using namespace LAMMPS_NS;
using namespace LIGGGHTS::ContactModels;

namespace {

const char* const kUsage =
    "fix wall/gran/moving: expected the fix wall/gran arguments of a primitive wall followed by "
    "'surface_ang_vel origin ox oy oz axis ax ay az omega w' (the syntax of fix mesh/surface), "
    "'normal_velocity v_name' (a plane; an equal-style variable) or 'normal_load F M lo hi' (a plane: a plate of "
    "mass M under the force F along the axis, travelling in [lo, hi]; 'carry group-ID' adds the force on that "
    "group's atoms, moved with the plate by fix move), or a turning and a moving plane both";
const int kTurnWords = 11;    // surface_ang_vel origin x y z axis x y z omega w
const int kNormalWords = 2;   // normal_velocity v_name
const int kLoadWords = 5;     // normal_load F M lo hi
const int kCarryWords = 2;    // carry group-ID

// Moves the words of this fix's own keywords to the end of arg, in the order met, so that fix
// wall/gran parses the rest as its own; returns the count it is to read. Runs before the base
// class exists.
int set_keywords_aside(LAMMPS* lmp, int narg, char** arg) {
    int kept = 3, aside = 0;
    char* tail[kTurnWords + kNormalWords + kLoadWords + kCarryWords];
    for (int k = 3; k < narg;) {
        const int words = std::strcmp(arg[k], "surface_ang_vel") == 0   ? kTurnWords
                          : std::strcmp(arg[k], "normal_velocity") == 0 ? kNormalWords
                          : std::strcmp(arg[k], "normal_load") == 0     ? kLoadWords
                          : std::strcmp(arg[k], "carry") == 0           ? kCarryWords
                                                                        : 0;
        if (words == 0) {
            arg[kept++] = arg[k++];
            continue;
        }
        if (narg - k < words || aside + words > kTurnWords + kNormalWords + kLoadWords + kCarryWords)
            lmp->error->all(FLERR, kUsage);
        for (int w = 0; w < words; w++) tail[aside++] = arg[k++];
    }
    if (aside == 0) lmp->error->all(FLERR, kUsage);
    for (int w = 0; w < aside; w++) arg[kept + w] = tail[w];
    return kept;
}

}  // namespace

FixWallGranMoving::FixWallGranMoving(LAMMPS* lmp, int narg, char** arg)
    : FixWallGran(lmp, set_keywords_aside(lmp, narg, arg), arg) {
    if (!primitiveWall_)
        error->all(FLERR, "fix wall/gran/moving: a primitive wall only (a mesh moves with fix mesh/surface "
                          "surface_ang_vel or fix move/mesh)");
    if (shear_) error->all(FLERR, "fix wall/gran/moving: 'shear' and this fix's motions exclude each other");
    int k = narg_;  // the words set aside follow fix wall/gran's own
    while (k < narg) {
        char** t = arg + k;
        if (std::strcmp(t[0], "surface_ang_vel") == 0) {
            if (turning_ || std::strcmp(t[1], "origin") || std::strcmp(t[5], "axis") || std::strcmp(t[9], "omega"))
                error->all(FLERR, kUsage);
            double axis[3];
            for (int c = 0; c < 3; c++) {
                origin_[c] = force->numeric(FLERR, t[2 + c]);
                axis[c] = force->numeric(FLERR, t[6 + c]);
            }
            const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
            if (!(norm > 0)) error->all(FLERR, "fix wall/gran/moving: the axis must not be the zero vector");
            const double w = force->numeric(FLERR, t[10]);
            for (int c = 0; c < 3; c++) omega_[c] = w * axis[c] / norm;
            turning_ = true;
            k += kTurnWords;
        } else if (std::strcmp(t[0], "normal_load") == 0) {
            if (loaded_ || !variable_.empty())
                error->all(FLERR, "fix wall/gran/moving: a plane moves by one normal_velocity or one normal_load");
            load_ = force->numeric(FLERR, t[1]);
            mass_ = force->numeric(FLERR, t[2]);
            lowest_ = force->numeric(FLERR, t[3]);
            highest_ = force->numeric(FLERR, t[4]);
            if (!(mass_ > 0) || !(lowest_ < highest_))
                error->all(FLERR, "fix wall/gran/moving: normal_load F M lo hi needs M > 0 and lo < hi");
            loaded_ = true;
            k += kLoadWords;
        } else if (std::strcmp(t[0], "carry") == 0) {
            const int g = group->find(t[1]);
            if (g < 0 || carrybit_) error->all(FLERR, "fix wall/gran/moving: carry takes one existing group-ID");
            carrybit_ = group->bitmask[g];
            k += kCarryWords;
        } else {
            if (!variable_.empty() || loaded_ || std::strncmp(t[1], "v_", 2) != 0 || !t[1][2])
                error->all(FLERR, "fix wall/gran/moving: normal_velocity takes one equal-style variable, v_name, "
                                  "and excludes normal_load");
            variable_ = t[1] + 2;
            k += kNormalWords;
        }
    }
    if (carrybit_ && !loaded_) error->all(FLERR, "fix wall/gran/moving: carry belongs to normal_load");
    if (!variable_.empty() || loaded_) {  // the plane: primitive type T xplane|yplane|zplane position
        int p = 3;
        while (p < narg_ && std::strcmp(arg[p], "primitive") != 0) p++;
        const char* style = p + 4 < narg_ ? arg[p + 3] : "";
        plane_axis_ = !std::strcmp(style, "xplane") ? 0 : !std::strcmp(style, "yplane") ? 1 : !std::strcmp(style, "zplane") ? 2 : -1;
        if (plane_axis_ < 0)
            error->all(FLERR, "fix wall/gran/moving: normal_velocity and normal_load move a plane (xplane, yplane, "
                              "zplane) only");
        position_ = force->numeric(FLERR, arg[p + 4]);
        if (loaded_ && !store_force())
            error->all(FLERR, "fix wall/gran/moving: normal_load needs store_force yes (the grains' force on the plate)");
        if (loaded_ && (position_ < lowest_ || position_ > highest_))
            error->all(FLERR, "fix wall/gran/moving: normal_load: the plane starts outside [lo, hi]");
        vector_flag = 1;
        size_vector = 2;
        global_freq = 1;
        extvector = 0;
    }
}

int FixWallGranMoving::setmask() { return FixWallGran::setmask() | (loaded_ ? FixConst::END_OF_STEP : 0); }

void FixWallGranMoving::init() {
    FixWallGran::init();
    if (loaded_ && !fix_wallforce())
        error->all(FLERR, "fix wall/gran/moving: normal_load needs store_force yes (the grains' force on the plate)");
    if (variable_.empty()) return;
    ivariable_ = input->variable->find(const_cast<char*>(variable_.c_str()));
    if (ivariable_ < 0 || !input->variable->equalstyle(ivariable_)) {
        const std::string msg = "fix wall/gran/moving: normal_velocity needs an equal-style variable " + variable_;
        error->all(FLERR, msg.c_str());
    }
}

// A run's setup computes forces with the plane where and as fast as the last step left it (at
// rest before the first step), as fix move/mesh leaves a mesh: it sets the velocity when it moves.
void FixWallGranMoving::advance() {
    if (update->setupflag || moved_at_ == update->ntimestep) return;  // a setup's forces, or moved already
    if (!loaded_) velocity_ = input->variable->compute_equal(ivariable_);
    position_ += velocity_ * update->dt;
    moved_at_ = update->ntimestep;
}

void FixWallGranMoving::end_of_step() {
    if (!loaded_) return;
    double** f = fix_wallforce()->array_atom;  // the wall's force on each grain this step
    const int* mask = atom->mask;
    double mine = 0.0, all = 0.0;
    double** fa = atom->f;  // the force on each atom this step: on a carried atom, the grains'
    if (!carrybit_) {
        // only the grains the force pass evaluated can push the plate; the others' stored force is
        // 0 and leaves the sum's bits as they are (x - 0.0 == x), so the index order is all that counts
        for (const int i : evaluated_) mine -= f[i][plane_axis_];
    } else {
        for (int i = 0; i < atom->nlocal; i++) {
            if (mask[i] & groupbit) mine -= f[i][plane_axis_];
            if (mask[i] & carrybit_) mine += fa[i][plane_axis_];
        }
    }
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
    const double dt = update->dt;
    velocity_ += (load_ + all) * dt / mass_;
    // at a stop the plate halts there (the carried atoms move by the same velocity: fix move)
    const double next = position_ + velocity_ * dt;
    if (next < lowest_) velocity_ = (lowest_ - position_) / dt;
    if (next > highest_) velocity_ = (highest_ - position_) / dt;
}

double FixWallGranMoving::compute_vector(int n) { return n == 0 ? position_ : velocity_; }

double FixWallGranMoving::resolve(const double* x, double r, double* delta) const {
    if (plane_axis_ < 0) return primitiveWall_->resolveContact(const_cast<double*>(x), r, delta);
    // PRIMITIVE_WALL_DEFINITIONS::Plane::resolveContact at the plane's current position
    delta[0] = delta[1] = delta[2] = 0.0;
    delta[plane_axis_] = position_ - x[plane_axis_];
    return std::fabs(delta[plane_axis_]) - r;
}

// fix wall/gran's loop over the wall's neighbours for spheres (FixWallGran::post_force_primitive,
// LIGGGHTS 3.8.0, without its superquadric branch, which Debian's build does not compile), with
// the wall velocity taken at each contact point; a moving plane loops over every owned grain.
void FixWallGranMoving::post_force_primitive(int) {
    const int* mask = atom->mask;
    const double* radius = atom->radius;
    const double contactDistanceMultiplier = neighbor->contactDistanceFactor - 1.0;
    double** c_history = dnum() > 0 ? fix_history_primitive_->array_atom : NULL;
    SurfacesIntersectData sidata;
    sidata.is_wall = true;
    if (plane_axis_ >= 0) advance();

    int* neighborList = NULL;
    const int nNeigh = plane_axis_ >= 0 ? atom->nlocal : primitiveWall_->getNeighbors(neighborList);
    evaluated_.clear();
    for (int iCont = 0; iCont < nNeigh; iCont++) {
        const int iPart = neighborList ? neighborList[iCont] : iCont;
        if (!(mask[iPart] & groupbit)) continue;

        sidata.radi = radius_ ? radius_[iPart] : r0_;
        if (fix_store_multicontact_data_) {
            double* deltaData = NULL;
            if (fix_store_multicontact_data_->haveContact(iPart, 1, deltaData)) sidata.radi += deltaData[3];
        }
        double delta[3];  // from the grain's centre to the wall's surface
        const double deltan = resolve(x_[iPart], sidata.radi, delta);
        if (deltan > cutneighmax_) continue;

        if (deltan <= 0 || deltan < contactDistanceMultiplier * radius[iPart]) {
            const bool intersectflag = (deltan <= 0);
            // the surface's velocity at the contact point p = x + delta: omega x (p - origin),
            // plus a moving plane's velocity along its normal
            const double p0 = x_[iPart][0] + delta[0] - origin_[0];
            const double p1 = x_[iPart][1] + delta[1] - origin_[1];
            const double p2 = x_[iPart][2] + delta[2] - origin_[2];
            double v_wall[3] = {omega_[1] * p2 - omega_[2] * p1, omega_[2] * p0 - omega_[0] * p2,
                                omega_[0] * p1 - omega_[1] * p0};
            if (plane_axis_ >= 0) v_wall[plane_axis_] += velocity_;
            sidata.i = iPart;
            sidata.contact_history = c_history ? c_history[iPart] : NULL;
            if (atom->shapetype_flag && !impl->checkSurfaceIntersect(sidata)) {
                if (c_history) vectorZeroizeN(c_history[iPart], dnum_);
                break;  // as fix wall/gran
            }
            evaluated_.push_back(iPart);
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
