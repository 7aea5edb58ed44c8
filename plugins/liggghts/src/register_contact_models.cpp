// Registers granlub's contact models with Debian's unmodified libliggghts.so.3 (LIGGGHTS 3.8.0):
// the names of the plugin's models (models/normal_model_*.h, models/tangential_model_*.h, through
// the headers CMakeLists.txt generates) go into ContactModels::Factory, and one pair-style and one
// wall creator per combination a normal model's header lists (its GRAN_MODEL lines) go into the
// pair and wall factories under ("gran", GranStyle<...>::HASHCODE); the other combinations with our
// models get creators that stop with a clear error (unsupported.cpp). Recipe and pitfalls:
// README.md of this plugin ("Building and using the plugin").
#include <mpi.h>

// LIGGGHTS 3.8.0 ships fix_insert_stream_predefined.h as a stub that needs this first.
#include "fix_insert_stream.h"
#include "contact_models.h"
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"

#include "granlub_liggghts.h"
#include "unsupported.h"

using namespace LAMMPS_NS;
using namespace LIGGGHTS;
using namespace LIGGGHTS::ContactModels;

// ABI guard: Debian builds LIGGGHTS without NONSPHERICAL_ACTIVE_FLAG / SUPERQUADRIC_ACTIVE_FLAG,
// which change the layout of the contact data the library fills in and hands to our models.
static_assert(sizeof(SurfacesCloseData) == 168,
              "SurfacesCloseData layout differs from Debian's libliggghts 3.8.0: build without "
              "NONSPHERICAL_ACTIVE_FLAG and SUPERQUADRIC_ACTIVE_FLAG");

namespace {

// Each creator also adds the plugin's fix and compute styles to the instance (register_fix_compute.cpp):
// with LD_PRELOAD into the stock liggghts no driver does, and `clear` remakes the style tables. So
// from the first pair_style or fix wall/gran with our models on, fix impulse/solve (which the pair
// style makes by default) and the others exist in every route.
template <typename T>
PairStyles::IGranularPairStyle* create_pair(LAMMPS* lmp, PairGran* parent, const int64_t hash) {
    granlub_liggghts_register_styles(lmp);
    return new T(lmp, parent, hash);
}

template <typename T>
Walls::IGranularWall* create_wall(LAMMPS* lmp, FixWallGran* parent, const int64_t hash) {
    granlub_liggghts_register_styles(lmp);
    return new T(lmp, parent, hash);
}

template <int M, int T, int C, int R, int S>
void add_combination() {
    typedef GranStyle<M, T, C, R, S> Style;
    typedef ContactModel<Style> Model;
    // the factory keys are int; every id is < 64, so the hash fits
    const int hash = static_cast<int>(Style::HASHCODE);
    PairStyles::Factory::instance().addStyle("gran", hash, &create_pair<PairStyles::Granular<Model> >);
    Walls::Factory::instance().addStyle("gran", hash, &create_wall<Walls::Granular<Model> >);
}

bool registered = false;

}  // namespace

extern "C" int granlub_liggghts_register(void) {
    if (registered) return 0;
    registered = true;
    Factory& models = Factory::instance();
#define NORMAL_MODEL(CLASS, NAME, ID) models.addNormalModel(#NAME, CLASS);
#include "granlub_normal_models.h"
#undef NORMAL_MODEL
#define TANGENTIAL_MODEL(CLASS, NAME, ID) models.addTangentialModel(#NAME, CLASS);
#include "granlub_tangential_models.h"
#undef TANGENTIAL_MODEL
    int n = 0;
#define GRANLUB_COMBINATIONS
#define GRAN_MODEL(M, T, C, R, S) \
    add_combination<M, T, C, R, S>(); \
    ++n;
#include "granlub_normal_models.h"
#undef GRAN_MODEL
#undef GRANLUB_COMBINATIONS
    granlub_liggghts_register_unsupported();  // clear errors for the rest (unsupported.cpp)
    return n;
}

// For LD_PRELOAD with the stock `liggghts` binary: runs after libliggghts' own initialisers.
__attribute__((constructor)) static void granlub_liggghts_autoregister() { granlub_liggghts_register(); }
