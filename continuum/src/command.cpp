#include "granlub/continuum/command.h"

#include "granlub/continuum/case_setup.h"

namespace granlub::continuum {

int run(const Case& c, const RunOptions& o) {
    const Settings s = settings_from_case(c);
    return run_sweep(c, "continuum", o, [&](const OperatingPoint& p, const std::filesystem::path& /*dir*/) {
        return solve_point(c, s, p);
    });
}

}  // namespace granlub::continuum
