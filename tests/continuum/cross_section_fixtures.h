// Shared set-up for the cross-section suites.
#pragma once
#include "granlub/continuum/cross_section_solver.h"

namespace granlub::continuum::testing {

inline constexpr double kPi = 3.14159265358979323846;

inline CrossSectionSettings grid(int ny, int nz) {
    CrossSectionSettings s;
    s.cells_y = ny, s.cells_z = nz;
    return s;
}

}  // namespace granlub::continuum::testing
