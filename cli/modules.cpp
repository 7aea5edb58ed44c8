#include "modules.h"

#include "granlub/error.h"

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
#ifdef GRANLUB_HAVE_POSTPROC
#include "granlub/postproc/command.h"
#endif

namespace granlub::cli {

const std::vector<SolverModule>& solver_modules() {
    static const std::vector<SolverModule> modules = [] {
        std::vector<SolverModule> m;
#ifdef GRANLUB_HAVE_CONTINUUM
        m.push_back({"continuum", "granular kinetic lubrication (GKL) continuum solver", continuum::run});
#endif
#ifdef GRANLUB_HAVE_AUTOMATON
        m.push_back({"automaton", "lattice cellular automaton (Jasti & Higgs 2006)", automaton::run});
#endif
#ifdef GRANLUB_HAVE_DEM
        m.push_back({"dem", "particle simulation in LIGGGHTS with granlub's contact models", dem::run});
#endif
#ifdef GRANLUB_HAVE_YADE
        m.push_back({"yade", "particle simulation in YADE (cross-check)", yade::run});
#endif
        return m;
    }();
    return modules;
}

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

bool have_compare() {
#ifdef GRANLUB_HAVE_POSTPROC
    return true;
#else
    return false;
#endif
}

int compare([[maybe_unused]] const Case& c, [[maybe_unused]] const RunOptions& o) {
#ifdef GRANLUB_HAVE_POSTPROC
    return postproc::compare(c, o);
#else
    throw Error("this granlub was built without postproc: `granlub compare` is not available");
#endif
}

}  // namespace granlub::cli
