// What each solver's numbers mean: which body forces it models, what its "stresses" are and how
// long it ran. Read from the summaries the solvers write (run block) and the case; shown beside
// the numbers so that a continuum stress is not read as a DEM one.
#pragma once
#include <string>

#include "results/collect.h"

namespace granlub::postproc {

struct SolverScope {
    std::string body_forces;  // "gravity ... included", or the solver's own note on what it ignores
    std::string stresses;     // what its wall stresses are
    std::string run_length;   // simulated time, steps or iterations over the compared points
    std::string grains_walls; // the grains' sizes and the walls this solver had
};

SolverScope solver_scope(const Case& c, const Collection& col, const std::string& solver);

// A lattice solver's wall stresses (the automaton's) are lattice analogues (wall momentum per
// lattice step scaled by rho_p nu_max U^2, so proportional to U^2 by construction), not measured
// stresses: a run's, or a solver's (Collection::kind).
bool lattice_stresses(const Run& r);
bool lattice_stresses(const Collection& col, const std::string& solver);

// A text field of a run's summary (run.<key>), or "" when it has none.
std::string run_text(const Run& r, const char* key);
// An object field of a run's summary (run.<key>, e.g. the dense_step record), or null when it has none.
const nlohmann::json* run_object(const Run& r, const char* key);
// How often [dem]'s dense rule halved the case's step for this run (run.dense_step.halvings): 0 without
// the record, 1 when the record has no count (every result before quarter_step_inertial_number), else 2.
int dense_step_halvings(const Run& r);
inline constexpr const char* kLatticeStressNote =
    "the automaton's stresses are lattice analogues (wall momentum per lattice step × ρ_p ν_max U², so ∝ U² by "
    "construction), drawn in Pa for scale only: not a measured stress, neither its magnitude nor its exponent "
    "compares with the other solvers'";

}  // namespace granlub::postproc
