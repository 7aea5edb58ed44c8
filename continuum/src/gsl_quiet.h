// GSL aborts on errors by default; granlub reports them as SolverError instead.
#pragma once
#include <gsl/gsl_errno.h>

namespace granlub::continuum::detail {
inline void gsl_quiet() {
    static const bool once = [] {
        gsl_set_error_handler_off();
        return true;
    }();
    (void)once;
}
}  // namespace granlub::continuum::detail
