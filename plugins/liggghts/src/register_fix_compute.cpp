// Adds granlub's fix and compute styles to a LAMMPS instance. LIGGGHTS 3.8 has no plugin hook for
// them: the name -> creator maps are Modify's private members fix_map and compute_map, filled from
// the compiled-in style_fix.h / style_compute.h when Modify is made. A pointer to each member is
// obtained the standard-conforming way (an explicit template instantiation may name a private
// member; C++11 [temp.explicit]/12), so this depends on the members' names and types only, not on
// the class layout.
#include <cstdio>
#include <map>
#include <string>

#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "pair_gran_proxy.h"

#include "compute_wall_gran_force.h"
#include "fix_check_timestep_impulse.h"
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

// LIGGGHTS' own check/timestep/gran (its creator, kept when the plugin takes the name over)
FixCreator liggghts_check_timestep = NULL;

// check/timestep/gran: the impulse model's check when the pair style is model impulse, LIGGGHTS' otherwise
Fix* create_check_timestep(LAMMPS* lmp, int narg, char** arg) {
    PairGranProxy* pair = dynamic_cast<PairGranProxy*>(lmp->force->pair);
    if (pair && pair->contact_match("normal", "impulse")) return new FixCheckTimestepImpulse(lmp, narg, arg);
    return liggghts_check_timestep(lmp, narg, arg);
}

// The plugin's styles, for the maps and for `-h` (one list).
struct FixStyleEntry {
    const char* name;
    FixCreator create;
    const char* what;
};
const FixStyleEntry kFixes[] = {
    {"centripetal/annulus", &create_fix<FixCentripetalAnnulus>, "body force of a turning annulus (doc/fix_centripetal_annulus.txt)"},
    {"impulse/solve", &create_fix<FixImpulseSolve>, "the impulse contacts solved to convergence (doc/fix_impulse_solve.txt)"},
    {"wall/gran/moving", &create_fix<FixWallGranMoving>, "exact moving primitive walls (doc/fix_wall_gran_moving.txt)"},
};

}  // namespace

extern "C" int granlub_liggghts_register_styles(void* lammps) {
    LAMMPS* lmp = static_cast<LAMMPS*>(lammps);
    std::map<std::string, FixCreator>* fixes = lmp->modify->*fix_map_member(FixMapTag());
    std::map<std::string, ComputeCreator>* computes = lmp->modify->*compute_map_member(ComputeMapTag());
    int n = 0;
    for (const FixStyleEntry& f : kFixes) {
        (*fixes)[f.name] = f.create;
        ++n;
    }
    FixCreator& check = (*fixes)["check/timestep/gran"];
    if (check && check != &create_check_timestep) {
        liggghts_check_timestep = check;
        check = &create_check_timestep;
        ++n;
    }
    (*computes)["wall/gran/force"] = &create_compute<ComputeWallGranForce>;
    return n + 1;
}

extern "C" void granlub_liggghts_print_styles(void* file) {
    FILE* out = static_cast<FILE*>(file);
    std::fprintf(out, "granlub plugin (libliggghts_granlub.so), in addition to LIGGGHTS' styles listed below:\n"
                      "* contact models (pair_style gran, fix wall/gran): %s\n* fix styles:\n",
                 granlub_liggghts_combinations());
    for (const FixStyleEntry& f : kFixes) std::fprintf(out, "    %-20s %s\n", f.name, f.what);
    std::fprintf(out, "    %-20s with model impulse: travel per step against the diameter and the skin "
                      "(doc/fix_check_timestep_impulse.txt)\n"
                      "* compute styles:\n    %-20s forces and torques of fix wall/gran walls "
                      "(doc/compute_wall_gran_force.txt)\n\n",
                 "check/timestep/gran", "wall/gran/force");
}
