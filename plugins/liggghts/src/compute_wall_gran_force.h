// compute ID group wall/gran/force wallID1 [wallID2 ...] [torque ox oy oz ax ay az]: the total force
// of each listed `fix wall/gran ... store_force yes` on the grains of the group, this step, in one
// pass; with `torque`, also its torque on them about the axis through o along a.
// Doc: plugins/liggghts/doc/compute_wall_gran_force.txt.
#ifndef GRANLUB_COMPUTE_WALL_GRAN_FORCE_H
#define GRANLUB_COMPUTE_WALL_GRAN_FORCE_H

#include <string>
#include <vector>

#include "compute.h"

namespace LAMMPS_NS {

class ComputeWallGranForce : public Compute {
public:
    ComputeWallGranForce(class LAMMPS* lmp, int& iarg, int narg, char** arg);
    ~ComputeWallGranForce();
    void init();
    void compute_vector();

private:
    class FixWallGran* find_wall(const std::string& id);
    static int candidates(class FixWallGran* wall, const class FixWallGranMoving* moving, const int*& list, int n);
    double torque(const class FixWallGranMoving* moving, class PrimitiveWall* prim, double* x, double r,
                  const double* F) const;

    std::vector<std::string> walls_;         // the wall fixes' IDs, in output order
    std::vector<class FixWallGran*> fixes_;  // found again by every init (a wall may be re-made)
    std::vector<double> local_;              // this rank's sums, per_wall_ per wall
    int per_wall_ = 3;                       // fx fy fz [torque about the axis]
    double origin_[3] = {0, 0, 0};           // the torque's axis: a point on it
    double axis_[3] = {0, 0, 0};             // and its unit direction
};

}  // namespace LAMMPS_NS

#endif
