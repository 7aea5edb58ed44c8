#include "full_schema.h"

#ifdef GRANLUB_HAVE_CONTINUUM
#include "granlub/continuum/command.h"
#endif
#ifdef GRANLUB_HAVE_AUTOMATON
#include "granlub/automaton/command.h"
#endif
#ifdef GRANLUB_HAVE_DEM
#include "granlub/dem/command.h"
#endif
#ifdef GRANLUB_HAVE_YADE
#include "granlub/yade/command.h"
#endif

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
