#include "granlub/continuum/command.h"

#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/cross_section_setup.h"

namespace granlub::continuum {

void check(const Case& c, const RunOptions& o) {
    const Settings s = resolve_settings(c);
    for_each_run(c, o, [&](const OperatingPoint& p, const RunOptions&) {
        if (s.cross_section) cross_section_problem_for(c, s, p);
        else problem_for(c, s, p);
    });
}

int run(const Case& c, const RunOptions& o) {
    const Settings s = resolve_settings(c);
    return run_sweep(c, kSolver.name, o, [&](const OperatingPoint& p, const std::filesystem::path& dir) {
        return s.cross_section ? solve_cross_section_point(c, p, s, dir) : solve_point(c, p, s);
    });
}

}  // namespace granlub::continuum
