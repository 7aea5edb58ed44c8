// The bulk-rheology table of a case (cases/bulk_shear): one row per DEM point, the core's rheology
// (bulk_rheology.h) of the point's answer and its change against the run it was Delta-t-checked
// against, with the point's status. What `granlub bulk-rheology` writes; its format (columns, units,
// comment lines) is documented in cases/bulk_shear/README.md, and kBulkTableFormat names it.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/case/case.h"

namespace granlub {

inline constexpr const char* kBulkTableFormat = "granlub-bulk-rheology 1";
inline constexpr const char* kBulkTableFile = "bulk_rheology.csv";

struct BulkTable {
    std::string csv;                 // comment lines (format, provenance), header, rows
    std::size_t rows = 0;
    std::vector<std::string> notes;  // the points left out, and why (also in the comment lines)
};

// Reads results_root/dem/<point>/ for every point of the case. A point whose result is missing, stale
// or corrupt (load_result) is left out with a note; a complete one is a row whatever its status
// (steady, transient, dt-unconverged: the row says which). Throws Error when a complete result lacks
// what the reduction needs (a profile column, too few core stations).
BulkTable bulk_rheology_table(const Case& c, const std::filesystem::path& results_root);

}  // namespace granlub
