// The bulk-rheology table of a case (cases/bulk_shear): one row per DEM point, the core's rheology
// (bulk_rheology.h) of the point's answer and its change against the run it was Delta-t-checked
// against, with the point's status. What `granlub bulk-rheology` writes; its format (columns, units,
// comment lines) is documented in cases/bulk_shear/README.md, and kBulkTableFormat names it.
// Its one reader is read_bulk_table (below): what a fit takes from it, and which rows are answers.
#pragma once
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/particles/bulk_rheology.h"

namespace granlub {

inline constexpr const char* kBulkTableFormat = "granlub-bulk-rheology 1";
inline constexpr const char* kBulkTableFile = "bulk_rheology.csv";
// The walls' columns (WallLayers, bulk_rheology.h), written after the core's; a table written before them has
// none, and reads the same (its rows' wall values NaN, BulkRows::missing_wall_columns naming them).
inline constexpr const char* kWallColumns[] = {"slip_bottom_over_U",    "slip_bottom_err",    "slip_top_over_U",
                                               "slip_top_err",          "T_wall_bottom_over_U2", "T_wall_bottom_err",
                                               "T_wall_top_over_U2",    "T_wall_top_err"};

struct BulkTable {
    std::string csv;                 // comment lines (format, provenance), header, rows
    std::size_t rows = 0;
    std::vector<std::string> notes;  // the points left out, and why (also in the comment lines)
};

// Reads results_root/<solver>/<point>/ for every point of the case (solver: the one declared with
// SolverInfo::bulk_rheology, granlub/run/solver_info.h). A point whose result is missing, stale
// or corrupt (load_result) is left out with a note; a complete one is a row whatever its status
// (steady, transient, dt-unconverged: the row says which). Throws Error when a complete result lacks
// what the reduction needs (a profile column, too few core stations).
BulkTable bulk_rheology_table(const Case& c, const std::filesystem::path& results_root, const std::string& solver);

// One row of a table as a reader needs it. Cells left empty by the writer (not available) read as NaN.
struct BulkRow {
    std::string point, status, core_dt_check;
    std::size_t line = 0;         // the row's line in its file, for messages
    double load = 0;              // load_Pa: the imposed normal stress, Pa
    double speed = NAN;           // speed_m_s: U, m/s (NaN when the table has no such column)
    Measured pressure;            // pressure_Pa, pressure_err: the core's P, Pa
    Measured inertial;            // I, I_err
    Measured friction;            // mu, mu_err
    Measured solid_fraction;      // nu, nu_err
    Measured temperature_scaled;  // T_scaled, T_scaled_err: T/(d gamma_dot)^2
    // kWallColumns: slip/U at each wall and T/U^2 next to each wall's bump tops; NaN when the table lacks them
    Measured slip_bottom{NAN, NAN}, slip_top{NAN, NAN}, T_wall_bottom{NAN, NAN}, T_wall_top{NAN, NAN};
};

// The reading rule (cases/bulk_shear/README.md, "The table"): a row is an answer when its status is `steady`
// and its core_dt_check `converged`; every other row is a labelled measurement, never a point of a fit.
bool is_answer(const BulkRow& r);

struct BulkRows {
    std::string source;                   // the file, as messages name it
    std::vector<std::string> provenance;  // the comment lines after the format line, without '# '
    std::vector<BulkRow> rows;            // every row, in the file's order
    std::vector<std::string> missing_wall_columns;  // the kWallColumns the table lacks (a table written before them)
    std::vector<BulkRow> answers() const;  // the rows is_answer() takes
};

// Throws Error naming the source (and the line) for a table of another format (its first line is not
// "# format <kBulkTableFormat>"), a column the reader needs missing (named with its unit), a cell that is not a
// number, and an answer row whose values cannot be (I, P not positive; nu outside (0, 1); a value or an error
// non-finite or an error negative).
BulkRows parse_bulk_table(std::string_view text, const std::string& source);
BulkRows read_bulk_table(const std::filesystem::path& file);

}  // namespace granlub
