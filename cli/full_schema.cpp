#include "full_schema.h"

#include "modules.h"

namespace granlub::cli {

// The common sections plus each compiled solver's own (one table: modules.cpp).
Schema full_schema() {
    Schema s = Schema::common();
    for (const SolverModule& m : solver_modules()) s.add(m.section());
    return s;
}

}  // namespace granlub::cli
