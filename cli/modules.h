// The solver modules compiled into this `granlub`, in the order `granlub run` uses them.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/run/solver_info.h"
#include "granlub/run/sweep.h"

namespace granlub::cli {

struct SolverModule {
    SolverInfo info;   // what the solver is (its kSolver row)
    std::string name;  // info.name: subcommand and results folder name
    std::function<int(const Case&, const RunOptions&)> run;
    std::function<void(const Case&, const RunOptions&)> check;  // what run would reject, without running
};

const std::vector<SolverModule>& solver_modules();
// full_schema() with each solver's section carrying its declaration (SectionSpec::solver): the
// schema `granlub` reads cases with, so that the report knows the solvers' data from the case.
Schema case_schema();
// m.check(c, o) before any run: bad input throws (CaseError, exit 2); a point m cannot run does not
// (its run names it and goes on with the other points).
void check_input(const SolverModule& m, const Case& c, const RunOptions& o);
// `granlub check` after the case parses: every compiled solver's check() on every point (quick
// and --full run lengths). One line per solver; returns 2 when any finds bad input (the error
// names it); points a solver cannot run (e.g. a smooth wall in the continuum) are warnings.
int check_solvers(const Case& c, const RunOptions& o);
// `granlub compare` if postproc is compiled in; otherwise throws.
int compare(const Case& c, const RunOptions& o);
bool have_compare();
// `granlub continuum-fit CASE --table FILE` if the continuum is compiled in (continuum/command.h run_fit);
// otherwise throws.
struct ContinuumFitArgs {
    std::string table, out, bulk_case;
    std::vector<std::string> free;
    bool temperature = false;
};
int continuum_fit(const Case& c, const ContinuumFitArgs& a);
bool have_continuum();  // whether the continuum is compiled in (its continuum-fit)
// The closing table of `granlub run`: one row per solver and point (postproc's summary table when
// postproc is built in, else the mean solid fraction and wall stresses read from the summaries).
void closing_table(const Case& c, const RunOptions& o);

}  // namespace granlub::cli
