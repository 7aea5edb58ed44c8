// Adds granlub's fix and compute styles to a LAMMPS instance. LIGGGHTS 3.8 has no plugin hook for
// them: the name -> creator maps are Modify's private members fix_map and compute_map, filled from
// the compiled-in style_fix.h / style_compute.h when Modify is made. A pointer to each member is
// obtained the standard-conforming way (an explicit template instantiation may name a private
// member; C++11 [temp.explicit]/12), so this depends on the members' names and types only, not on
// the class layout.
#include <map>
#include <string>

#include "lammps.h"
#include "modify.h"

#include "compute_wall_gran_force.h"
#include "fix_centripetal_annulus.h"
#include "fix_impulse_solve.h"
#include "fix_wall_gran_moving.h"
#include "granlub_liggghts.h"

using namespace LAMMPS_NS;

namespace {

typedef Fix* (*FixCreator)(LAMMPS*, int, char**);
typedef Compute* (*ComputeCreator)(LAMMPS*, int, int, char**);  // Modify's own is private
typedef std::map<std::string, FixCreator>* Modify::*FixMapMember;
typedef std::map<std::string, ComputeCreator>* Modify::*ComputeMapMember;

struct FixMapTag {
    friend FixMapMember fix_map_member(FixMapTag);
};
struct ComputeMapTag {
    friend ComputeMapMember compute_map_member(ComputeMapTag);
};

template <FixMapMember M>
struct FixMapAccess {
    friend FixMapMember fix_map_member(FixMapTag) { return M; }
};
template struct FixMapAccess<&Modify::fix_map>;

template <ComputeMapMember M>
struct ComputeMapAccess {
    friend ComputeMapMember compute_map_member(ComputeMapTag) { return M; }
};
template struct ComputeMapAccess<&Modify::compute_map>;

template <typename T>
Fix* create_fix(LAMMPS* lmp, int narg, char** arg) {
    return new T(lmp, narg, arg);
}

template <typename T>
Compute* create_compute(LAMMPS* lmp, int iarg, int narg, char** arg) {
    return new T(lmp, iarg, narg, arg);
}

}  // namespace

extern "C" int granlub_liggghts_register_styles(void* lammps) {
    LAMMPS* lmp = static_cast<LAMMPS*>(lammps);
    std::map<std::string, FixCreator>* fixes = lmp->modify->*fix_map_member(FixMapTag());
    std::map<std::string, ComputeCreator>* computes = lmp->modify->*compute_map_member(ComputeMapTag());
    (*fixes)["centripetal/annulus"] = &create_fix<FixCentripetalAnnulus>;
    (*fixes)["impulse/solve"] = &create_fix<FixImpulseSolve>;
    (*fixes)["wall/gran/moving"] = &create_fix<FixWallGranMoving>;
    (*computes)["wall/gran/force"] = &create_compute<ComputeWallGranForce>;
    return 4;
}
