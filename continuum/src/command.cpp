#include "granlub/continuum/command.h"

#include "granlub/continuum/case_setup.h"

namespace granlub::continuum {

void check(const Case& c, const RunOptions& o) {
    const Settings s = resolve_settings(c);
    for_each_run(c, o, [&](const OperatingPoint& p, const RunOptions&) { problem_for(c, s, p); });
}

int run(const Case& c, const RunOptions& o) {
    const Settings s = resolve_settings(c);
    return run_sweep(c, "continuum", o, [&](const OperatingPoint& p, const std::filesystem::path& /*dir*/) {
        return solve_point(c, p, s);
    });
}

}  // namespace granlub::continuum
