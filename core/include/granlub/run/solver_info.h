// A solver's declaration: its name and what differs between the solvers, as data. Each solver
// module declares its row as kSolver in granlub/<name>/command.h, beside the three functions every
// module has:
//   SectionSpec section();                           its case section, one line per key
//   int run(const Case&, const RunOptions&);         the selected points through run_sweep(); the exit code
//   void check(const Case&, const RunOptions&);      what run() would reject for the selected points
//       (quick and --full run lengths), without running: CaseError for bad input, SolverError for a
//       case the solver cannot run
// `granlub` reads the row (its subcommand, options and stage; cmake/GranlubSolverList.cmake lists the modules), the
// solver's own code names itself by it, and every summary.json it writes records its kind
// ("kind"): how the report, which reads files only, tells the kinds of results apart.
#pragma once

#include <vector>

#include "granlub/case/schema.h"

namespace granlub {

struct Case;
struct RunOptions;

// What a solver's results are, as the report reads them.
enum class SolverKind {
    Continuum,  // fields of a continuum model (no particles, no walls but the gap's two)
    Lattice,    // a lattice of grains: solid fraction is occupancy, stresses are lattice analogues
    Particles,  // grains in a particle engine: stresses in Pa on walls that exist
};

// The summary's "kind": "continuum", "lattice", "particles".
constexpr const char* to_string(SolverKind k) {
    return k == SolverKind::Continuum ? "continuum" : k == SolverKind::Lattice ? "lattice" : "particles";
}

struct SolverInfo {
    const char* name;         // its namespace, command, case section and results folder
    const char* description;  // its command's line in `granlub --help`
    SolverKind kind;
    // its points are processes of an external engine (LIGGGHTS, YADE), which `granlub run` runs
    // side by side with the other engines' (cli/run_all.cpp)
    bool engine = false;
    bool seeded = false;  // stochastic: takes --seed and --threads
    bool ranks = false;   // runs MPI ranks: takes --np
    // `granlub <name> CASE --map`: the case's (U, P) map instead of its points, written to
    // <results>/<name>/kMapFile (the report reads it); nullptr: no map
    int (*map)(const Case& c, const RunOptions& o, int speeds, int loads) = nullptr;
    // runs a ring case ([cell] geometry = "annulus") as built; the report sets these results beside
    // its slice case's ([report] slice_case)
    bool whole_ring = false;
    // its points are what `granlub bulk-rheology` reduces to the bulk-rheology table
    bool bulk_rheology = false;
    // with its section's start = "warm", each point starts from this solver's final state of the same
    // point (its results folder), so it runs after it; nullptr: always cold
    const char* warm_from = nullptr;
};

// The file of a solver's (U, P) map under <results>/<name>/ (SolverInfo::map).
inline constexpr const char* kMapFile = "map.csv";

// The declarations of the solvers a schema's sections carry (Schema::declare_solver; `granlub`'s
// case_schema(), cli/modules.h), in its order (`granlub run` order): what the report, which links no
// solver, knows of them.
inline std::vector<const SolverInfo*> declared_solvers(const Schema& schema) {
    std::vector<const SolverInfo*> out;
    for (const SectionSpec& s : schema.sections())
        if (s.solver) out.push_back(s.solver);
    return out;
}

}  // namespace granlub
