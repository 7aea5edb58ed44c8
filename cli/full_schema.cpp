#include "full_schema.h"

#include "solver_commands.h"

namespace granlub::cli {

// Section declarations only, not the modules' run/check (modules.cpp): the case-parser fuzzer
// builds this schema from the solvers' section files alone (tests/core/fuzz).
Schema full_schema() {
    Schema s = Schema::common();
#define GRANLUB_SOLVER(module) s.add(module::section());
#include "solvers.h"
#undef GRANLUB_SOLVER
    return s;
}

}  // namespace granlub::cli
