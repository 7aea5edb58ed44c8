#include "full_schema.h"

#include "solver_commands.h"

namespace granlub::cli {

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
