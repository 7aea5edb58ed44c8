// A solver's declaration: its name and what differs between the solvers, as data. Each solver
// module declares its row as kSolver in granlub/<name>/command.h, beside the three functions every
// module has:
//   SectionSpec section();                           its case section, one line per key
//   int run(const Case&, const RunOptions&);         the selected points through run_sweep(); the exit code
//   void check(const Case&, const RunOptions&);      what run() would reject for the selected points
//       (quick and --full run lengths), without running: CaseError for bad input, SolverError for a
//       case the solver cannot run
// `granlub` reads the row (its subcommand, options and stage; cli/solvers.h lists the modules), the
// solver's own code names itself by it, and every summary.json it writes records its kind
// ("kind"): how the report, which reads files only, tells the kinds of results apart.
#pragma once

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
    // `granlub <name> CASE --map`: the case's (U, P) map instead of its points; nullptr: no map
    int (*map)(const Case& c, const RunOptions& o, int speeds, int loads) = nullptr;
};

}  // namespace granlub
