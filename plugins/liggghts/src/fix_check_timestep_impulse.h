// fix ID group check/timestep/gran ... with model impulse: what a step size means for rigid contacts
// (travel per step against the diameter, and against the neighbor skin) in place of LIGGGHTS'
// Rayleigh and Hertz time fractions, which need a stiffness the model does not have. The plugin
// makes this fix for `check/timestep/gran` when the pair style is model impulse, LIGGGHTS' own
// otherwise (register_fix_compute.cpp). Doc: plugins/liggghts/doc/fix_check_timestep_impulse.txt.
#ifndef GRANLUB_FIX_CHECK_TIMESTEP_IMPULSE_H
#define GRANLUB_FIX_CHECK_TIMESTEP_IMPULSE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixCheckTimestepImpulse : public Fix {
public:
    FixCheckTimestepImpulse(class LAMMPS* lmp, int narg, char** arg);
    int setmask();
    void init();
    void end_of_step();
    double compute_vector(int n);

    // a step moving grains by more than this fraction of the smallest diameter (relative to each
    // other) leaves overlaps beyond fix impulse/solve's default overlap_limit (0.05 of r_i + r_j)
    static constexpr double kTravelLimit = 0.05;

private:
    bool warn_, error_;
    double vmax_user_;
    double travel_, skin_fraction_, warned_travel_;
    bool noted_;
};

}  // namespace LAMMPS_NS

#endif
