// The solver modules compiled into this `granlub`, in the order `granlub run` uses them.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "granlub/case.h"
#include "granlub/sweep.h"

namespace granlub::cli {

struct SolverModule {
    std::string name;         // subcommand and results folder name
    std::string description;
    std::function<int(const Case&, const RunOptions&)> run;
};

const std::vector<SolverModule>& solver_modules();
// `granlub compare` if postproc is compiled in; otherwise throws.
int compare(const Case& c, const RunOptions& o);
bool have_compare();
// The closing table of `granlub run`: one row per solver and point (postproc's summary table when
// postproc is built in, else the mean solid fraction and wall stresses read from the summaries).
void closing_table(const Case& c, const RunOptions& o);

}  // namespace granlub::cli
