// The one reader of granlub's numeric text tables (table.h).
#include "granlub/results/table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/results/file_io.h"

namespace granlub {

Table& Table::add(std::string name, std::vector<double> values) {
    if (!columns.empty() && values.size() != rows())
        throw Error(fmt::format("internal: table column '{}' has {} rows, others have {}", name, values.size(), rows()));
    if (has(name)) throw Error(fmt::format("internal: table column '{}' added twice", name));
    names.push_back(std::move(name));
    columns.push_back(std::move(values));
    return *this;
}

bool Table::has(std::string_view name) const {
    for (const auto& n : names)
        if (n == name) return true;
    return false;
}

const std::vector<double>& Table::column(std::string_view name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return columns[i];
    throw Error(fmt::format("table has no column '{}' (columns: {})", name, fmt::join(names, ", ")));
}

namespace {

void split(const std::string& line, TableFormat::Separator sep, std::vector<std::string>& cells) {
    cells.clear();
    if (sep == TableFormat::Separator::whitespace) {
        std::istringstream ss(line);
        for (std::string t; ss >> t;) cells.push_back(std::move(t));
        return;
    }
    for (std::size_t start = 0;;) {
        const auto comma = line.find(',', start);
        cells.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos) return;
        start = comma + 1;
    }
}

void set_names(Table& t, std::vector<std::string> names) {
    t.names = std::move(names);
    t.columns.assign(t.names.size(), {});
}

}  // namespace

Table parse_table(std::string_view text, const std::string& source, const TableFormat& f) {
    Table t;
    if (!f.header && !f.names.empty()) set_names(t, f.names);
    bool named = !t.names.empty();
    std::size_t first_row_line = 0;
    std::string line;
    std::vector<std::string> cells;
    std::size_t lineno = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t eol = std::min(text.find('\n', start), text.size());
        line.assign(text.substr(start, eol - start));
        start = eol + 1;
        ++lineno;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        split(line, f.separator, cells);
        if (cells.empty()) continue;  // a whitespace-only line
        if (!named && f.header) {
            if (!f.expected_header.empty() && line != f.expected_header)
                throw Error(fmt::format("{}:{}: header '{}', expected '{}'", source, lineno, line, f.expected_header));
            set_names(t, cells);
            named = true;
            continue;
        }
        if (!named) {  // no header, no names: the first row sets the count
            std::vector<std::string> numbers;
            for (std::size_t c = 1; c <= cells.size(); ++c) numbers.push_back(std::to_string(c));
            set_names(t, std::move(numbers));
            named = true;
            first_row_line = lineno;
        }
        if (cells.size() != t.names.size()) {
            if (f.header)
                throw Error(fmt::format("{}:{}: {} values, the header has {} columns", source, lineno, cells.size(),
                                        t.names.size()));
            if (!f.names.empty())
                throw Error(fmt::format("{}:{}: {} values, expected {}: {}", source, lineno, cells.size(),
                                        t.names.size(), fmt::join(t.names, " ")));
            throw Error(fmt::format("{}:{}: {} values, expected {} as on line {}", source, lineno, cells.size(),
                                    t.names.size(), first_row_line));
        }
        for (std::size_t c = 0; c < cells.size(); ++c) {
            char* end = nullptr;
            const double v = std::strtod(cells[c].c_str(), &end);
            if (cells[c].empty() || end == cells[c].c_str() || *end != '\0')
                throw Error(fmt::format("{}:{}: '{}' is not a number (column '{}')", source, lineno, cells[c], t.names[c]));
            if (f.finite && !std::isfinite(v))
                throw Error(fmt::format("{}:{}: non-finite value '{}' in column '{}'{}{}", source, lineno, cells[c],
                                        t.names[c], f.nonfinite_hint.empty() ? "" : ": ", f.nonfinite_hint));
            t.columns[c].push_back(v);
        }
        t.line.push_back(lineno);
    }
    if (f.header && !named) throw Error(fmt::format("{}: empty table (no header row)", source));
    return t;
}

Table read_table(const std::filesystem::path& file, const TableFormat& format) {
    return parse_table(read_file(file), file.string(), format);
}

Table read_solver_output(const std::filesystem::path& file, const TableFormat& format, std::string_view missing) {
    if (!std::filesystem::exists(file)) throw SolverError(fmt::format("{}: {}", file.string(), missing));
    try {
        return read_table(file, format);
    } catch (const SolverError&) {
        throw;
    } catch (const Error& e) {
        throw SolverError(e.what());
    }
}

}  // namespace granlub
