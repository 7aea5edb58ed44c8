#include "full_schema.h"

#include "solver_commands.h"

namespace granlub::cli {

// Section declarations only, not the modules' run/check (modules.cpp): the case-parser fuzzer
// builds this schema from the solvers' section files alone (tests/core/fuzz).
Schema full_schema() {
    Schema s = Schema::common();
#ifdef GRANLUB_HAVE_CONTINUUM
    s.add(continuum::section());
#endif
#ifdef GRANLUB_HAVE_AUTOMATON
    s.add(automaton::section());
#endif
#ifdef GRANLUB_HAVE_DEM
    s.add(dem::section());
#endif
#ifdef GRANLUB_HAVE_YADE
    s.add(yade::section());
#endif
    return s;
}

}  // namespace granlub::cli
