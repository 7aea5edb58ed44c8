// ParaView files: per operating point, <dir>/<point>.vtm, a multiblock data set with one block per
// solver (named after it), each block a .vtp polyline across the gap at x = z = 0 (y in metres)
// carrying the profile columns as point data (ASCII, so the files are also plain XML); a particle
// run with a section.csv adds a block "<solver> cross-section", an image of y x z cells (width: the
// case's trough width; none when it is 0, i.e. periodic) with solid_fraction and u_over_U.
#pragma once
#include <filesystem>
#include <vector>

#include "results/collect.h"

namespace granlub::postproc {

// Returns the .vtm files written (one per point that has at least one usable run).
std::vector<std::filesystem::path> write_paraview(const Collection& col, double gap, double width,
                                                  const std::filesystem::path& dir);

}  // namespace granlub::postproc
