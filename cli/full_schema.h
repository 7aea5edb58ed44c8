// The schema `granlub` parses cases with: the common sections plus the section of every solver
// module compiled in. Its own file so that the case-parser fuzzer (tests/core/fuzz) can compile
// it with the section declarations alone, without the solvers.
#pragma once
#include "granlub/case/case.h"

namespace granlub::cli {

// Common sections plus every compiled module's section.
Schema full_schema();

}  // namespace granlub::cli
