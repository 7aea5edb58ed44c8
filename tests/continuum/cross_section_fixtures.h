// Shared set-up for the cross-section suites.
#pragma once
#include "fixtures.h"
#include "granlub/continuum/cross_section_solver.h"

namespace granlub::continuum::testing {

inline constexpr double kPi = 3.14159265358979323846;

inline CrossSectionSettings grid(int ny, int nz) {
    CrossSectionSettings s;
    s.cells_y = ny, s.cells_z = nz;
    return s;
}

// S&T's grains between family-K walls at speed U, a gap of `lambda` diameters and a width of `width` diameters, the
// side walls as the floor; with the illustrative contact stress (fixtures.h, not fitted) when `mu_c` >= 0.
inline CrossSectionProblem contact_trough(double U, double lambda, double width, double mu_c = kIllustrativeMuC) {
    CrossSectionProblem p;
    p.gap = problem(sawyer(U));
    p.gap.Lambda = lambda;
    if (mu_c >= 0) p.gap = with_contact(p.gap, illustrative_contact(mu_c));
    p.outer = p.inner = p.gap.bottom;
    p.width = width;
    return p;
}

}  // namespace granlub::continuum::testing
