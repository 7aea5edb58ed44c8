// fix ID group wall/gran/turning <fix wall/gran primitive arguments> surface_ang_vel origin ox oy oz
//     axis ax ay az omega w
// A primitive granular wall (plane or cylinder) whose surface turns about an axis, as an exact
// surface of revolution: the floor and the cylinders of an annular shear cell without STL meshes.
// Doc: plugins/liggghts/doc/fix_wall_gran_turning.txt.
#ifdef FIX_CLASS
FixStyle(wall/gran/turning,FixWallGranTurning)
#else
#ifndef GRANLUB_FIX_WALL_GRAN_TURNING_H
#define GRANLUB_FIX_WALL_GRAN_TURNING_H

#include "fix_wall_gran.h"

namespace LAMMPS_NS {

class FixWallGranTurning : public FixWallGran {
public:
    FixWallGranTurning(class LAMMPS* lmp, int narg, char** arg);

protected:
    void post_force_primitive(int vflag);

private:
    double origin_[3];  // a point on the axis
    double omega_[3];   // angular velocity: omega times the unit axis
};

}  // namespace LAMMPS_NS

#endif
#endif
