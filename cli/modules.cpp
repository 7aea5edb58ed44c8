#include "modules.h"

#include <cstdio>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/registry.h"
#include "granlub/results/results.h"
#include "solver_commands.h"

#ifdef GRANLUB_HAVE_POSTPROC
#include "granlub/postproc/command.h"
#endif

namespace granlub::cli {

// The solver table from the one list of solver modules (solvers.h); granlub/registry.h looks the
// rows up.
const std::vector<SolverModule>& solver_modules() {
    static const std::vector<SolverModule> modules = [] {
        std::vector<SolverModule> m;
#define GRANLUB_SOLVER(module) m.push_back({module::kSolver, module::kSolver.name, module::run, module::check});
#include "solvers.h"
#undef GRANLUB_SOLVER
        registry_checked(m, "solver");
        return m;
    }();
    return modules;
}

void check_input(const SolverModule& m, const Case& c, const RunOptions& o) {
    try {
        m.check(c, o);
    } catch (const CaseError&) {
        throw;
    } catch (const Error&) {
    }
}


int continuum_fit(const Case& c, const ContinuumFitArgs& a) {
#ifdef GRANLUB_HAVE_CONTINUUM
    return continuum::run_fit(c, {a.table, a.out, a.free, a.temperature});
#else
    (void)c, (void)a;
    throw Error("granlub was built without the continuum module: no continuum-fit");
#endif
}

bool have_continuum() {
#ifdef GRANLUB_HAVE_CONTINUUM
    return true;
#else
    return false;
#endif
}

int check_solvers(const Case& c, const RunOptions& o) {
    int rc = 0;
    fmt::print("\n# solver checks (every point, quick and --full run lengths)\n");
    std::fflush(stdout);  // the errors and warnings on stderr follow the lines they belong to
    for (const auto& m : solver_modules()) {
        std::vector<std::string> cannot;  // points this solver cannot run: a warning, not bad input
        std::size_t no_answer = 0;        // of which the model has no answer for (error.h, NoAnswer)
        std::string at;                   // the point whose check found bad input (a key that fails there)
        try {
            for (const OperatingPoint* p : c.select(o.point)) {
                at = p->id;
                RunOptions one = o;
                one.point = p->id;
                try {
                    m.check(c, one);
                } catch (const CaseError&) {
                    throw;
                } catch (const Error& e) {
                    const std::string why = e.what();
                    const std::string id = fmt::format("point {}: ", p->id);
                    const bool none = dynamic_cast<const NoAnswer*>(&e) != nullptr;
                    no_answer += none;
                    cannot.push_back(fmt::format("{} {}", none ? "has no answer for" : "will fail on",
                                                 why.starts_with(id) ? why : id + why));
                }
            }
        } catch (const CaseError& e) {
            fmt::print("#   {:<10} bad input, found at point {} (see the error)\n", m.name, at);
            std::fflush(stdout);
            fmt::print(stderr, "error: {}: {}\n", m.name, e.what());
            rc = 2;
            continue;
        }
        if (cannot.empty()) {
            fmt::print("#   {:<10} ok\n", m.name);
            std::fflush(stdout);
            continue;
        }
        fmt::print("#   {:<10} cannot run {} of {} point(s){} (see the warnings)\n", m.name, cannot.size(),
                   c.select(o.point).size(), no_answer ? fmt::format(", {} with no answer in its model", no_answer) : "");
        std::fflush(stdout);
        for (const auto& w : cannot) fmt::print(stderr, "warning: {} {}\n", m.name, w);
    }
    std::fflush(stdout);
    return rc;
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
