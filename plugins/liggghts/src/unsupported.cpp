// Clear errors for the combinations with one of the plugin's models (`model impulse`, `tangential
// impulse`) that the plugin does not register (e.g. `model impulse tangential history`, `...
// rolling_friction cdt`, `... cohesion sjkr`, `model hertz tangential impulse`).
//
// Why here, in the factories: pair gran and fix wall/gran both look the selected combination up in
// PairStyles::Factory / Walls::Factory; an unregistered one falls back to the generic contact model
// compiled into Debian's libliggghts.so.3, which does not know our ids and stops with "Unknown normal
// model" before any of our code runs (so a check in the model's constructor or connectToProperties
// is never reached). A check in the driver before LIGGGHTS parses would miss LD_PRELOAD with the stock
// binary, variables and included files. So every such combination of the known model names gets a
// creator of its own that stops with a message naming the real problem.
#include <mpi.h>

#include <set>
#include <string>

// LIGGGHTS 3.8.0 ships fix_insert_stream_predefined.h as a stub that needs this first.
#include "fix_insert_stream.h"
#include "contact_models.h"
#include "error.h"
#include "fix_wall_gran_base.h"
#include "pair_gran_base.h"

#include "granlub_liggghts.h"
#include "unsupported.h"

using namespace LAMMPS_NS;
using namespace LIGGGHTS;
using namespace LIGGGHTS::ContactModels;

namespace {

struct Named {
    int id;
    const char* name;
};

// id -> name of every model LIGGGHTS' style headers (installed ones plus ours) declare
const Named kNormal[] = {{NORMAL_OFF, "off"},
#define NORMAL_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "style_normal_model.h"
#undef NORMAL_MODEL
};
const Named kTangential[] = {{TANGENTIAL_OFF, "off"},
#define TANGENTIAL_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "style_tangential_model.h"
#undef TANGENTIAL_MODEL
};
const Named kCohesion[] = {{COHESION_OFF, "off"},
#define COHESION_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "style_cohesion_model.h"
#undef COHESION_MODEL
};
const Named kRolling[] = {{ROLLING_OFF, "off"},
#define ROLLING_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "style_rolling_model.h"
#undef ROLLING_MODEL
};
const Named kSurface[] = {
#define SURFACE_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "style_surface_model.h"
#undef SURFACE_MODEL
};
// the plugin's own (models/, through the headers CMakeLists.txt generates)
const Named kOurNormal[] = {
#define NORMAL_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "granlub_normal_models.h"
#undef NORMAL_MODEL
};
const Named kOurTangential[] = {
#define TANGENTIAL_MODEL(CLASS, NAME, ID) {ID, #NAME},
#include "granlub_tangential_models.h"
#undef TANGENTIAL_MODEL
};

template <size_t N>
bool listed(const Named (&table)[N], int id) {
    for (size_t k = 0; k < N; ++k)
        if (table[k].id == id) return true;
    return false;
}

template <size_t N>
std::string name_of(const Named (&table)[N], int id) {
    for (size_t k = 0; k < N; ++k)
        if (table[k].id == id) return table[k].name;
    return "#" + std::to_string(id);
}

int field(int64_t hash, int shift) { return static_cast<int>((hash >> shift) & 63); }

// The keywords of a combination as a user writes them, defaults (off, surface default) left out.
std::string keywords(int64_t hash) {
    std::string s = "model " + name_of(kNormal, field(hash, 0));
    if (field(hash, 6) != TANGENTIAL_OFF) s += " tangential " + name_of(kTangential, field(hash, 6));
    if (field(hash, 12) != COHESION_OFF) s += " cohesion " + name_of(kCohesion, field(hash, 12));
    if (field(hash, 18) != ROLLING_OFF) s += " rolling_friction " + name_of(kRolling, field(hash, 18));
    if (field(hash, 24) != SURFACE_DEFAULT) s += " surface " + name_of(kSurface, field(hash, 24));
    return s;
}

// the hashes of the registered combinations (the GRAN_MODEL lines of the normal models' headers)
std::set<int64_t> supported() {
    std::set<int64_t> s;
#define GRANLUB_COMBINATIONS
#define GRAN_MODEL(M, T, C, R, S) s.insert(Utils::generate_gran_hashcode(M, T, C, R, S));
#include "granlub_normal_models.h"
#undef GRAN_MODEL
#undef GRANLUB_COMBINATIONS
    return s;
}

std::string allowed_keywords() {
    std::string allowed;
    for (int64_t h : supported()) allowed += (allowed.empty() ? "'" : ", '") + keywords(h) + "'";
    return allowed;
}

[[noreturn]] void reject(LAMMPS* lmp, int64_t hash) {
    const std::string allowed = allowed_keywords();
    const std::string what = listed(kOurNormal, field(hash, 0)) ? "model " + name_of(kNormal, field(hash, 0))
                                                                : "tangential " + name_of(kTangential, field(hash, 6));
    const std::string msg = what + " combines only as " + allowed + " (granlub plugin: no other tangential, " +
                            "cohesion, rolling_friction or surface model); got '" + keywords(hash) + "'";
    lmp->error->all(FLERR, msg.c_str());
    MPI_Abort(MPI_COMM_WORLD, 1);  // error->all does not return; for the compiler
    __builtin_unreachable();
}

PairStyles::IGranularPairStyle* reject_pair(LAMMPS* lmp, PairGran*, const int64_t hash) { reject(lmp, hash); }
Walls::IGranularWall* reject_wall(LAMMPS* lmp, FixWallGran*, const int64_t hash) { reject(lmp, hash); }

}  // namespace

extern "C" const char* granlub_liggghts_combinations(void) {
    static const std::string text = allowed_keywords();
    return text.c_str();
}

int granlub_liggghts_register_unsupported() {
    const std::set<int64_t> ok = supported();
    int n = 0;
    for (const Named& nm : kNormal)
        for (const Named& t : kTangential) {
            if (!listed(kOurNormal, nm.id) && !listed(kOurTangential, t.id)) continue;
            for (const Named& c : kCohesion)
                for (const Named& r : kRolling)
                    for (const Named& s : kSurface) {
                        const int64_t hash = Utils::generate_gran_hashcode(nm.id, t.id, c.id, r.id, s.id);
                        if (ok.count(hash)) continue;
                        // the factory keys are int; every id is < 64, so the hash fits
                        PairStyles::Factory::instance().addStyle("gran", static_cast<int>(hash), &reject_pair);
                        Walls::Factory::instance().addStyle("gran", static_cast<int>(hash), &reject_wall);
                        ++n;
                    }
        }
    return n;
}
