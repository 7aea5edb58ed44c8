#include "modules.h"

#include <cstdio>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/results.h"
#include "solver_commands.h"

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

void closing_table(const Case& c, const RunOptions& o) {
#ifdef GRANLUB_HAVE_POSTPROC
    fmt::print("\n{}", postproc::summary_table(c, o));
#else
    fmt::print("\n{:<10} {:<14} {:>10} {:>14} {:>14}\n", "solver", "point", "mean nu", "sigma_yy Pa", "tau_xy Pa");
    for (const auto& m : solver_modules())
        for (const auto& p : c.points) {
            const auto dir = result_dir(results_root(c, o), m.name, p.id);
            if (result_status(dir, c.inputs_hash(m.name)).state != ResultState::Complete) continue;
            const Summary s = read_summary(dir / "summary.json");
            fmt::print("{:<10} {:<14} {:>10.3f} {:>14.4g} {:>14.4g}\n", m.name, p.id, s.value("mean_solid_fraction"),
                       s.value("normal_stress_bottom"), s.value("shear_stress_bottom"));
        }
#endif
    std::fflush(stdout);
}

}  // namespace granlub::cli
