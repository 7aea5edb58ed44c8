// fix ID group wall/gran/moving <fix wall/gran primitive arguments> [surface_ang_vel origin ox oy oz
//     axis ax ay az omega w] [normal_velocity v_name]
//     [normal_load F M lo hi [carry group-ID]]
// A primitive granular wall whose surface moves: a plane or cylinder turning in place about an axis
// (the floor and the cylinders of an annular shear cell without STL meshes), and a plane moving
// along its normal at a velocity an equal-style variable gives (a servo-driven plate) or as a rigid
// plate of mass M under a constant force F and the grains' forces (a weighted plate).
// Doc: plugins/liggghts/doc/fix_wall_gran_moving.txt.
#ifdef FIX_CLASS
FixStyle(wall/gran/moving,FixWallGranMoving)
#else
#ifndef GRANLUB_FIX_WALL_GRAN_MOVING_H
#define GRANLUB_FIX_WALL_GRAN_MOVING_H

#include <string>
#include <vector>

#include "fix_wall_gran.h"

namespace LAMMPS_NS {

class FixWallGranMoving : public FixWallGran {
public:
    FixWallGranMoving(class LAMMPS* lmp, int narg, char** arg);
    int setmask();
    void init();
    // A moving plane: the grains' force on it along the normal, summed at the step's end
    // (normal_load), and its Newton step: v += (F + that force) dt / M.
    void end_of_step();
    // A moving plane: [1] its position along its axis, [2] its velocity.
    double compute_vector(int n);
    // The contact of a sphere (centre x, radius r) with the wall where it is now: returns the gap
    // (< 0: overlap), delta from the centre to the contact point on the surface.
    double resolve(const double* x, double r, double* delta) const;
    // The owned grains whose contact with this wall its last force pass evaluated, in index order:
    // every grain whose stored force can be nonzero is among them (the sums need not visit the rest).
    const std::vector<int>& evaluated() const { return evaluated_; }

protected:
    void post_force_primitive(int vflag);

private:
    void advance();  // a moving plane: one step along its normal at the variable's velocity

    bool turning_ = false;
    double origin_[3] = {0, 0, 0};  // a point on the axis
    double omega_[3] = {0, 0, 0};   // angular velocity: omega times the unit axis
    int plane_axis_ = -1;           // a moving plane: its normal's axis (0, 1, 2), else -1
    double position_ = 0.0;         // and where it is on that axis now
    double velocity_ = 0.0;         // and its velocity along it this step
    std::string variable_;          // the equal-style variable giving that velocity
    int ivariable_ = -1;
    bool loaded_ = false;           // normal_load: the plane moves by its own Newton's law
    double load_ = 0.0;             // F: the force on the plate along the axis besides the grains'
    double mass_ = 0.0;             // M
    double lowest_ = 0.0, highest_ = 0.0;  // its travel along the axis
    int carrybit_ = 0;              // carry: the group whose atoms ride the plate
    bigint moved_at_ = -1;          // the step the plane was last advanced in
    std::vector<int> evaluated_;    // see evaluated(); refilled by every force pass (keeps its capacity)
};

}  // namespace LAMMPS_NS

#endif
#endif
