// `granlub compare CASE`: the cross-code comparison report.
//
// Reads every solver's results (results/<solver>/<point>/{profile.csv, summary.json}) for every
// operating point and writes results/report/: index.html (self-contained), report.md,
// metrics.csv, plots/ (SVG + data + gnuplot scripts) and paraview/ (.vtm + .vtp per point).
// Works with any subset of solvers; the report states which are missing, stale or corrupt.
#pragma once
#include <string>

#include "granlub/case/case.h"
#include "granlub/run/sweep.h"

namespace granlub::postproc {

// Writes the report (replacing any previous one as a whole) and prints where it went.
// Returns 0 when every result found was usable, 1 when some were stale or corrupt (the report is
// still written without them and names them). Throws Error when no usable result exists at all.
// Honours o.point (only that point) and o.results_root. Holds each point it reads locked shared (of
// every solver) and the report exclusive while it works (granlub/run/run_lock.h): another run writing
// one of those points makes it wait, or with o.wait false throw ResultsInUse; runs on other points
// do not.
int compare(const Case& c, const RunOptions& o);

// The closing table for `granlub run`: one row per solver and point with the result state and
// the headline numbers (nu_bar/nu_max, wall stresses, slip/U, wall-clock). Reads result files
// only; never throws for bad results (they show as stale/corrupt). Ends with a newline.
std::string summary_table(const Case& c, const RunOptions& o);

}  // namespace granlub::postproc
