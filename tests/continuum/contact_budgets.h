// The budgets per wall of the trough's cross-section with the contact stress (docs/continuum-model.md §2.9a), shared
// by the contact suites: on 10 x 30, 20 x 60 and 40 x 120 cells the walls' forces (kinetic + contact tractions)
// balance, the contacts take a real share of the work, and the energy defect (work - bulk dissipation - sinks -
// contacts' dissipation) falls at second order to zero, not to a constant (Richardson's extrapolation).
#pragma once
#include <cmath>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "cross_section_fixtures.h"

namespace granlub::continuum::testing {

// `each(observables)`: the suite's own checks on every grid.
template <class Each>
void check_contact_budgets(const CrossSectionProblem& p, const Each& each) {
    std::vector<double> defects;
    for (int n : {10, 20, 40}) {
        const CrossSectionSolution s = solve_cross_section(p, grid(n, 3 * n));
        const auto o = observe(p, s);
        double work = 0;
        for (const auto& w : o.walls) work += w.work;
        BOOST_TEST_MESSAGE(n << " x " << 3 * n << ": force balance " << o.force_balance << ", energy defect "
                             << o.energy_defect << ", contacts' share of the work " << o.contact_dissipation / work
                             << ", side share " << o.side_share);
        BOOST_TEST(std::abs(o.force_balance) < 1e-8);
        BOOST_TEST(o.contact_dissipation > 0.2 * work);
        each(o);
        defects.push_back(o.energy_defect);
    }
    BOOST_TEST(defects[0] / defects[1] > 3.0);  // second order: x4 per halving
    BOOST_TEST(defects[1] / defects[2] > 3.0);
    const double limit = (4 * defects[2] - defects[1]) / 3;
    BOOST_TEST_MESSAGE("extrapolated defect " << limit);
    BOOST_TEST(std::abs(limit) < 0.2 * std::abs(defects[2]));
}

}  // namespace granlub::continuum::testing
