// ParaView files: per operating point, <dir>/<point>.vtm, a multiblock data set with one block per
// solver (named after it), each block a .vtp polyline across the gap at x = z = 0 (y in metres)
// carrying the profile columns as point data (ASCII, so the files are also plain XML).
#pragma once
#include <filesystem>
#include <vector>

#include "collect.h"

namespace granlub::postproc {

// Returns the .vtm files written (one per point that has at least one usable run).
std::vector<std::filesystem::path> write_paraview(const Collection& col, double gap, const std::filesystem::path& dir);

}  // namespace granlub::postproc
