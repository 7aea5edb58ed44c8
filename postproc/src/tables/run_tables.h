// The tables of what each run is and gave: its state per solver and point, the key numbers, what
// each solver's numbers mean (results/scope.h) and how ordered the particle packings are.
#pragma once
#include <string>

#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

std::string state_name(ResultState s);
// Result state per solver (rows, missing solvers included) and point (columns).
Table status_table(const Collection& col);
// Every run with a state that has a reason, with that reason (solver, point, state, why).
Table state_reasons(const Collection& col);
// Key numbers per solver and point (nu_bar/nu_max, wall stresses, slip/U, wall clock; under load
// control also the gap and P_top / target); used by the report and by summary_table().
Table key_numbers(const Case& c, const Collection& col);
// Whether any run's values were checked at half the time step (the key numbers carry [Δt x]).
bool any_dt_checked(const Collection& col);
// The most halvings of the case's step the dense rule gave any usable run: 0 (none), 1 (half the
// case's step, [dem] dense_inertial_number) or 2 (a quarter, [dem] quarter_step_inertial_number).
int dense_step_halvings(const Collection& col);
// Per solver: the body forces it models, what its wall stresses are, how long it ran (scope.h).
Table scope_table(const Case& c, const Collection& col);
// The packing's order and contacts of the particle solvers (run.order, run.flow_regime).
Table order_table(const Collection& col);

}  // namespace granlub::postproc
