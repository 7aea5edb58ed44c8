// The continuum's (U, P) map (results/continuum/map.csv, written by `granlub continuum CASE --map`;
// format in continuum/include/granlub/continuum/map.h) drawn under the particle solvers' points:
// contour lines of the continuum's mu (top wall) and mean solid fraction over speed x load, its
// contact/collision boundary, and mu(I) lines at the case's loads beside the particle results and
// Jop, Forterre & Pouliquen 2006. Nothing when the case has no map. The report reads files only.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "results/collect.h"
#include "formats/figure_model.h"

namespace granlub::postproc {

struct ContinuumMapRow {
    double speed = 0, load = 0;  // m/s, Pa
    std::string status;          // steady | ordered | failed
    double nu = 0, gap = 0, mu_bottom = 0, mu_top = 0, inertial = 0;
    bool collision = false;
};

// The rows of a map file; empty when the file does not exist. Throws Error naming the file and line
// for a malformed row.
std::vector<ContinuumMapRow> read_continuum_map(const std::filesystem::path& file);

std::vector<Figure> continuum_map_figures(const Case& c, const Collection& col);

}  // namespace granlub::postproc
