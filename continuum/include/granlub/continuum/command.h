// `granlub continuum CASE [--point ID]`: the GKL continuum solver on every operating point.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/case/schema.h"
#include "granlub/run/solver_info.h"
#include "granlub/run/sweep.h"

namespace granlub::continuum {

// The functions every solver module has (granlub/run/solver_info.h).
SectionSpec section();
int run(const Case& c, const RunOptions& o);
void check(const Case& c, const RunOptions& o);
// `granlub continuum CASE --map [--map-grid SPEEDS,LOADS]`: the case's (U, P) map (map.h) written to
// <results>/continuum/map.csv under its lock (run_lock.h: continuum/map.csv), and one line with its cost. Returns 0,
// or 1 when no point of the grid could be solved (the file is written either way).
int run_map(const Case& c, const RunOptions& o, int speeds, int loads);

// `granlub continuum-fit CASE --table FILE`: the case's closures' free constants fitted on a bulk-rheology table
// (rheology_fit.h); prints the fit and writes the fitted constants as a TOML fragment, atomically. Returns 0; throws
// CaseError for bad input (the table, the free keys, too few answers), SolverError when the fit does not converge.
struct FitCommand {
    std::filesystem::path table;
    std::filesystem::path out;        // empty: CASE/continuum_fit.toml
    std::vector<std::string> free;    // empty: the constants of the branches the case chooses
    bool temperature = false;         // fit T/(d gamma_dot)^2 too
    // with a wall key free (slip_dissipation): the bulk case whose walls the table measured; empty: the case the
    // table's provenance line names (`# case NAME (PATH), ...`), PATH relative to the working directory
    std::filesystem::path bulk_case;
};
inline constexpr const char* kFitFile = "continuum_fit.toml";
int run_fit(const Case& c, const FitCommand& o);

// What the solver is (granlub/run/solver_info.h).
inline constexpr SolverInfo kSolver{.name = "continuum", .description = "granular kinetic lubrication (GKL) continuum solver",
                                    .kind = SolverKind::Continuum, .map = &run_map};

}  // namespace granlub::continuum
