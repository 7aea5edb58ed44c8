// The failure of JH06's literal steady-state protocol (docs/automaton-model.md §4.5), as a clear error.
#include <fmt/format.h>

#include "granlub/automaton/ensemble.h"
#include "granlub/error.h"

namespace granlub::automaton {

void require_converged(const std::string& point, const Params& p, const RunsProtocol& rp) {
    if (!rp.used || rp.converged) return;
    std::string tried;
    for (std::size_t k = 0; k < rp.lengths.size(); ++k) tried += (k ? ", " : "") + std::to_string(rp.lengths[k]);
    const std::string last =
        rp.du.empty() ? "only one run fitted, nothing was compared"
                      : fmt::format("last max |du| = {:.4f} U (row {}), max |dnu| = {:.4f} (row {}), between the "
                                    "runs of {} and {} steps",
                                    rp.du.back(), rp.du_row, rp.dnu.back(), rp.dnu_row,
                                    rp.lengths[rp.lengths.size() - 2], rp.lengths.back());
    throw SolverError(fmt::format(
        "point {}: [automaton] steady_state = \"runs\" (JH06's literal protocol) did not converge: runs of {} steps "
        "({} replicas) never agreed within runs_tol_u = {} U and runs_tol_nu = {} before runs_max_steps = {}; {}. "
        "Try: a larger runs_max_steps, more replicas (less noise per reading), or steady_state = \"blocks\". A run "
        "that needs more than ~2000 steps points to a jammed configuration (e.g. vector mode with "
        "vec_blocked = \"wait\")",
        point, tried, p.run.replicas, p.run.runs_tol_u, p.run.runs_tol_nu, p.run.runs_max_steps, last));
}

}  // namespace granlub::automaton
