// The one reader of granlub's numeric text tables. Two dialects, one parser:
//  - the CSV files granlub and its YADE driver write (profile.csv, section.csv, particles.csv,
//    wallforce.csv, plate.csv): a header row naming the columns, comma-separated numbers;
//  - LIGGGHTS' `fix ave/time` and `fix print` outputs: whitespace-separated numbers, no header.
// Blank lines and lines starting with '#' are comments in both. A format may name columns kept as text
// (a status, an id: TableFormat::text) and let empty cells stand for "not available" (NaN).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace granlub {

// Named columns of equal length; `line` is each row's line in its source (for error messages).
// `names`/`columns` are the numeric columns, `text_names`/`text_columns` those TableFormat::text names.
struct Table {
    std::vector<std::string> names;
    std::vector<std::vector<double>> columns;
    std::vector<std::string> text_names;
    std::vector<std::vector<std::string>> text_columns;
    std::vector<std::size_t> line;

    Table& add(std::string name, std::vector<double> values);  // throws on length mismatch
    bool has(std::string_view name) const;                     // a numeric column
    bool has_text(std::string_view name) const;
    const std::vector<double>& column(std::string_view name) const;     // throws naming the columns
    const std::vector<std::string>& text(std::string_view name) const;  // throws naming the text columns
    std::size_t rows() const {
        return !columns.empty() ? columns.front().size() : text_columns.empty() ? 0 : text_columns.front().size();
    }
};

struct TableFormat {
    enum class Separator { comma, whitespace };
    Separator separator = Separator::comma;
    // With a header the first data line names the columns; without one they are `names` when
    // given (which also fixes the column count), else "1", "2", ... as many as the first row has.
    bool header = true;
    std::vector<std::string> names;
    std::string expected_header;  // with a header: it must read exactly this ("" = any)
    bool finite = false;          // reject nan and inf (strtod reads them; a blown-up run prints them)
    std::string nonfinite_hint;   // appended to the non-finite error, e.g. what to do about it
    std::vector<std::string> text;  // columns read as text, not numbers (Table::text); absent ones are not an error
    bool empty_cells = false;       // an empty numeric cell reads as NaN ("not available") instead of an error
};

// Throws Error naming source:line for a bad header, a row of another length, a cell that is not a
// number, or (with `finite`) a non-finite one; and for a table without a header when one is due.
Table parse_table(std::string_view text, const std::string& source, const TableFormat& format = {});

// The file's text through parse_table; Error "<file>: cannot be read" when it cannot be opened.
Table read_table(const std::filesystem::path& file, const TableFormat& format = {});

// A solver's own output file: missing or malformed, it is the run's failure (SolverError), and a
// missing file says `missing` ("LIGGGHTS wrote no wall-force file").
Table read_solver_output(const std::filesystem::path& file, const TableFormat& format, std::string_view missing);

}  // namespace granlub
