// Adds granlub's fix styles to a LAMMPS instance. LIGGGHTS 3.8 has no plugin hook for fixes: the
// name -> creator map is Modify's private member fix_map, filled from the compiled-in
// style_fix.h when Modify is made. A pointer to that member is obtained the standard-conforming
// way (an explicit template instantiation may name a private member; C++11 [temp.explicit]/12),
// so this depends on the member's name and type only, not on the class layout.
#include <map>
#include <string>

#include "lammps.h"
#include "modify.h"

#include "fix_centripetal_annulus.h"
#include "granlub_liggghts.h"

using namespace LAMMPS_NS;

namespace {

typedef Fix* (*FixCreator)(LAMMPS*, int, char**);
typedef std::map<std::string, FixCreator>* Modify::*FixMapMember;

struct FixMapTag {
    friend FixMapMember fix_map_member(FixMapTag);
};

template <FixMapMember M>
struct FixMapAccess {
    friend FixMapMember fix_map_member(FixMapTag) { return M; }
};
template struct FixMapAccess<&Modify::fix_map>;

template <typename T>
Fix* create_fix(LAMMPS* lmp, int narg, char** arg) {
    return new T(lmp, narg, arg);
}

}  // namespace

extern "C" int granlub_liggghts_register_fixes(void* lammps) {
    LAMMPS* lmp = static_cast<LAMMPS*>(lammps);
    std::map<std::string, FixCreator>* fixes = lmp->modify->*fix_map_member(FixMapTag());
    (*fixes)["centripetal/annulus"] = &create_fix<FixCentripetalAnnulus>;
    return 1;
}
