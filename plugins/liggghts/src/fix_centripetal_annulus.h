// fix ID group centripetal/annulus R: the centripetal body force of grains in an annular shear
// cell unrolled into a plane (x along the flow, z across the width, the annulus axis at z = R).
// Doc: plugins/liggghts/doc/fix_centripetal_annulus.txt.
#ifndef GRANLUB_FIX_CENTRIPETAL_ANNULUS_H
#define GRANLUB_FIX_CENTRIPETAL_ANNULUS_H

#include "fix.h"

namespace LAMMPS_NS {

class FixCentripetalAnnulus : public Fix {
public:
    FixCentripetalAnnulus(class LAMMPS* lmp, int narg, char** arg);
    int setmask();
    void init();
    void setup(int vflag);
    void min_setup(int vflag);
    void post_force(int vflag);
    void min_post_force(int vflag);

private:
    double radius_;  // R: distance of the plane z = 0 from the annulus axis
};

}  // namespace LAMMPS_NS

#endif
